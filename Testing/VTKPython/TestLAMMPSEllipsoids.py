"""LAMMPS ellipsoids (atom_style ellipsoid) through vtkLAMMPSDumpReader into vtkParticleSphereMapper.

1. Real LAMMPS (Debian's lmp runs Testing/Data/Generators/in.dump_ellipsoids): its 2021 dump has
   the shapes and quaternions as c_shape[1] ... c_shape[7]; the reader gives them as the
   7-component "c_shape", equal to an independent parse. The same file with the columns named as
   newer LAMMPS writes them (shapex ... quatk), in a shuffled column order, gives "shape" (the
   diameters), "semi_axes" (half of them) and "orientation" (w, i, j, k), equal to the parse.
2. Both drawn: the named arrays (AxesArrayName "semi_axes", OrientationArrayName "orientation")
   and the c_shape components picked by hand (AxesArrayComponent 0 with AxesAreDiameters,
   OrientationArrayComponent 3) give the same picture, bit for bit, and the reference's.
3. The bundled Testing/Data/gb_ellipsoids.lammpstrj.gz (Gay-Berne rods, 3 steps): 1440 rods of
   semi-axes (0.5, 0.5, 1.5), unit quaternions, drawn as ellipsoids.

usage: python3 TestLAMMPSEllipsoids.py --generator DIR --data DIR --temp DIR
"""
import argparse
import os
import random
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import particlerendering as pr  # noqa: E402
from prVTKTesting import actor_view, check, compare, finish, grab_image  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline  # noqa: E402
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401

parser = argparse.ArgumentParser()
parser.add_argument("--generator", required=True)
parser.add_argument("--data", required=True)
parser.add_argument("--temp", required=True)
args = parser.parse_args()

NAMED = ["shapex", "shapey", "shapez", "quatw", "quati", "quatj", "quatk"]


def parse_dump(path):
    """Every snapshot as (timestep, column names, rows of words)."""
    snaps = []
    lines = open(path).read().splitlines()
    i = 0
    while i < len(lines):
        assert lines[i] == "ITEM: TIMESTEP"
        step = int(lines[i + 1])
        count = int(lines[i + 3])
        names = lines[i + 8].split()[2:]
        rows = [lines[i + 9 + k].split() for k in range(count)]
        snaps.append((step, names, rows))
        i += 9 + count
    return snaps


def read(path, k=-1):
    reader = pr.vtkLAMMPSDumpReader()
    reader.SetFileName(path)
    reader.UpdateInformation()
    times = reader.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    reader.UpdateTimeStep(times[k])
    return reader.GetOutput(), list(times)


def point_array(poly, name):
    a = poly.GetPointData().GetArray(name)
    return None if a is None else vtk_to_numpy(a).reshape(poly.GetNumberOfPoints(), -1)


# ---- 1. the dump of Debian's LAMMPS, as written and with the newer column names
lmp = shutil.which("lmp")
if not lmp:
    print("FAIL: LAMMPS (lmp, Debian package lammps) is not installed")
    sys.exit(1)
work = os.path.join(args.temp, "TestLAMMPSEllipsoids")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
subprocess.run([lmp, "-in", os.path.abspath(os.path.join(args.generator, "in.dump_ellipsoids")),
                "-log", "none", "-screen", "none"], cwd=work, check=True)
raw = os.path.join(work, "dump.ellipsoids")
snaps = parse_dump(raw)
step, names, rows = snaps[-1]
values = np.array([[float(w) for w in row] for row in rows])
shape_columns = [names.index("c_shape[%d]" % k) for k in range(1, 8)]
expected = values[:, shape_columns].astype(np.float32)
poly, times = read(raw)
c_shape = point_array(poly, "c_shape")
check(times == [s[0] for s in snaps], "time steps %s" % times)
check(c_shape is not None and c_shape.shape == (64, 7) and np.array_equal(c_shape, expected),
      "the 2021 dump's c_shape[1..7] read as the 7-component c_shape")

# newer LAMMPS's names, the columns shuffled (the reader orders the components by name)
named = os.path.join(work, "dump.named")
order = list(range(len(names)))
random.Random(3).shuffle(order)
with open(raw) as f, open(named, "w") as out:
    for line in f:
        words = line.split()
        if line.startswith("ITEM: ATOMS"):
            header = [dict(zip(["c_shape[%d]" % k for k in range(1, 8)], NAMED)).get(n, n)
                      for n in names]
            line = "ITEM: ATOMS " + " ".join(header[i] for i in order) + "\n"
        elif len(words) == len(names) and not line.startswith("ITEM"):
            line = " ".join(words[i] for i in order) + "\n"
        out.write(line)
poly, _ = read(named)
shape = point_array(poly, "shape")
semi = point_array(poly, "semi_axes")
orientation = point_array(poly, "orientation")
check(shape is not None and np.array_equal(shape, expected[:, :3]), "shape = shapex/y/z")
check(semi is not None and np.array_equal(semi, 0.5 * expected[:, :3]), "semi_axes = shape / 2")
check(orientation is not None and np.array_equal(orientation, expected[:, 3:]),
      "orientation = quatw, quati, quatj, quatk in that order")
check(poly.GetPointData().GetArray("shapex") is None and
      poly.GetPointData().GetArray("quatw") is None, "no separate shapex ... quatk arrays")
print("read: c_shape %s, shape/semi_axes/orientation %s"
      % (None if c_shape is None else c_shape.shape,
         None if orientation is None else (shape.shape, semi.shape, orientation.shape)))

# ---- 2. drawn from the named arrays and from the c_shape components: the same picture
pictures = {}
for label, path in (("named", named), ("c_shape", raw)):
    poly, _ = read(path)
    mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(poly)
    mapper.SetShapeToEllipsoid()
    if label == "named":
        mapper.SetAxesArrayName("semi_axes")
        mapper.SetOrientationArrayName("orientation")
    else:
        mapper.SetAxesArrayName("c_shape")
        mapper.SetAxesArrayComponent(0)
        mapper.SetAxesAreDiameters(True)
        mapper.SetOrientationArrayName("c_shape")
        mapper.SetOrientationArrayComponent(3)
    actor, renderer, window = actor_view(mapper, (300, 300))
    renderer.GetActiveCamera().SetPosition(30, 20, 40)
    renderer.GetActiveCamera().SetFocalPoint(5, 5, 5)
    renderer.ResetCamera()
    pictures[label] = grab_image(window)
    check(mapper.GetDrawsEllipsoids() and mapper.GetLastInputWarning() == "",
          label + ": drawn as ellipsoids without a warning (%s)" % mapper.GetLastInputWarning())
    if label == "named":
        r = compare(window, renderer, actor, 1.5)
        print("named arrays vs reference: %d covered, coverage differs in %d + %d, depth error "
              "max %.2e" % (r["covered"], r["only_gpu"], r["only_ref"], r["max_smooth"]))
        check(r["covered"] > 3000, "the ellipsoids are drawn")
        check(r["only_gpu"] + r["only_ref"] <= 2e-3 * r["covered"], "coverage vs reference")
        check(r["max_smooth"] <= 1e-4, "depth vs reference %.2e" % r["max_smooth"])
check(np.array_equal(pictures["named"], pictures["c_shape"]),
      "the c_shape components picked by hand draw another picture")

# ---- 3. the bundled Gay-Berne dump
bundled = os.path.join(args.data, "gb_ellipsoids.lammpstrj.gz")
poly, times = read(bundled)
semi = point_array(poly, "semi_axes")
orientation = point_array(poly, "orientation")
lengths = np.linalg.norm(orientation, axis=1) if orientation is not None else np.zeros(1)
print("bundled: steps %s, %d rods, semi-axes %s, |q| - 1 within %.1e"
      % (times, poly.GetNumberOfPoints(), None if semi is None else np.unique(semi, axis=0),
         np.abs(lengths - 1).max()))
check(times == [0.0, 1000.0, 2000.0], "bundled: time steps %s" % times)
check(poly.GetNumberOfPoints() == 1440, "bundled: 1440 rods")
check(semi is not None and np.all(semi == [0.5, 0.5, 1.5]), "bundled: semi-axes 0.5 0.5 1.5")
check(np.abs(lengths - 1).max() < 1e-5, "bundled: unit quaternions")
mapper = pr.vtkParticleSphereMapper()
mapper.SetInputData(poly)
mapper.SetShapeToEllipsoid()
mapper.SetAxesArrayName("semi_axes")
mapper.SetOrientationArrayName("orientation")
actor, renderer, window = actor_view(mapper, (300, 300))
renderer.ResetCamera()
image = grab_image(window)
check(mapper.GetDrawsEllipsoids() and mapper.GetNumberOfSkippedParticles() == 0,
      "bundled: drawn as ellipsoids")
drawn = int(np.sum(np.any(image[:, :3] > 0, axis=1)))
print("bundled: %d of 90000 pixels show rods" % drawn)
check(drawn > 10000, "bundled: the rods fill the view (%d pixels)" % drawn)

sys.exit(finish())
