"""The speed/accuracy trade as a ParaView user meets it (vtkParticleFrameBudget): per technique and
scene, the frame of an interactive render (what the GUI draws while the mouse moves) and of a
still render, as ratios of the opaque core's still frame measured in the same process, and the
interactive picture's error against the still one.

usage: pvpython --force-offscreen-rendering Benchmarks/quality_benchmark.py --plugin PLUGIN.so
           --data Testing/Data [--frames 5] [--size 1024x768] [--csv quality.csv] [--png quality.png]

Scenes (bundled): dense = fcc_block.vtp (32 000 atoms, an FCC block), mixed = lj_film.vtp (19 360,
a film with gas), sparse = lj_droplets.vtp (11 033, droplets in gas); radii from 'radius',
coloured by type. Techniques: the opaque core; translucent (opacity 0.6, Overlapping Particles
Automatic); density-volume AO, voxel-cone AO, PointAO (Particle Render View); metaballs.
Frames: wall clock of the render (it ends with the image in the window), median over --frames
frames with the camera turned by 2 degrees between frames. Columns:
- still_s: simple.Render (a still render: every technique exact);
- interactive_s, interactive_level: InteractiveRender with Interactive Quality Adaptive and
  ParaView's interactive budget (200 ms): the level the technique chose on this machine;
- cheap_s: InteractiveRender with Interactive Quality 'Interactive' (the cheap level);
- *_vs_core: divided by the opaque core's still frame of the scene;
- error of the cheap level's picture against the still one at the same camera, in 1/255: mean
  over pixels and channels, the 99th percentile and maximum of the pixels' largest channel
  difference, and the share of pixels over 2/255;
- translucent only: sorted_s and exact_overlap_s, the still frame with Overlapping Particles
  'Sorted Spheres' and 'Exact Overlap'; automatic_vs_sorted, Automatic's still frame over the
  sorted one (the two measured interleaved); sorted_share_over_2, the share of pixels where the
  sorted picture is more than 2/255 from the exact-overlap one (the image criterion: 0.0001).
"""
import argparse
import csv
import os
import statistics
import sys
import time

import numpy as np
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--data", required=True)
parser.add_argument("--frames", type=int, default=5)
parser.add_argument("--size", default="1024x768")
parser.add_argument("--csv", default="")
parser.add_argument("--png", default="")
parser.add_argument("--scenes", default="dense,mixed,sparse")
parser.add_argument("--renderer", default="Mesa llvmpipe")
parser.add_argument("--techniques", default="",
                    help="comma-separated subset (the opaque core is always measured)")
args, _ = parser.parse_known_args()
simple.LoadPlugin(args.plugin, remote=False)
size = [int(v) for v in args.size.split("x")]
SCENES = {"dense": "fcc_block.vtp", "mixed": "lj_film.vtp", "sparse": "lj_droplets.vtp"}
TECHNIQUES = ["opaque core", "translucent", "density AO", "voxel-cone AO", "PointAO", "metaballs"]
if args.techniques:
    TECHNIQUES = ["opaque core"] + [t for t in args.techniques.split(",") if t != "opaque core"]
AO = {"density AO": "Density Volume", "voxel-cone AO": "Voxel Cone Tracing", "PointAO": "PointAO"}


def setup(path, technique):
    reader = simple.XMLPolyDataReader(FileName=[path])
    view = simple.CreateView("ParticleRenderView")
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.UseFXAA = 0
    display = simple.Show(reader, view)
    display.Representation = "Particles"
    display.UseRadiusArray = 1
    display.RadiusArray = ["POINTS", "radius"]
    simple.ColorBy(display, ("POINTS", "type"))
    display.Specular = 0.4
    if technique == "translucent":
        display.Opacity = 0.6
    if technique == "metaballs":
        display.Technique = "Metaballs"
    if technique in AO:
        view.ParticleAmbientOcclusion = AO[technique]
    simple.Render(view)
    simple.ResetCamera(view)
    camera = view.GetActiveCamera()
    camera.Azimuth(30)
    camera.Elevation(20)
    simple.Render(view)
    return reader, view, display


def level_text(view, display, technique):
    view.SMProxy.UpdatePropertyInformation()
    display.SMProxy.UpdatePropertyInformation()
    if technique in AO:
        return view.GetPropertyValue("AmbientOcclusionQualityText")
    return display.GetPropertyValue("QualityText")


def timed_once(view, interactive=False):
    view.GetActiveCamera().Azimuth(2.0)
    start = time.perf_counter()
    if interactive:
        view.SMProxy.InteractiveRender()
    else:
        simple.Render(view)
    return time.perf_counter() - start


def timed(view, interactive):
    return statistics.median([timed_once(view, interactive) for _ in range(args.frames)])


def grab(view):
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(view.GetRenderWindow())
    grabber.ShouldRerenderOff()
    grabber.ReadFrontBufferOff()
    grabber.Update()
    return vtk_to_numpy(grabber.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)


def overlap_paths(view, display):
    """Translucent only: the still frames with Overlapping Particles 'Sorted Spheres' and
    'Automatic' measured interleaved (rounds of: switch, one frame untimed, two timed; this
    machine's frame times drift by more than the difference between the two), the exact-overlap
    still frame, and the share of pixels where the sorted picture is more than 2/255 from the
    exact-overlap one (same camera)."""
    times = {"Sorted Spheres": [], "Automatic": []}
    for _ in range(max(2, (args.frames + 1) // 2)):
        for mode in times:
            display.OverlapCompositing = mode
            simple.Render(view)
            times[mode] += [timed_once(view) for _ in range(2)]
    display.OverlapCompositing = "Sorted Spheres"
    simple.Render(view)
    sorted_picture = grab(view)
    display.OverlapCompositing = "Exact Overlap"
    simple.Render(view)
    exact_picture = grab(view)
    exact_s = timed(view, False)
    display.OverlapCompositing = "Automatic"
    sorted_s = statistics.median(times["Sorted Spheres"])
    return {"sorted_s": sorted_s, "exact_overlap_s": exact_s,
            "automatic_vs_sorted": statistics.median(times["Automatic"]) / sorted_s,
            "sorted_share_over_2": float(np.mean(
                np.abs(sorted_picture - exact_picture).max(axis=1) > 2))}


rows = []
for scene in args.scenes.split(","):
    path = os.path.join(args.data, SCENES[scene])
    core = None
    for technique in TECHNIQUES:
        reader, view, display = setup(path, technique)
        timed(view, False)  # first frames: shader compiles, volumes, sorts
        still = timed(view, False)
        interactive = timed(view, True)
        chosen = level_text(view, display, technique).split(" (")[0]
        chosen = "-" if technique == "opaque core" else chosen
        quality_owner = view if technique in AO else display
        quality_owner.InteractiveQuality = "Interactive"
        view.SMProxy.InteractiveRender()
        cheap = timed(view, True)
        view.SMProxy.InteractiveRender()
        cheap_picture = grab(view)
        quality_owner.InteractiveQuality = "Adaptive"
        simple.Render(view)
        still_picture = grab(view)
        difference = np.abs(cheap_picture - still_picture)
        per_pixel = difference.max(axis=1)
        overlap = overlap_paths(view, display) if technique == "translucent" else {}
        core = still if technique == "opaque core" else core
        row = {"scene": scene, "technique": technique, "particles":
               reader.GetDataInformation().GetNumberOfPoints(), "width": size[0],
               "height": size[1], "frames": args.frames, "still_s": still,
               "interactive_s": interactive, "interactive_level": chosen, "cheap_s": cheap,
               "still_vs_core": still / core, "interactive_vs_core": interactive / core,
               "cheap_vs_core": cheap / core, "error_mean": float(difference.mean()),
               "error_p99": float(np.percentile(per_pixel, 99)),
               "error_max": int(per_pixel.max()), "share_over_2": float(np.mean(per_pixel > 2)),
               "sorted_s": overlap.get("sorted_s", ""),
               "exact_overlap_s": overlap.get("exact_overlap_s", ""),
               "automatic_vs_sorted": overlap.get("automatic_vs_sorted", ""),
               "sorted_share_over_2": overlap.get("sorted_share_over_2", "")}
        rows.append(row)
        print("%-7s %-14s still %7.3f s (%5.2fx core)  interactive %7.3f s (%5.2fx, %s)  "
              "cheap %7.3f s (%5.2fx)  error mean %.2f p99 %.0f max %d /255"
              % (scene, technique, still, row["still_vs_core"], interactive,
                 row["interactive_vs_core"], chosen, cheap, row["cheap_vs_core"],
                 row["error_mean"], row["error_p99"], row["error_max"]), flush=True)
        if overlap:
            print("%-7s %-14s sorted %7.3f s, exact overlap %7.3f s, Automatic / sorted %.2f; "
                  "sorted vs exact overlap: %.4f %% of pixels over 2/255"
                  % (scene, technique, overlap["sorted_s"], overlap["exact_overlap_s"],
                     overlap["automatic_vs_sorted"], 100.0 * overlap["sorted_share_over_2"]),
                  flush=True)
        simple.Delete(display)
        simple.Delete(view)
        simple.Delete(reader)

if args.csv:
    with open(args.csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: ("%.4g" % v if isinstance(v, float) else v)
                             for k, v in row.items()})
if args.png:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8))
    width = 0.8 / len(scenes)
    x = np.arange(len(TECHNIQUES))
    for i, scene in enumerate(scenes):
        sel = [next(r for r in rows if r["scene"] == scene and r["technique"] == t)
               for t in TECHNIQUES]
        axes[0].bar(x + i * width, [r["still_vs_core"] for r in sel], width, alpha=0.35,
                    color="C%d" % i)
        axes[0].bar(x + i * width, [r["cheap_vs_core"] for r in sel], width,
                    color="C%d" % i, label="%s: cheap (solid) / still (light)" % scene)
        axes[1].bar(x + i * width, [r["error_mean"] for r in sel], width, color="C%d" % i,
                    label=scene)
    axes[0].axhline(2.0, color="k", lw=0.8, ls="--")
    axes[0].set_yscale("log")
    axes[0].set_ylabel("frame time / opaque core's still frame")
    axes[1].set_ylabel("cheap vs still picture: mean error (1/255)")
    for ax in axes:
        ax.set_xticks(x + 0.4 - width / 2)
        ax.set_xticklabels(TECHNIQUES, rotation=20)
        ax.legend(fontsize=8)
    fig.suptitle("Interactive (cheap level) and still frames, %dx%d, ParaView, %s"
                 % (size[0], size[1], args.renderer))
    fig.tight_layout()
    fig.savefig(args.png, dpi=90)
