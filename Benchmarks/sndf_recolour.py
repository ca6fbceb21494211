"""vtkSNDFRenderPass: a colour-map change after convergence, re-shaded from the samples against
sampling again to the same sample count (what the pass did before, and what plain
super-sampling must do). llvmpipe, one run.

Scene: the fcc crystal of sndf_benchmark.py (two species, CELLS^3 unit cells) seen whole at
WIDTHxHEIGHT, headlight, coloured through a vtkColorTransferFunction by
- MODE "types": a "type" scalar (0 or 1); new colours for the two types are a linear function of
  the old ones (the bins' colours times a 3x3 matrix);
- MODE "speed": a "speed" scalar drawn at random per atom in [0, 1]; a new continuous map
  re-shades from the bins' moments of the speed (KeepColourCoordinates).
KEEP (1 or 0) sets KeepColourCoordinates (the moments' cost shows in the sample pass and the
accumulation; with 0 and "speed" a new map samples again: no recolour time).
Measured in the same run:
- sample pass: a refinement frame with SamplesPerFrame 1, mean over SAMPLES frames, and its
  accumulation stage (GPU timer query);
- recolour: the frame after a new colour map (SNDFRecolour.glsl over the cached tiles, their
  rebake, the shade), mean of two changes;
- re-sampling to the same quality: SAMPLES sample passes.

usage: Scripts/with_xvfb.sh python3 Benchmarks/sndf_recolour.py [CELLS WIDTH HEIGHT SAMPLES MODE KEEP]
(PYTHONPATH=build/lib/python3/dist-packages:Testing/VTKPython); appends to
Benchmarks/results/sndf_recolour.csv and draws sndf_recolour.png from its rows.
(another directory: PR_BENCHMARK_RESULTS=DIR; Benchmarks/run.py --out sets it)
"""
import os
import sys
import time

import numpy as np

import particlerendering as pr
from prVTKTesting import append_csv, crystal_view, fcc_crystal
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction

args = sys.argv[1:7] + ["40", "1280", "720", "64", "types", "1"][len(sys.argv[1:7]):]
cells, width, height, samples = (int(a) for a in args[:4])
mode, keep = args[4], int(args[5]) != 0
xyz, rgb = fcc_crystal(cells)
if mode == "types":
    values = (rgb[:, 0] > 128).astype(np.float32)
    MAPS = ([(0.0, 0.23, 0.30, 0.75), (1.0, 0.71, 0.02, 0.15)],
            [(0.0, 0.95, 0.80, 0.20), (1.0, 0.20, 0.60, 0.35)],
            [(0.0, 0.40, 0.40, 0.90), (1.0, 0.90, 0.50, 0.10)])
else:
    values = np.random.default_rng(3).random(len(xyz)).astype(np.float32)
    MAPS = ([(0.0, 0.23, 0.30, 0.75), (0.5, 0.87, 0.87, 0.87), (1.0, 0.71, 0.02, 0.15)],
            [(0.0, 0.27, 0.00, 0.33), (0.5, 0.13, 0.57, 0.55), (1.0, 0.99, 0.91, 0.14)],
            [(0.0, 0.0, 0.0, 1.0), (0.25, 0.0, 1.0, 1.0), (0.5, 0.0, 1.0, 0.0), (0.75, 1.0, 1.0, 0.0),
             (1.0, 1.0, 0.0, 0.0)])


def timed(window):
    t = time.perf_counter()
    window.Render()
    window.GetRGBACharPixelData(0, 0, 0, 0, 0)  # wait for the GPU
    return time.perf_counter() - t


def set_map(ctf, points):
    ctf.RemoveAllPoints()
    for point in points:
        ctf.AddRGBPoint(*point)


sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(1)
sndf.SetTargetSamples(samples)
sndf.SetKeepColourCoordinates(keep)
sndf.CollectTimingsOn()
renderer, window, actor = crystal_view(xyz, rgb, (width, height), sndf,
                                       position=(2.5 * cells, 1.9 * cells, 3.4 * cells),
                                       focal_point=(cells / 2, cells / 2, cells / 2))
array = numpy_to_vtk(values, deep=True)
array.SetName("type")
mapper = actor.GetMapper()
mapper.GetInput().GetPointData().AddArray(array)
ctf = vtkColorTransferFunction()
set_map(ctf, MAPS[0])
mapper.SetLookupTable(ctf)
mapper.SetColorModeToMapScalars()
mapper.SetScalarModeToUsePointFieldData()
mapper.SelectColorArray("type")
mapper.SetScalarRange(0.0, 1.0)
timed(window)  # the frame of the change
sample_times = []
accumulate_times = []
for _ in range(samples):
    sample_times.append(timed(window))
    accumulate_times.append(sndf.GetLastAccumulateSeconds())
assert sndf.GetConverged()
sample = np.mean(sample_times[1:])  # (the first builds the programs)
accumulate = np.mean(accumulate_times[1:])
passes = sndf.GetNumberOfSamplePasses()
tiles = sndf.GetTileCache().GetNumberOfRecolouredTiles()
recolour = []
for points in MAPS[1:]:
    set_map(ctf, points)
    recolour.append(timed(window))
resample = samples * sample
if sndf.GetNumberOfSamplePasses() == passes and sndf.GetNumberOfRecolours() == 2:
    tiles = (sndf.GetTileCache().GetNumberOfRecolouredTiles() - tiles) // 2
    recolour = float(np.mean(recolour))
    ratio = resample / recolour
else:
    tiles, recolour, ratio = 0, float("nan"), float("nan")  # sampled again

row = [len(xyz), width, height, samples, mode, int(keep), sample, accumulate, recolour, resample,
       ratio, tiles, sndf.GetMemoryBytes() / 1048576.0]
# PR_BENCHMARK_RESULTS (set by Benchmarks/run.py --out) overrides the results directory
results = os.environ.get("PR_BENCHMARK_RESULTS") or os.path.join(os.path.dirname(__file__),
                                                                 "results")
path = os.path.join(results, "sndf_recolour.csv")
header = ("particles,width,height,samples,mode,keep_coordinates,sample_pass_s,accumulate_s,"
          "recolour_s,resample_s,resample_over_recolour,tiles,cache_mb\n")
append_csv(path, header, row)


def plot(path):
    """sndf_recolour.png from every row of the CSV with a mode: recolour frame against re-sampling
    to the same sample count, log scale."""
    import csv
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(path) as f:
        rows = [r for r in csv.DictReader(f) if r["mode"] and r["keep_coordinates"]]
    labels = ["%s, moments %s\n%.2g atoms" % (r["mode"], "on" if r["keep_coordinates"] == "1" else "off",
                                             float(r["particles"])) for r in rows]
    x = np.arange(len(rows))
    recolour = [float(r["recolour_s"]) for r in rows]
    resample = [float(r["resample_s"]) for r in rows]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.bar(x - 0.2, resample, 0.4, label="re-sampling (samples x sample pass)")
    ax.bar(x + 0.2, [v if v == v else 0.0 for v in recolour], 0.4, label="recolour frame")
    for i, v in enumerate(recolour):
        ax.text(x[i] + 0.2, v * 1.1 if v == v else 0.15, "%.2f s" % v if v == v else "samples\nagain",
                ha="center", fontsize=8)
    ax.set_yscale("log")
    ax.set_ylim(0.1, 100.0)
    ax.set_xticks(x)
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylabel("seconds (llvmpipe)")
    ax.set_title("S-NDF: a new colour map after convergence (%s x %s, %s samples)"
                 % (rows[-1]["width"], rows[-1]["height"], rows[-1]["samples"]))
    ax.legend(fontsize=8, loc="upper center", ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.splitext(path)[0] + ".png", dpi=100)


plot(path)
