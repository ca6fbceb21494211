"""Cost of vtkPointAOPass (PointAO, Eichelbaum et al. 2013): frame time with the pass over the
frame time of the plain core (vtkParticleSphereMapper, no pass) in the same window, at 1e4 ...
1e6 particles and two window sizes, with the GPU time of each stage (timer queries: the scene
into the G-buffer, the occlusion, the blur, the composite) and, measured in the same run,
vtkPointAOPass at half resolution, vtkSSAOPass (radius two mean radii, 32 samples, blur) and
vtkDensityVolumeAOPass (defaults, static scene: its volume is built once).

A screen-space pass costs per pixel: the occlusion and the blur do not depend on the particle
count, only the G-buffer pass (the delegate's draw with a second render target) does. The
density-volume pass shades per fragment instead, so on llvmpipe its cost grows with the
fragments drawn (dense scenes: many hidden fragments), see ao_timing.csv.

Data: make_particles.py --kind clustered (radii 0.3-0.5), the camera orbiting (0.5 degrees per
frame); the frame time is the median over FRAMES frames, wall clock with the GPU finished
(GetZbufferDataAtPoint); each configuration is measured twice in opposite orders (medians).

usage: /usr/bin/python3 Benchmarks/pointao_benchmark.py --out Benchmarks/results
           [--counts 1e4,1e5,1e6] [--sizes 640x360,1280x720]
       (PYTHONPATH=<build>/lib/python3/dist-packages, under Xvfb; Benchmarks/run_pointao.sh)
appends to pointao_timing.csv, writes pointao_timing.png
"""
import argparse
import csv
import os
import statistics
import sys
import time

import particlerendering as pr
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass, vtkSSAOPass
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_particles  # noqa: E402

FIELDS = ["particles", "width", "height", "method", "frames", "median_frame_s", "plain_frame_s",
          "ratio_vs_plain", "gpu_gbuffer_s", "gpu_occlusion_s", "gpu_blur_s", "gpu_composite_s"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    parser.add_argument("--counts", default="1e4,1e5,1e6")
    parser.add_argument("--sizes", default="640x360,1280x720")
    parser.add_argument("--frames", type=int, default=9)
    args = parser.parse_args()
    rows = []
    for size in args.sizes.split(","):
        width, height = (int(v) for v in size.split("x"))
        for count in (int(float(c)) for c in args.counts.split(",")):
            data = make_particles.make("clustered", count, seed=1)
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
            pointao = pr.vtkPointAOPass()
            pointao.SetDelegatePass(vtkRenderStepsPass())
            pointao.SetCollectTimings(True)
            ssao = vtkSSAOPass()
            ssao.SetDelegatePass(vtkRenderStepsPass())
            ssao.SetRadius(2 * 0.4)
            ssao.SetKernelSize(32)
            ssao.SetBias(0.004)
            ssao.BlurOn()
            half = pr.vtkPointAOPass()
            half.SetDelegatePass(vtkRenderStepsPass())
            half.SetHalfResolution(True)
            density = pr.vtkDensityVolumeAOPass()
            density.SetDelegatePass(vtkRenderStepsPass())
            passes = {"none": None, "pointao": pointao, "pointao-half": half, "ssao": ssao,
                      "density-volume": density}

            def frame():
                renderer.GetActiveCamera().Azimuth(0.5)
                start = time.perf_counter()
                window.Render()
                window.GetZbufferDataAtPoint(0, 0)  # waits for the GPU
                return time.perf_counter() - start

            for order in (0, 1):
                names = list(passes)
                for name in (names if order == 0 else list(reversed(names))):
                    renderer.SetPass(passes[name])
                    frame()
                    frame()
                    times = []
                    stages = [[] for _ in range(4)]
                    for _ in range(args.frames):
                        times.append(frame())
                        if name == "pointao":
                            for k in range(4):
                                stages[k].append(pointao.GetStageSeconds(k))
                    row = dict(particles=count, width=width, height=height, method=name,
                               frames=args.frames, median_frame_s=statistics.median(times))
                    if name == "pointao":
                        for k, key in enumerate(FIELDS[-4:]):
                            row[key] = statistics.median(stages[k])
                    rows.append(row)
                    print("%dx%d %8d %-15s %8.1f ms%s" % (
                        width, height, count, name, 1e3 * row["median_frame_s"],
                        "  (GPU: G-buffer %.1f, occlusion %.1f, blur %.1f, composite %.1f ms)"
                        % tuple(1e3 * row[k] for k in FIELDS[-4:]) if name == "pointao" else ""),
                        flush=True)
            renderer.SetPass(None)
            window.Finalize()
    merged = []
    for key in sorted({(r["width"], r["height"], r["particles"], r["method"]) for r in rows}):
        group = [r for r in rows if (r["width"], r["height"], r["particles"], r["method"]) == key]
        row = dict(group[0])
        row["median_frame_s"] = statistics.median(r["median_frame_s"] for r in group)
        for k in FIELDS[-4:]:
            if k in row:
                row[k] = statistics.median(r[k] for r in group)
        merged.append(row)
    for row in merged:
        plain = [r["median_frame_s"] for r in merged if r["method"] == "none" and
                 (r["width"], r["particles"]) == (row["width"], row["particles"])]
        row["plain_frame_s"] = plain[0]
        row["ratio_vs_plain"] = row["median_frame_s"] / plain[0]
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "pointao_timing.csv")
    new = not os.path.exists(path)
    with open(path, "a", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS, extrasaction="ignore")
        if new:
            writer.writeheader()
        writer.writerows(merged)
    print("\n| window | particles | plain | PointAO | ratio | PointAO half | ratio | SSAO | ratio "
          "| density volume | ratio | PointAO GPU: G-buffer / occlusion / blur / composite |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for width, height, count in sorted({(r["width"], r["height"], r["particles"]) for r in merged}):
        get = {r["method"]: r for r in merged
               if (r["width"], r["height"], r["particles"]) == (width, height, count)}
        p = get["pointao"]
        print("| %dx%d | %d | %.1f ms | %.1f ms | %.2f | %.1f ms | %.2f | %.1f ms | %.2f | "
              "%.1f ms | %.2f | %.1f / %.1f / %.1f / %.1f ms |" % (
                  width, height, count, 1e3 * get["none"]["median_frame_s"],
                  1e3 * p["median_frame_s"], p["ratio_vs_plain"],
                  1e3 * get["pointao-half"]["median_frame_s"],
                  get["pointao-half"]["ratio_vs_plain"],
                  1e3 * get["ssao"]["median_frame_s"], get["ssao"]["ratio_vs_plain"],
                  1e3 * get["density-volume"]["median_frame_s"],
                  get["density-volume"]["ratio_vs_plain"],
                  *(1e3 * p[k] for k in FIELDS[-4:])))
    plot(merged, args.out)


def plot(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    sizes = sorted({(r["width"], r["height"]) for r in rows})
    fig, axes = plt.subplots(1, len(sizes), figsize=(6 * len(sizes), 4.5), squeeze=False)
    for ax, (width, height) in zip(axes[0], sizes):
        for method, colour in (("pointao", "C3"), ("pointao-half", "C1"), ("ssao", "C0"),
                               ("density-volume", "C2")):
            points = sorted((r["particles"], r["ratio_vs_plain"]) for r in rows
                            if r["method"] == method and (r["width"], r["height"]) == (width, height))
            if points:
                ax.plot(*zip(*points), "o-", color=colour, label=method)
        ax.axhline(1.0, color="grey", ls=":")
        ax.set_xscale("log")
        ax.set_xlabel("particles")
        ax.set_ylabel("frame time / plain core")
        ax.set_title("%d x %d (llvmpipe)" % (width, height))
        ax.grid(alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pointao_timing.png"), dpi=90)


if __name__ == "__main__":
    main()
