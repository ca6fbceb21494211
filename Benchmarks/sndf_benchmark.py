"""vtkSNDFRenderPass against the plain core, paper Table 2/3 style (llvmpipe, one run).

Scene: an fcc crystal of two species seen whole (CELLS^3 unit cells, 4 atoms each), radius 0.36
lattice constants, headlight, at WIDTHxHEIGHT. Measured in the same run:
- plain: a frame of the core (vtkCameraPass -> vtkRenderStepsPass), median;
- sample pass: a refinement frame with SamplesPerFrame 1 (delegate into the G-buffer,
  accumulation, re-shade, composite), median over SAMPLES - 1 frames, interleaved with the
  plain frames (one of each in turn);
- re-light: a frame after a light change once refinement stopped (table + re-shade, no sample);
- re-sample to the same quality: SAMPLES sample passes (what plain super-sampling costs after the
  same light change);
- memory of the S-NDFs;
- a pan by 10 pixels in parallel projection: the frame that moves the S-NDFs with the picture
  and takes one sample, against a restart's frame (the plain image);
- per-stage GPU times (timer queries, a second run with CollectTimings on): a sample pass's
  delegate draw into the G-buffer, its accumulation into the S-NDFs, the shade + composite; and
  the re-light's shade (table + bin sums formed again + composite).

usage: Scripts/with_xvfb.sh python3 Benchmarks/sndf_benchmark.py [CELLS WIDTH HEIGHT SAMPLES]
(PYTHONPATH=build/lib/python3/dist-packages:Testing/VTKPython); appends to
Benchmarks/results/sndf_timings.csv and (the pan) sndf_pan.csv
(another directory: PR_BENCHMARK_RESULTS=DIR; Benchmarks/run.py --out sets it)
"""
import os
import sys
import time

import numpy as np

import particlerendering as pr
from prVTKTesting import append_csv, crystal_view, fcc_crystal, pan_camera
from vtkmodules.vtkRenderingCore import vtkLight

cells, width, height, samples = (int(a) for a in (sys.argv[1:5] + ["40", "1280", "720", "64"][len(sys.argv[1:5]):]))
xyz, rgb = fcc_crystal(cells)


def view(sndf):
    renderer, window, _ = crystal_view(xyz, rgb, (width, height), sndf,
                                       position=(2.5 * cells, 1.9 * cells, 3.4 * cells),
                                       focal_point=(cells / 2, cells / 2, cells / 2))
    return renderer, window


def timed(window):
    t = time.perf_counter()
    window.Render()
    window.GetRGBACharPixelData(0, 0, 0, 0, 0)  # wait for the GPU
    return time.perf_counter() - t


# plain and refinement frames interleaved (one of each in turn, medians): llvmpipe's frame times
# drift by up to 30 % between runs and within one, which a plain mean measured first and a
# sample mean measured after it turned into the ratio
_, plain_window = view(None)
timed(plain_window)
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(1)
sndf.SetTargetSamples(samples)
renderer, window = view(sndf)
timed(window)  # the frame of the change
timed(window)  # (the first sample pass builds the programs)
plain_times = []
sample_times = []
while not sndf.GetConverged():
    plain_times.append(timed(plain_window))
    sample_times.append(timed(window))
plain = float(np.median(plain_times))
sample = float(np.median(sample_times))
del plain_window
light = vtkLight()
light.SetLightTypeToCameraLight()
light.SetPosition(1, 0.5, 0.4)
renderer.RemoveAllLights()
renderer.AddLight(light)
relight = timed(window)
light.SetIntensity(0.8)
relight = min(relight, timed(window))
resample = samples * sample

# per-stage GPU times
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(1)
sndf.SetTargetSamples(samples)
sndf.CollectTimingsOn()
renderer, window = view(sndf)
timed(window)
stages = []
for k in range(samples):
    timed(window)
    if k > 0:
        stages.append([sndf.GetLastSampleSeconds(), sndf.GetLastAccumulateSeconds(),
                       sndf.GetLastShadeSeconds()])
stages = np.mean(stages, axis=0)
light = vtkLight()
light.SetLightTypeToCameraLight()
light.SetPosition(1, 0.5, 0.4)
renderer.RemoveAllLights()
renderer.AddLight(light)
timed(window)
relight_shade = sndf.GetLastShadeSeconds()

# pan (parallel projection, 10 pixels right): the frame that moves the S-NDFs and takes one
# sample, against the frame of a restart (plain)
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(16)
sndf.SetTargetSamples(samples)
renderer, window = view(sndf)
camera = renderer.GetActiveCamera()
camera.ParallelProjectionOn()
camera.SetParallelScale(0.6 * cells)
renderer.ResetCameraClippingRange()
timed(window)
while not sndf.GetConverged():
    timed(window)
sndf.SetSamplesPerFrame(1)
pan_camera(camera, 10, 0, height)
pan = timed(window)
assert sndf.GetNumberOfPans() == 1
camera.Azimuth(1)
restart = timed(window)

row = [len(xyz), width, height, samples, sndf.GetActiveBinsPerAxis(), plain, sample,
       sample / plain, relight, resample, resample / relight, sndf.GetMemoryBytes() / 2**20,
       stages[0], stages[1], stages[2], relight_shade]
# PR_BENCHMARK_RESULTS (set by Benchmarks/run.py --out) overrides the results directory
results = os.environ.get("PR_BENCHMARK_RESULTS") or os.path.join(os.path.dirname(__file__),
                                                                 "results")
path = os.path.join(results, "sndf_timings.csv")
header = ("particles,width,height,samples,bins,plain_s,sample_pass_s,sample_over_plain,"
          "relight_s,resample_s,resample_over_relight,memory_MB,gpu_sample_s,gpu_accumulate_s,"
          "gpu_shade_s,gpu_relight_shade_s\n")
append_csv(path, header, row)
pan_path = os.path.join(results, "sndf_pan.csv")
append_csv(pan_path, "particles,width,height,samples,pan_frame_s,restart_frame_s",
           [len(xyz), width, height, samples, pan, restart])
print("pan frame %.3f s, restart frame %.3f s" % (pan, restart))
