"""vtkSNDFRenderPass, error against time (llvmpipe, one run): S-NDF refinement against plain
super-sampling at equal time, and the bins knob.

Scene: the fcc crystal of two species of TestSNDFRenderPass (16^3 cells, 16 384 atoms, radius
0.36 lattice constants), about two pixels per atom at WIDTHxHEIGHT, headlight, specular 0.3.
Reference: the plain core rendered at 32x the size and box-filtered (1024 regular samples per
pixel). Measured in the same run:
- S-NDF, 8x8 bins: the error after N = 1, 2, 4, ..., 256 samples per pixel (SamplesPerFrame 1,
  the wall time of the renders since the change, read back with glFinish semantics);
- plain super-sampling: the core at k times the size (k = 1, 2, 4, 8, 16: N = k^2 samples per
  pixel), box-filtered, with the time of that render;
- the bins knob: 4x4, 8x8 and 16x16 bins after 256 samples (error and memory).
Errors are mean and 99th percentile of the per-pixel largest channel difference, in 8-bit steps.

usage: Scripts/with_xvfb.sh /usr/bin/python3 Benchmarks/sndf_accuracy_study.py [WIDTH HEIGHT]
(PYTHONPATH=build/lib/python3/dist-packages:Testing/VTKPython); writes
Benchmarks/results/sndf_accuracy.csv and sndf_accuracy.png
(another directory: PR_BENCHMARK_RESULTS=DIR; Benchmarks/run.py --out sets it)
"""
import os
import sys
import time

import numpy as np

import particlerendering as pr
from prVTKTesting import crystal_view, fcc_crystal, window_pixels

W, H = (int(a) for a in (sys.argv[1:3] + ["160", "120"][len(sys.argv[1:3]):]))
REFERENCE_FACTOR = 32
xyz, rgb = fcc_crystal(16)
# PR_BENCHMARK_RESULTS (set by Benchmarks/run.py --out) overrides the results directory
results = (os.environ.get("PR_BENCHMARK_RESULTS") or
           os.path.join(os.path.dirname(os.path.abspath(__file__)), "results"))


def view(size, sndf=None):
    return crystal_view(xyz, rgb, size, sndf, specular=0.3)[1]


def timed_render(window):
    start = time.perf_counter()
    window.Render()
    window.GetRGBACharPixelData(0, 0, 0, 0, 0)  # waits for the GPU
    return time.perf_counter() - start


def plain_supersampled(k):
    window = view((W * k, H * k))
    window.Render()  # programs and buffers
    seconds = min(timed_render(window) for _ in range(3))
    image = window_pixels(window, W * k, H * k).reshape(H, k, W, k, 3).mean(axis=(1, 3))
    return image, seconds


def error(image, reference):
    d = np.abs(image - reference).max(axis=2)
    return d.mean(), np.percentile(d, 99)


reference, _ = plain_supersampled(REFERENCE_FACTOR)
rows = []
for k in (1, 2, 4, 8, 16):
    image, seconds = plain_supersampled(k)
    rows.append(("plain super-sampling", 8, k * k, seconds) + error(image, reference) + (0.0,))

for bins in (4, 8, 16):
    sndf = pr.vtkSNDFRenderPass()
    sndf.SetBinsPerAxis(bins)
    sndf.SetSamplesPerFrame(1)
    sndf.SetTargetSamples(256)
    window = view((W, H), sndf)
    window.Render()  # the frame of the change (plain)
    timed_render(window)  # the first sample builds the programs and the table: restart after it
    sndf.Restart()
    elapsed = timed_render(window)  # the frame of the change again
    while not sndf.GetConverged():
        elapsed += timed_render(window)
        n = sndf.GetNumberOfSamples()
        if bins == 8 and (n & (n - 1)) == 0 or n == 256:
            rows.append(("S-NDF", bins, n, elapsed) + error(window_pixels(window, W, H), reference)
                        + (sndf.GetMemoryBytes() / 2**20,))

header = "method,bins,samples_per_pixel,seconds,mean_error,p99_error,memory_MB\n"
with open(os.path.join(results, "sndf_accuracy.csv"), "w") as f:
    f.write(header)
    for row in rows:
        f.write("%s,%d,%d,%.4f,%.3f,%.2f,%.1f\n" % row)
print(header + "\n".join(",".join(str(v) for v in row) for row in rows))

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, axes = plt.subplots(1, 2, figsize=(11, 4))
for method, bins, style in (("plain super-sampling", 8, "s-"), ("S-NDF", 8, "o-")):
    pick = [r for r in rows if r[0] == method and r[1] == bins]
    label = method if method != "S-NDF" else "S-NDF, 8x8 bins"
    axes[0].loglog([r[2] for r in pick], [r[4] for r in pick], style, label=label)
    axes[1].loglog([r[3] for r in pick], [r[4] for r in pick], style, label=label)
for bins, marker in ((4, "v"), (16, "^")):
    pick = [r for r in rows if r[0] == "S-NDF" and r[1] == bins]
    axes[0].loglog([r[2] for r in pick], [r[4] for r in pick], marker,
                   label="S-NDF, %dx%d bins" % (bins, bins))
    axes[1].loglog([r[3] for r in pick], [r[4] for r in pick], marker,
                   label="S-NDF, %dx%d bins" % (bins, bins))
axes[0].set_xlabel("samples per pixel")
axes[1].set_xlabel("seconds (llvmpipe, %dx%d)" % (W, H))
for ax in axes:
    ax.set_ylabel("mean error vs 32x32 super-sampled (/255)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
fig.suptitle("vtkSNDFRenderPass: fcc crystal, 16 384 atoms at ~2 px per atom")
fig.tight_layout()
fig.savefig(os.path.join(results, "sndf_accuracy.png"), dpi=100)
