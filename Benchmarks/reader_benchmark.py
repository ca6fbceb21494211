"""Speed and memory of vtkLAMMPSDumpReader against the text readers a pvpython user has, on one
LAMMPS dump of 10^7 atoms (written by Debian's LAMMPS: write_dump custom id type x y z vx vy vz,
LAMMPS's default %g format), all measured in the same run.

Methods (each run in a fresh process; time = wall time of the read alone, after the imports):
  reader, 2 threads    vtkLAMMPSDumpReader (index + parse of the step), vtkSMPTools STDThread
  reader, 1 thread     the same with VTK_SMP_BACKEND_IN_USE=Sequential
  reader, index only   RequestInformation alone (finding the snapshots)
  numpy.loadtxt        numpy.loadtxt(skiprows=9) of the same file (C-accelerated in numpy 1.24)
  ParaView CSV reader  vtkDelimitedTextReader (what ParaView's CSV Reader runs), space
                       delimited, consecutive delimiters merged, on a copy of the file holding
                       only the atom lines with the column names as header (it cannot skip the
                       dump header) -- the peers get the easier job
Reported: seconds, MB/s (file bytes / s), atoms/s, ratio of each method's time to the reader's
(2 threads), and the peak resident memory the read added (ru_maxrss after the read minus the
resident size before it), against the size of the reader's output arrays.

usage: /usr/bin/python3 Benchmarks/reader_benchmark.py --out Benchmarks/results [--atoms 1e7]
       [--work /tmp/reader_benchmark] [--repeat 3]
(PYTHONPATH=<build>/lib/python3/dist-packages; Benchmarks/run_reader.sh does this)
writes reader_speed.csv, reader_speed.png
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys

RUNNER = r'''
import json, os, resource, sys, time
method, path, csv_path = sys.argv[1], sys.argv[2], sys.argv[3]
def rss_mb():
    for line in open("/proc/self/status"):
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024.0
if method.startswith("reader"):
    import particlerendering as pr
    reader = pr.vtkLAMMPSDumpReader()
    reader.SetFileName(path)
    before = rss_mb()
    start = time.perf_counter()
    reader.UpdateInformation()
    if method != "reader-index":
        reader.Update()
    seconds = time.perf_counter() - start
    out = reader.GetOutput()
    atoms = out.GetNumberOfPoints() if method != "reader-index" else reader.GetStepNumberOfAtoms(0)
    output_mb = out.GetActualMemorySize() / 1024.0 if method != "reader-index" else 0.0
elif method == "numpy":
    import numpy
    before = rss_mb()
    start = time.perf_counter()
    data = numpy.loadtxt(path, skiprows=9)
    seconds = time.perf_counter() - start
    atoms = data.shape[0]
    output_mb = data.nbytes / 2 ** 20
elif method == "csv":
    from vtkmodules.vtkIOInfovis import vtkDelimitedTextReader
    reader = vtkDelimitedTextReader()
    reader.SetFileName(csv_path)
    reader.SetFieldDelimiterCharacters(" ")
    reader.MergeConsecutiveDelimitersOn()
    reader.SetHaveHeaders(True)
    reader.DetectNumericColumnsOn()
    before = rss_mb()
    start = time.perf_counter()
    reader.Update()
    seconds = time.perf_counter() - start
    atoms = reader.GetOutput().GetNumberOfRows()
    output_mb = sum(reader.GetOutput().GetColumn(i).GetActualMemorySize()
                    for i in range(reader.GetOutput().GetNumberOfColumns())) / 1024.0
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
print(json.dumps({"seconds": seconds, "atoms": atoms, "added_mb": peak - before,
                  "output_mb": output_mb}))
'''

METHODS = [
    ("reader-2", "vtkLAMMPSDumpReader, 2 threads", {}),
    ("reader-1", "vtkLAMMPSDumpReader, 1 thread", {"VTK_SMP_BACKEND_IN_USE": "Sequential"}),
    ("reader-index", "vtkLAMMPSDumpReader, index only", {}),
    ("numpy", "numpy.loadtxt", {}),
    ("csv", "ParaView CSV reader (vtkDelimitedTextReader)", {}),
]


def make_dump(path, atoms):
    lmp = shutil.which("lmp")
    if not lmp:
        sys.exit("LAMMPS (lmp) is needed to write the dump")
    work = os.path.dirname(path)
    edge = (atoms / 1.0) ** (1.0 / 3.0)
    script = os.path.join(work, "in.reader_benchmark")
    with open(script, "w") as f:
        f.write("units lj\natom_style atomic\nregion box block 0 %g 0 %g 0 %g\ncreate_box 2 box\n"
                "create_atoms 1 random %d 4211 NULL\ncreate_atoms 2 random %d 5129 NULL\n"
                "mass * 1.0\nvelocity all create 1.0 9177 loop geom\n"
                "write_dump all custom %s id type x y z vx vy vz\n"
                % (edge, edge, edge, int(0.7 * atoms), atoms - int(0.7 * atoms),
                   os.path.basename(path)))
    subprocess.run([lmp, "-in", script, "-screen", "none", "-log", "none"], cwd=work, check=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--atoms", type=float, default=1e7)
    parser.add_argument("--work", default="/tmp/reader_benchmark")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    os.makedirs(args.out, exist_ok=True)
    atoms = int(args.atoms)
    dump = os.path.join(args.work, "dump.%d" % atoms)
    if not os.path.exists(dump):
        make_dump(dump, atoms)
    csv_copy = dump + ".csv"
    if not os.path.exists(csv_copy):
        with open(dump) as src, open(csv_copy, "w") as dst:
            for _ in range(8):
                src.readline()
            dst.write(src.readline().split(None, 2)[2])  # column names
            shutil.copyfileobj(src, dst, 1 << 24)
    megabytes = os.path.getsize(dump) / 1e6
    print("dump: %s, %d atoms, %.1f MB" % (dump, atoms, megabytes))
    runner = os.path.join(args.work, "reader_benchmark_runner.py")
    with open(runner, "w") as f:
        f.write(RUNNER)
    rows = []
    for key, label, env in METHODS:
        repeat = args.repeat if key.startswith("reader") else 1
        results = []
        for _ in range(repeat):
            environment = dict(os.environ, **env)
            out = subprocess.run([sys.executable, runner, key, dump, csv_copy], env=environment,
                                 check=True, capture_output=True, text=True).stdout
            import json
            results.append(json.loads(out.strip().splitlines()[-1]))
        best = min(results, key=lambda r: r["seconds"])
        rows.append({"method": label, "seconds": best["seconds"], "atoms": best["atoms"],
                     "MB_per_s": megabytes / best["seconds"],
                     "atoms_per_s": best["atoms"] / best["seconds"],
                     "added_memory_MB": best["added_mb"], "output_MB": best["output_mb"],
                     "runs": repeat})
        print("%-45s %7.2f s  %7.1f MB/s  %6.2f M atoms/s  +%.0f MB (output %.0f MB)"
              % (label, best["seconds"], megabytes / best["seconds"],
                 best["atoms"] / best["seconds"] / 1e6, best["added_mb"], best["output_mb"]))
    reference = rows[0]["seconds"]
    for row in rows:
        row["time_vs_reader"] = row["seconds"] / reference
        row["memory_vs_output"] = (row["added_memory_MB"] / row["output_MB"]
                                   if row["output_MB"] > 0 else "")
    with open(os.path.join(args.out, "reader_speed.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: ("%.4g" % v if isinstance(v, float) else v) for k, v in row.items()})
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 3.6))
    labels = [r["method"] for r in rows]
    values = [r["MB_per_s"] for r in rows]
    bars = ax.barh(labels, values, color=["#1f77b4", "#6baed6", "#9ecae1", "#d62728", "#ff7f0e"])
    ax.set_xscale("log")
    ax.invert_yaxis()
    for bar, row in zip(bars, rows):
        ax.text(bar.get_width(), bar.get_y() + bar.get_height() / 2,
                "  %.0f MB/s, %.2f s" % (row["MB_per_s"], row["seconds"]), va="center", fontsize=8)
    ax.set_xlabel("MB/s (log scale)")
    ax.set_title("LAMMPS dump, %d atoms (%.0f MB), 2 cores" % (atoms, megabytes), fontsize=10)
    ax.set_xlim(right=max(values) * 20)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "reader_speed.png"), dpi=110)
    print("wrote %s" % os.path.join(args.out, "reader_speed.csv"))


if __name__ == "__main__":
    main()
