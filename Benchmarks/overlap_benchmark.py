#!/usr/bin/env python3
"""Exact overlap compositing (vtkTransparentSphereMapper EXACT_OVERLAP, vtkParticleFragmentLists)
against the paper's sorted spheres (SORTED_SPHERES): error against the reference's exact
integral and frame time, on
  - lj_film: the LAMMPS Lennard-Jones film of Testing/Data (19 360 atoms, radii 0.4-0.5 sigma,
    i.e. about sigma/2: little overlap), coloured by type,
  - molecule_2k / molecule_20k: a synthetic globular polymer at van der Waals radii (C 1.70,
    N 1.55, O 1.52, S 1.80 Angstrom, bonds 1.5 Angstrom, bond angle 111 degrees, non-bonded atoms
    at least 2.9 Angstrom apart, packed in a sphere at 0.04 atoms / Angstrom^3): heavy overlap,
    CPK colours,
  - gas_1e5 / gas_1e6: the random gas of make_particles.py (radii 0.3-0.5, density 0.1): many
    slight overlaps, the cost of the default (AUTOMATIC picks the lists there).
Errors: 512 x 384, RGB 8-bit, against vtkParticleReferenceRenderer in its exact mode (gas only
up to 1e5). Times: 1024 x 768, median wall time of FRAMES frames with the camera orbiting 3
degrees per frame (the sorted path sorts every frame), each frame ended by glFinish
(WaitForCompletion); the first two frames (shader builds, allocation) are not counted.
Opacity 0.5 (the film also 0.9), constant density, VolumeMix 0.5. "penetrating": whether two
spheres penetrate by more than OverlapTolerance (0.25), i.e. what AUTOMATIC picks.

usage: Scripts/with_xvfb.sh /usr/bin/python3 Benchmarks/overlap_benchmark.py [--build build]
       [--out Benchmarks/results] [--frames 7] [--quick]
writes overlap_compositing.csv and overlap_compositing.png into --out
"""
import argparse
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
    p.add_argument("--quick", action="store_true",
                   help="smoke run: the LJ film at opacity 0.5 and the 2k molecule only")
    return p.parse_args()


ARGS = parse()
sys.path.insert(0, os.path.join(ARGS.build, "lib", "python3", "dist-packages"))
sys.path.insert(0, HERE)
import particlerendering as pr  # noqa: E402
import make_particles  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPolyData  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter  # noqa: E402
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401

M = pr.vtkTransparentSphereMapper
VDW = {"C": 1.70, "N": 1.55, "O": 1.52, "S": 1.80}
CPK = {"C": (144, 144, 144), "N": (48, 80, 248), "O": (255, 13, 13), "S": (255, 200, 50)}


def molecule(n, seed=5):
    """A globular self-avoiding chain (see the module comment)."""
    rng = np.random.default_rng(seed)
    radius = (3.0 * n / (4.0 * np.pi * 0.04)) ** (1.0 / 3.0)
    cell = 3.0
    grid = {}
    pos = np.zeros((n, 3))

    def key(p):
        return tuple((p // cell).astype(int))

    def clear(p, upto):
        k = key(p)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for j in grid.get((k[0] + dx, k[1] + dy, k[2] + dz), ()):
                        if j < upto - 3 and np.sum((pos[j] - p) ** 2) < 2.9 ** 2:
                            return False
        return True

    pos[1] = pos[0] + np.array([1.5, 0, 0])
    grid.setdefault(key(pos[0]), []).append(0)
    grid.setdefault(key(pos[1]), []).append(1)
    i = 2
    stuck = 0
    while i < n:
        b = pos[i - 1] - pos[i - 2]
        b /= np.linalg.norm(b)
        for _ in range(60):
            # bond angle 111 degrees, random torsion, pulled inwards at the surface
            perp = np.cross(b, rng.normal(size=3))
            perp /= np.linalg.norm(perp)
            angle = np.radians(180.0 - 111.0)
            step = np.cos(angle) * b + np.sin(angle) * perp
            candidate = pos[i - 1] + 1.5 * step
            if np.linalg.norm(candidate) < radius and clear(candidate, i):
                break
        else:
            stuck += 1
            if stuck > 50:  # restart the tail elsewhere inside
                candidate = rng.uniform(-radius, radius, size=3) * 0.8
                stuck = 0
            else:
                continue
        pos[i] = candidate
        grid.setdefault(key(candidate), []).append(i)
        i += 1
    elements = rng.choice(["C", "N", "O", "S"], size=n, p=[0.62, 0.17, 0.19, 0.02])
    radii = np.array([VDW[e] for e in elements])
    rgb = np.array([CPK[e] for e in elements], dtype=np.uint8)
    return pos, radii, rgb


def polydata(pos, radii, rgb):
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(pos, dtype=np.float32), deep=True))
    data = vtkPolyData()
    data.SetPoints(points)
    for name, values in (("radius", radii.astype(np.float32)), ("rgb", rgb)):
        array = numpy_to_vtk(np.ascontiguousarray(values), deep=True)
        array.SetName(name)
        data.GetPointData().AddArray(array)
    return data


def type_colors(types):
    palette = np.array([[230, 120, 60], [70, 130, 230], [90, 200, 90], [200, 80, 200],
                        [220, 200, 60]], dtype=np.uint8)
    return palette[(types.astype(int) - 1) % len(palette)]


def scenes():
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(TOP, "Testing", "Data", "lj_film.vtp"))
    reader.Update()
    film = reader.GetOutput()
    pd = film.GetPointData()
    film_data = polydata(vtk_to_numpy(film.GetPoints().GetData()),
                         vtk_to_numpy(pd.GetArray("radius")),
                         type_colors(vtk_to_numpy(pd.GetArray("type"))))
    yield "lj_film", film_data, True, 0.5
    if ARGS.quick:
        yield "molecule_2k", polydata(*molecule(2000)), True, 0.5
        return
    yield "lj_film_opacity0.9", film_data, True, 0.9
    for n, label in ((2000, "molecule_2k"), (20000, "molecule_20k")):
        yield label, polydata(*molecule(n)), True, 0.5
    for n, label, with_error in ((10**5, "gas_1e5", True), (10**6, "gas_1e6", False)):
        arrays = make_particles.make_arrays("gas", n, seed=1)
        yield (label, polydata(arrays["points"], arrays["radius"], type_colors(arrays["type"])),
               with_error, 0.5)


def setup(data, mode, size, opacity):
    mapper = M()
    mapper.SetInputData(data)
    mapper.SetRadiusArrayName("radius")
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("rgb")
    mapper.SetColorModeToDirectScalars()
    mapper.SetOverlapCompositing(mode)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetOpacity(opacity)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1.0, 1.0, 1.0)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(25)
    camera.Elevation(15)
    camera.Zoom(1.3)
    renderer.ResetCameraClippingRange()
    return mapper, actor, renderer, window


def grab(window):
    f = vtkWindowToImageFilter()
    f.SetInput(window)
    f.Update()
    return vtk_to_numpy(f.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)


def main():
    os.makedirs(ARGS.out, exist_ok=True)
    rows = []
    for label, data, with_error, opacity in scenes():
        n = data.GetNumberOfPoints()
        # error against the exact reference
        errors = {}
        if with_error:
            reference_image = None
            for mode in (M.EXACT_OVERLAP, M.SORTED_SPHERES):
                mapper, actor, renderer, window = setup(data, mode, (512, 384), opacity)
                window.Render()
                image = grab(window)
                if reference_image is None:
                    start = time.perf_counter()
                    reference = pr.vtkParticleReferenceRenderer()
                    reference.SetRenderer(renderer)
                    reference.SetActor(actor)
                    reference.Render()
                    rgba = vtk_to_numpy(reference.GetColorImage().GetPointData().GetScalars())
                    reference_image = np.round(np.clip(rgba[:, :3], 0, 1) * 255).astype(int)
                    print("%s: reference in %.1f s" % (label, time.perf_counter() - start),
                          flush=True)
                e = np.abs(image - reference_image).max(axis=1)
                errors[mode] = (int(e.max()), float(e.mean()), float(np.percentile(e, 99.9)),
                                int((e > 2).sum()))
        # frame time at 1024 x 768
        for mode in (M.SORTED_SPHERES, M.EXACT_OVERLAP):
            mapper, actor, renderer, window = setup(data, mode, (1024, 768), opacity)
            times = []
            for frame in range(ARGS.frames + 2):
                start = time.perf_counter()
                window.Render()
                window.WaitForCompletion()
                if frame >= 2:
                    times.append(time.perf_counter() - start)
                renderer.GetActiveCamera().Azimuth(3)
                renderer.ResetCameraClippingRange()
            lists = mapper.GetFragmentLists()
            exact = mode == M.EXACT_OVERLAP
            row = {
                "scene": label, "particles": n, "opacity": opacity,
                "mode": "exact" if exact else "sorted",
                "penetrating": int(mapper.HasOverlappingSpheres()),
                "frame_s": statistics.median(times),
                "fragments": lists.GetLastNumberOfFragments() if exact else "",
                "fragments_per_pixel": ("%.2f" % (lists.GetLastNumberOfFragments() / (1024 * 768.0))
                                        if exact else ""),
                "bands": lists.GetLastNumberOfBands() if exact else "",
                "list_memory_mb": ("%.1f" % (lists.GetAllocatedBytes() / 1e6)) if exact else "",
                "incomplete_pixels": lists.GetLastNumberOfIncompletePixels() if exact else "",
            }
            if errors:
                err = errors[mode]
                row.update({"max_error": err[0], "mean_error": "%.3f" % err[1],
                            "p999_error": "%.1f" % err[2], "pixels_over_2": err[3]})
            rows.append(row)
            print(row, flush=True)
            del mapper, actor, renderer, window
    keys = ["scene", "particles", "opacity", "mode", "penetrating", "frame_s", "fragments",
            "fragments_per_pixel", "bands", "list_memory_mb", "incomplete_pixels", "max_error",
            "mean_error", "p999_error", "pixels_over_2"]
    path = os.path.join(ARGS.out, "overlap_compositing.csv")
    with open(path, "w") as f:
        f.write("# made by: Scripts/with_xvfb.sh /usr/bin/python3 Benchmarks/overlap_benchmark.py"
                " --frames %d\n" % ARGS.frames)
        f.write(",".join(keys) + "\n")
        for row in rows:
            f.write(",".join(str(row.get(k, "")) if not isinstance(row.get(k), float)
                             else "%.4f" % row[k] for k in keys) + "\n")
    print("wrote", path)
    plot(rows)


def plot(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes_ = []
    for r in rows:
        if r["scene"] not in scenes_:
            scenes_.append(r["scene"])
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    x = np.arange(len(scenes_))
    for k, mode in enumerate(("sorted", "exact")):
        t = [next(r["frame_s"] for r in rows if r["scene"] == s and r["mode"] == mode)
             for s in scenes_]
        axes[0].bar(x + (k - 0.5) * 0.38, t, 0.38, label=mode)
        e = [next((r.get("max_error", np.nan) for r in rows
                   if r["scene"] == s and r["mode"] == mode), np.nan) for s in scenes_]
        axes[1].bar(x + (k - 0.5) * 0.38, [np.nan if v == "" else v for v in e], 0.38, label=mode)
    for ax, title in ((axes[0], "frame time, 1024x768, orbiting [s]"),
                      (axes[1], "max error vs exact reference, 512x384 [1/255]")):
        ax.set_xticks(x)
        ax.set_xticklabels(scenes_, rotation=20)
        ax.set_title(title)
        ax.legend()
    axes[0].set_yscale("log")
    fig.tight_layout()
    path = os.path.join(ARGS.out, "overlap_compositing.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main()
