"""Plots, power-law fits and tables of the translucent-particle benchmark (run_transparent.sh).

Reads transparent_timing.csv, transparent_errors.csv and transparent_early_termination.csv from
--results and writes there:
  transparent_time.png               median frame time per mapper vs particles, and the ratio
                                     to vtksphere-ddp
  transparent_stages.png             the transparent mapper's stages vs particles with the fitted
                                     laws time = a N^b
  transparent_early_termination.png  early-termination speed-up and masked-pixel fraction
  transparent_fits.csv               a and b per stage
and prints the Markdown tables of Benchmarks/README.md.

Stages of the transparent mapper (see README for why draw and composite are wall-clock):
  upload     CPU wall time of the particle upload (GetLastUploadSeconds, first frame)
  sort       GPU time of the depth sort (GetLastSortGPUSeconds, median over orbiting frames)
  draw       static-camera frame - frame with one particle (translucent draw of N particles)
  composite  frame with one particle - empty frame (fixed per-pixel cost of the translucent stage
             with dual depth peeling: opaque depth copy, blend, peeling set-up)
  frame      median frame time with the camera orbiting (everything)

usage: plot_transparent.py [--results DIR]
"""
import argparse
import csv
import math
import os
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MAPPERS = ["vtksphere-ddp", "pointgaussian", "transparent", "transparent-et"]
PEER = "vtksphere-ddp"
STAGES = ["upload", "sort", "draw", "composite", "frame"]


def read(path):
    if not os.path.exists(path):
        return []
    rows = []
    with open(path) as f:
        for row in csv.DictReader(f):
            out = {}
            for k, v in row.items():
                try:
                    out[k] = float(v)
                except ValueError:
                    out[k] = v
            out["particles"] = int(out["particles"])
            rows.append(out)
    return rows


def aggregate(rows):
    """Best (smallest) value over the repeated runs of each (particles, mapper, camera), for every
    timing: another process on the shared machine can only slow a run down. The runs' median frame
    times, in the CSV's order (run k of every mapper in the k-th process), are kept in "runs"."""
    groups = defaultdict(list)
    for r in rows:
        groups[(r["particles"], r["mapper"], r["camera"])].append(r)
    out = []
    for rs in groups.values():
        m = dict(rs[0])
        for k, v in rs[0].items():
            if isinstance(v, float) and k.endswith("_s"):
                m[k] = min(r[k] for r in rs)
        m["runs"] = [r["median_frame_s"] for r in rs]
        out.append(m)
    return out


def run_ratios(a, b):
    """Ratios a/b of the frame times of the same runs (same process, same load): mean, min, max."""
    rs = [x / y for x, y in zip(a["runs"], b["runs"])]
    return sum(rs) / len(rs), min(rs), max(rs)


def fit_power(ns, ts):
    """Least squares of log t = log a + b log N over the positive samples; (a, b, points)."""
    pts = [(math.log(n), math.log(t)) for n, t in zip(ns, ts) if t > 0]
    if len(pts) < 2:
        return float("nan"), float("nan"), len(pts)
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in pts)
    b = sxy / sxx
    return math.exp(my - b * mx), b, len(pts)


def ms(t):
    return "%.1f ms" % (1e3 * t) if t < 1 else "%.2f s" % t


def sup(n):
    e = int(round(math.log10(n)))
    return "10" + "".join("⁰¹²³⁴⁵⁶⁷⁸⁹"[int(d)] for d in str(e)) if 10 ** e == n else str(n)


def stages(timing):
    """Per particle count: the transparent mapper's stage times."""
    orbit = {r["particles"]: r for r in timing if r["mapper"] == "transparent" and r["camera"] == "orbit"}
    still = {r["particles"]: r for r in timing if r["mapper"] == "transparent" and r["camera"] == "static"}
    out = {}
    for n in sorted(orbit):
        o, s = orbit[n], still.get(n)
        st = {"upload": o["upload_s"], "sort": o["sort_gpu_s"], "frame": o["median_frame_s"]}
        if s:
            st["draw"] = s["median_frame_s"] - o["one_particle_frame_s"]
            st["composite"] = o["one_particle_frame_s"] - o["empty_frame_s"]
            st["sort_wall"] = o["median_frame_s"] - s["median_frame_s"]
            st["static"] = s["median_frame_s"]
            st["draw_gpu"] = s["draw_gpu_s"]
        out[n] = st
    return out


def plot_time(timing, png):
    series = defaultdict(dict)
    runs = {(r["particles"], r["mapper"]): r for r in timing if r["camera"] == "orbit"}
    for r in timing:
        key = r["mapper"] if r["camera"] == "orbit" else r["mapper"] + " (static camera)"
        series[key][r["particles"]] = r["median_frame_s"]
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11.5, 4.4))
    for key in sorted(series, key=lambda k: (k.split(" ")[0] not in MAPPERS, k)):
        pts = sorted(series[key].items())
        style = "s--" if "static" in key else "o-"
        ax0.loglog([p[0] for p in pts], [p[1] for p in pts], style, label=key)
        if "static" not in key:
            rp = [(n,) + run_ratios(runs[(n, key)], runs[(n, PEER)]) for n, _ in pts
                  if (n, PEER) in runs]
            ax1.errorbar([p[0] for p in rp], [p[1] for p in rp],
                         yerr=[[p[1] - p[2] for p in rp], [p[3] - p[1] for p in rp]],
                         fmt="o-", capsize=3, label=key)
    ax0.set_xlabel("particles")
    ax0.set_ylabel("median frame time [s]")
    ax0.grid(True, which="both", alpha=0.3)
    ax0.legend(fontsize=8)
    ax0.set_title("frame time (best of 2 runs)")
    ax1.axhline(1.0, color="grey", lw=0.8)
    ax1.set_xscale("log")
    ax1.set_xlabel("particles")
    ax1.set_ylabel("frame time / %s frame time (same run)" % PEER)
    ax1.set_yscale("log")
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=8)
    ax1.set_title("ratio to %s" % PEER)
    fig.suptitle("Translucent particles, opacity 0.5 (random gas, 1024x768, llvmpipe)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def plot_stages(st, fits, png):
    fig, ax = plt.subplots(figsize=(7.5, 5))
    ns = sorted(st)
    for i, name in enumerate(STAGES):
        pts = [(n, st[n].get(name, float("nan"))) for n in ns]
        pts = [p for p in pts if p[1] > 0]
        if not pts:
            continue
        color = "C%d" % i
        a, b, _, local = fits[name]
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o", color=color,
                  label="%s: b = %.2f (10⁵→10⁶: %.2f)" % (name, b, local))
        if not math.isnan(b):
            xs = [ns[0] * (ns[-1] / ns[0]) ** (k / 40.0) for k in range(41)]
            ax.loglog(xs, [a * x ** b for x in xs], "-", color=color, lw=1, alpha=0.7)
    ax.set_xlabel("particles N")
    ax.set_ylabel("time [s]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, title="fit time = a N^b")
    ax.set_title("vtkTransparentSphereMapper stages (gas, opacity 0.5, 1024x768)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def early_pairs(early):
    """(N, opacity) -> {camera: (off rows, on rows)}; run_transparent.sh runs each twice."""
    out = defaultdict(dict)
    for cam in ("orbit", "static"):
        groups = defaultdict(lambda: ([], []))
        for r in early:
            if r["camera"] == cam and r["mapper"] in ("transparent", "transparent-et"):
                groups[(r["particles"], r["opacity"])][r["mapper"] == "transparent-et"].append(r)
        for k, (off, on) in groups.items():
            if off and on:
                out[k][cam] = (off, on)
    return out


def mean(rows, key="median_frame_s"):
    return sum(r[key] for r in rows) / len(rows)


def speedup(pair):
    """Frame time off / on of the adjacent runs (off, on | on, off): mean, min, max."""
    rs = [off["median_frame_s"] / on["median_frame_s"] for off, on in zip(pair[0], pair[1])]
    return sum(rs) / len(rs), min(rs), max(rs)


def plot_early(early, png):
    pairs = early_pairs(early)
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11.5, 4.4))
    opacities = sorted({k[1] for k in pairs}, reverse=True)
    for i, op in enumerate(opacities):
        ks = sorted(k for k in pairs if k[1] == op)
        for cam, style in (("orbit", "o-"), ("static", "s--")):
            pts = [(k[0],) + speedup(pairs[k][cam]) for k in ks if cam in pairs[k]]
            ax0.errorbar([p[0] for p in pts], [p[1] for p in pts],
                         yerr=[[p[1] - p[2] for p in pts], [p[3] - p[1] for p in pts]],
                         fmt=style, color="C%d" % i, capsize=3,
                         label="opacity %g, %s camera" % (op, cam))
        masked = [(k[0], mean(pairs[k]["orbit"][1], "masked_fraction")) for k in ks]
        covered = [(k[0], mean(pairs[k]["orbit"][1], "covered_fraction")) for k in ks]
        ax1.semilogx([p[0] for p in masked], [p[1] for p in masked], "o-", color="C%d" % i,
                     label="opacity %g: masked" % op)
        ax1.semilogx([p[0] for p in covered], [p[1] for p in covered], "x:", color="C%d" % i,
                     label="opacity %g: covered" % op)
    ax0.axhline(1.0, color="grey", lw=0.8)
    ax0.set_xscale("log")
    ax0.set_xlabel("particles")
    ax0.set_ylabel("frame time off / frame time on (> 1: faster with it)")
    ax0.grid(True, which="both", alpha=0.3)
    ax0.legend(fontsize=8)
    ax0.set_title("early termination speed-up (20 chunks)")
    ax1.set_xlabel("particles")
    ax1.set_ylabel("fraction of the image's pixels")
    ax1.set_ylim(0, 1)
    ax1.grid(True, which="both", alpha=0.3)
    ax1.legend(fontsize=8)
    ax1.set_title("pixels masked after the last chunk, pixels covered")
    fig.suptitle("Early termination, clustered data, 1024x768, llvmpipe")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--results", default=os.path.join(here, "results"))
    args = parser.parse_args()
    res = args.results
    timing = read(os.path.join(res, "transparent_timing.csv"))
    errors = read(os.path.join(res, "transparent_errors.csv"))
    early = read(os.path.join(res, "transparent_early_termination.csv"))

    if timing:
        timing = aggregate(timing)
        plot_time(timing, os.path.join(res, "transparent_time.png"))
        frame = {(r["particles"], r["mapper"], r["camera"]): r for r in timing}
        ns = sorted({r["particles"] for r in timing})
        print("### Frame times (gas, opacity 0.5, 1024x768, camera orbiting; best of 2 runs)\n")
        print("| particles | vtksphere-ddp | pointgaussian | transparent | transparent-et "
              "| transparent, static camera | transparent / vtksphere-ddp (2 runs) "
              "| pointgaussian / vtksphere-ddp | transparent-et / transparent |")
        print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for n in ns:
            t = {m: frame[(n, m, "orbit")] for m in MAPPERS if (n, m, "orbit") in frame}
            s = frame.get((n, "transparent", "static"))
            tp = t[PEER]
            rt = run_ratios(t["transparent"], tp)
            print("| %s | %s | %s | %s | %s | %s | %.2f (%.2f, %.2f) | %.2f | %.2f |" % (
                sup(n), ms(tp["median_frame_s"]), ms(t["pointgaussian"]["median_frame_s"]),
                ms(t["transparent"]["median_frame_s"]), ms(t["transparent-et"]["median_frame_s"]),
                ms(s["median_frame_s"]) if s else "-", rt[0], rt[1], rt[2],
                run_ratios(t["pointgaussian"], tp)[0],
                run_ratios(t["transparent-et"], t["transparent"])[0]))
        print()

        st = stages(timing)
        fits = {}
        nsorted = sorted(st)
        with open(os.path.join(res, "transparent_fits.csv"), "w") as f:
            f.write("stage,a,b,points,local_b_1e5_1e6\n")
            for name in STAGES:
                ys = [st[n].get(name, float("nan")) for n in nsorted]
                a, b, k = fit_power(nsorted, ys)
                local = float("nan")
                if 100000 in st and 1000000 in st:
                    y0, y1 = st[100000].get(name, 0), st[1000000].get(name, 0)
                    if y0 > 0 and y1 > 0:
                        local = math.log(y1 / y0) / math.log(10.0)
                fits[name] = (a, b, k, local)
                f.write("%s,%.6g,%.4f,%d,%.4f\n" % (name, a, b, k, local))
        plot_stages(st, fits,
                    os.path.join(res, "transparent_stages.png"))
        print("### Stages of the transparent mapper\n")
        print("| particles | upload | sort (GPU timer) | sort (orbit - static) | draw | composite "
              "| frame |")
        print("|---:|---:|---:|---:|---:|---:|---:|")
        for n in nsorted:
            x = st[n]
            print("| %s | %s | %s | %s | %s | %s | %s |" % (
                sup(n), ms(x["upload"]), ms(x["sort"]), ms(x.get("sort_wall", float("nan"))),
                ms(x.get("draw", float("nan"))), ms(x.get("composite", float("nan"))),
                ms(x["frame"])))
        print("| **b** (fit 10³–10⁶) | %s |" % " | ".join(
            "%.2f" % fits[s][1] for s in ("upload", "sort")) + " – | %s |" % " | ".join(
            "%.2f" % fits[s][1] for s in ("draw", "composite", "frame")))
        print("| b (10⁵→10⁶) | %s |" % " | ".join(
            "%.2f" % fits[s][3] for s in ("upload", "sort")) + " – | %s |" % " | ".join(
            "%.2f" % fits[s][3] for s in ("draw", "composite", "frame")))
        print()

    if errors:
        print("### Errors against the reference (RGB, 512x384, in 1/255)\n")
        print("| data | particles (dropped) | mapper | peels | RMSE | max | pixels > 2/255 "
              "| order error RMSE (4 vs 200 peels) | order error max |")
        print("|---|---:|---|---:|---:|---:|---:|---:|---:|")
        for r in errors:
            conv = r["rmse_vs_converged"] >= 0 and r["peels"] == 4 and "transparent" not in r["mapper"]
            print("| %s | %d (%d) | %s | %d | %.2f | %.1f | %.1f %% | %s | %s |" % (
                r["label"], r["particles"], r["dropped_intersecting"], r["mapper"], r["peels"],
                255 * r["rmse_vs_reference"], 255 * r["max_vs_reference"],
                100 * r["over_2_255_fraction"],
                "%.3f" % (255 * r["rmse_vs_converged"]) if conv else "",
                "%.0f" % (255 * r["max_vs_converged"]) if conv else ""))
        print()

    if early:
        plot_early(early, os.path.join(res, "transparent_early_termination.png"))
        pairs = early_pairs(early)
        print("### Early termination (clustered, 1024x768, 20 chunks; mean of 2 runs, speed-up "
              "per adjacent off/on pair)\n")
        print("| particles | opacity | off | on | speed-up, orbiting (range) "
              "| speed-up, static (range) | masked / covered pixels | covered | max diff |")
        print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for k in sorted(pairs, key=lambda k: (k[0], -k[1])):
            off, on = pairs[k]["orbit"]
            su = speedup(pairs[k]["orbit"])
            ss = speedup(pairs[k]["static"]) if "static" in pairs[k] else None
            cov = mean(on, "covered_fraction")
            print("| %s | %g | %s | %s | %.2f (%.2f–%.2f) | %s | %.2f | %.2f | %.1f/255 |" % (
                sup(k[0]), k[1], ms(mean(off)), ms(mean(on)), su[0], su[1], su[2],
                "%.2f (%.2f–%.2f)" % ss if ss else "-",
                mean(on, "masked_fraction") / cov if cov > 0 else 0.0, cov,
                255 * max(r["max_vs_transparent"] for r in on)))
        print()


if __name__ == "__main__":
    main()
