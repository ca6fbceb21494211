"""Plot a prBenchmark CSV: median frame time per mapper against particle count (log-log), and the
ratio to the peer. usage: plot_results.py results.csv out.png [--title TEXT]"""
import argparse
import csv
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    series = defaultdict(list)
    ratios = defaultdict(list)
    peer = None
    with open(args.csv) as f:
        for row in csv.DictReader(f):
            n = int(row["particles"])
            series[row["mapper"]].append((n, float(row["median_frame_s"])))
            ratios[row["mapper"]].append((n, float(row["ratio_vs_peer"])))
            peer = row["peer"]

    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11, 4.2))
    for mapper, points in sorted(series.items()):
        points.sort()
        ax0.loglog([p[0] for p in points], [p[1] for p in points], "o-", label=mapper)
    ax0.set_xlabel("particles")
    ax0.set_ylabel("median frame time [s]")
    ax0.grid(True, which="both", alpha=0.3)
    ax0.legend()
    for mapper, points in sorted(ratios.items()):
        points.sort()
        ax1.semilogx([p[0] for p in points], [p[1] for p in points], "o-", label=mapper)
    ax1.axhline(1.0, color="grey", lw=0.8)
    ax1.set_xlabel("particles")
    ax1.set_ylabel("frame time / %s frame time" % peer)
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend()
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
