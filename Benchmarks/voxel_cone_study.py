"""Accuracy and cost of vtkVoxelConeAOPass (Staib et al. 2015) against ray-traced ambient
occlusion, with vtkDensityVolumeAOPass and VTK's vtkSSAOPass on the same chart.

The scenes, the white ambient-only material (a pixel is the method's occlusion factor A) and the
error measures are those of ao_study.py (rmse, affine_rmse: after the best affine map of A,
bias). Opaque particles: here the transparency-aware A_O of Eq. 5 is the ray-traced visibility.
Two references per scene, vtkParticleReferenceRenderer's cosine-distributed rays against the real
spheres up to
  near  4 mean radii (the density volume's range; ao_study.py's reference)
  far   the cone length of the voxel-cone pass, 0.25 of the largest extent (the paper's default)
Each method is scored against both.

Knobs of the voxel-cone pass, varied one at a time around the defaults (per fragment, resolution
0 = automatic, 3 cones, aperture 60 degrees, start offset 1 voxel, length 0.25): resolution (voxels
along the longest axis), cone count, aperture, start offset; and the per-sphere retrieval with 1,
3 and 6 cones per axis. Frame times: the shortest of FRAMES frames of
a slowly orbiting camera (static scene, the volume is not rebuilt), and one volume build.

usage: /usr/bin/python3 Benchmarks/voxel_cone_study.py --data Testing/Data --out Benchmarks/results
       (PYTHONPATH=<build>/lib/python3/dist-packages:Benchmarks, under Xvfb)
writes voxel_cone_accuracy.csv and voxel_cone_accuracy.png
"""
import argparse
import csv
import os

import numpy as np

import particlerendering as pr
from ao_study import Scene, errors
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass, vtkSSAOPass


def measure(scene, refs, base, method, extra, rows):
    frame = scene.timed()
    image = scene.image()
    row = dict(base, method=method, frame_s=frame, **extra)
    for key, (ref, mask) in refs.items():
        rmse, affine, bias = errors(image, ref, mask)
        row["rmse_" + key] = rmse
        row["affine_rmse_" + key] = affine
        row["bias_" + key] = bias
    rows.append(row)
    print("  %-13s %-40s %6.1f ms  far: rmse %.3f affine %.3f bias %+.3f | near: rmse %.3f "
          "affine %.3f" % (method, " ".join("%s=%s" % kv for kv in extra.items()), 1e3 * frame,
                           row["rmse_far"], row["affine_rmse_far"], row["bias_far"],
                           row["rmse_near"], row["affine_rmse_near"]), flush=True)
    return image


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", type=int, default=320)
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--samples", type=int, default=128)
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    scenes = [("film", "lj_film.vtp"), ("fcc", "fcc_block.vtp")]
    if args.quick:
        scenes = scenes[1:]
    for name, file in scenes:
        scene = Scene(name, os.path.join(args.data, file), args.size, args.frames)
        b = scene.data.GetBounds()
        extent = max(b[1] - b[0], b[3] - b[2], b[5] - b[4]) + 2 * scene.mean_radius
        refs = {}
        for key, distance in (("near", 4.0 * scene.mean_radius), ("far", 0.25 * extent)):
            ref, mask, seconds = scene.reference(args.samples, distance)
            refs[key] = (ref, mask)
            print("%s: reference %s (distance %.2f): %.1f s, mean A %.3f" %
                  (name, key, distance, seconds, ref[mask].mean()), flush=True)
        scene.renderer.SetPass(None)
        plain = scene.timed()
        base = dict(scene=name, particles=scene.data.GetNumberOfPoints(), size=args.size,
                    reference_samples=args.samples, plain_frame_s=plain,
                    near_distance=4.0 * scene.mean_radius, far_distance=0.25 * extent)
        measure(scene, refs, base, "none", {}, rows)

        cones = pr.vtkVoxelConeAOPass()
        cones.SetDelegatePass(vtkRenderStepsPass())
        scene.renderer.SetPass(cones)
        volume = cones.GetAmbientVolume()
        defaults = dict(resolution=0, cones=3, aperture=60.0, start=1.0, retrieval=0)
        variations = [dict(defaults)]
        for res in (32, 64, 128, 256):
            variations.append(dict(defaults, resolution=res))
        for count in (1, 6, 9):
            variations.append(dict(defaults, cones=count))
        for aperture in (30.0, 45.0, 90.0):
            variations.append(dict(defaults, aperture=aperture))
        for start in (0.5, 2.0):
            variations.append(dict(defaults, start=start))
        for count in (1, 3, 6):  # per sphere (vertex stage)
            variations.append(dict(defaults, retrieval=1, cones=count))
        if args.quick:
            variations = variations[:2]
        for v in variations:
            volume.SetResolution(v["resolution"])
            cones.SetConeCount(v["cones"])
            cones.SetConeAperture(v["aperture"])
            cones.SetStartOffset(v["start"])
            cones.SetRetrievalMode(v["retrieval"])
            builds = cones.GetNumberOfVolumeBuilds()
            scene.data.GetPoints().Modified()  # a new time step: rebuild
            rebuild = scene.frame()
            assert cones.GetNumberOfVolumeBuilds() == builds + 1
            dims = volume.GetDimensions()
            extra = dict(v, dims="%dx%dx%d" % dims)
            measure(scene, refs, base, "voxel-cone", extra, rows)
            rows[-1]["build_s"] = max(0.0, rebuild - rows[-1]["frame_s"])

        density = pr.vtkDensityVolumeAOPass()
        density.SetDelegatePass(vtkRenderStepsPass())
        scene.renderer.SetPass(density)
        for strength in (1.0, 2.0):
            density.SetStrength(strength)
            measure(scene, refs, base, "density-volume", dict(strength=strength), rows)

        ssao = vtkSSAOPass()
        ssao.SetDelegatePass(vtkRenderStepsPass())
        ssao.BlurOn()
        scene.renderer.SetPass(ssao)
        for radius_factor in ((2.0, 8.0) if not args.quick else (2.0,)):
            ssao.SetRadius(radius_factor * scene.mean_radius)
            ssao.SetKernelSize(32)
            ssao.SetBias(0.01 * scene.mean_radius)
            measure(scene, refs, base, "ssao", dict(ssao_radius=radius_factor), rows)
        scene.renderer.SetPass(None)

    fields = ["scene", "particles", "size", "method", "retrieval", "resolution", "dims", "cones",
              "aperture", "start", "strength", "ssao_radius", "frame_s", "plain_frame_s", "build_s"]
    for key in ("far", "near"):
        fields += ["rmse_" + key, "affine_rmse_" + key, "bias_" + key]
    fields += ["reference_samples", "near_distance", "far_distance"]
    with open(os.path.join(args.out, "voxel_cone_accuracy.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow(row)
    plot(rows, args.out, [s for s, _ in scenes])


def plot(rows, out, scenes):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(scenes), 2, figsize=(13, 4.8 * len(scenes)), squeeze=False)
    knobs = [("resolution", "tab:blue", "o"), ("cones", "tab:green", "s"),
             ("aperture", "tab:purple", "^"), ("start", "tab:brown", "v")]
    for i, name in enumerate(scenes):
        mine = [r for r in rows if r["scene"] == name]
        for j, key in enumerate(("rmse_far", "rmse_near")):
            ax = axes[i][j]
            vc = [r for r in mine if r["method"] == "voxel-cone" and r["retrieval"] == 0]
            default = vc[0]
            for knob, colour, marker in knobs:
                pts = [r for r in vc[1:] if any(r[k] != default[k] for k in (knob,))
                       and all(r[k] == default[k] for k, _, _ in knobs if k != knob)]
                pts = sorted(pts + [default], key=lambda r: r[knob])
                ax.plot([1e3 * r["frame_s"] for r in pts], [r[key] for r in pts], marker=marker,
                        color=colour, label="voxel cone: %s" % knob)
                for r in pts:
                    ax.annotate(str(r[knob]), (1e3 * r["frame_s"], r[key]), fontsize=6)
            ax.plot([1e3 * default["frame_s"]], [default[key]], "*", color="red", markersize=14,
                    label="voxel cone, defaults")
            ps = sorted([r for r in mine if r["method"] == "voxel-cone" and r["retrieval"] == 1],
                        key=lambda r: r["cones"])
            ax.plot([1e3 * r["frame_s"] for r in ps], [r[key] for r in ps], marker="P",
                    color="tab:red", linestyle=":", label="voxel cone per sphere: cones")
            for r in ps:
                ax.annotate(str(r["cones"]), (1e3 * r["frame_s"], r[key]), fontsize=6)
            for method, colour, marker in (("density-volume", "tab:orange", "D"),
                                           ("ssao", "tab:gray", "x")):
                pts = [r for r in mine if r["method"] == method]
                ax.plot([1e3 * r["frame_s"] for r in pts], [r[key] for r in pts], marker=marker,
                        linestyle="none", color=colour, label=method)
            none = [r for r in mine if r["method"] == "none"][0]
            ax.axhline(none[key], color="grey", linestyle="-.", label="no AO")
            ax.set_xlabel("frame time [ms] (static scene, llvmpipe)")
            ax.set_ylabel("RMSE of A vs ray-traced AO (%s)" % key.split("_")[1])
            ax.set_title("%s: against rays up to %s" % (name, "the cone length (0.25 extent)"
                                                         if key.endswith("far")
                                                         else "4 mean radii"))
            ax.set_ylim(bottom=0)
            if i == 0 and j == 0:
                ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "voxel_cone_accuracy.png"), dpi=110)


if __name__ == "__main__":
    main()
