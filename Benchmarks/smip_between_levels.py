"""vtkSNDFRenderPass with ZoomBetweenLevels: a parallel zoom by a factor other than a power of two
keeps the samples (the view placed at the finer S-MIP level, each pixel the box filter of its
texels) against sampling anew at the view's pixels (the default). llvmpipe, one run.

Scene: the crystal of smip_benchmark.py (CELLS^3 fcc cells, seen whole in parallel projection at
WIDTHxHEIGHT). Level 0 is converged to SAMPLES samples (SamplesPerFrame 1), then the parallel
scale is multiplied by FACTOR about the centre. Measured:
- kept: the first frame after the zoom (the cached texels shown, the new ones sampled once), the
  frames and seconds until every texel of the rectangle holds SAMPLES samples;
- anew: a pass started at the zoomed view: its plain frame and SAMPLES sample frames (seconds);
- accuracy: both converged pictures against the zoomed view super-sampled 4x4 (the core at 4x
  the size, box filtered; mean / p99 / max /255), and the first kept frame against it.

usage: Scripts/with_xvfb.sh /usr/bin/python3 Benchmarks/smip_between_levels.py [CELLS WIDTH HEIGHT SAMPLES FACTOR]
(PYTHONPATH=build/lib/python3/dist-packages:Testing/VTKPython:Benchmarks); appends to
Benchmarks/results/smip_between_levels.csv
(another directory: PR_BENCHMARK_RESULTS=DIR; Benchmarks/run.py --out sets it)
"""
import os
import sys

import numpy as np

import particlerendering as pr
import smip_benchmark as sb
from prVTKTesting import append_csv, image_error, window_pixels

args = sys.argv[1:6] + ["63", "1280", "720", "64", "1.25"][len(sys.argv[1:6]):]
cells, sb.width, sb.height, samples = (int(a) for a in args[:4])
factor = float(args[4])
width, height = sb.width, sb.height
name, scene = sb.make_scenes(cells, 1)[0]
zoom = 1.0 / factor


def new_pass(between):
    sndf = pr.vtkSNDFRenderPass()
    sndf.SetSamplesPerFrame(1)
    sndf.SetTargetSamples(samples)
    sndf.SetMaximumMemory(4000)
    sndf.SetZoomBetweenLevels(between)
    return sndf


# kept: level 0 converged, then the zoom
sndf = new_pass(True)
renderer, window = sb.make_view(scene, sndf)
sb.converge(sndf, window)
restarts = sndf.GetNumberOfRestarts()
renderer.GetActiveCamera().SetParallelScale(scene[5] * factor)
renderer.ResetCameraClippingRange()
kept_times = sb.converge(sndf, window)
assert sndf.GetNumberOfRestarts() == restarts, "the zoom restarted"
kept = window_pixels(window, width, height)
first_frame = kept_times[0]

# anew: a pass started at the zoomed view
anew_pass = new_pass(False)
anew_renderer, anew_window = sb.make_view(scene, anew_pass, zoom=zoom)
anew_times = sb.converge(anew_pass, anew_window)
anew = window_pixels(anew_window, width, height)

# reference: the core at 4x the size, box filtered
S = 4
ref_renderer, ref_window = sb.make_view(scene, None, size=(width * S, height * S), zoom=zoom)
ref_window.Render()
ref = window_pixels(ref_window, width * S, height * S).reshape(height, S, width, S, 3).mean(axis=(1, 3))
e_kept = image_error(kept, ref)
e_anew = image_error(anew, ref)

row = [len(scene[0]), width, height, samples, factor, first_frame, len(kept_times),
       sum(kept_times), len(anew_times), sum(anew_times)] + list(e_kept) + list(e_anew)
header = ("particles,width,height,samples,factor,kept_first_frame_s,kept_frames,kept_total_s,"
          "anew_frames,anew_total_s,kept_mean,kept_p99,kept_max,anew_mean,anew_p99,anew_max\n")
path = os.path.join(sb.results, "smip_between_levels.csv")
append_csv(path, header, row)
