"""vtkLAMMPSDataReader against data files written by real LAMMPS (Debian's lmp runs
Testing/Data/Generators/in.data_formats: write_data in the atom styles atomic, charge, full,
sphere, dipole and a triclinic atomic box, each with image flags, Velocities and Masses).

Every file is also parsed independently here (split on whitespace, Python's float()); the reader
must reproduce it exactly: the atom count of the header, points, ids, types, mol, q, diameter
(radius = diameter / 2), mu, image flags, velocities joined by id, per-type masses, the box.
Also: unwrapping with the image flags, SortById, a file without the "# style" comment read with
AtomStyle, gzip, and bad input (an unknown style, a short line, a non-number, velocities of an
unknown atom, a header count larger than the section) -- each an error naming the file and line.

usage: python3 TestLAMMPSDataReader.py --generator DIR --temp DIR
"""
import argparse
import gzip
import os
import shutil
import subprocess
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import particlerendering as pr
from prVTKTesting import Messages, check, finish  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

STYLES = {"atomic": ["type", "x", "y", "z"], "charge": ["type", "q", "x", "y", "z"],
          "full": ["mol", "type", "q", "x", "y", "z"],
          "sphere": ["type", "diameter", "density", "x", "y", "z"],
          "dipole": ["type", "q", "x", "y", "z", "mux", "muy", "muz"]}




def parse(path):
    """The header counts, box, masses, Atoms rows and Velocities rows of a data file."""
    text = open(path).read().split("\n")
    info = {"masses": {}, "atoms": [], "velocities": {}, "tilt": [0.0, 0.0, 0.0]}
    section = None
    for line in text[1:]:
        words = line.split("#")[0].split()
        if not words:
            continue
        if not words[0].lstrip("-").replace(".", "", 1).replace("e", "", 1).isdigit():
            section = " ".join(words)
            if section == "Atoms":
                info["style"] = line.split("#")[1].split()[0]
            continue
        if section is None:
            if words[-1] == "atoms":
                info["n"] = int(words[0])
            elif words[-1] in ("xhi", "yhi", "zhi"):
                info[words[-1][0]] = (float(words[0]), float(words[1]))
            elif words[-1] == "yz":
                info["tilt"] = [float(w) for w in words[:3]]
        elif section == "Masses":
            info["masses"][int(words[0])] = float(words[1])
        elif section == "Atoms":
            info["atoms"].append(words)
        elif section == "Velocities":
            info["velocities"][int(words[0])] = [float(w) for w in words[1:4]]
    return info


def read(path, **settings):
    reader = pr.vtkLAMMPSDataReader()
    messages = Messages(reader)
    reader.SetFileName(path)
    for key, value in settings.items():
        getattr(reader, "Set" + key)(value)
    reader.Update()
    return reader.GetOutput(), reader.GetOutput(1), messages


def array(out, name):
    a = out.GetPointData().GetArray(name)
    return None if a is None else vtk_to_numpy(a)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--generator", required=True)
    parser.add_argument("--temp", required=True)
    args = parser.parse_args()
    work = os.path.join(args.temp, "TestLAMMPSDataReader")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    subprocess.run(["lmp", "-in", os.path.join(args.generator, "in.data_formats"), "-screen", "none",
                    "-log", "log.lammps"], cwd=work, check=True)
    quiet = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(quiet)

    for style in ("atomic", "triclinic", "charge", "full", "sphere", "dipole"):
        path = os.path.join(work, "data." + style)
        info = parse(path)
        columns = STYLES["atomic" if style == "triclinic" else style]
        check(info["style"] == ("atomic" if style == "triclinic" else style), "%s: style" % style)
        out, outline, messages = read(path)
        n = info["n"]
        check(not messages.text, "%s: messages %s" % (style, messages.text))
        check(out.GetNumberOfPoints() == n == len(info["atoms"]) and out.GetNumberOfVerts() == n,
              "%s: %d points, header %d" % (style, out.GetNumberOfPoints(), n))
        rows = info["atoms"]
        col = lambda name: numpy.array([float(r[1 + columns.index(name)]) for r in rows])  # noqa: E731
        xyz = numpy.stack([col(c) for c in "xyz"], axis=1)
        check(numpy.array_equal(vtk_to_numpy(out.GetPoints().GetData()), xyz), "%s: points" % style)
        ids = numpy.array([int(r[0]) for r in rows])
        check(numpy.array_equal(array(out, "id"), ids), "%s: ids" % style)
        check(numpy.array_equal(array(out, "type"), col("type").astype(int)), "%s: types" % style)
        image = numpy.array([[int(w) for w in r[-3:]] for r in rows])
        check(numpy.array_equal(array(out, "image"), image), "%s: image flags" % style)
        for name in ("q", "mol", "diameter", "density"):
            if name in columns:
                expected = col(name).astype(int if name == "mol" else numpy.float32)
                check(numpy.array_equal(array(out, name), expected), "%s: %s" % (style, name))
        if "mux" in columns:
            mu = numpy.stack([col(c) for c in ("mux", "muy", "muz")], axis=1).astype(numpy.float32)
            check(numpy.array_equal(array(out, "mu"), mu), "%s: mu" % style)
        radius = (col("diameter") / 2 if "diameter" in columns else numpy.full(n, 0.5)).astype(numpy.float32)
        check(numpy.array_equal(array(out, "radius"), radius), "%s: radius" % style)
        velocity = numpy.array([info["velocities"][i] for i in ids], dtype=numpy.float32)
        check(numpy.array_equal(array(out, "velocity"), velocity), "%s: velocities by id" % style)
        if info["masses"]:
            mass = numpy.array([info["masses"][t] for t in col("type").astype(int)], dtype=numpy.float32)
            check(numpy.array_equal(array(out, "mass"), mass), "%s: masses" % style)
        lo = [info[k][0] for k in "xyz"]
        length = [info[k][1] - info[k][0] for k in "xyz"]
        bounds = [out.GetFieldData().GetArray("BoxBounds").GetValue(i) for i in range(6)]
        tilt = [out.GetFieldData().GetArray("BoxTilt").GetValue(i) for i in range(3)]
        check(bounds == [info["x"][0], info["x"][1], info["y"][0], info["y"][1], info["z"][0], info["z"][1]]
              and tilt == info["tilt"], "%s: box %s %s" % (style, bounds, tilt))
        check(outline.GetNumberOfLines() == 12, "%s: box outline" % style)
        # unwrapped with the image flags
        unwrapped, _, _ = read(path, PositionSource=pr.vtkLAMMPSDataReader.UNWRAPPED)
        xy, xz, yz = info["tilt"]
        expected = xyz.copy()
        expected[:, 0] += image[:, 0] * length[0] + image[:, 1] * xy + image[:, 2] * xz
        expected[:, 1] += image[:, 1] * length[1] + image[:, 2] * yz
        expected[:, 2] += image[:, 2] * length[2]
        err = numpy.abs(vtk_to_numpy(unwrapped.GetPoints().GetData()) - expected).max()
        check(err <= 1e-12 * max(length) and numpy.abs(image).max() > 0,
              "%s: unwrapped, max error %g" % (style, err))
        print("%-9s %d atoms, %d with non-zero image flags, unwrap error %.2g"
              % (style, n, int((image != 0).any(axis=1).sum()), err))

    # SortById, gzip, no style comment
    path = os.path.join(work, "data.full")
    out, _, _ = read(path, SortById=True)
    ids = array(out, "id")
    check(numpy.array_equal(ids, numpy.sort(ids)), "SortById")
    with open(path, "rb") as src, gzip.open(path + ".gz", "wb") as dst:
        dst.write(src.read())
    plain, _, _ = read(path)
    packed, _, _ = read(path + ".gz")
    check(numpy.array_equal(vtk_to_numpy(plain.GetPoints().GetData()),
                            vtk_to_numpy(packed.GetPoints().GetData())), "gzip")
    text = open(path).read().replace("Atoms # full", "Atoms")
    nocomment = os.path.join(work, "nocomment.data")
    open(nocomment, "w").write(text)
    out, _, messages = read(nocomment, AtomStyle="full")
    check(numpy.array_equal(array(out, "mol"), array(plain, "mol")) and not messages.text,
          "no style comment, AtomStyle full")
    check(pr.vtkLAMMPSDataReader.CanReadFile(path) == 1 and
          pr.vtkLAMMPSDataReader.CanReadFile(os.path.join(work, "log.lammps")) == 0, "CanReadFile")

    # bad input: errors naming the file and the line
    lines = open(path).read().split("\n")
    first_atom = lines.index("Atoms # full") + 2  # 0-based index of the first atom line
    cases = []
    bad = list(lines)
    bad[first_atom - 2] = "Atoms # body"
    cases.append(("style.data", bad, first_atom - 1, "atom style 'body' is not supported"))
    bad = list(lines)
    bad[first_atom + 4] = " ".join(bad[first_atom + 4].split()[:5])
    cases.append(("short.data", bad, first_atom + 5, "5 values where atom style 'full' has 7"))
    bad = list(lines)
    words = bad[first_atom + 2].split()
    words[4] = "oops"
    bad[first_atom + 2] = " ".join(words)
    cases.append(("word.data", bad, first_atom + 3, "'oops' (x) is not a number"))
    bad = list(lines)
    v = lines.index("Velocities") + 2
    bad[v + 1] = "99999 0 0 0"
    cases.append(("velocity.data", bad, v + 2, "velocity of atom 99999, which is not in Atoms"))
    bad = [l.replace("256 atoms", "300 atoms") for l in lines]
    cases.append(("count.data", bad, None, "the Atoms section ends after 256 of 300 atoms"))
    for name, content, line, what in cases:
        p = os.path.join(work, name)
        open(p, "w").write("\n".join(content))
        out, _, messages = read(p)
        text = " ".join(messages.text)
        where = "%s, line %d: " % (name, line) if line else name + ", line "
        check(out.GetNumberOfPoints() == 0 and where in text and what in text,
              "%s: %d points, error %r (expected %r %r)" % (name, out.GetNumberOfPoints(), text, where, what))

    return finish()


if __name__ == "__main__":
    sys.exit(main())
