"""Markdown tables of the AO study (ao_accuracy.csv, ao_fcc_volume.csv) for Benchmarks/README.md.

usage: /usr/bin/python3 Benchmarks/summarise_ao.py [--results Benchmarks/results]
"""
import argparse
import csv
import os


def load(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--results", default=os.path.join(os.path.dirname(__file__), "results"))
    args = parser.parse_args()
    rows = load(os.path.join(args.results, "ao_accuracy.csv"))
    for r in rows:
        for k in ("frame_s", "rmse", "affine_rmse", "bias"):
            r[k] = float(r[k])
    print("| scene | method | frame | RMSE | RMSE after affine fit | bias | FCC artefact std |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for scene in dict.fromkeys(r["scene"] for r in rows):
        mine = [r for r in rows if r["scene"] == scene]

        def line(label, r):
            print("| %s | %s | %.1f ms | %.3f | %.3f | %+.3f | %s |" % (
                scene, label, 1e3 * r["frame_s"], r["rmse"], r["affine_rmse"], r["bias"],
                ("%.4f" % float(r["artefact_std"])) if r["artefact_std"] else ""))
        line("no AO", [r for r in mine if r["method"] == "none"][0])
        ours = [r for r in mine if r["method"] == "density-volume"]
        default = [r for r in ours if r["splat"] == "trilinear" and r["resolution"] == "0" and
                   float(r["fetch"]) == 0.5][0]
        line("ours, defaults (trilinear, auto %s, fetch 0.5)" % default["dims"], default)
        paper = [r for r in ours if r["splat"] == "nearest" and r["resolution"] == "0" and
                 float(r["fetch"]) == 0.5][0]
        line("ours, nearest-voxel splat (paper), auto, fetch 0.5", paper)
        old = [r for r in ours if r["splat"] == "trilinear" and r["resolution"] == "0" and
               float(r["fetch"]) == 1.0][0]
        line("ours, trilinear, auto, fetch 1.0", old)
        best = min(ours, key=lambda r: r["affine_rmse"])
        line("ours, best structure (%s, res %s = %s, fetch %s)" % (
            best["splat"], best["resolution"], best["dims"], best["fetch"]), best)
        ssao = [r for r in mine if r["method"] == "ssao"]
        equal = min(ssao, key=lambda r: abs(r["frame_s"] - default["frame_s"]))
        line("vtkSSAOPass nearest in time (radius %.2f, kernel %s)" % (
            float(equal["ssao_radius"]), equal["ssao_kernel"]), equal)
        best = min(ssao, key=lambda r: r["affine_rmse"])
        line("vtkSSAOPass best structure (radius %.2f, kernel %s)" % (
            float(best["ssao_radius"]), best["ssao_kernel"]), best)
        best = min(ssao, key=lambda r: r["rmse"])
        line("vtkSSAOPass lowest RMSE (radius %.2f, kernel %s)" % (
            float(best["ssao_radius"]), best["ssao_kernel"]), best)
        ref = [r for r in mine if r["method"] == "reference"][0]
        line("reference (CPU ray tracing)", ref)
    volume = os.path.join(args.results, "ao_fcc_volume.csv")
    if os.path.exists(volume):
        print("\n| splat | resolution | voxels | edge / lattice constant | interior CV | min | max |")
        print("|---|---:|---|---:|---:|---:|---:|")
        for r in load(volume):
            print("| %s | %s | %s | %.2f | %.3f | %.3f | %.3f |" % (
                r["splat"], r["resolution"] if r["resolution"] != "0" else "auto", r["dims"],
                float(r["voxel_per_lattice"]), float(r["cv"]), float(r["min"]), float(r["max"])))


if __name__ == "__main__":
    main()
