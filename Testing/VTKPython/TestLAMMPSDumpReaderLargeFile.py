"""vtkLAMMPSDumpReader with byte offsets beyond 2^31: a dump whose first snapshot holds 140
million atom lines (2.24 GB of text) and whose second snapshot (3 atoms) therefore starts past
the 2 GB mark. The index must find both snapshots (skipping the 140 million lines by counting
line ends, without parsing them) and reading the second must seek past 2^31 and give its exact
values. The file is written in the test's temp directory and removed afterwards.

usage: python3 TestLAMMPSDumpReaderLargeFile.py --temp DIR
"""
import argparse
import os
import sys
import time

import particlerendering as pr
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp

LINES = 140_000_000
LINE = b"1 1 0.5 0.5 0.5\n"  # 16 bytes


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--temp", required=True)
    args = parser.parse_args()
    path = os.path.join(args.temp, "TestLAMMPSDumpReaderLargeFile.dump")
    header = b"ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\n" \
        b"ITEM: ATOMS id type x y z\n"
    start = time.time()
    try:
        with open(path, "wb") as f:
            f.write(header % (0, LINES))
            chunk = LINE * 1_000_000
            for _ in range(LINES // 1_000_000):
                f.write(chunk)
            offset = f.tell()
            f.write(header % (7, 3))
            f.write(b"11 2 0.125 0.25 0.375\n12 1 1e-3 -2.5 3.75\n13 2 -0 7 8\n")
        print("wrote %.2f GB in %.1f s; the second snapshot starts at byte %d (2^31 = %d)"
              % (os.path.getsize(path) / 1e9, time.time() - start, offset, 2 ** 31))
        ok = offset > 2 ** 31
        start = time.time()
        reader = pr.vtkLAMMPSDumpReader()
        reader.SetFileName(path)
        reader.UpdateInformation()
        info = reader.GetOutputInformation(0)
        times = list(info.Get(sddp.TIME_STEPS())) if info.Has(sddp.TIME_STEPS()) else []
        print("indexed in %.1f s: timesteps %s, atoms %s" % (
            time.time() - start, times,
            [reader.GetStepNumberOfAtoms(k) for k in range(reader.GetNumberOfSteps())]))
        ok &= times == [0.0, 7.0] and reader.GetStepNumberOfAtoms(0) == LINES
        reader.UpdateTimeStep(7.0)
        out = reader.GetOutput()
        points = [out.GetPoint(i) for i in range(out.GetNumberOfPoints())]
        ids = [out.GetPointData().GetArray("id").GetValue(i) for i in range(out.GetNumberOfPoints())]
        print("second snapshot: ids %s, points %s" % (ids, points))
        ok &= ids == [11, 12, 13] and points == [(0.125, 0.25, 0.375), (1e-3, -2.5, 3.75), (-0.0, 7.0, 8.0)]
    finally:
        if os.path.exists(path):
            os.remove(path)
    print("PASSED" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
