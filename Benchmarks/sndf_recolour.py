"""vtkSNDFRenderPass: a colour-map change after convergence, re-shaded from the samples (the
bins' colours multiplied by the 3x3 matrix that maps the old colours to the new ones) against
sampling again to the same sample count (what the pass did before, and what plain
super-sampling must do). llvmpipe, one run.

Scene: the fcc crystal of sndf_benchmark.py (two species, CELLS^3 unit cells) coloured by a
"type" scalar (0 or 1) through a vtkColorTransferFunction, seen whole at WIDTHxHEIGHT, headlight.
Measured in the same run:
- sample pass: a refinement frame with SamplesPerFrame 1, mean over SAMPLES frames;
- recolour: the frame after new colours for the two types (SNDFRecolour.glsl over the cached
  tiles, their rebake, the shade), mean of two changes;
- re-sampling to the same quality: SAMPLES sample passes.

usage: Scripts/with_xvfb.sh python3 Benchmarks/sndf_recolour.py [CELLS WIDTH HEIGHT SAMPLES]
(PYTHONPATH=build/lib/python3/dist-packages:Testing/VTKPython); appends to
Benchmarks/results/sndf_recolour.csv
"""
import os
import sys
import time

import numpy as np

import particlerendering as pr
from prVTKTesting import append_csv, crystal_view, fcc_crystal
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction

cells, width, height, samples = (int(a) for a in (sys.argv[1:5] + ["40", "1280", "720", "64"][len(sys.argv[1:5]):]))
xyz, rgb = fcc_crystal(cells)
types = (rgb[:, 0] > 128).astype(np.float32)
MAPS = ([(0.0, 0.23, 0.30, 0.75), (1.0, 0.71, 0.02, 0.15)],
        [(0.0, 0.95, 0.80, 0.20), (1.0, 0.20, 0.60, 0.35)],
        [(0.0, 0.40, 0.40, 0.90), (1.0, 0.90, 0.50, 0.10)])


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
renderer, window, actor = crystal_view(xyz, rgb, (width, height), sndf,
                                       position=(2.5 * cells, 1.9 * cells, 3.4 * cells),
                                       focal_point=(cells / 2, cells / 2, cells / 2))
array = numpy_to_vtk(types, deep=True)
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
sample_times = [timed(window) for _ in range(samples)]
assert sndf.GetConverged()
sample = np.mean(sample_times[1:])  # (the first builds the programs)
passes = sndf.GetNumberOfSamplePasses()
tiles = sndf.GetTileCache().GetNumberOfRecolouredTiles()
recolour = []
for points in MAPS[1:]:
    set_map(ctf, points)
    recolour.append(timed(window))
assert sndf.GetNumberOfSamplePasses() == passes and sndf.GetNumberOfRecolours() == 2
tiles = (sndf.GetTileCache().GetNumberOfRecolouredTiles() - tiles) // 2
recolour = float(np.mean(recolour))
resample = samples * sample

row = [len(xyz), width, height, samples, sample, recolour, resample, resample / recolour, tiles]
path = os.path.join(os.path.dirname(__file__), "results", "sndf_recolour.csv")
header = "particles,width,height,samples,sample_pass_s,recolour_s,resample_s,resample_over_recolour,tiles\n"
append_csv(path, header, row)
