"""Frame time of the Particles representation in ParaView's views, measured in one pvpython
process: in the plain Render View and in the Particle Render View with AO off (is the pass chain
free when no pass is on?), each alone and rendered alternately with a Point Gaussian (Sphere) view
of the same data sharing the lookup table (does anything get redone when views alternate?).
Point Gaussian's own frame time is the peer.

usage: pvpython Benchmarks/view_overhead.py --plugin build/lib/.../ParticleRendering.so
           [--count 1000000] [--frames 10] [--csv Benchmarks/results/view_overhead.csv]
Data: the random gas of make_particles.py (radii 0.3-0.5, coloured by speed), in memory.
Frame time: wall clock of simple.Render() (which ends with the image on the screen), median.
"""
import argparse
import csv
import os
import statistics
import sys
import time

from paraview import simple
from paraview.vtk.util.numpy_support import numpy_to_vtk  # noqa: F401 (numpy through ParaView)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_particles  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--count", type=int, default=1000000)
parser.add_argument("--frames", type=int, default=10)
parser.add_argument("--size", default="1024x768")
parser.add_argument("--csv", default="")
args, _ = parser.parse_known_args()
simple.LoadPlugin(args.plugin, remote=False)
size = [int(v) for v in args.size.split("x")]

source = simple.TrivialProducer()
source.GetClientSideObject().SetOutput(make_particles.make("gas", args.count, seed=1, radius=0.5))


def make_view(kind, representation):
    view = simple.CreateView(kind)
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    simple.GetSettingsProxy("RenderViewSettings").UseFXAA = 0
    view.UseFXAA = 0
    display = simple.Show(source, view)
    display.Representation = representation
    if representation == "Point Gaussian":
        display.ShaderPreset = "Sphere"
        display.GaussianRadius = 1.0  # times the radius array
        display.ScaleByArray = 1
        display.SetScaleArray = ["POINTS", "radius"]
        display.UseScaleFunction = 0
    else:
        display.UseRadiusArray = 1
        display.RadiusArray = ["POINTS", "radius"]
    simple.ColorBy(display, ("POINTS", "speed"))
    display.Specular = 0.3
    simple.Render(view)
    simple.ResetCamera(view)
    simple.Render(view)
    return view


def frame(view):
    view.GetActiveCamera().Azimuth(360.0 / args.frames)
    start = time.perf_counter()
    simple.Render(view)
    return time.perf_counter() - start


views = {
    "Render View, Particles": make_view("RenderView", "Particles"),
    "Particle Render View (AO off), Particles": make_view("ParticleRenderView", "Particles"),
    "Render View, Point Gaussian": make_view("RenderView", "Point Gaussian"),
}
gaussian = views["Render View, Point Gaussian"]
rows = []
for name, view in views.items():
    alone = statistics.median(frame(view) for _ in range(args.frames))
    alternating = alone
    if view is not gaussian:
        times = []
        for _ in range(args.frames):
            frame(gaussian)
            times.append(frame(view))
        alternating = statistics.median(times)
    rows.append((name, alone, alternating))
peer = rows[-1][1]
print("%-45s %10s %14s %8s" % ("view, representation", "alone [s]", "alternating [s]", "/ PG"))
for name, alone, alternating in rows:
    print("%-45s %10.3f %14.3f %8.2f" % (name, alone, alternating, alone / peer))
if args.csv:
    with open(args.csv, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["particles", "width", "height", "frames", "view", "median_alone_s",
                         "median_alternating_with_point_gaussian_s", "ratio_vs_point_gaussian"])
        for name, alone, alternating in rows:
            writer.writerow([args.count, size[0], size[1], args.frames, name, "%.4f" % alone,
                             "%.4f" % alternating, "%.3f" % (alone / peer)])
