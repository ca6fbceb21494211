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
        rows = list(csv.DictReader(f))
    labels = {row["label"] for row in rows}
    for row in rows:
        n = int(row["particles"])
        # one series per scene and mapper when the table holds several scenes
        key = row["mapper"] if len(labels) == 1 else "%s: %s" % (row["label"], row["mapper"])
        series[key].append((n, float(row["median_frame_s"])))
        ratios[key].append((n, float(row["ratio_vs_peer"])))
        peer = row["peer"]

    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(13, 5.2))
    # colour by mapper, line and marker by scene
    mappers = sorted({row["mapper"] for row in rows})
    scenes = sorted(labels)
    styles = {}
    for key in series:
        label, _, mapper = key.rpartition(": ")
        styles[key] = dict(color="C%d" % mappers.index(mapper),
                           ls=["-", "--", ":", "-."][scenes.index(label) % 4] if label else "-",
                           marker="osD^v"[scenes.index(label) % 5] if label else "o")
    for mapper, points in sorted(series.items()):
        points.sort()
        ax0.loglog([p[0] for p in points], [p[1] for p in points], label=mapper, **styles[mapper])
    ax0.set_xlabel("particles")
    ax0.set_ylabel("median frame time [s]")
    ax0.grid(True, which="both", alpha=0.3)
    ax0.legend(fontsize=7)
    for mapper, points in sorted(ratios.items()):
        points.sort()
        ax1.semilogx([p[0] for p in points], [p[1] for p in points], label=mapper, **styles[mapper])
    ax1.axhline(1.0, color="grey", lw=0.8)
    ax1.set_xlabel("particles")
    ax1.set_ylabel("frame time / %s frame time" % peer)
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=7)
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)


if __name__ == "__main__":
    main()
