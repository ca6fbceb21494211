"""Cost of vtkDensityVolumeAOPass in the style of Grottel et al. 2012, Table 1: frame time with
ambient occlusion over frame time with plain spheres (vtkParticleSphereMapper, no pass), in the
same window, at 1e4 ... 1e6 particles, for
  static       the camera orbits (0.5 degrees per frame), the data stays: the volume is built once
  time series  every frame shows a new time step (the positions switch between two clustered data
               sets of the same size): the spheres are re-uploaded, and with AO the volume is
               rebuilt every frame -- on the CPU (vtkSMPTools) or on the GPU (compute shader)
and the per-fragment and per-sphere retrievals (static). Data: make_particles.py --kind clustered
(seeds 1 and 2), radii 0.3-0.5; automatic volume resolution, default settings otherwise.
The frame time is the median over FRAMES frames, wall clock with the GPU finished
(GetZbufferDataAtPoint); the build time is read as (time series with AO) - (time series plain).

usage: /usr/bin/python3 Benchmarks/ao_benchmark.py --out Benchmarks/results [--counts 1e4,1e5,1e6]
       (PYTHONPATH=<build>/lib/python3/dist-packages, under Xvfb; Benchmarks/run_ao.sh does this)
writes ao_timing.csv and ao_overhead.png
"""
import argparse
import csv
import os
import statistics
import sys
import time

import particlerendering as pr
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_particles  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--counts", default="1e4,1e5,1e6")
    parser.add_argument("--frames", type=int, default=9)
    parser.add_argument("--size", default="1280x720")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    rows = []
    for count in (int(float(c)) for c in args.counts.split(",")):
        steps = [make_particles.make("clustered", count, seed=seed) for seed in (1, 2)]
        data = steps[0]
        points = [s.GetPoints() for s in steps]
        mapper = pr.vtkParticleSphereMapper()
        mapper.SetInputData(data)
        mapper.SetRadiusArrayName("radius")
        mapper.ScalarVisibilityOff()
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(0.85, 0.8, 0.7)
        renderer = vtkRenderer()
        renderer.AddActor(actor)
        window = vtkRenderWindow()
        window.SetSize(width, height)
        window.SetMultiSamples(0)
        window.AddRenderer(renderer)
        renderer.ResetCamera()
        renderer.GetActiveCamera().Elevation(20)
        renderer.ResetCameraClippingRange()
        ao = pr.vtkDensityVolumeAOPass()
        ao.SetDelegatePass(vtkRenderStepsPass())
        step = [0]

        def frame(series):
            if series:
                step[0] ^= 1
                data.SetPoints(points[step[0]])
            else:
                renderer.GetActiveCamera().Azimuth(0.5)
            start = time.perf_counter()
            window.Render()
            window.GetZbufferDataAtPoint(0, 0)  # waits for the GPU
            return time.perf_counter() - start

        def measure(label, use_ao, series, generation=0, retrieval=0):
            renderer.SetPass(ao if use_ao else None)
            ao.SetGenerationMode(generation)
            ao.SetRetrievalMode(retrieval)
            builds = ao.GetNumberOfVolumeBuilds()
            frame(series)  # warm up: shaders, first build
            frame(series)
            times = [frame(series) for _ in range(args.frames)]
            row = dict(particles=count, width=width, height=height, scene=label,
                       ao="none" if not use_ao else ("per-sphere" if retrieval else
                                                     "per-fragment"),
                       generation=("gpu" if generation else "cpu") if use_ao else "",
                       last_generation=("gpu" if ao.GetLastGenerationMode() else "cpu")
                       if use_ao else "",
                       frames=args.frames, median_frame_s=statistics.median(times),
                       builds=ao.GetNumberOfVolumeBuilds() - builds,
                       dims="%dx%dx%d" % ao.GetDensityVolume().GetDimensions())
            rows.append(row)
            print("%8d %-11s %-12s %-3s: %8.1f ms (%d builds, volume %s)" %
                  (count, label, row["ao"], row["generation"], 1e3 * row["median_frame_s"],
                   row["builds"], row["dims"]), flush=True)
            return row

        # twice in opposite orders against drifts of the shared machine's load
        for order in (0, 1):
            runs = [("static", False, False, 0, 0), ("static", True, False, 0, 0),
                    ("static", True, False, 0, 1), ("time series", False, True, 0, 0),
                    ("time series", True, True, 0, 0), ("time series", True, True, 1, 0)]
            for run in (runs if order == 0 else list(reversed(runs))):
                measure(*run)
        window.Finalize()

    # ratios against plain spheres of the same scene (medians of the two orders)
    for row in rows:
        plain = [r["median_frame_s"] for r in rows if r["particles"] == row["particles"] and
                 r["scene"] == row["scene"] and r["ao"] == "none"]
        row["plain_frame_s"] = statistics.median(plain)
        row["ratio_vs_plain"] = row["median_frame_s"] / row["plain_frame_s"]
    fields = ["particles", "width", "height", "scene", "ao", "generation", "last_generation",
              "frames", "median_frame_s", "plain_frame_s", "ratio_vs_plain", "builds", "dims"]
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "ao_timing.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)
    table(rows)
    plot(rows, args.out)


def summary(rows):
    out = {}
    for r in rows:
        key = (r["particles"], r["scene"], r["ao"], r["generation"])
        out.setdefault(key, []).append(r)
    return {k: (statistics.median([r["median_frame_s"] for r in v]),
                statistics.median([r["ratio_vs_plain"] for r in v])) for k, v in out.items()}


def table(rows):
    s = summary(rows)
    counts = sorted({r["particles"] for r in rows})
    print("\n| particles | static: plain | AO per fragment | ratio | AO per sphere | ratio | "
          "time series: plain | AO, CPU build | ratio | AO, GPU build | ratio |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for n in counts:
        def cell(scene, ao, gen):
            t, ratio = s.get((n, scene, ao, gen), (float("nan"), float("nan")))
            return "%.1f ms | %.2f" % (1e3 * t, ratio)
        print("| %d | %.1f ms | %s | %s | %.1f ms | %s | %s |" % (
            n, 1e3 * s[(n, "static", "none", "")][0], cell("static", "per-fragment", "cpu"),
            cell("static", "per-sphere", "cpu"), 1e3 * s[(n, "time series", "none", "")][0],
            cell("time series", "per-fragment", "cpu"), cell("time series", "per-fragment", "gpu")))


def plot(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    s = summary(rows)
    counts = sorted({r["particles"] for r in rows})
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for key, label, style in ((("static", "per-fragment", "cpu"), "static, per fragment", "o-"),
                              (("static", "per-sphere", "cpu"), "static, per sphere", "s-"),
                              (("time series", "per-fragment", "cpu"),
                               "time series, CPU build", "^--"),
                              (("time series", "per-fragment", "gpu"),
                               "time series, GPU build", "v--")):
        ratios = [s[(n,) + key][1] for n in counts]
        times = [1e3 * s[(n,) + key][0] for n in counts]
        axes[0].plot(counts, ratios, style, label=label)
        axes[1].plot(counts, times, style, label="AO " + label)
    for scene, style in (("static", "k-"), ("time series", "k--")):
        axes[1].plot(counts, [1e3 * s[(n, scene, "none", "")][0] for n in counts], style,
                     label="plain spheres, " + scene)
    axes[0].axhline(1.25, color="red", linewidth=0.8, label="goal: +25 % (static)")
    axes[0].set_xscale("log")
    axes[0].set_xlabel("particles")
    axes[0].set_ylabel("frame time with AO / without")
    axes[0].legend(fontsize=7)
    axes[1].set_xscale("log")
    axes[1].set_yscale("log")
    axes[1].set_xlabel("particles")
    axes[1].set_ylabel("median frame time [ms], 1280x720, llvmpipe")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "ao_overhead.png"), dpi=110)


if __name__ == "__main__":
    main()
