"""Metaballs (vtkMetaballMapper, Mueller et al. 2007) measured against the exact surface
(vtkParticleReferenceRenderer, metaball mode) and against the peer a ParaView user has today:
the field on a grid and a contour.

Tables (Benchmarks/results/metaball_*.csv, plot metaball_benchmark.png):
- metaball_frames.csv: per scene (the LAMMPS droplets tiled 1x and 2x, 1.1e4 and 8.8e4 atoms; a
  gas with 10 % or 90 % of the atoms in clusters, the paper's Sim-1 / Sim-3 contrast) the frame
  time of the opaque sphere core and of the metaballs while only the camera moves (the vicinity
  method, with its depth pre-pass and in one pass; the walking depth plane walked to
  convergence, with its passes), the vicinity method's neighbour-list build (the per-time-step cost besides the upload) and the list size.
- metaball_accuracy.csv: depth error (units of the radius) and normal error (degrees) of the
  metaballs against the exact surface, and the frame time, versus Tolerance, RefinementSteps
  and IterationLimit (vicinity) and WalkingTolerance, MaximumPasses, TimeBudget and the step
  oracle (walking depth plane; droplets, 1.1e4 atoms).
- metaball_peer.csv: per time step of the droplets 1x and 2x (8.8e4 atoms, the issue's 1e5
  scale), vtkMetaballMapper (list build + frame after the positions changed) and the peer at
  grid resolutions 64..384: vtkGaussianSplatter (ParaView's
  "Gaussian Resampling") onto the grid, vtkFlyingEdges3D, rendering; its time per time step and
  the depth error of contouring the exact metaball field sampled on that grid (the best a grid
  method of that resolution can do), against the same reference.

usage: python3 metaball_benchmark.py [--out Benchmarks/results] [--quick]
       python3 metaball_benchmark.py --plot-only      (the PNG from Benchmarks/results)
(run under Scripts/with_xvfb.sh with PYTHONPATH=build/lib/python3/dist-packages:Testing/VTKPython)
"""
import argparse
import csv
import os
import time

import numpy as np

import particlerendering as pr
from prMetaballTesting import type_lookup_table
from prVTKTesting import actor_view, compare, gpu_view_depth
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkImagingHybrid import vtkGaussianSplatter
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import vtkPolyDataMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "Testing", "Data", "lj_droplets.vtp")
SIZE = (480, 360)


def polydata(xyz, radius, kind):
    out = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz, dtype=np.float64), deep=True))
    out.SetPoints(points)
    for name, values in (("radius", radius), ("type", kind)):
        array = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.float32), deep=True)
        array.SetName(name)
        out.GetPointData().AddArray(array)
    return out


def droplets(k):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(DATA)
    reader.Update()
    data = reader.GetOutput()
    xyz = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
    radius = vtk_to_numpy(data.GetPointData().GetArray("radius"))
    kind = vtk_to_numpy(data.GetPointData().GetArray("type"))
    size = xyz.max(axis=0) - xyz.min(axis=0)
    shifts = [np.array([i, j, l]) * size for i in range(k) for j in range(k) for l in range(k)]
    return (np.concatenate([xyz + s for s in shifts]), np.tile(radius, len(shifts)),
            np.tile(kind, len(shifts)))


def clustered(n, share, seed=1):
    """n atoms of radius 0.5 in a box at liquid spacing inside clusters of ~200 atoms holding
    `share` of them, the rest a dilute gas (the paper's Sim-1: few clustered, Sim-3: most)."""
    rng = np.random.default_rng(seed)
    side = (n / 0.02) ** (1.0 / 3.0)
    n_cl = int(n * share)
    centres = rng.uniform(0.1 * side, 0.9 * side, (max(1, n_cl // 200), 3))
    member = rng.integers(0, len(centres), n_cl)
    offsets = rng.normal(0.0, 1.0, (n_cl, 3))
    offsets *= (3.0 * np.cbrt(rng.random(n_cl)) / np.linalg.norm(offsets, axis=1))[:, None]
    cl = centres[member] + offsets * 3.4  # ~200 atoms in a ball of radius ~3.4 sigma
    gas = rng.uniform(0, side, (n - n_cl, 3))
    xyz = np.vstack([cl, gas])
    return xyz, np.full(n, 0.5), np.r_[np.full(n_cl, 2.0), np.ones(n - n_cl)]


def view(mapper, data):
    mapper.SetInputData(data)
    mapper.SetRadiusArrayName("radius")
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("type")
    mapper.SetLookupTable(type_lookup_table(1, 2))
    mapper.SetUseLookupTableScalarRange(1)
    actor, renderer, window = actor_view(mapper, SIZE)  # one sample per pixel, like the reference
    renderer.GetActiveCamera().SetPosition(-1.0, -1.4, 1.2)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Zoom(1.6)
    return actor, renderer, window


def walking(mapper, **settings):
    """Switch a vtkMetaballMapper to the walking depth plane, walked to convergence unless the
    settings say otherwise."""
    mapper.SetMethodToWalkingDepthPlane()
    mapper.SetTimeBudget(1000.0)
    mapper.SetMaximumPasses(1000)
    for knob, value in settings.items():
        getattr(mapper, "Set" + knob)(value)
    return mapper


def frame_seconds(window, renderer, frames):
    window.Render()
    start = time.time()
    for _ in range(frames):
        renderer.GetActiveCamera().Azimuth(0.5)
        window.Render()
    return (time.time() - start) / frames


def exact_field_grid(xyz, radius, k, bounds, resolution):
    """The metaball field sum_i c (1 - r^2/(k R_i)^2)^2 sampled on a resolution^3 grid."""
    c = 1.0 / (1.0 - 1.0 / k ** 2) ** 2
    lo = np.array(bounds[0::2])
    hi = np.array(bounds[1::2])
    spacing = (hi - lo) / (resolution - 1)
    field = np.zeros((resolution,) * 3)
    for p, r in zip(xyz, radius):
        reach = k * r
        i0 = np.maximum(np.floor((p - reach - lo) / spacing).astype(int), 0)
        i1 = np.minimum(np.ceil((p + reach - lo) / spacing).astype(int), resolution - 1)
        axes = [lo[a] + spacing[a] * np.arange(i0[a], i1[a] + 1) - p[a] for a in range(3)]
        d2 = (axes[0][:, None, None] ** 2 + axes[1][None, :, None] ** 2 +
              axes[2][None, None, :] ** 2)
        q = np.maximum(1.0 - d2 / reach ** 2, 0.0)
        field[i0[0]:i1[0] + 1, i0[1]:i1[1] + 1, i0[2]:i1[2] + 1] += c * q * q
    image = vtkImageData()
    image.SetDimensions(resolution, resolution, resolution)
    image.SetOrigin(*lo)
    image.SetSpacing(*spacing)
    # VTK's x-fastest order
    image.GetPointData().SetScalars(numpy_to_vtk(field.transpose(2, 1, 0).ravel().copy(), deep=1))
    return image


def peer_rows(name, xyz, radius, kind, resolutions):
    """Per time step of the scene: vtkMetaballMapper (the vicinity method: list build, upload and
    the frame after the positions changed) and the peer at each grid resolution (the splat that
    ParaView's Gaussian Resampling does, timed; the contour of the exact field on that grid, the
    best a grid of that resolution can do; the render), with the mean depth error (R) against
    the exact surface."""
    data = polydata(xyz, radius, kind)
    r_mean = float(np.mean(radius))
    mapper = pr.vtkMetaballMapper()
    actor, renderer, window = view(mapper, data)
    window.Render()
    reference = pr.vtkParticleReferenceRenderer()
    reference.SetRenderer(renderer)
    reference.SetActor(actor)
    reference.SetImageSize(*SIZE)
    reference.Render()
    ref_t = vtk_to_numpy(reference.GetViewDepthImage().GetPointData().GetScalars()).copy()

    def error_row(method, resolution, step_s, **extra):
        gt = gpu_view_depth(window, reference)
        both = (gt >= 0) & (ref_t >= 0)
        err = np.abs(gt - ref_t)[both] / r_mean
        row = {"scene": name, "atoms": len(xyz), "method": method, "resolution": resolution,
               "splat_s": "", "contour_s": "", "render_s": "", "step_s": round(step_s, 3),
               "triangles": "", "depth_mean_R": "%.3g" % err.mean(),
               "depth_p99_R": "%.3g" % np.percentile(err, 99),
               "coverage_differs": int(((gt >= 0) != (ref_t >= 0)).sum())}
        row.update(extra)
        print(row, flush=True)
        return row

    # ours: a new time step (the positions changed: the lists are rebuilt) and its frame
    steps = []
    for _ in range(3):
        data.GetPoints().Modified()
        start = time.time()
        window.Render()
        steps.append(time.time() - start)
    rows = [error_row("vtkMetaballMapper vicinity", "", min(steps),
                      render_s=round(min(steps) - mapper.GetLastListBuildSeconds(), 3))]
    bounds = mapper.GetBounds()
    for resolution in resolutions:
        splat = vtkGaussianSplatter()
        splat.SetInputData(data)
        splat.SetSampleDimensions(resolution, resolution, resolution)
        splat.SetModelBounds(bounds)
        splat.SetRadius(2.0 * r_mean / (bounds[1] - bounds[0]))
        splat.ScalarWarpingOff()
        start = time.time()
        splat.Update()
        splat_s = time.time() - start
        del splat
        grid = exact_field_grid(xyz, radius, 2.0, bounds, resolution)
        contour = vtkFlyingEdges3D()
        contour.SetInputData(grid)
        contour.SetValue(0, 1.0)
        contour.ComputeNormalsOn()
        start = time.time()
        contour.Update()
        contour_s = time.time() - start
        surface = vtkPolyDataMapper()
        surface.SetInputData(contour.GetOutput())
        surface.ScalarVisibilityOff()
        actor.SetMapper(surface)
        start = time.time()
        window.Render()
        render_s = time.time() - start
        rows.append(error_row("grid + vtkFlyingEdges3D", resolution,
                              splat_s + contour_s + render_s, splat_s=round(splat_s, 3),
                              contour_s=round(contour_s, 3), render_s=round(render_s, 3),
                              triangles=contour.GetOutput().GetNumberOfCells()))
        actor.SetMapper(mapper)
        del grid, contour, surface
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", default=os.path.join(HERE, "results"))
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    frames = 2 if args.quick else 4

    # ---- frames and list builds
    scenes = [("droplets 1x", droplets(1)), ("droplets 2x", droplets(2)),
              ("Sim-1-like 10 % clustered", clustered(20000, 0.1)),
              ("Sim-3-like 90 % clustered", clustered(20000, 0.9))]
    rows = []
    for name, (xyz, radius, kind) in scenes:
        data = polydata(xyz, radius, kind)
        core = pr.vtkParticleSphereMapper()
        _, renderer, window = view(core, data)
        core_s = frame_seconds(window, renderer, frames)
        metaballs = pr.vtkMetaballMapper()
        _, renderer, window = view(metaballs, data)
        metaball_s = frame_seconds(window, renderer, frames)
        one_pass = pr.vtkMetaballMapper()
        one_pass.SetDepthPrePass(False)
        _, renderer, window = view(one_pass, data)
        one_pass_s = frame_seconds(window, renderer, frames)
        plane = walking(pr.vtkMetaballMapper())
        _, renderer, window = view(plane, data)
        walking_s = frame_seconds(window, renderer, frames)
        walk = plane.GetWalkingPlane()
        rows.append({"scene": name, "atoms": len(xyz), "core_frame_s": round(core_s, 4),
                     "metaball_frame_s": round(metaball_s, 4),
                     "ratio": round(metaball_s / core_s, 2),
                     "one_pass_frame_s": round(one_pass_s, 4),
                     "one_pass_ratio": round(one_pass_s / core_s, 2),
                     "walking_frame_s": round(walking_s, 4),
                     "walking_ratio": round(walking_s / core_s, 2),
                     "walking_passes": walk.GetNumberOfPasses(),
                     "walking_termination": walk.GetTerminationAsString(walk.GetTermination()),
                     "list_build_s": round(metaballs.GetLastListBuildSeconds(), 4),
                     "list_entries": metaballs.GetNumberOfListEntries(),
                     "isolated": metaballs.GetNumberOfIsolatedParticles()})
        print(rows[-1], flush=True)
    with open(os.path.join(args.out, "metaball_frames.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)

    # ---- accuracy versus the knobs (droplets 1x)
    xyz, radius, kind = droplets(1)
    data = polydata(xyz, radius, kind)
    r_mean = float(np.mean(radius))
    settings = [("vicinity", "Tolerance", v) for v in (0.2, 0.05, 0.01, 0.001)] + \
               [("vicinity", "RefinementSteps", v) for v in (0, 2, 6, 12)] + \
               [("vicinity", "IterationLimit", v) for v in (10, 20, 40, 100)] + \
               [("walking", "WalkingTolerance", v) for v in (1e-2, 1e-3, 1e-4)] + \
               [("walking", "MaximumPasses", v) for v in (10, 20, 40, 80, 160)] + \
               [("walking", "TimeBudget", v) for v in (0.1, 0.3, 1.0)] + \
               [("walking", "StepOracle", v) for v in (0, 1)]
    rows = []
    for method, knob, value in settings:
        mapper = pr.vtkMetaballMapper()
        if method == "walking":
            walking(mapper)
        getattr(mapper, "Set" + knob)(value)
        if knob == "TimeBudget":
            # the budget bounds interactive frames only (still frames walk to convergence)
            mapper.GetFrameBudget().SetQuality(pr.vtkParticleFrameBudget.INTERACTIVE)
        actor, renderer, window = view(mapper, data)
        seconds = frame_seconds(window, renderer, frames)
        r = compare(window, renderer, actor, r_mean, normals=True)
        passes = mapper.GetWalkingPlane().GetNumberOfPasses() if method == "walking" else ""
        rows.append({"method": method, "knob": knob, "value": value, "passes": passes,
                     "frame_s": round(seconds, 4),
                     "depth_mean_R": "%.3g" % r["mean"], "depth_p99_R": "%.3g" % r["p99"],
                     "depth_max_smooth_R": "%.3g" % r["max_smooth"],
                     "missing_pixels": r["only_ref"], "extra_pixels": r["only_gpu"],
                     "covered": r["covered"], "normal_mean_deg": "%.3g" % r["normal_mean"]})
        print(rows[-1], flush=True)
    with open(os.path.join(args.out, "metaball_accuracy.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)

    # ---- the peer: a grid and a contour, at several resolutions, per time step; and ours
    rows = []
    for name, k, resolutions in (("droplets 1x", 1, (64, 128, 192, 256)),
                                 ("droplets 2x", 2, (128, 256, 384))):
        if args.quick:
            resolutions = resolutions[:2]
        rows += peer_rows(name, *droplets(k), resolutions)
    with open(os.path.join(args.out, "metaball_peer.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    return args.out


def plot(out):
    """metaball_benchmark.png from the three tables: frame-time ratios, error versus frame time
    per knob, the peer's error and time per step versus the metaballs'."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def read(name):
        with open(os.path.join(out, name)) as f:
            return list(csv.DictReader(f))
    frames = read("metaball_frames.csv")
    accuracy = read("metaball_accuracy.csv")
    peer = read("metaball_peer.csv")
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    ax = axes[0]
    x = np.arange(len(frames))
    ax.bar(x - 0.27, [float(r["ratio"]) for r in frames], 0.27, label="vicinity")
    ax.bar(x, [float(r["one_pass_ratio"]) for r in frames], 0.27,
           label="vicinity without the depth pre-pass")
    ax.bar(x + 0.27, [float(r["walking_ratio"]) for r in frames], 0.27,
           label="walking depth plane (to convergence)")
    for i, r in enumerate(frames):
        ax.annotate("%s passes" % r["walking_passes"], (i + 0.27, float(r["walking_ratio"])),
                    fontsize=7, ha="center")
        ax.annotate("%.1fx" % float(r["ratio"]), (i - 0.27, float(r["ratio"])), fontsize=7,
                    ha="center")
    ax.set_yscale("log")
    ax.legend(fontsize=8)
    ax.set_xticks(range(len(frames)))
    ax.set_xticklabels(["%s\n%s atoms" % (r["scene"].replace(" 10 %", "\n10 %").replace(
        " 90 %", "\n90 %"), r["atoms"]) for r in frames], fontsize=7)
    ax.set_ylabel("metaball frame / opaque sphere core frame")
    ax.set_title("camera-only frames, llvmpipe, %dx%d" % SIZE)
    ax = axes[1]
    for knob in ("Tolerance", "RefinementSteps", "IterationLimit", "WalkingTolerance",
                 "MaximumPasses", "TimeBudget", "StepOracle"):
        rows = [r for r in accuracy if r["knob"] == knob]
        style = "o-" if rows and rows[0]["method"] == "vicinity" else "s--"
        ax.plot([float(r["frame_s"]) for r in rows],
                [max(float(r["depth_mean_R"]), 1e-7) for r in rows], style,
                label=("%s (%s)" % (knob, rows[0]["method"])) if rows else knob)
        for r in rows:
            ax.annotate(r["value"], (float(r["frame_s"]), max(float(r["depth_mean_R"]), 1e-7)),
                        fontsize=7)
    ax.set_yscale("log")
    ax.set_xscale("log")
    ax.set_xlabel("frame time (s)")
    ax.set_ylabel("mean depth error (R) vs the exact surface")
    ax.set_title("droplets 1x: error vs time per knob")
    ax.legend(fontsize=8)
    ax = axes[2]
    for scene, color in (("droplets 1x", "C0"), ("droplets 2x", "C1")):
        grid = [r for r in peer if r["scene"] == scene and r["resolution"]]
        ours = [r for r in peer if r["scene"] == scene and not r["resolution"]]
        if not grid:
            continue
        ax.plot([float(r["step_s"]) for r in grid], [float(r["depth_mean_R"]) for r in grid],
                "s-", color=color,
                label="%s (%s atoms): grid + vtkFlyingEdges3D" % (scene, grid[0]["atoms"]))
        for r in grid:
            ax.annotate("%s^3" % r["resolution"], (float(r["step_s"]), float(r["depth_mean_R"])),
                        fontsize=7)
        for r in ours:
            ax.plot([float(r["step_s"])], [max(float(r["depth_mean_R"]), 1e-7)], "*",
                    color=color, markersize=12,
                    label="%s: vtkMetaballMapper vicinity (lists + frame)" % scene)
    walked = [r for r in accuracy if r["knob"] == "WalkingTolerance" and float(r["value"]) == 1e-3]
    if walked:
        ax.plot([float(walked[0]["frame_s"])], [max(float(walked[0]["depth_mean_R"]), 1e-7)],
                "m*", markersize=12, label="droplets 1x: walking depth plane (frame)")
    ax.set_yscale("log")
    ax.set_xscale("log")
    ax.set_xlabel("time per time step (s)")
    ax.set_ylabel("mean depth error (R)")
    ax.set_title("a time step: peer vs metaballs")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "metaball_benchmark.png"), dpi=110)


if __name__ == "__main__":
    if "--plot-only" in os.sys.argv:
        plot(os.path.join(HERE, "results"))
    else:
        plot(main())
