"""Accuracy and cost of vtkVoxelConeAOPass on translucent particles (Staib et al. 2015, the
paper's own case) against vtkParticleReferenceRenderer's transparency-aware ray-traced ambient
occlusion (Eq. 5-7: rays through the exact emission-absorption spheres), with
vtkDensityVolumeAOPass and VTK's vtkSSAOPass on the same chart.

Scenes (Testing/Data): the film breaking up (lj_film.vtp) and the colliding droplets
(lj_droplets.vtp), drawn by vtkTransparentSphereMapper (constant density, VolumeMix 0) with a
white, ambient-only material, so a pixel is the composited sum_i T_i Theta_i A_O,i of the glyphs
along its ray (no AO: sum_i T_i Theta_i). Translucency from the local density, as the paper does
for its droplets and film: n_i = neighbours within 1.5 particle diameters (vtkStaticPointLocator),
Theta_i = clip(1 - 0.9 n_i / n_bulk, 0.1, 0.9) with n_bulk the 90th percentile of n -- the surface
and the vapour are opaque, the bulk liquid clear, so the interfaces show.

Reference: the same camera and pixels, AmbientOcclusionSamples rays per composited surface, up to
the voxel-cone pass's default cone length (0.25 of the largest extent), ApplyAmbientOcclusion.
Errors over the pixels the reference covers (translucent alpha > 0.01): rmse, affine_rmse (after
the best affine map) and bias of the pixel value, as in ao_study.py. One configuration also adds
ambient illumination (alpha_A = 0.5, e_A = 1) in both.

Knobs of the voxel-cone pass, one at a time around the defaults (per fragment, automatic
resolution, 3 sub-grid samples, 3 cones, aperture 60, length 0.25): resolution, sub-grid samples,
cone count, aperture, cone length; the per-sphere retrieval. Frame times: the shortest of FRAMES
frames of a slowly orbiting camera (the volume is not rebuilt; the translucent particles are
sorted every frame), and one volume build.

usage: /usr/bin/python3 Benchmarks/voxel_cone_translucent_study.py --data Testing/Data \
           --out Benchmarks/results
       (PYTHONPATH=<build>/lib/python3/dist-packages:Benchmarks, under Xvfb)
writes voxel_cone_translucent.csv and voxel_cone_translucent.png
"""
import argparse
import csv
import os
import time

import numpy as np

import particlerendering as pr
import ao_study
from ao_study import errors
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkCommonDataModel import vtkStaticPointLocator
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass, vtkSSAOPass
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)


def density_opacity(data, radius):
    """Theta_i from the local density (see the module description)."""
    locator = vtkStaticPointLocator()
    locator.SetDataSet(data)
    locator.BuildLocator()
    ids = vtkIdList()
    points = data.GetPoints()
    counts = np.empty(data.GetNumberOfPoints())
    for i in range(data.GetNumberOfPoints()):
        locator.FindPointsWithinRadius(3.0 * radius, points.GetPoint(i), ids)
        counts[i] = ids.GetNumberOfIds() - 1
    bulk = max(1.0, np.percentile(counts, 90))
    return np.clip(1.0 - 0.9 * counts / bulk, 0.1, 0.9)


class Scene(ao_study.Scene):
    """ao_study's scene (white ambient-only material, the oblique camera) with the particles as
    emission-absorption spheres whose Theta_i comes from the local density."""

    def make_mapper(self):
        radius = float(vtk_to_numpy(self.data.GetPointData().GetArray("radius")).mean())
        theta = density_opacity(self.data, radius)
        array = numpy_to_vtk(theta.astype(np.float32), deep=True)
        array.SetName("opacity")
        self.data.GetPointData().AddArray(array)
        self.mean_theta = float(theta.mean())
        b = self.data.GetBounds()
        self.extent = max(b[1] - b[0], b[3] - b[2], b[5] - b[4]) + 2 * radius
        mapper = pr.vtkTransparentSphereMapper()
        mapper.SetOpacityArrayName("opacity")
        mapper.SetOpacityRange(0.0, 1.0)
        mapper.SetVolumeMix(0.0)
        return mapper

    def reference(self, samples, distance, illumination):
        ref = pr.vtkParticleReferenceRenderer()
        ref.SetRenderer(self.renderer)
        ref.SetActor(self.actor)
        ref.SetImageSize(self.size, self.size)
        ref.SetAmbientOcclusionSamples(samples)
        ref.SetAmbientOcclusionDistance(distance)
        ref.SetApplyAmbientOcclusion(True)
        ref.SetAmbientIllumination(illumination)
        self.reset_camera()
        start = time.perf_counter()
        ref.Render()
        seconds = time.perf_counter() - start
        color = vtk_to_numpy(ref.GetColorImage().GetPointData().GetScalars())
        alpha = vtk_to_numpy(ref.GetTranslucentAlphaImage().GetPointData().GetScalars())
        return (color[:, 0].reshape(self.size, self.size).astype(np.float64),
                alpha.reshape(self.size, self.size) > 0.01, seconds)


def measure(scene, ref, base, method, extra, rows):
    frame = scene.timed()
    image = scene.image()
    rmse, affine, bias = errors(image, ref[0], ref[1])
    row = dict(base, method=method, frame_s=frame, rmse=rmse, affine_rmse=affine, bias=bias,
               **extra)
    rows.append(row)
    print("  %-14s %-52s %7.1f ms  rmse %.4f affine %.4f bias %+.4f" %
          (method, " ".join("%s=%s" % kv for kv in extra.items()), 1e3 * frame, rmse, affine,
           bias), flush=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--samples", type=int, default=64)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--cache", help="directory for the reference images (reused when the "
                        "scene, size, samples and distance match)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    scenes = [("film", "lj_film.vtp"), ("droplets", "lj_droplets.vtp")]
    if args.quick:
        scenes = scenes[:1]
    for name, file in scenes:
        scene = Scene(name, os.path.join(args.data, file), args.size, args.frames)
        distance = 0.25 * scene.extent
        refs = {}
        for illumination in (0.0, 0.5):
            cached = None
            if args.cache:
                os.makedirs(args.cache, exist_ok=True)
                cached = os.path.join(args.cache, "%s_%d_%d_%.4f_%.1f.npz" % (
                    name, args.size, args.samples, distance, illumination))
            if cached and os.path.exists(cached):
                z = np.load(cached)
                refs[illumination] = (z["value"], z["mask"], float(z["seconds"]))
            else:
                refs[illumination] = scene.reference(args.samples, distance, illumination)
                if cached:
                    np.savez(cached, value=refs[illumination][0], mask=refs[illumination][1],
                             seconds=refs[illumination][2])
            print("%s: %d particles, mean Theta %.2f, reference (alpha_A %.1f, distance %.2f): "
                  "%.1f s, mean %.3f" % (name, scene.data.GetNumberOfPoints(), scene.mean_theta,
                                          illumination, distance, refs[illumination][2],
                                          refs[illumination][0][refs[illumination][1]].mean()),
                  flush=True)
        scene.renderer.SetPass(None)
        plain = scene.timed()
        base = dict(scene=name, particles=scene.data.GetNumberOfPoints(), size=args.size,
                    reference_samples=args.samples, plain_frame_s=plain, distance=distance,
                    reference_s=refs[0.0][2], illumination=0.0)
        measure(scene, refs[0.0], base, "none", {}, rows)

        cones = pr.vtkVoxelConeAOPass()
        cones.SetDelegatePass(vtkRenderStepsPass())
        scene.renderer.SetPass(cones)
        volume = cones.GetAmbientVolume()
        defaults = dict(resolution=0, subgrid=3, cones=3, aperture=60.0, length=0.25,
                        retrieval=0, illumination=0.0)
        variations = [dict(defaults)]
        for res in (32, 64, 128, 256):
            variations.append(dict(defaults, resolution=res))
        for subgrid in (1, 2, 5):
            variations.append(dict(defaults, subgrid=subgrid))
        for count in (1, 6, 9):
            variations.append(dict(defaults, cones=count))
        for aperture in (30.0, 45.0, 90.0):
            variations.append(dict(defaults, aperture=aperture))
        for length in (0.0625, 0.125, 0.5):
            variations.append(dict(defaults, length=length))
        for count in (1, 3):
            variations.append(dict(defaults, retrieval=1, cones=count))
        variations.append(dict(defaults, illumination=0.5))
        if args.quick:
            variations = variations[:2]
        for v in variations:
            volume.SetResolution(v["resolution"])
            volume.SetSubGridSamples(v["subgrid"])
            cones.SetConeCount(v["cones"])
            cones.SetConeAperture(v["aperture"])
            cones.SetConeLength(v["length"])
            cones.SetRetrievalMode(v["retrieval"])
            cones.SetAmbientIllumination(v["illumination"])
            builds = cones.GetNumberOfVolumeBuilds()
            scene.data.GetPoints().Modified()  # a new time step: rebuild
            rebuild = scene.frame()
            assert cones.GetNumberOfVolumeBuilds() == builds + 1
            extra = dict(v, dims="%dx%dx%d" % volume.GetDimensions())
            measure(scene, refs[v["illumination"]], dict(base, illumination=v["illumination"]),
                    "voxel-cone", extra, rows)
            rows[-1]["build_s"] = max(0.0, rebuild - rows[-1]["frame_s"])

        density = pr.vtkDensityVolumeAOPass()
        density.SetDelegatePass(vtkRenderStepsPass())
        scene.renderer.SetPass(density)
        for strength in (1.0, 2.0):
            density.SetStrength(strength)
            measure(scene, refs[0.0], base, "density-volume", dict(strength=strength), rows)

        ssao = vtkSSAOPass()
        ssao.SetDelegatePass(vtkRenderStepsPass())
        ssao.BlurOn()
        ssao.SetRadius(2.0 * scene.mean_radius)
        ssao.SetKernelSize(32)
        ssao.SetBias(0.01 * scene.mean_radius)
        scene.renderer.SetPass(ssao)
        measure(scene, refs[0.0], base, "ssao", dict(ssao_radius=2.0), rows)
        scene.renderer.SetPass(None)

    fields = ["scene", "particles", "size", "method", "retrieval", "resolution", "dims",
              "subgrid", "cones", "aperture", "length", "illumination", "strength",
              "ssao_radius", "frame_s", "plain_frame_s", "build_s", "rmse", "affine_rmse",
              "bias", "reference_samples", "reference_s", "distance"]
    with open(os.path.join(args.out, "voxel_cone_translucent.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow(row)
    plot(rows, args.out, [s for s, _ in scenes])


def plot(rows, out, scenes):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(scenes), figsize=(6.5 * len(scenes), 5), squeeze=False)
    knobs = [("resolution", "tab:blue", "o"), ("subgrid", "tab:cyan", "h"),
             ("cones", "tab:green", "s"), ("aperture", "tab:purple", "^"),
             ("length", "tab:brown", "v")]
    for i, name in enumerate(scenes):
        ax = axes[0][i]
        mine = [r for r in rows if r["scene"] == name]
        vc = [r for r in mine if r["method"] == "voxel-cone" and r["retrieval"] == 0
              and r["illumination"] == 0.0]
        default = vc[0]
        for knob, colour, marker in knobs:
            pts = [r for r in vc[1:] if r[knob] != default[knob]
                   and all(r[k] == default[k] for k, _, _ in knobs if k != knob)]
            pts = sorted(pts + [default], key=lambda r: r[knob])
            ax.plot([1e3 * r["frame_s"] for r in pts], [r["rmse"] for r in pts], marker=marker,
                    color=colour, label="voxel cone: %s" % knob)
            for r in pts:
                ax.annotate(str(r[knob]), (1e3 * r["frame_s"], r["rmse"]), fontsize=6)
        ax.plot([1e3 * default["frame_s"]], [default["rmse"]], "*", color="red", markersize=14,
                label="voxel cone, defaults")
        ps = [r for r in mine if r["method"] == "voxel-cone" and r["retrieval"] == 1]
        ax.plot([1e3 * r["frame_s"] for r in ps], [r["rmse"] for r in ps], marker="P",
                color="tab:red", linestyle="none", label="voxel cone per sphere (1, 3 cones)")
        for method, colour, marker in (("density-volume", "tab:orange", "D"),
                                       ("ssao", "tab:gray", "x")):
            pts = [r for r in mine if r["method"] == method]
            ax.plot([1e3 * r["frame_s"] for r in pts], [r["rmse"] for r in pts], marker=marker,
                    linestyle="none", color=colour, label=method)
        none = [r for r in mine if r["method"] == "none"][0]
        ax.axhline(none["rmse"], color="grey", linestyle="-.", label="no AO")
        ax.set_xlabel("frame time [ms] (translucent, sorted every frame; llvmpipe)")
        ax.set_ylabel("RMSE of the composited pixel vs ray-traced Eq. 5/7")
        ax.set_title("%s, translucency from local density" % name)
        ax.set_ylim(bottom=0)
        if i == 0:
            ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "voxel_cone_translucent.png"), dpi=110)


if __name__ == "__main__":
    main()
