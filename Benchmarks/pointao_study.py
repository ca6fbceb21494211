"""Accuracy against time of vtkPointAOPass (PointAO, Eichelbaum et al. 2013) against ray-traced
ambient occlusion, with vtkSSAOPass (ParaView's "Use Ambient Occlusion"), vtkDensityVolumeAOPass
and vtkVoxelConeAOPass on the same chart.

As in ao_study.py every method renders a white, ambient-only material, so a pixel's value is the
method's ambient-occlusion factor A; the reference is vtkParticleReferenceRenderer's ray-traced
AO within four mean radii (cosine-distributed rays against the real spheres) on the same camera
and pixels. Per configuration:
  rmse, bias     over the pixels where the reference hits a sphere
  band_rmse      the same over a 3-pixel band around the silhouettes against the background
                 (where a screen-space method's halo would show)
  frame_s        the shortest frame of a slow orbit (as ao_study.py), the plain core's in the
                 same window in plain_frame_s
and for each method's default configuration
  orbit_change   mean |A(t+1) - A(t)| under an orbit by 0.25 degrees per frame, over the static
                 pixels (the same particle at the pixel and its neighbours in both frames); the
                 reference's own change in its row (its own ray noise included)
  resize_change  mean |A(2x window) - A| in 4 x 4 blocks of the smaller window (the reference's
                 own in its row)
Knobs: PointAO levels (1-4) and directions (2-16) at the automatic radius (four mean radii),
and at half resolution ("pointao-half": 3 levels with 4 and 8 directions, 4 with 8);
vtkSSAOPass radius (1-8 mean radii) and kernel (8-128), blur on; the density volume's
resolution (automatic, 32, 64) at strength 2; voxel cone tracing with 3 and 6 cones.

Scenes: Testing/Data/lj_film.vtp (a LAMMPS liquid film, oblique perspective view),
lj_droplets.vtp (LAMMPS droplets in vapour, perspective), fcc_block.vtp (an FCC crystal face on,
parallel projection).

usage: /usr/bin/python3 Benchmarks/pointao_study.py --data Testing/Data --out Benchmarks/results
       (PYTHONPATH=<build>/lib/python3/dist-packages, under Xvfb; Benchmarks/run_pointao.sh)
writes pointao_accuracy.csv and pointao_accuracy.png
"""
import argparse
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ao_study  # noqa: E402  (the scenes, the reference and the error measures)

import particlerendering as pr  # noqa: E402
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass, vtkSSAOPass  # noqa: E402


def band(mask, width=3):
    near = np.zeros_like(mask)
    for dy in range(-width, width + 1):
        for dx in range(-width, width + 1):
            near |= np.roll(np.roll(~mask, dy, 0), dx, 1)
    return mask & near


def measure(scene, ref, mask, silhouette):
    frame = scene.timed()
    image = scene.image()
    rmse, affine, bias = ao_study.errors(image, ref, mask)
    d = image[silhouette] - ref[silhouette]
    return dict(frame_s=frame, rmse=rmse, affine_rmse=affine, bias=bias,
                band_rmse=float(np.sqrt(np.mean(d * d)))), image


def blocks(image, factor, size):
    n = size // 4
    return image.reshape(n, 4 * factor, n, 4 * factor).mean(axis=(1, 3))


def stability(scene, make_pass, ref, mask, distance, samples):
    """(orbit_change, resize_change) of a method, and of the reference when make_pass is None.
    The orbit change is taken over the static pixels: the same particle seen at the pixel and
    its four neighbours in both frames (where the particle under a pixel changes, the occlusion
    changes too)."""
    size = scene.size
    scene.renderer.SetPass(make_pass() if make_pass else None)
    scene.reset_camera()
    camera = scene.renderer.GetActiveCamera()
    previous = scene.image() if make_pass else ref
    scene.reference(1, distance, reset=False)
    previous_ids = scene.reference_ids
    changes = []
    for _ in range(2):
        camera.Azimuth(0.25)
        scene.renderer.ResetCameraClippingRange()
        scene.frame()
        if make_pass:
            current = scene.image(reset=False)
            scene.reference(1, distance, reset=False)
            ids = scene.reference_ids
        else:
            current = scene.reference(samples, distance, reset=False)[0]
            ids = scene.reference_ids
        still = static(previous_ids, ids)
        changes.append(float(np.abs(current - previous)[still].mean()))
        previous, previous_ids = current, ids
    scene.reset_camera()
    # twice the window
    big = StudyScene(scene.name, scene.path, 2 * size, 1)
    big.renderer.SetPass(make_pass() if make_pass else None)
    if make_pass:
        large = big.image()
        small = scene.image()
    else:
        large, _, _ = big.reference(samples, distance)
        small = ref
    full = blocks(mask.astype(float), 1, size) > 0.75
    resize = float(np.abs(blocks(large, 2, size) - blocks(small, 1, size))[full].mean())
    scene.renderer.SetPass(None)
    return max(changes), resize


def static(ids_a, ids_b):
    same = (ids_a == ids_b) & (ids_a >= 0)
    for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)):
        same &= np.roll(np.roll(ids_a, dy, 0), dx, 1) == ids_a
    return same


class StudyScene(ao_study.Scene):
    """ao_study's scene (its view from the name: "fcc" face on, any other oblique), with its
    file's path for the window of twice the size."""

    def __init__(self, name, path, size, frames):
        self.path = path
        super().__init__(name, path, size, frames)


def pointao(levels=3, directions=8, half=False):
    def make():
        p = pr.vtkPointAOPass()
        p.SetDelegatePass(vtkRenderStepsPass())
        p.SetNumberOfLevels(levels)
        p.SetSamplesPerLevel(directions)
        p.SetHalfResolution(half)
        return p
    return make


def ssao(radius, kernel, mean_radius):
    def make():
        p = vtkSSAOPass()
        p.SetDelegatePass(vtkRenderStepsPass())
        p.SetRadius(radius)
        p.SetKernelSize(kernel)
        p.SetBias(0.01 * mean_radius)
        p.BlurOn()
        return p
    return make


def density(resolution):
    def make():
        p = pr.vtkDensityVolumeAOPass()
        p.SetDelegatePass(vtkRenderStepsPass())
        p.SetStrength(2.0)
        p.GetDensityVolume().SetResolution(resolution)
        return p
    return make


def voxel_cone(cones):
    def make():
        p = pr.vtkVoxelConeAOPass()
        p.SetDelegatePass(vtkRenderStepsPass())
        p.SetConeCount(cones)
        return p
    return make


def plot(rows, out, scenes):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, len(scenes), figsize=(5.2 * len(scenes), 8.5), squeeze=False)
    style = {"pointao": ("C3", "o"), "pointao-half": ("C1", "v"), "ssao": ("C0", "s"),
             "density-volume": ("C2", "^"), "voxel-cone": ("C4", "D")}
    for column, scene in enumerate(scenes):
        for row_index, key in enumerate(("rmse", "band_rmse")):
            ax = axes[row_index][column]
            for method, (colour, marker) in style.items():
                points = [(r["frame_s"] * 1e3, r[key]) for r in rows
                          if r["scene"] == scene and r["method"] == method]
                if points:
                    xs, ys = zip(*sorted(points))
                    ax.scatter(xs, ys, c=colour, marker=marker, label=method, s=22)
            for r in rows:
                if r["scene"] == scene and r["method"] == "none":
                    ax.axhline(r[key], color="grey", ls=":", lw=1)
                    ax.axvline(r["frame_s"] * 1e3, color="grey", ls=":", lw=1)
            ax.set_xscale("log")
            ax.set_xlabel("frame time [ms] (dotted: plain core)")
            ax.set_ylabel("RMSE of A vs ray-traced AO" if key == "rmse"
                          else "RMSE in the 3-px silhouette band")
            ax.set_title("%s: %s" % (scene, "all particle pixels" if key == "rmse"
                                     else "silhouette band"))
            ax.grid(alpha=0.3)
            if row_index == 0 and column == 0:
                ax.legend(fontsize=8)
    fig.suptitle("PointAO against vtkSSAOPass, density volume and voxel cones "
                 "(llvmpipe, same run; reference: 256 rays within 4 mean radii)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pointao_accuracy.png"), dpi=90)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", type=int, default=384)
    parser.add_argument("--frames", type=int, default=9)
    parser.add_argument("--samples", type=int, default=256)
    parser.add_argument("--quick", action="store_true", help="few configurations")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    scenes = [("film", "lj_film.vtp"), ("droplets", "lj_droplets.vtp"), ("fcc", "fcc_block.vtp")]
    if args.quick:
        scenes = scenes[:1]
    for name, file in scenes:
        path = os.path.join(args.data, file)
        scene = StudyScene(name, path, args.size, args.frames)
        distance = 4.0 * scene.mean_radius
        ref, mask, ref_seconds = scene.reference(args.samples, distance)
        silhouette = band(mask)
        scene.renderer.SetPass(None)
        base = dict(scene=name, particles=scene.data.GetNumberOfPoints(), size=args.size,
                    reference_samples=args.samples, reference_distance=distance)
        result, _ = measure(scene, ref, mask, silhouette)
        plain = result["frame_s"]
        base["plain_frame_s"] = plain
        rows.append(dict(base, method="none", **result))
        orbit, resize = stability(scene, None, ref, mask, distance, args.samples)
        rows.append(dict(base, method="reference", frame_s=ref_seconds, rmse=0, bias=0,
                         band_rmse=0, orbit_change=orbit, resize_change=resize))
        print("%s: %d particles, reference %.1f s; plain %.1f ms, reference orbit %.4f resize "
              "%.4f" % (name, scene.data.GetNumberOfPoints(), ref_seconds, 1e3 * plain, orbit,
                        resize), flush=True)
        configs = []
        for levels in ([3] if args.quick else [1, 2, 3, 4]):
            for directions in ([4, 8] if args.quick else [2, 4, 8, 16]):
                configs.append(("pointao", dict(levels=levels, directions=directions),
                                pointao(levels, directions), (levels, directions) == (3, 4)))
        for levels, directions in ([] if args.quick else [(3, 4), (3, 8), (4, 8)]):
            configs.append(("pointao-half", dict(levels=levels, directions=directions),
                            pointao(levels, directions, True), False))
        for factor in ([2.0] if args.quick else [1.0, 2.0, 4.0, 8.0]):
            for kernel in ([32] if args.quick else [8, 32, 128]):
                configs.append(("ssao", dict(ssao_radius=factor * scene.mean_radius,
                                             ssao_kernel=kernel),
                                ssao(factor * scene.mean_radius, kernel, scene.mean_radius),
                                (factor, kernel) == (2.0, 32)))
        for resolution in ([0] if args.quick else [0, 32, 64]):
            configs.append(("density-volume", dict(resolution=resolution), density(resolution),
                            resolution == 0))
        for cones in ([3] if args.quick else [3, 6]):
            configs.append(("voxel-cone", dict(cones=cones), voxel_cone(cones), cones == 3))
        for method, knobs, make, default in configs:
            scene.renderer.SetPass(make())
            result, _ = measure(scene, ref, mask, silhouette)
            row = dict(base, method=method, **knobs, **result)
            if default:
                row["orbit_change"], row["resize_change"] = stability(
                    scene, make, ref, mask, distance, args.samples)
            rows.append(row)
            print("  %-14s %-40s %6.1f ms  rmse %.4f bias %+.4f band %.4f%s"
                  % (method, knobs, 1e3 * result["frame_s"], result["rmse"], result["bias"],
                     result["band_rmse"],
                     "  orbit %.4f resize %.4f" % (row["orbit_change"], row["resize_change"])
                     if default else ""), flush=True)
        scene.renderer.SetPass(None)
    fields = ["scene", "particles", "size", "method", "levels", "directions", "ssao_radius",
              "ssao_kernel", "resolution", "cones", "frame_s", "plain_frame_s", "rmse",
              "affine_rmse", "bias", "band_rmse", "orbit_change", "resize_change",
              "reference_samples", "reference_distance"]
    with open(os.path.join(args.out, "pointao_accuracy.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow(row)
    plot(rows, args.out, [s for s, _ in scenes])


if __name__ == "__main__":
    main()
