"""Zoom out against re-sampling at equal quality (the S-MIP of vtkSNDFRenderPass, paper Sec. 6).

smip_benchmark.py times the zoom out by 2 (averaging level 1 from the cached level 0) against
re-sampling level 1 to the same SAMPLES samples per pixel. The averaged level holds 4 x SAMPLES
samples per texel, so "the same quality" needs its own measurement. Here, per scene of
smip_benchmark.py (same camera, same pixel size as its 1280x720 view, cropped to the centre
WIDTH x HEIGHT of it):
- level 0 is converged to SAMPLES samples over the 2 x 2 views around the centre and the view
  zooms out by 2 (no sample is taken): the zoomed picture;
- level 1 is rendered directly by a pass started there, its picture kept at 16, 32, ..., 4 x
  SAMPLES samples per pixel;
- every picture is compared with the plain core rendered at level 1 with SUPER x SUPER samples
  per pixel (a regular grid, box-filtered: independent of the passes' Halton samples, so that
  the errors are not correlated with the reference);
- the equal-quality sample count N* is where the direct pictures' mean error (log-log
  interpolated) equals the zoomed one's.
The time ratio of smip_benchmark.py (re-sampling SAMPLES / zoom) then scales by N* / SAMPLES:
re-sampling to equal quality takes N* sample passes.

usage: Scripts/with_xvfb.sh /usr/bin/python3 Benchmarks/smip_quality.py [CELLS REPEAT WIDTH HEIGHT SAMPLES SUPER]
(defaults 63 8 640 360 64 16; PYTHONPATH=build/lib/python3/dist-packages:Testing/VTKPython);
writes Benchmarks/results/smip_quality.csv.
(another directory: PR_BENCHMARK_RESULTS=DIR; Benchmarks/run.py --out sets it)
"""
import os
import sys

import numpy as np

import particlerendering as pr
import smip_benchmark as sb
from prVTKTesting import image_error, window_pixels

args = sys.argv[1:7] + ["63", "8", "640", "360", "64", "16"][len(sys.argv[1:7]):]
cells, repeat, width, height, samples, super_ = (int(a) for a in args)
sb.width, sb.height = width, height
crop = 720.0 / height  # the parallel scale is smip_benchmark's for 720 pixels


error = image_error


def converge_to(sndf, window, target):
    sndf.SetTargetSamples(target)
    window.Render()
    while not sndf.GetConverged():
        window.Render()
    return window_pixels(window, width, height)


def measure(name, scene):
    # the reference: the plain core at level 1, SUPER x SUPER samples per pixel
    renderer, window = sb.make_view(scene, None, (width * super_, height * super_), crop)
    camera = renderer.GetActiveCamera()
    camera.SetParallelScale(2.0 * camera.GetParallelScale())
    window.Render()
    big = window_pixels(window, width * super_, height * super_)
    reference = big.reshape(height, super_, width, super_, 3).mean(axis=(1, 3))
    del big, window, renderer

    # level 0 over the 2 x 2 views around the centre, then the zoom out
    sndf = pr.vtkSNDFRenderPass()
    sndf.SetSamplesPerFrame(16)
    sndf.SetTargetSamples(samples)
    sndf.SetMaximumMemory(3000)
    renderer, window = sb.make_view(scene, sndf, (width, height), crop)
    camera = renderer.GetActiveCamera()
    window.Render()
    for dx, dy in [(-width // 2, -height // 2), (width, 0), (0, height), (-width, 0)]:
        sb.pan(camera, dx, dy)
        sb.converge(sndf, window)
    sb.pan(camera, width // 2, -height // 2)
    camera.SetParallelScale(2.0 * camera.GetParallelScale())
    passes = sndf.GetNumberOfSamplePasses()
    window.Render()
    assert sndf.GetNumberOfSamplePasses() == passes and sndf.GetConverged(), "the zoom sampled"
    zoomed = error(window_pixels(window, width, height), reference)
    rows = [[name, len(scene[0]), width, height, "zoomed", 4 * samples] + list(zoomed)]
    del window, renderer, sndf

    # level 1 rendered directly
    direct = pr.vtkSNDFRenderPass()
    direct.SetSamplesPerFrame(16)
    renderer, window = sb.make_view(scene, direct, (width, height), crop)
    camera = renderer.GetActiveCamera()
    camera.SetParallelScale(2.0 * camera.GetParallelScale())
    window.Render()
    counts = [16 * 2 ** k for k in range(int(np.log2(4 * samples / 16)) + 1)]
    for n in counts:
        rows.append([name, len(scene[0]), width, height, "direct", n]
                    + list(error(converge_to(direct, window, n), reference)))
    # the plain image of level 1 (one sample at the pixel centre)
    renderer, window = sb.make_view(scene, None, (width, height), crop)
    renderer.GetActiveCamera().SetParallelScale(2.0 * renderer.GetActiveCamera().GetParallelScale())
    window.Render()
    rows.append([name, len(scene[0]), width, height, "plain", 1]
                + list(error(window_pixels(window, width, height), reference)))

    # N*: the direct sample count of the zoomed picture's mean error
    n = np.array(counts, float)
    e = np.array([r[6] for r in rows if r[4] == "direct"])
    z = zoomed[0]
    if z >= e[0]:
        equal = n[0]
    elif z <= e[-1]:
        equal = float("inf")
    else:
        k = int(np.nonzero(e <= z)[0][0])
        t = (np.log(e[k - 1]) - np.log(z)) / (np.log(e[k - 1]) - np.log(e[k]))
        equal = float(np.exp(np.log(n[k - 1]) + t * (np.log(n[k]) - np.log(n[k - 1]))))
    for r in rows:
        r.append(equal)
    return rows


path = os.path.join(sb.results, "smip_quality.csv")
header = "scene,particles,width,height,picture,samples,mean_255,p99_255,max_255,equal_quality_samples\n"
with open(path, "w") as f:
    f.write(header)
    for name, scene in sb.make_scenes(cells, repeat):
        for row in measure(name, scene):
            line = ",".join("%.4g" % v if isinstance(v, (float, np.floating)) else str(v) for v in row)
            f.write(line + "\n")
            print(line, flush=True)
