"""Compare the np N pictures of mpi_partition_accuracy.py with the np 1 pictures (and the cases
of REFERENCES, at every rank count, with an exact reference case's np 1 picture): per case and
rank count the largest difference (8-bit steps, any channel) and the pixels over 2/255 and 3/255
(the distributed criterion: at most 0.01 % over 2/255, none over 3/255). Writes a CSV and prints
a Markdown table; with PNG, a bar chart of the pixels over 2/255 per case and rank count against
the criterion's allowance.
usage: python3 mpi_partition_accuracy_compare.py IMAGE_DIR CSV [PNG]
"""
import csv
import glob
import os
import sys

import numpy as np
from PIL import Image


# cases also compared with another case's np 1 picture, an exact reference for them: two
# translucent Particles representations with the same settings against one representation of
# all their particles (in one process the second representation's composite lies over the first
# one's whatever the depth, so np 1 is not the reference there); two opaque representations with
# ambient occlusion against one representation of all their atoms (the same AO volume)
REFERENCES = {"mixed_two-same_automatic": "mixed_merged_automatic",
              "mixed_two-opaque-dvao_automatic": "mixed_merged-opaque-dvao_automatic",
              "mixed_two-opaque-vcao_automatic": "mixed_merged-opaque-vcao_automatic"}


def compare(a, b):
    d = np.abs(a - b).max(axis=2)
    allowed = int(1e-4 * d.size)
    return {"max": int(d.max()), "px_over_2": int((d > 2).sum()), "px_over_3": int((d > 3).sum()),
            "pixels": int(d.size),
            "criterion": "met" if (d > 3).sum() == 0 and (d > 2).sum() <= allowed else "missed"}


def read(path):
    return np.asarray(Image.open(path).convert("RGB")).astype(int)


def main():
    directory, csv_path = sys.argv[1], sys.argv[2]
    rows = []
    for single in sorted(glob.glob(os.path.join(directory, "*_np1.png"))):
        a = read(single)
        case = os.path.basename(single)[:-len("_np1.png")]
        for ranks in (2, 3, 4):
            other = single.replace("_np1.png", "_np%d.png" % ranks)
            if not os.path.exists(other):
                continue
            rows.append(dict({"case": case, "ranks": ranks}, **compare(a, read(other))))
        reference = REFERENCES.get(case)
        reference_path = os.path.join(directory, "%s_np1.png" % reference) if reference else ""
        if reference and os.path.exists(reference_path):
            exact = read(reference_path)
            for ranks in (1, 2, 3, 4):
                other = single.replace("_np1.png", "_np%d.png" % ranks)
                if os.path.exists(other):
                    rows.append(dict({"case": "%s vs %s" % (case, reference), "ranks": ranks},
                                     **compare(exact, read(other))))
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print("| case | ranks | max | px over 2/255 | px over 3/255 | criterion |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print("| %s | %d | %d/255 | %d | %d | %s |" % (r["case"], r["ranks"], r["max"],
                                                      r["px_over_2"], r["px_over_3"],
                                                      r["criterion"]))
    if len(sys.argv) > 3:
        plot(rows, sys.argv[3])


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = sorted({r["case"] for r in rows})
    fig, ax = plt.subplots(figsize=(10, 0.32 * len(cases) + 1.5))
    rank_counts = sorted({r["ranks"] for r in rows})
    width = 0.8 / len(rank_counts)
    for k, ranks in enumerate(rank_counts):
        values = [next((r["px_over_2"] for r in rows if r["case"] == c and r["ranks"] == ranks), 0)
                  for c in cases]
        ax.barh([i + width * k for i in range(len(cases))], [max(v, 0.5) for v in values], width,
                label="np %d" % ranks)
    allowed = 1e-4 * rows[0]["pixels"]
    ax.axvline(allowed, color="k", linestyle="--", label="criterion (0.01 %% = %d px)" % allowed)
    ax.set_xscale("log")
    ax.set_yticks([i + 0.4 - width / 2 for i in range(len(cases))])
    ax.set_yticklabels(cases, fontsize=8)
    ax.set_xlabel("pixels over 2/255 against the single-process picture ('A vs B': against B's; "
                  "of %d; 0 drawn at 0.5)" % rows[0]["pixels"])
    ax.set_title("Distributed rendering vs one process (Benchmarks/run_mpi_partition_accuracy.sh)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


main()
