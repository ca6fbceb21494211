"""Accuracy and cost of vtkDensityVolumeAOPass (Grottel et al. 2012) against ray-traced ambient
occlusion, with VTK's vtkSSAOPass (ParaView's "Use Ambient Occlusion") on the same chart.

Every method renders the same scene with a white, ambient-only material (ambient 1, diffuse 0,
specular 0), so a pixel's value is the method's ambient-occlusion factor A in [0, 1]. The
reference is vtkParticleReferenceRenderer's ray-traced AO (cosine-distributed stratified rays
against the real spheres, up to a maximum distance) on the same camera and pixels. Errors are over
the pixels where the reference hits a sphere:
  rmse         root mean square of A - A_ref
  affine_rmse  the same after the best affine map a A + b (least squares): what is left when the
               strength of the darkening is tuned away (the structure error)
  bias         mean of A - A_ref
Times: the shortest of FRAMES frames of a slowly orbiting camera (the volume is not rebuilt:
static scene; the minimum, because the shared cores disturb single frames by up to 50 %), the same for plain spheres (no pass) in the same window, and the time of one volume build
(a frame after the particles were marked modified minus a static frame).

Scenes:
  film  Testing/Data/lj_film.vtp (a liquid film breaking up, like the paper's Fig. 1), oblique
        perspective view
  fcc   Testing/Data/fcc_block.vtp (an FCC crystal block) seen face-on (+x face, parallel
        projection): the paper's Fig. 6 artefact. artefact_std is the standard deviation of A
        box-filtered over 3x3 lattice cells across the face: large-scale non-uniformity where the
        crystal face is uniform (the reference's own value is its noise floor)

Knobs of ours: splat (nearest voxel = the paper's Eq. 5, trilinear = the default), resolution
(voxels along the longest axis; 0 = automatic, voxels of 4 mean radii) and fetch distance (voxel
edges). Knobs of vtkSSAOPass: radius (world units) and kernel size (samples); blur on.

usage: /usr/bin/python3 Benchmarks/ao_study.py --data Testing/Data --out Benchmarks/results
       (PYTHONPATH=<build>/lib/python3/dist-packages, under Xvfb; Benchmarks/run_ao.sh does this)
writes ao_accuracy.csv, ao_accuracy.png (error vs frame time, static and with a volume rebuild
every frame), ao_fcc_volume.csv, ao_fcc_artefact.png
"""
import argparse
import csv
import os
import time

import numpy as np

import particlerendering as pr
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkRenderer, vtkRenderWindow,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass, vtkSSAOPass
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)


class Scene:
    def __init__(self, name, path, size, frames):
        self.name = name
        self.size = size
        self.frames = frames
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        self.data = reader.GetOutput()
        radii = vtk_to_numpy(self.data.GetPointData().GetArray("radius"))
        self.mean_radius = float(radii.mean())
        self.mapper = self.make_mapper()
        self.mapper.SetInputData(self.data)
        self.mapper.SetRadiusArrayName("radius")
        self.mapper.ScalarVisibilityOff()
        self.actor = vtkActor()
        self.actor.SetMapper(self.mapper)
        prop = self.actor.GetProperty()
        prop.SetColor(1, 1, 1)
        prop.SetAmbient(1)
        prop.SetDiffuse(0)
        prop.SetSpecular(0)
        self.renderer = vtkRenderer()
        self.renderer.AddActor(self.actor)
        self.renderer.SetBackground(0, 0, 0)
        self.window = vtkRenderWindow()
        self.window.SetSize(size, size)
        self.window.SetMultiSamples(0)
        self.window.AddRenderer(self.renderer)
        camera = self.renderer.GetActiveCamera()
        b = self.data.GetBounds()
        centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
        if name == "fcc":
            # face-on onto the +x face, the middle 90 % of it
            camera.ParallelProjectionOn()
            camera.SetFocalPoint(b[1], centre[1], centre[2])
            camera.SetPosition(b[1] + 100, centre[1], centre[2])
            camera.SetViewUp(0, 1, 0)
            self.renderer.ResetCameraClippingRange()
            camera.SetParallelScale(0.45 * (b[3] - b[2]))
            self.lattice = ((4.0 / 1.07) ** (1.0 / 3.0))  # LJ fcc, rho* = 1.07
            self.pixel = 2 * camera.GetParallelScale() / size
        else:
            camera.SetFocalPoint(*centre)
            camera.SetPosition(centre[0] + 0.9 * (b[1] - b[0]), centre[1] - 1.2 * (b[3] - b[2]),
                               centre[2] + 0.8 * (b[5] - b[4]))
            camera.SetViewUp(0, 0, 1)
            self.renderer.ResetCamera()
            camera.Zoom(1.3)
        self.window.Render()
        self.camera_state = (camera.GetPosition(), camera.GetFocalPoint(), camera.GetViewUp())

    def make_mapper(self):
        """The particles' mapper (a subclass may draw them otherwise)."""
        return pr.vtkParticleSphereMapper()

    def reset_camera(self):
        camera = self.renderer.GetActiveCamera()
        camera.SetPosition(*self.camera_state[0])
        camera.SetFocalPoint(*self.camera_state[1])
        camera.SetViewUp(*self.camera_state[2])
        self.renderer.ResetCameraClippingRange()

    def frame(self):
        start = time.perf_counter()
        self.window.Render()
        self.window.GetZbufferDataAtPoint(0, 0)  # waits for the GPU
        return time.perf_counter() - start

    def timed(self):
        """Shortest frame time with the camera orbiting by 0.2 degrees per frame: the least
        disturbed by other work on the shared cores (a static frame costs the same every time)."""
        self.frame()
        times = []
        for _ in range(self.frames):
            self.renderer.GetActiveCamera().Azimuth(0.2)
            times.append(self.frame())
        self.reset_camera()
        return min(times)

    def image(self, reset=True):
        """The first channel of the window as A in [0, 1] (reset: at the scene's camera)."""
        if reset:
            self.reset_camera()
        self.frame()
        grab = vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.ReadFrontBufferOff()
        grab.Update()
        rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
        return rgb.reshape(self.size, self.size, -1)[:, :, 0].astype(np.float64) / 255.0

    def reference(self, samples, distance, reset=True):
        """(A, mask of the particle pixels, seconds) of the reference at the scene's camera
        (reset) or the current one; the particle ids of its pixels in self.reference_ids."""
        ref = pr.vtkParticleReferenceRenderer()
        ref.SetRenderer(self.renderer)
        ref.SetActor(self.actor)
        ref.SetImageSize(self.size, self.size)
        ref.SetAmbientOcclusionSamples(samples)
        ref.SetAmbientOcclusionDistance(distance)
        if reset:
            self.reset_camera()
        start = time.perf_counter()
        ref.Render()
        seconds = time.perf_counter() - start
        ao = vtk_to_numpy(ref.GetAmbientOcclusionImage().GetPointData().GetScalars())
        ids = vtk_to_numpy(ref.GetIdImage())
        self.reference_ids = ids.reshape(self.size, self.size).copy()
        return (ao.reshape(self.size, self.size).astype(np.float64),
                self.reference_ids >= 0, seconds)


def errors(ao, ref, mask):
    a = ao[mask]
    r = ref[mask]
    diff = a - r
    design = np.vstack([a, np.ones_like(a)]).T
    coeff, *_ = np.linalg.lstsq(design, r, rcond=None)
    fitted = design @ coeff - r
    return (float(np.sqrt(np.mean(diff ** 2))), float(np.sqrt(np.mean(fitted ** 2))),
            float(np.mean(diff)))


def artefact_std(scene, ao, mask):
    """Std of A box-filtered over 3x3 lattice cells, over the face (mask eroded by the box)."""
    if scene.name != "fcc":
        return ""
    w = max(1, int(round(3 * scene.lattice / scene.pixel)))
    filled = np.where(mask, ao, 0.0)
    c = np.cumsum(np.cumsum(np.pad(filled, ((1, 0), (1, 0))), 0), 1)
    m = np.cumsum(np.cumsum(np.pad(mask.astype(float), ((1, 0), (1, 0))), 0), 1)
    s = c[w:, w:] - c[:-w, w:] - c[w:, :-w] + c[:-w, :-w]
    n = m[w:, w:] - m[:-w, w:] - m[w:, :-w] + m[:-w, :-w]
    full = n >= 0.5 * w * w  # windows mostly on spheres (the gaps between them are background)
    return float(np.std(s[full] / n[full]))


def stretch(ao, mask, gain=4.0):
    return np.where(mask, np.clip(1.0 - gain * (1.0 - ao), 0.0, 1.0), 0.0)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", type=int, default=384)
    parser.add_argument("--frames", type=int, default=9)
    parser.add_argument("--samples", type=int, default=256)
    parser.add_argument("--quick", action="store_true", help="few configurations (smoke test)")
    parser.add_argument("--plot-only", action="store_true",
                        help="redraw ao_accuracy.png from the CSV in --out (no images)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.plot_only:
        with open(os.path.join(args.out, "ao_accuracy.csv")) as f:
            rows = list(csv.DictReader(f))
        for row in rows:
            for key, value in row.items():
                try:
                    row[key] = float(value) if key not in ("resolution", "ssao_kernel") \
                        else int(float(value))
                except ValueError:
                    pass
        plot(rows, {}, args.out, list(dict.fromkeys(r["scene"] for r in rows)))
        return

    rows = []
    panels = {}
    scenes = [("film", "lj_film.vtp"), ("fcc", "fcc_block.vtp")]
    if args.quick:
        scenes = scenes[1:]
    for name, file in scenes:
        scene = Scene(name, os.path.join(args.data, file), args.size, args.frames)
        # reference: rays up to one default voxel edge (4 mean radii)
        distance = 4.0 * scene.mean_radius
        ref, mask, ref_seconds = scene.reference(args.samples, distance)
        print("%s: %d particles, reference %.1f s (%d rays per pixel, distance %.2f)" %
              (name, scene.data.GetNumberOfPoints(), ref_seconds, args.samples, distance),
              flush=True)
        scene.renderer.SetPass(None)
        plain = scene.timed()
        plain_image = scene.image()
        rmse, affine, bias = errors(plain_image, ref, mask)
        base = dict(scene=name, particles=scene.data.GetNumberOfPoints(), size=args.size,
                    reference_samples=args.samples, reference_distance=distance,
                    plain_frame_s=plain)
        rows.append(dict(base, method="none", frame_s=plain, rmse=rmse, affine_rmse=affine,
                         bias=bias, artefact_std=artefact_std(scene, plain_image, mask)))
        rows.append(dict(base, method="reference", frame_s=ref_seconds, rmse=0, affine_rmse=0,
                         bias=0, artefact_std=artefact_std(scene, ref, mask)))
        panels[(name, "reference")] = ref
        panels[(name, "mask")] = mask

        ao = pr.vtkDensityVolumeAOPass()
        ao.SetDelegatePass(vtkRenderStepsPass())
        volume = ao.GetDensityVolume()
        scene.renderer.SetPass(ao)
        resolutions = [0, 8, 16, 32, 64, 128]
        fetches = [0.5, 1.0, 2.0]
        splats = [1, 0]
        if args.quick:
            resolutions, fetches = [0, 16], [0.5, 1.0]
        for splat in splats:
            for res in resolutions:
                for fetch in fetches:
                    volume.SetSplatMode(splat)
                    volume.SetResolution(res)
                    ao.SetFetchDistance(fetch)
                    frame = scene.timed()
                    scene.mapper.Modified()  # not a geometry change: no rebuild
                    scene.data.GetPoints().Modified()  # a new time step: rebuild
                    builds = ao.GetNumberOfVolumeBuilds()
                    rebuild = scene.frame()
                    assert ao.GetNumberOfVolumeBuilds() == builds + 1
                    image = scene.image()
                    rmse, affine, bias = errors(image, ref, mask)
                    dims = volume.GetDimensions()
                    row = dict(base, method="density-volume",
                               splat="trilinear" if splat else "nearest", resolution=res,
                               dims="%dx%dx%d" % dims, voxel=volume.GetVoxelSize(),
                               fetch=fetch, frame_s=frame, build_s=max(0.0, rebuild - frame),
                               rmse=rmse, affine_rmse=affine, bias=bias,
                               artefact_std=artefact_std(scene, image, mask))
                    rows.append(row)
                    print("  ours %-9s res %3d (%s) fetch %.1f: %.1f ms (plain %.1f), rmse %.4f "
                          "affine %.4f bias %+.4f artefact %s" %
                          (row["splat"], res, row["dims"], fetch, 1e3 * frame, 1e3 * plain, rmse,
                           affine, bias, row["artefact_std"]), flush=True)
                    if res == 0 and fetch == 0.5:
                        panels[(name, row["splat"])] = image

        ssao = vtkSSAOPass()
        ssao.SetDelegatePass(vtkRenderStepsPass())
        ssao.BlurOn()
        scene.renderer.SetPass(ssao)
        radii = [1.0, 2.0, 4.0, 8.0]
        kernels = [8, 32, 128]
        if args.quick:
            radii, kernels = [2.0], [32]
        for radius_factor in radii:
            for kernel in kernels:
                radius = radius_factor * scene.mean_radius
                ssao.SetRadius(radius)
                ssao.SetKernelSize(kernel)
                ssao.SetBias(0.01 * scene.mean_radius)
                frame = scene.timed()
                image = scene.image()
                rmse, affine, bias = errors(image, ref, mask)
                row = dict(base, method="ssao", ssao_radius=radius, ssao_kernel=kernel,
                           frame_s=frame, rmse=rmse, affine_rmse=affine, bias=bias,
                           artefact_std=artefact_std(scene, image, mask))
                rows.append(row)
                print("  ssao radius %.2f kernel %3d: %.1f ms, rmse %.4f affine %.4f bias %+.4f"
                      % (radius, kernel, 1e3 * frame, rmse, affine, bias), flush=True)
                if radius_factor == 2.0 and kernel == 32:
                    panels[(name, "ssao")] = image
        scene.renderer.SetPass(None)
        panels[(name, "none")] = plain_image

    fields = ["scene", "particles", "size", "method", "splat", "resolution", "dims", "voxel",
              "fetch", "ssao_radius", "ssao_kernel", "frame_s", "plain_frame_s", "build_s",
              "rmse", "affine_rmse", "bias", "artefact_std", "reference_samples",
              "reference_distance"]
    with open(os.path.join(args.out, "ao_accuracy.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow(row)
    volume_uniformity(os.path.join(args.data, "fcc_block.vtp"), args.out)
    plot(rows, panels, args.out, [s for s, _ in scenes])


def volume_uniformity(path, out):
    """The artefact in the volume itself: the coefficient of variation of the density over the
    FCC block's interior voxels (2 voxels clear of its faces and of the cylinder of smaller atoms,
    where the crystal is uniform), per splat and resolution -> ao_fcc_volume.csv"""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    radius = data.GetPointData().GetArray("radius")
    r = vtk_to_numpy(radius)
    xyz = vtk_to_numpy(data.GetPoints().GetData())
    small = xyz[r < 0.45]  # the cylinder (type 2, radius 0.4) along z
    axis = small[:, :2].mean(axis=0)
    cylinder = np.sqrt(((small[:, :2] - axis) ** 2).sum(axis=1)).max()
    lattice = (4.0 / 1.07) ** (1.0 / 3.0)
    with open(os.path.join(out, "ao_fcc_volume.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["splat", "resolution", "dims", "voxel", "voxel_per_lattice",
                         "interior_voxels", "mean", "cv", "min", "max"])
        for splat in (0, 1):
            for res in (0, 8, 10, 12, 16, 20, 24, 32):
                v = pr.vtkParticleDensityVolume()
                v.SetSplatMode(splat)
                v.SetResolution(res)
                v.SetUpGrid(data.GetBounds(), float(r.mean()))
                v.ComputeOnCPU(data.GetPoints().GetData(), radius)
                d = v.GetDimensions()
                e = v.GetVoxelSize()
                o = v.GetOrigin()
                a = np.array(v.GetVolume()).reshape(d[2], d[1], d[0])
                z, y, x = np.meshgrid(*[o[k] + (np.arange(d[k]) + 0.5) * e for k in (2, 1, 0)],
                                      indexing="ij")
                b = data.GetBounds()
                inside = ((x > b[0] + 2 * e) & (x < b[1] - 2 * e) & (y > b[2] + 2 * e) &
                          (y < b[3] - 2 * e) & (z > b[4] + 2 * e) & (z < b[5] - 2 * e) &
                          (np.sqrt((x - axis[0]) ** 2 + (y - axis[1]) ** 2) > cylinder + 2 * e))
                values = a[inside]
                if values.size < 8:
                    continue
                writer.writerow(["trilinear" if splat else "nearest", res,
                                 "%dx%dx%d" % d, e, e / lattice, values.size, values.mean(),
                                 values.std() / values.mean(), values.min(), values.max()])


def plot(rows, panels, out, scenes):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(scenes), 3, figsize=(18, 4.8 * len(scenes)), squeeze=False)
    for i, name in enumerate(scenes):
        mine = [r for r in rows if r["scene"] == name]
        plain = [r for r in mine if r["method"] == "none"][0]
        for j, (key, rebuild) in enumerate([("rmse", False), ("affine_rmse", False),
                                            ("affine_rmse", True)]):
            ax = axes[i][j]

            def t(r):
                return 1e3 * (r["frame_s"] + (r.get("build_s", 0.0) if rebuild else 0.0))
            for splat, marker in (("trilinear", "o"), ("nearest", "x")):
                for fetch, colour in ((0.5, "tab:green"), (1.0, "tab:blue"), (2.0, "tab:purple")):
                    pts = sorted([r for r in mine if r["method"] == "density-volume" and
                                  r["splat"] == splat and r["fetch"] == fetch and
                                  r["resolution"] != 0], key=lambda r: r["resolution"])
                    if not pts:
                        continue
                    ax.plot([t(r) for r in pts], [r[key] for r in pts],
                            marker=marker, color=colour, linestyle="-" if splat == "trilinear"
                            else ":", label="ours %s, fetch %.1f voxel" % (splat, fetch))
                    for r in pts:
                        ax.annotate(str(r["resolution"]), (t(r), r[key]), fontsize=6)
            auto = [r for r in mine if r["method"] == "density-volume" and r["resolution"] == 0
                    and r["fetch"] == 0.5 and r["splat"] == "trilinear"]
            if auto:
                ax.plot([t(auto[0])], [auto[0][key]], "*", color="red",
                        markersize=14, label="ours, defaults")
            ss = [r for r in mine if r["method"] == "ssao"]
            for kernel, marker in ((8, "v"), (32, "s"), (128, "^")):
                pts = sorted([r for r in ss if r["ssao_kernel"] == kernel],
                             key=lambda r: r["ssao_radius"])
                if pts:
                    ax.plot([1e3 * r["frame_s"] for r in pts], [r[key] for r in pts],
                            marker=marker, color="tab:orange", linestyle="--",
                            label="vtkSSAOPass kernel %d (radius 1-8 mean radii)" % kernel)
            ax.axhline(plain[key], color="grey", linestyle="-.", label="no AO")
            ax.axvline(1e3 * plain["frame_s"], color="grey", linewidth=0.5)
            ax.set_xlabel("frame time [ms] (%s, llvmpipe)" %
                          ("volume rebuilt every frame: time series" if rebuild
                           else "static scene"))
            ax.set_ylabel(key.replace("_", " ") + " of A vs ray-traced AO")
            ax.set_title("%s: %s" % (name, "raw error" if key == "rmse" else
                                     "error after the best affine map of A"))
            ax.set_ylim(bottom=0)
            if i == 0 and j == 0:
                ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "ao_accuracy.png"), dpi=110)

    if ("fcc", "reference") in panels:
        mask = panels[("fcc", "mask")]
        keys = [("none", "no AO"), ("reference", "ray traced (reference)"),
                ("nearest", "nearest-voxel splat (paper)"), ("trilinear", "trilinear splat (default)"),
                ("ssao", "vtkSSAOPass")]
        keys = [k for k in keys if ("fcc", k[0]) in panels]
        fig, axes = plt.subplots(1, len(keys), figsize=(3.2 * len(keys), 3.6))
        for ax, (key, title) in zip(axes, keys):
            ax.imshow(stretch(panels[("fcc", key)], mask), cmap="gray", vmin=0, vmax=1)
            ax.set_title(title, fontsize=8)
            ax.axis("off")
        fig.suptitle("FCC block, +x face, automatic resolution, fetch 0.5 voxel; "
                     "contrast 1 - 4(1 - A)", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "ao_fcc_artefact.png"), dpi=110)


if __name__ == "__main__":
    main()
