"""Compare the np N pictures of mpi_partition_accuracy.py with the np 1 pictures: per case and
rank count the largest difference (8-bit steps, any channel) and the pixels over 2/255 and 3/255
(the distributed criterion: at most 0.01 % over 2/255, none over 3/255). Writes a CSV and prints
a Markdown table.
usage: python3 mpi_partition_accuracy_compare.py IMAGE_DIR CSV
"""
import csv
import glob
import os
import sys

import numpy as np
from PIL import Image


def main():
    directory, csv_path = sys.argv[1], sys.argv[2]
    rows = []
    for single in sorted(glob.glob(os.path.join(directory, "*_np1.png"))):
        a = np.asarray(Image.open(single).convert("RGB")).astype(int)
        case = os.path.basename(single)[:-len("_np1.png")]
        for ranks in (2, 3, 4):
            other = single.replace("_np1.png", "_np%d.png" % ranks)
            if not os.path.exists(other):
                continue
            b = np.asarray(Image.open(other).convert("RGB")).astype(int)
            d = np.abs(a - b).max(axis=2)
            allowed = int(1e-4 * d.size)
            rows.append({"case": case, "ranks": ranks, "max": int(d.max()),
                         "px_over_2": int((d > 2).sum()), "px_over_3": int((d > 3).sum()),
                         "pixels": int(d.size),
                         "criterion": "met" if (d > 3).sum() == 0 and (d > 2).sum() <= allowed
                         else "missed"})
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


main()
