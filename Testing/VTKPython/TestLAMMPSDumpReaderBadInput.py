"""vtkLAMMPSDumpReader on bad input: every case gives a clear message that names the file and
the line, an empty output for the bad step, the other steps still readable, and no crash:
  truncated last snapshot, a column count that differs from the header, a non-numeric field, an
  integer column holding a float, NaN/Inf values (read, with a warning), a missing ITEM: line,
  an empty file, a binary file, a text file that is not a dump, a snapshot with 0 atoms (valid),
  columns that change between snapshots (valid), a line longer than the parse block (valid),
  Windows line ends (valid).

usage: python3 TestLAMMPSDumpReaderBadInput.py --temp DIR
"""
import argparse
import math
import os
import sys

import particlerendering as pr
import prVTKTesting  # noqa: E402
from prVTKTesting import check, finish  # noqa: E402
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow





def snapshot(timestep, rows, columns="id type x y z vx", box="0 10\n0 10\n0 10"):
    text = "ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS pp pp pp\n%s\n" % (
        timestep, len(rows), box)
    text += "ITEM: ATOMS %s\n" % columns
    return text + "".join(r + "\n" for r in rows)


ROWS = ["%d %d %g %g %g %g" % (i + 1, 1 + i % 2, 1.0 + i, 2.0 + i, 3.0 + i, 0.1 * i) for i in range(6)]
VALID = snapshot(0, ROWS) + snapshot(100, ROWS) + snapshot(200, ROWS)


def open_reader(path):
    return prVTKTesting.open_reader(pr.vtkLAMMPSDumpReader(), path)


def read_step(reader, time):
    reader.UpdateTimeStep(time)
    return reader.GetOutput().GetNumberOfPoints()


def write(temp, name, content, mode="w"):
    path = os.path.join(temp, name)
    with open(path, mode) as f:
        f.write(content)
    return path


def line_of(text, needle, occurrence=1):
    """1-based number of the line holding the occurrence-th needle."""
    count = 0
    for number, line in enumerate(text.split("\n"), 1):
        if needle in line:
            count += 1
            if count == occurrence:
                return number
    raise ValueError(needle)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--temp", required=True)
    args = parser.parse_args()
    temp = os.path.join(args.temp, "TestLAMMPSDumpReaderBadInput")
    os.makedirs(temp, exist_ok=True)
    # the pipeline's own messages about failed steps go to a string window; the reader's are observed
    quiet = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(quiet)

    # valid: 3 steps of 6 atoms
    path = write(temp, "valid.dump", VALID)
    reader, messages, times = open_reader(path)
    check(times == [0.0, 100.0, 200.0] and not messages.errors and not messages.warnings,
          "valid file: %s %s %s" % (times, messages.errors, messages.warnings))
    check(all(read_step(reader, t) == 6 for t in times), "valid file: 6 atoms per step")

    # truncated last snapshot: the two before it are read, a warning names the file and line
    cut = VALID[: VALID.rindex("4 2 ")]
    path = write(temp, "truncated.dump", cut)
    reader, messages, times = open_reader(path)
    text = " ".join(messages.warnings)
    check(times == [0.0, 100.0], "truncated: steps %s" % times)
    check("truncated.dump, line %d: the file ends here" % cut.count("\n") in text and
          "truncated: 3 of 6 atom lines" in text, "truncated: warning %r" % text)
    check(read_step(reader, 0.0) == 6 and read_step(reader, 100.0) == 6, "truncated: earlier steps")

    # a column count that differs from the header, in the second snapshot
    bad = VALID.split("ITEM: TIMESTEP\n100")[0] + "ITEM: TIMESTEP\n100" + \
        VALID.split("ITEM: TIMESTEP\n100")[1].replace("3 1 3 4 5 0.2", "3 1 3 4 5", 1)
    path = write(temp, "columns.dump", bad)
    reader, messages, times = open_reader(path)
    check(len(times) == 3, "columns: all 3 steps indexed")
    check(read_step(reader, 0.0) == 6, "columns: step 0 readable")
    n = read_step(reader, 100.0)
    text = " ".join(messages.errors)
    expected_line = line_of(bad, "3 1 3 4 5", 2)
    check(n == 0 and "columns.dump, line %d" % expected_line in text and
          "5 values where ITEM: ATOMS names 6 columns" in text,
          "columns: %d points, error %r (expected line %d)" % (n, text, expected_line))
    check(read_step(reader, 200.0) == 6, "columns: step 200 readable after the bad one")

    # a non-numeric field and an integer column holding a float
    for name, old, new, what in (("word.dump", "2 2 2 3 4 0.1", "2 2 2 abc 4 0.1", "column 4 ('abc') is not a number"),
                                 ("float_id.dump", "2 2 2 3 4 0.1", "2.5 2 2 3 4 0.1", "column 1 ('2.5') is not an integer")):
        path = write(temp, name, VALID.replace(old, new, 1))
        reader, messages, times = open_reader(path)
        n = read_step(reader, 0.0)
        text = " ".join(messages.errors)
        check(n == 0 and "%s, line %d" % (name, line_of(VALID, old)) in text and what in text,
              "%s: %d points, error %r" % (name, n, text))
        check(read_step(reader, 100.0) == 6, "%s: the next step readable" % name)

    # NaN and Inf values: read as such, with a warning
    path = write(temp, "nan.dump", VALID.replace("2 2 2 3 4 0.1", "2 2 nan 3 -inf 0.1", 1))
    reader, messages, times = open_reader(path)
    n = read_step(reader, 0.0)
    p = reader.GetOutput().GetPoint(1)
    check(n == 6 and math.isnan(p[0]) and p[2] == -math.inf and not messages.errors and
          any("2 NaN or infinite" in w for w in messages.warnings),
          "nan: %d points, point %s, warnings %s" % (n, p, messages.warnings))

    # a missing ITEM: line in the third snapshot: the two before it are read
    bad = VALID[: VALID.rindex("ITEM: NUMBER OF ATOMS")] + VALID[VALID.rindex("ITEM: NUMBER OF ATOMS") + len("ITEM: NUMBER OF ATOMS\n"):]
    path = write(temp, "missing.dump", bad)
    reader, messages, times = open_reader(path)
    text = " ".join(messages.warnings)
    expected_line = line_of(bad, "ITEM: TIMESTEP", 3) + 2  # the atom count where the ITEM: was
    check(times == [0.0, 100.0] and "missing.dump, line %d: expected 'ITEM: NUMBER OF ATOMS'"
          % expected_line in text, "missing ITEM: steps %s, warning %r (expected line %d)"
          % (times, text, expected_line))

    # files that cannot be used at all: an error, no steps, no crash
    for name, content, mode, what in (("empty.dump", "", "w", "the file is empty"),
                                      ("binary.dump", bytes(range(256)) * 64, "wb", "a binary file"),
                                      ("notes.dump", "hello\nworld\n", "w", "expected 'ITEM: TIMESTEP'")):
        path = write(temp, name, content, mode)
        reader, messages, times = open_reader(path)
        text = " ".join(messages.errors)
        check(times == [] and name in text and what in text, "%s: steps %s, error %r" % (name, times, text))
        check(pr.vtkLAMMPSDumpReader.CanReadFile(path) == 0, "%s: CanReadFile says no" % name)

    # valid oddities: 0 atoms, changing columns, a very long line, Windows line ends
    odd = snapshot(0, []) + snapshot(10, ["1 1 0.5 0.5 0.5"], "id type xs ys zs") + \
        snapshot(20, ["1 1 1.5" + " " * 6000 + "2 3"], "id type x y z")
    path = write(temp, "odd.dump", odd.replace("\n", "\r\n"))
    reader, messages, times = open_reader(path)
    reader.SetBlockSize(4096)
    counts = [read_step(reader, t) for t in times]
    p10 = None
    reader.UpdateTimeStep(10.0)
    p10 = reader.GetOutput().GetPoint(0)
    check(times == [0.0, 10.0, 20.0] and counts == [0, 1, 1] and not messages.errors and
          p10 == (5.0, 5.0, 5.0), "odd: steps %s, counts %s, point %s, errors %s"
          % (times, counts, p10, messages.errors))

    return finish()


if __name__ == "__main__":
    sys.exit(main())
