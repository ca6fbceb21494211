"""Side by side: two runs of an accuracy study (e.g. pointao_study.py before and after a change),
row by row on the configuration columns. Writes, per configuration present in both, the error
columns of each run and their difference, and prints the largest difference.

usage: python3 Benchmarks/compare_accuracy.py BEFORE.csv AFTER.csv OUT.csv
       [--errors rmse,bias,band_rmse]
"""
import argparse
import csv

CONFIGURATION = ("scene", "method", "levels", "directions", "ssao_radius", "ssao_kernel",
                 "resolution", "cones")


def load(path):
    with open(path) as f:
        return {tuple(row.get(c, "") for c in CONFIGURATION): row for row in csv.DictReader(f)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("out")
    parser.add_argument("--errors", default="rmse,bias,band_rmse")
    args = parser.parse_args()
    errors = args.errors.split(",")
    before, after = load(args.before), load(args.after)
    largest = 0.0
    with open(args.out, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(list(CONFIGURATION) + ["%s_%s" % (e, w) for e in errors
                                               for w in ("before", "after", "change")])
        for key, row in before.items():
            if key not in after:
                continue
            values = []
            for e in errors:
                if row.get(e, "") == "" or after[key].get(e, "") == "":
                    values += ["", "", ""]
                    continue
                a, b = float(row[e]), float(after[key][e])
                largest = max(largest, abs(b - a))
                values += ["%.6g" % a, "%.6g" % b, "%.3g" % (b - a)]
            writer.writerow(list(key) + values)
    print("%d configurations in both runs; largest change of %s: %.3g"
          % (len(set(before) & set(after)), "/".join(errors), largest))


if __name__ == "__main__":
    main()
