"""Plot Benchmarks/results/mpi_scaling.csv (Benchmarks/mpi_scaling.py): frame and time-step
times against the number of ranks, per particle count (the newest row of each pair).
usage: /usr/bin/python3 Benchmarks/plot_mpi_scaling.py [CSV [PNG]]
(defaults Benchmarks/results/mpi_scaling.csv and mpi_scaling.png next to the CSV)"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "results", "mpi_scaling.csv")
png = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(path), "mpi_scaling.png")
rows = {}
with open(path) as f:
    for row in csv.DictReader(f):
        rows[(int(row["particles"]), int(row["ranks"]))] = row  # the newest wins
counts = sorted({p for p, _ in rows})
fig, axes = plt.subplots(1, len(counts), figsize=(5 * len(counts), 4), squeeze=False)
for ax, particles in zip(axes[0], counts):
    ranks = sorted(r for p, r in rows if p == particles)
    for key, label in [("opaque_frame_s", "frame, opaque"),
                       ("translucent_frame_s", "frame, translucent"),
                       ("translucent_ao_frame_s", "frame, translucent + AO"),
                       ("step_s", "time step (translucent + AO)"),
                       ("partition_s", "partition in that step")]:
        ax.plot(ranks, [float(rows[(particles, r)][key]) for r in ranks], "o-", label=label)
    ax.set_xticks(ranks)
    ax.set_xlabel("MPI ranks (2 cores)")
    ax.set_ylabel("seconds")
    ax.set_title("%d particles" % particles)
    ax.grid(alpha=0.3)
axes[0][0].legend(fontsize=8)
fig.tight_layout()
fig.savefig(png, dpi=100)
print("wrote", png)
