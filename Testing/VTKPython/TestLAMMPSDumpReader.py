"""vtkLAMMPSDumpReader against files written by real LAMMPS (Debian's lmp runs
Testing/Data/Generators/in.dump_formats in a temporary directory: dump atom, custom with every
coordinate flavour, image flags only, custom/gz, a file series, a triclinic box, atom counts that
change from snapshot to snapshot).

What LAMMPS says it wrote: the thermo output of its log (step, atoms) -- every snapshot's timestep
and atom count must match it. The values: an independent pure-Python parse of the same text
(split on whitespace, Python's float()), which the reader must reproduce exactly (points in double,
other columns as float32 of the same value, integers exactly). Coordinate flavours must agree to the
printed precision: scaled coordinates through the (triclinic) box against x y z, wrapped
coordinates unwrapped with the image flags against xu yu zu. Also: gzip equals plain text, a series
given in shuffled order equals the single file, DeltaTime scales the time values, SortById orders
every array by id, radii come from the per-type table, the box is in the field data and on the
second output port.

usage: python3 TestLAMMPSDumpReader.py --generator DIR --temp DIR
"""
import argparse
import gzip
import os
import random
import re
import shutil
import subprocess
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import particlerendering as pr
from prVTKTesting import check, finish  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy





def run_lammps(generator, temp):
    lmp = shutil.which("lmp")
    if not lmp:
        print("FAIL: LAMMPS (lmp, Debian package lammps) is not installed")
        sys.exit(1)
    work = os.path.join(temp, "TestLAMMPSDumpReader")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    subprocess.run([lmp, "-in", os.path.join(generator, "in.dump_formats"), "-log", "log.lammps",
                    "-screen", "none"], cwd=work, check=True)
    return work


def lammps_log(path):
    """(step, atoms) of every thermo line, per run."""
    rows = []
    lines = open(path).read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].split()[:2] == ["Step", "Atoms"]:
            i += 1
            while i < len(lines) and not lines[i].startswith("Loop time"):
                words = lines[i].split()
                rows.append((int(words[0]), int(words[1])))
                i += 1
        i += 1
    return rows


def parse_dump(path):
    """Snapshots of a text dump, parsed independently: dicts with timestep, atoms, box (3 rows
    of floats), columns, rows (list of word lists)."""
    opener = gzip.open if path.endswith(".gz") else open
    lines = opener(path, "rt").read().splitlines()
    snaps = []
    i = 0
    while i < len(lines):
        assert lines[i] == "ITEM: TIMESTEP", lines[i]
        snap = {"timestep": int(lines[i + 1])}
        n = int(lines[i + 3])
        snap["atoms"] = n
        snap["tilted"] = "xy xz yz" in lines[i + 4]
        snap["box"] = [[float(w) for w in lines[i + 5 + k].split()] for k in range(3)]
        snap["columns"] = lines[i + 8].split()[2:]
        snap["rows"] = [lines[i + 9 + k].split() for k in range(n)]
        snaps.append(snap)
        i += 9 + n
    return snaps


def column(snap, name, kind=float):
    j = snap["columns"].index(name)
    return numpy.array([kind(r[j]) for r in snap["rows"]])


def box_of(snap):
    """lo (3), lengths (3), tilt (xy, xz, yz) of the box itself (tilt removed from the
    bounding box LAMMPS writes)."""
    b = snap["box"]
    tilt = [b[k][2] if snap["tilted"] else 0.0 for k in range(3)]
    xy, xz, yz = tilt
    lo = [b[0][0] - min(0.0, xy, xz, xy + xz), b[1][0] - min(0.0, yz), b[2][0]]
    hi = [b[0][1] - max(0.0, xy, xz, xy + xz), b[1][1] - max(0.0, yz), b[2][1]]
    return lo, [hi[k] - lo[k] for k in range(3)], tilt


class Reader:
    def __init__(self, *paths, **settings):
        self.reader = pr.vtkLAMMPSDumpReader()
        for p in paths:
            self.reader.AddFileName(p)
        for key, value in settings.items():
            getattr(self.reader, "Set" + key)(value)
        self.reader.UpdateInformation()
        info = self.reader.GetOutputInformation(0)
        from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
        self.times = list(info.Get(sddp.TIME_STEPS())) if info.Has(sddp.TIME_STEPS()) else []

    def step(self, k):
        self.reader.UpdateTimeStep(self.times[k])
        return self.reader.GetOutput()

    def outline(self):
        return self.reader.GetOutput(1)


def points(poly):
    return vtk_to_numpy(poly.GetPoints().GetData())


def array(poly, name):
    a = poly.GetPointData().GetAbstractArray(name)
    if a is None:
        return None
    return vtk_to_numpy(a)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--generator", required=True)
    parser.add_argument("--temp", required=True)
    args = parser.parse_args()
    work = run_lammps(args.generator, args.temp)
    path = lambda name: os.path.join(work, name)  # noqa: E731
    log = lammps_log(path("log.lammps"))
    first_run = log[:5]
    second_run = log[5:]
    print("LAMMPS log (step, atoms):", log)

    custom = parse_dump(path("dump.custom"))
    # ---- counts and timesteps: what LAMMPS says it wrote
    for name, expected in (("dump.atom", first_run), ("dump.custom", first_run),
                           ("dump.image", first_run), ("dump.custom.gz", first_run),
                           ("dump.triclinic", second_run)):
        r = Reader(path(name))
        got = [(r.reader.GetStepTimestep(k), r.reader.GetStepNumberOfAtoms(k))
               for k in range(r.reader.GetNumberOfSteps())]
        check(got == expected, "%s: (timestep, atoms) %s, LAMMPS logged %s" % (name, got, expected))
        check(r.times == [float(t) for t, _ in expected], "%s: time values %s" % (name, r.times))
        for k, (t, n) in enumerate(expected):
            out = r.step(k)
            check(out.GetNumberOfPoints() == n and out.GetNumberOfVerts() == n,
                  "%s step %d: %d points, %d vertex cells, expected %d"
                  % (name, k, out.GetNumberOfPoints(), out.GetNumberOfVerts(), n))
            step_field = out.GetFieldData().GetArray("Timestep")
            check(step_field is not None and step_field.GetValue(0) == t,
                  "%s step %d: Timestep field data" % (name, k))

    # ---- values of the custom dump: exactly the text's values
    r = Reader(path("dump.custom"))
    for k, snap in enumerate(custom):
        out = r.step(k)
        xyz = numpy.stack([column(snap, c) for c in ("x", "y", "z")], axis=1)
        check(numpy.array_equal(points(out), xyz), "custom step %d: points != x y z" % k)
        for name, cols in (("velocity", ("vx", "vy", "vz")), ("force", ("fx", "fy", "fz")),
                           ("unwrapped", ("xu", "yu", "zu")), ("scaled", ("xs", "ys", "zs")),
                           ("scaled_unwrapped", ("xsu", "ysu", "zsu")),
                           ("c_s", ("c_s[1]", "c_s[2]", "c_s[3]"))):
            expected = numpy.stack([column(snap, c) for c in cols], axis=1).astype(numpy.float32)
            got = array(out, name)
            check(got is not None and got.shape == expected.shape and numpy.array_equal(got, expected),
                  "custom step %d: array %s" % (k, name))
        check(numpy.array_equal(array(out, "c_ke"), column(snap, "c_ke").astype(numpy.float32)),
              "custom step %d: c_ke" % k)
        check(numpy.array_equal(array(out, "id"), column(snap, "id", int)), "custom step %d: id" % k)
        check(numpy.array_equal(array(out, "type"), column(snap, "type", int)),
              "custom step %d: type" % k)
        image = numpy.stack([column(snap, c, int) for c in ("ix", "iy", "iz")], axis=1)
        check(numpy.array_equal(array(out, "image"), image), "custom step %d: image" % k)
        check(out.GetPointData().GetArray("image").GetDataTypeAsString() == "int" and
              out.GetPointData().GetArray("id").GetDataTypeAsString() == "idtype",
              "custom step %d: integer columns as integer arrays" % k)
    check(numpy.abs(image).max() > 0, "the run has atoms with non-zero image flags")

    # ---- flavours agree to the printed precision
    lo, length, tilt = box_of(custom[-1])
    last = custom[-1]
    xu = numpy.stack([column(last, c) for c in ("xu", "yu", "zu")], axis=1)
    x = numpy.stack([column(last, c) for c in ("x", "y", "z")], axis=1)
    unwrapped = Reader(path("dump.image"), PositionSource=pr.vtkLAMMPSDumpReader.UNWRAPPED)
    err = numpy.abs(points(unwrapped.step(4)) - xu).max()
    check(err <= 1e-12 * max(length), "x + image flags vs xu: max error %g" % err)
    r_u = Reader(path("dump.custom"), PositionSource=pr.vtkLAMMPSDumpReader.UNWRAPPED)
    check(numpy.array_equal(points(r_u.step(4)), xu), "PositionSource UNWRAPPED takes xu yu zu")
    atom = Reader(path("dump.atom"))  # id type xs ys zs at %g: 6 significant digits
    atom_snap = parse_dump(path("dump.atom"))[-1]
    ids_atom = column(atom_snap, "id", int)
    order = numpy.argsort(ids_atom)
    order_custom = numpy.argsort(column(last, "id", int))
    err = numpy.abs(points(atom.step(4))[order] - x[order_custom]).max()
    check(err <= 5e-6 * max(length), "dump atom (xs ys zs at %%g) vs x y z: max error %g" % err)
    print("scaled (6 digits) vs x: max error %.3g (box %.3g)" % (err, max(length)))

    # ---- triclinic: scaled through the tilted box, unwrapped by image flags
    tri = parse_dump(path("dump.triclinic"))
    lo, length, tilt = box_of(tri[-1])
    check(tilt == [1.3, 0.7, -0.9] or numpy.allclose(tilt, [1.3, 0.7, -0.9]), "triclinic tilt %s" % tilt)
    x = numpy.stack([column(tri[-1], c) for c in ("x", "y", "z")], axis=1)
    xu = numpy.stack([column(tri[-1], c) for c in ("xu", "yu", "zu")], axis=1)
    r_t = Reader(path("dump.triclinic"))
    check(numpy.array_equal(points(r_t.step(4)), x), "triclinic: wrapped x y z")
    # the same snapshot without x y z: rewrite the file keeping only xs ys zs / x y z + image
    def rewrite(src, dst, keep):
        snaps = parse_dump(src)
        with open(dst, "w") as f:
            for s in snaps:
                idx = [s["columns"].index(c) for c in keep]
                f.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\n" % (s["timestep"], s["atoms"]))
                f.write("ITEM: BOX BOUNDS xy xz yz pp pp pp\n")
                for row in s["box"]:
                    f.write(" ".join(repr(v) for v in row) + "\n")
                f.write("ITEM: ATOMS " + " ".join(keep) + "\n")
                for row in s["rows"]:
                    f.write(" ".join(row[j] for j in idx) + "\n")
    rewrite(path("dump.triclinic"), path("tri.scaled"), ["id", "type", "xs", "ys", "zs"])
    rewrite(path("dump.triclinic"), path("tri.image"), ["id", "type", "x", "y", "z", "ix", "iy", "iz"])
    err = numpy.abs(points(Reader(path("tri.scaled")).step(4)) - x).max()
    check(err <= 1e-12 * max(length), "triclinic xs ys zs through the box vs x y z: max error %g" % err)
    err_u = numpy.abs(points(Reader(path("tri.image"),
                                    PositionSource=pr.vtkLAMMPSDumpReader.UNWRAPPED).step(4)) - xu).max()
    check(err_u <= 1e-12 * max(length), "triclinic x + image vs xu: max error %g" % err_u)
    print("triclinic: scaled vs x %.3g, image-unwrapped vs xu %.3g" % (err, err_u))
    field = r_t.step(4).GetFieldData()
    bounds = [field.GetArray("BoxBounds").GetValue(i) for i in range(6)]
    check(numpy.allclose(bounds, [lo[0], lo[0] + length[0], lo[1], lo[1] + length[1],
                                  lo[2], lo[2] + length[2]], rtol=0, atol=1e-14),
          "triclinic BoxBounds %s" % bounds)
    check(field.GetAbstractArray("BoxPeriodicity").GetValue(0) == "pp pp pp", "BoxPeriodicity")
    outline = r_t.outline()
    check(outline.GetNumberOfPoints() == 8 and outline.GetNumberOfLines() == 12, "box outline")

    # ---- gzip equals plain text; the series equals the single file
    gz = Reader(path("dump.custom.gz"))
    plain = Reader(path("dump.custom"))
    for k in range(5):
        a, b = gz.step(k), plain.step(k)
        check(numpy.array_equal(points(a), points(b)) and
              numpy.array_equal(array(a, "velocity"), array(b, "velocity")), "gz step %d" % k)
    files = [f for f in os.listdir(work) if re.fullmatch(r"dump\.\d+", f)]
    random.Random(3).shuffle(files)
    series = Reader(*[path(f) for f in files])
    check(series.times == [float(t) for t, _ in first_run], "series times %s" % series.times)
    for k in range(5):
        check(numpy.array_equal(points(series.step(k)), points(plain.step(k))), "series step %d" % k)

    # ---- time values, SortById, radii
    scaled_time = Reader(path("dump.custom"), DeltaTime=0.002)
    check(numpy.allclose(scaled_time.times, [0.002 * t for t, _ in first_run], rtol=1e-15),
          "DeltaTime: %s" % scaled_time.times)
    sorted_reader = Reader(path("dump.custom"), SortById=True)
    out = sorted_reader.step(3)
    ids = column(custom[3], "id", int)
    order = numpy.argsort(ids, kind="stable")
    check(numpy.array_equal(array(out, "id"), ids[order]), "SortById: ids ascending")
    vel = numpy.stack([column(custom[3], c) for c in ("vx", "vy", "vz")], axis=1).astype(numpy.float32)
    check(numpy.array_equal(array(out, "velocity"), vel[order]), "SortById: velocity follows")
    xyz = numpy.stack([column(custom[3], c) for c in ("x", "y", "z")], axis=1)
    check(numpy.array_equal(points(out), xyz[order]), "SortById: points follow")
    check(not numpy.array_equal(ids, numpy.sort(ids)), "the dump's own order is not by id")
    radii = Reader(path("dump.custom"))
    radii.reader.SetTypeRadius(2, 0.4)
    radii.reader.Modified()
    out = radii.step(0)
    expected = numpy.where(column(custom[0], "type", int) == 2, 0.4, 0.5).astype(numpy.float32)
    check(numpy.array_equal(array(out, "radius"), expected), "radius from the per-type table")

    # ---- progress: reported per parse block (4 KiB blocks here), increasing, ending at 1 (the
    # pipeline itself also reports 0 and 1 around each request)
    progress = []
    r_p = pr.vtkLAMMPSDumpReader()
    r_p.SetFileName(path("dump.custom"))
    r_p.SetBlockSize(4096)
    r_p.AddObserver("ProgressEvent", lambda obj, event: progress.append(obj.GetProgress()))
    r_p.Update()
    blocks = [v for v in progress if 0.1 < v < 1.0]  # the parse's own reports, per block
    check(len(blocks) > 20 and blocks == sorted(blocks) and progress[-1] == 1.0,
          "progress: %d block reports, last %s" % (len(blocks), progress[-1:] if progress else None))

    # ---- CanReadFile
    check(pr.vtkLAMMPSDumpReader.CanReadFile(path("dump.custom.gz")) == 1 and
          pr.vtkLAMMPSDumpReader.CanReadFile(path("log.lammps")) == 0, "CanReadFile")

    return finish()


if __name__ == "__main__":
    sys.exit(main())
