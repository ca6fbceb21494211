"""Margins of the image tests, read from a CTest log (build/Testing/Temporary/LastTest.log).

Every image test prints its score through vtkParticleImageComparison ("image test NAME: passed,
score S") and the scores of the wrong pictures it must reject ("MUST-FAIL NAME ...: rejected,
score S"): the built-in ones (the baseline 10 % darker, the baseline shifted one pixel past the
mask) and, for tests with a --must-fail case, the rendered wrong picture (CTest entries
ParticleRendering.MustFail.<Test>.<case>, printed as "<Test>_mustfail_<case>"). A score is the
largest ratio of a measured error to its limit, so a picture passes at <= 1. This script writes one
row per image test: its score, each must-fail score and the nearest one (the smallest), and their
ratio (how far the nearest wrong picture is from the real one, in units of the real picture's
score; "inf" when the real picture scores 0).

usage: python3 Scripts/image_test_margins.py build/Testing/Temporary/LastTest.log
           [--csv Benchmarks/results/image_test_margins.csv] [--summary PLATFORM]
--summary prints one line instead of the table (.ci/run, per platform): how many image tests,
whether every must-fail picture was rejected, and the smallest ratio with its test.
"""
import argparse
import csv
import os
import re
import sys

IMAGE = re.compile(r"^image test (\S+): (passed|FAILED), score ([0-9.e+-]+|inf)")
MUST_FAIL = re.compile(r"^MUST-FAIL (\S+)(?: \((.*?)\))?(?: (.*?))?: (rejected|ACCEPTED.*?|NOT COMPARED.*?), "
                       r"score ([0-9.e+-]+|inf)")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("log")
    parser.add_argument("--csv")
    parser.add_argument("--summary", metavar="PLATFORM")
    args = parser.parse_args()
    real = {}
    wrong = {}
    if not os.path.exists(args.log):
        print(f"margins {args.summary or ''}: no CTest log at {args.log} (the tests did not run)")
        return 1
    with open(args.log, errors="replace") as log:
        for line in log:
            line = line.strip()
            match = IMAGE.match(line)
            if match:
                real[match.group(1)] = float(match.group(3))
                continue
            match = MUST_FAIL.match(line)
            if match:
                name, builtin, extra, verdict, score = match.groups()
                what = builtin or extra or ""
                if "_mustfail_" in name:
                    name, what = name.split("_mustfail_", 1)
                wrong.setdefault(name, []).append((what.strip(), float(score), verdict))
    rows = []
    for name in sorted(real):
        if not name.startswith("Test") or name.startswith("TestImageComparison"):
            continue  # the comparison's own unit test (deliberately loose criteria included)
        cases = wrong.get(name, [])
        if not cases:
            continue  # comparisons inside a test (panels, differences) without wrong pictures
        nearest = min(cases, key=lambda c: c[1])
        ratio = nearest[1] / real[name] if real[name] > 0 else float("inf")
        rows.append({
            "test": name,
            "score": "%.4g" % real[name],
            "must_fail": "; ".join("%s %.4g" % (what, score) for what, score, _ in cases),
            "nearest_must_fail": nearest[0],
            "nearest_score": "%.4g" % nearest[1],
            "ratio": "%.4g" % ratio,
            "all_rejected": all(v == "rejected" for _, _, v in cases),
        })
    if args.summary:
        rejected = all(row["all_rejected"] for row in rows)
        nearest = min(rows, key=lambda row: float(row["ratio"])) if rows else None
        print("margins %s: %d image tests with must-fail pictures, every must-fail picture %s, "
              "smallest ratio %s (%s: %s)" % (
                  args.summary, len(rows), "rejected" if rejected else "NOT rejected",
                  nearest["ratio"] if nearest else "-", nearest["test"] if nearest else "-",
                  nearest["nearest_must_fail"] if nearest else "-"))
        if args.csv is None:
            return 0 if rows and rejected else 1
    writer = csv.DictWriter(open(args.csv, "w", newline="") if args.csv else sys.stdout,
                            fieldnames=list(rows[0].keys()) if rows else ["test"])
    writer.writeheader()
    writer.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
