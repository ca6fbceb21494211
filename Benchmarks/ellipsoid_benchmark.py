#!/usr/bin/env python3
"""Frame time of oriented ellipsoids (vtkParticleSphereMapper, Shape Ellipsoid) against the
sphere core on the same particles and against ParaView's Tensor Glyph (vtkTensorGlyph of a
sphere, drawn by VTK's polygon mapper), measured in the same run.

Scenes: N in {1e4, 1e5, 1e6} ellipsoids at uniformly random positions in a cube at number density
0.05 (a gas: most are visible) in uniformly random orientations, two aspect ratios: rods 1:1:3
(semi-axes 0.5 0.5 1.5) and needles 1:1:10 (0.3 0.3 3.0). Drawn as
  - ellipsoids: the exact ray-cast ellipsoids;
  - spheres: the sphere core at the same centres, radius the ellipsoids' volume radius
    cbrt(a b c) (the same volume, the cost the core had before);
  - tensor glyph 8 / 16: vtkTensorGlyph (ParaView's Tensor Glyph filter; ExtractEigenvalues off,
    the tensor's columns the scaled body axes) of a vtkSphereSource with theta/phi resolution 8
    (ParaView's default sphere glyph) or 16, drawn by vtkPolyDataMapper; the glyph filter's own
    time (CPU, once per data change) is reported apart. Up to 1e5 particles: 1e6 glyphs of
    resolution 16 are 2.3e8 points.
Times: 1024 x 768, median wall time of FRAMES frames with the camera orbiting 3 degrees per frame,
each ended by WaitForCompletion (glFinish); the first two frames (shader builds, uploads) are not
counted. Occlusion culling as by default (on from 8192 particles). Ratios: the
ellipsoids over the spheres and over each tensor glyph of the same scene.

usage: Scripts/with_xvfb.sh /usr/bin/python3 Benchmarks/ellipsoid_benchmark.py [--build build]
       [--out Benchmarks/results] [--frames 7] [--counts 1e4,1e5,1e6] [--quick]
writes ellipsoids.csv and ellipsoids.png into --out
"""
import argparse
import csv
import os
import statistics
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)


def parse():
    p = argparse.ArgumentParser()
    p.add_argument("--build", default=os.path.join(TOP, "build"))
    p.add_argument("--out", default=os.path.join(HERE, "results"))
    p.add_argument("--frames", type=int, default=7)
    p.add_argument("--counts", default="1e4,1e5,1e6")
    p.add_argument("--size", default="1024x768")
    p.add_argument("--glyph-limit", type=float, default=1e5,
                   help="largest particle count drawn as tensor glyphs")
    p.add_argument("--quick", action="store_true", help="1e3 particles, 3 frames, 320x240")
    return p.parse_args()


ARGS = parse()
if ARGS.quick:
    ARGS.counts, ARGS.frames, ARGS.size = "1e3", 3, "320x240"
sys.path.insert(0, os.path.join(ARGS.build, "lib", "python3", "dist-packages"))
sys.path.insert(0, os.path.join(TOP, "Testing", "VTKPython"))
import particlerendering as pr  # noqa: E402
from prVTKTesting import quaternion_rotations, random_quaternions  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPolyData  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkTensorGlyph  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,  # noqa: E402
                                         vtkRenderWindow)
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401

WIDTH, HEIGHT = (int(v) for v in ARGS.size.split("x"))
SHAPES = {"rods 1:1:3": (0.5, 0.5, 1.5), "needles 1:1:10": (0.3, 0.3, 3.0)}


def scene(n, axes, seed=11):
    rng = np.random.default_rng(seed)
    side = (n / 0.05) ** (1.0 / 3.0)
    xyz = rng.uniform(0.0, side, size=(n, 3))
    q = random_quaternions(n, rng)
    data = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(xyz, deep=True))
    data.SetPoints(points)
    for name, values in (("axes", np.tile(axes, (n, 1))), ("quat", q)):
        array = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.float32), deep=True)
        array.SetName(name)
        data.GetPointData().AddArray(array)
    # the tensor of vtkTensorGlyph (ExtractEigenvalues off: components 0-2, 3-5, 6-8 are the
    # glyph's axes, their norms the scales): the columns of R diag(a), one after the other
    tensor = quaternion_rotations(q) * np.asarray(axes)[None, None, :]
    columns = np.transpose(tensor, (0, 2, 1)).reshape(n, 9)
    array = numpy_to_vtk(np.ascontiguousarray(columns, dtype=np.float32), deep=True)
    array.SetName("tensor")
    data.GetPointData().SetTensors(array)
    return data, side


def mapper_for(kind, data, axes):
    if kind in ("ellipsoids", "spheres"):
        mapper = pr.vtkParticleSphereMapper()
        mapper.SetInputData(data)
        if kind == "ellipsoids":
            mapper.SetShapeToEllipsoid()
            mapper.SetAxesArrayName("axes")
            mapper.SetOrientationArrayName("quat")
        else:
            mapper.SetRadius(float(np.prod(axes)) ** (1.0 / 3.0))
        return mapper, 0.0
    resolution = 8 if kind == "tensor glyph 8" else 16
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(resolution)
    sphere.SetPhiResolution(resolution)
    sphere.SetRadius(1.0)
    glyphs = vtkTensorGlyph()
    glyphs.SetInputData(data)
    glyphs.SetSourceConnection(sphere.GetOutputPort())
    glyphs.ExtractEigenvaluesOff()
    glyphs.ThreeGlyphsOff()
    glyphs.ColorGlyphsOff()
    start = time.perf_counter()
    glyphs.Update()
    glyph_seconds = time.perf_counter() - start
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(glyphs.GetOutputPort())
    mapper.ScalarVisibilityOff()
    return mapper, glyph_seconds


def measure(kind, data, axes, side):
    mapper, glyph_seconds = mapper_for(kind, data, axes)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.85, 0.55, 0.3)
    actor.GetProperty().SetSpecular(0.3)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(WIDTH, HEIGHT)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    # the same view for every mapper (not ResetCamera: each mapper's bounds differ)
    camera.SetFocalPoint(side / 2, side / 2, side / 2)
    camera.SetPosition(side / 2 + 1.6 * side, side / 2 - 1.2 * side, side / 2 + 1.1 * side)
    camera.SetViewAngle(40.0)
    renderer.ResetCameraClippingRange()
    times = []
    for frame in range(ARGS.frames + 2):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        if frame >= 2:
            times.append(time.perf_counter() - start)
        camera.Azimuth(3)
        renderer.ResetCameraClippingRange()
    window.Finalize()
    return statistics.median(times), glyph_seconds


def main():
    os.makedirs(ARGS.out, exist_ok=True)
    rows = []
    for label, axes in SHAPES.items():
        for count in (int(float(c)) for c in ARGS.counts.split(",")):
            data, side = scene(count, axes)
            kinds = ["ellipsoids", "spheres"]
            if count <= ARGS.glyph_limit:
                kinds += ["tensor glyph 8", "tensor glyph 16"]
            result = {}
            for kind in kinds:
                frame, glyph = measure(kind, data, axes, side)
                result[kind] = frame
                rows.append({"shape": label, "particles": count, "drawn_as": kind,
                             "frame_s": "%.5f" % frame,
                             "glyph_filter_s": "%.3f" % glyph if glyph else ""})
                print("%-15s %8d %-16s frame %8.4f s  glyph filter %s"
                      % (label, count, kind, frame, rows[-1]["glyph_filter_s"] or "-"),
                      flush=True)
            for row in rows:
                if row["shape"] == label and row["particles"] == count:
                    row["ellipsoids_over_this"] = "%.4g" % (result["ellipsoids"] /
                                                            result[row["drawn_as"]])
    path = os.path.join(ARGS.out, "ellipsoids.csv")
    fields = ["shape", "particles", "drawn_as", "frame_s", "glyph_filter_s",
              "ellipsoids_over_this"]
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)
    print("wrote " + path)
    plot(rows, os.path.join(ARGS.out, "ellipsoids.png"))


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, panels = plt.subplots(1, len(SHAPES), figsize=(5.5 * len(SHAPES), 4.2), sharey=True)
    for panel, label in zip(np.atleast_1d(panels), SHAPES):
        for kind, style in (("ellipsoids", "o-"), ("spheres", "s--"), ("tensor glyph 8", "^:"),
                            ("tensor glyph 16", "v:")):
            mine = [r for r in rows if r["shape"] == label and r["drawn_as"] == kind]
            if mine:
                panel.loglog([r["particles"] for r in mine],
                             [float(r["frame_s"]) for r in mine], style, label=kind)
        panel.set_title("%s, %dx%d, llvmpipe" % (label, WIDTH, HEIGHT))
        panel.set_xlabel("particles")
        panel.grid(True, which="both", alpha=0.3)
    np.atleast_1d(panels)[0].set_ylabel("frame time [s] (median, glFinish)")
    np.atleast_1d(panels)[0].legend()
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    print("wrote " + path)


if __name__ == "__main__":
    main()
