"""Frame and stage times of transparency + voxel-cone ambient occlusion (Staib et al. 2015,
Tables 2 and 3) on llvmpipe, against the opaque core in the same window.

Scene: the LAMMPS droplets (Testing/Data/lj_droplets.vtp) tiled k x k x k (k = 1, 2, 4: 1.1e4,
8.8e4, 7.1e5 atoms), translucency from the local density as in voxel_cone_translucent_study.py,
coloured by type, 640 x 480. Modes, each in a fresh renderer of the same window:
  opaque             vtkParticleSphereMapper (the paper's "local lighting")
  transparent        vtkTransparentSphereMapper (sorted every frame the camera moves)
  transparent+vc     the same with vtkVoxelConeAOPass, per fragment (the defaults)
  transparent+vc-ps  the same, per-sphere retrieval
  transparent+vc-cpu per fragment, the volume voxelised on the CPU and uploaded
                     (GPUVoxelisation off) instead of in compute shaders
Per mode: the first frame, the median of FRAMES frames of a rotating camera (1 degree per frame:
sort + trace, no voxelisation), a static camera, and a time series (the positions marked modified
every frame: voxelise + mips + upload + sort + trace). Stages (last time-series frame): gather,
voxelise, mip, upload (vtkParticleAmbientVolume's wall times, each finished with glFinish; on the
GPU "upload" is the spheres' and "mip" includes storing the levels into the texture), sort (GPU timer query of the
depth sort), trace = rotating(transparent+vc) - rotating(transparent). ratio_vs_opaque =
rotating frame / the opaque core's rotating frame.

usage: /usr/bin/python3 Benchmarks/voxel_cone_benchmark.py --data Testing/Data \
           --out Benchmarks/results [--tiles 1 2 4] [--frames 5]
       (PYTHONPATH=<build>/lib/python3/dist-packages:Benchmarks, under Xvfb)
writes voxel_cone_benchmark.csv and voxel_cone_benchmark.png
"""
import argparse
import csv
import os
import statistics
import time

import numpy as np

import particlerendering as pr
from voxel_cone_translucent_study import density_opacity
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)

MODES = ("opaque", "transparent", "transparent+vc", "transparent+vc-ps", "transparent+vc-cpu")


def tiled(path, k):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    xyz = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
    radius = vtk_to_numpy(data.GetPointData().GetArray("radius")).astype(np.float32)
    kind = vtk_to_numpy(data.GetPointData().GetArray("type")).astype(np.float32)
    theta = density_opacity(data, float(radius.mean())).astype(np.float32)
    size = xyz.max(axis=0) - xyz.min(axis=0)
    shifts = [np.array([i, j, l]) * size for i in range(k) for j in range(k) for l in range(k)]
    out = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.concatenate([xyz + s for s in shifts]), deep=True))
    out.SetPoints(points)
    for name, values in (("radius", radius), ("type", kind), ("opacity", theta)):
        array = numpy_to_vtk(np.tile(values, len(shifts)), deep=True)
        array.SetName(name)
        out.GetPointData().AddArray(array)
    return out


def make_renderer(data, mode):
    transparent = mode != "opaque"
    mapper = pr.vtkTransparentSphereMapper() if transparent else pr.vtkParticleSphereMapper()
    mapper.SetInputData(data)
    mapper.SetRadiusArrayName("radius")
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("type")
    lut = vtkLookupTable()
    lut.SetNumberOfTableValues(2)
    lut.SetTableValue(0, 0.85, 0.33, 0.10)
    lut.SetTableValue(1, 0.12, 0.47, 0.80)
    lut.SetTableRange(1, 2)
    mapper.SetLookupTable(lut)
    mapper.UseLookupTableScalarRangeOn()
    if transparent:
        mapper.SetOpacityArrayName("opacity")
        mapper.SetOpacityRange(0.0, 1.0)
        mapper.CollectTimingsOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.32, 0.34, 0.43)
    aopass = None
    if mode.startswith("transparent+vc"):
        aopass = pr.vtkVoxelConeAOPass()
        aopass.SetDelegatePass(vtkRenderStepsPass())
        aopass.SetRetrievalMode(1 if mode.endswith("-ps") else 0)
        aopass.GetAmbientVolume().SetGPUVoxelisation(not mode.endswith("-cpu"))
        renderer.SetPass(aopass)
    return renderer, mapper, aopass


def frame(window):
    start = time.perf_counter()
    window.Render()
    window.GetZbufferDataAtPoint(0, 0)  # waits for the GPU
    return time.perf_counter() - start


def measure(window, data, mode, frames):
    renderer, mapper, aopass = make_renderer(data, mode)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    b = data.GetBounds()
    centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
    camera.SetFocalPoint(*centre)
    camera.SetPosition(centre[0], centre[1] - 1.9 * (b[3] - b[2]), centre[2])
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    row = dict(mode=mode, first_frame_s=frame(window))
    rotating = []
    for _ in range(frames):
        camera.Azimuth(1.0)
        renderer.ResetCameraClippingRange()
        rotating.append(frame(window))
    row["rotating_s"] = statistics.median(rotating)
    row["static_s"] = statistics.median([frame(window) for _ in range(frames)])
    series = []
    for _ in range(max(2, frames // 2)):
        data.GetPoints().Modified()
        series.append(frame(window))
    row["series_s"] = statistics.median(series)
    if mode != "opaque":
        row["sort_gpu_s"] = mapper.GetLastSortGPUSeconds()
    if aopass is not None:
        volume = aopass.GetAmbientVolume()
        row.update(gather_s=volume.GetLastGatherSeconds(),
                   voxelise_s=volume.GetLastVoxeliseSeconds(),
                   mip_s=volume.GetLastMipSeconds(), upload_s=volume.GetLastUploadSeconds(),
                   dims="%dx%dx%d" % volume.GetDimensions(),
                   texture_mb=volume.GetTextureBytes() / 1e6,
                   builds=aopass.GetNumberOfVolumeBuilds(),
                   on_gpu=int(volume.GetLastBuildOnGPU()))
    window.RemoveRenderer(renderer)
    renderer.ReleaseGraphicsResources(window)
    return row


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--tiles", type=int, nargs="+", default=[1, 2, 4])
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--size", default="640x480")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    width, height = (int(v) for v in args.size.split("x"))
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    rows = []
    for k in args.tiles:
        data = tiled(os.path.join(args.data, "lj_droplets.vtp"), k)
        results = {}
        for mode in MODES:
            row = measure(window, data, mode, args.frames)
            row.update(particles=data.GetNumberOfPoints(), size=args.size)
            results[mode] = row
            rows.append(row)
        for mode, row in results.items():
            row["ratio_vs_opaque"] = row["rotating_s"] / results["opaque"]["rotating_s"]
            if mode.startswith("transparent+vc"):
                row["trace_s"] = row["rotating_s"] - results["transparent"]["rotating_s"]
            print("%8d %-18s first %7.3f s  rotating %7.3f s (%.1fx opaque)  static %7.3f s  "
                  "series %7.3f s  %s" % (
                      row["particles"], mode, row["first_frame_s"], row["rotating_s"],
                      row["ratio_vs_opaque"], row["static_s"], row["series_s"],
                      " ".join("%s %.3f" % (key, row[key]) for key in (
                          "sort_gpu_s", "gather_s", "voxelise_s", "mip_s", "upload_s", "trace_s")
                          if key in row)), flush=True)
    fields = ["particles", "size", "mode", "first_frame_s", "rotating_s", "static_s", "series_s",
              "ratio_vs_opaque", "sort_gpu_s", "gather_s", "voxelise_s", "mip_s", "upload_s",
              "trace_s", "dims", "texture_mb", "builds", "on_gpu"]
    with open(os.path.join(args.out, "voxel_cone_benchmark.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow(row)
    plot(rows, args.out)


def plot(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    counts = sorted({r["particles"] for r in rows})
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8))
    ax = axes[0]
    for mode, colour in zip(MODES, ("tab:gray", "tab:blue", "tab:red", "tab:orange",
                                    "tab:purple")):
        pts = sorted([r for r in rows if r["mode"] == mode], key=lambda r: r["particles"])
        ax.plot([r["particles"] for r in pts], [r["rotating_s"] for r in pts], "o-",
                color=colour, label=mode + " (rotating)")
        ax.plot([r["particles"] for r in pts], [r["series_s"] for r in pts], "x--",
                color=colour, label=mode + " (time series)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("particles")
    ax.set_ylabel("frame time [s] (llvmpipe, 640x480)")
    ax.legend(fontsize=7)
    ax = axes[1]
    stages = ("sort_gpu_s", "gather_s", "voxelise_s", "mip_s", "upload_s", "trace_s")
    vc = sorted([r for r in rows if r["mode"] in ("transparent+vc", "transparent+vc-cpu")],
                key=lambda r: (r["particles"], r["mode"]))
    labels = ["%d\n%s" % (r["particles"], "CPU" if r["mode"].endswith("-cpu") else "GPU")
              for r in vc]
    bottom = np.zeros(len(vc))
    for stage in stages:
        values = np.array([max(0.0, float(r.get(stage, 0.0) or 0.0)) for r in vc])
        ax.bar(labels, values, bottom=bottom, label=stage[:-2])
        bottom += values
    ax.set_ylabel("seconds per stage (time-series frame; trace from the rotating frames)")
    ax.set_xlabel("particles, voxelised on the GPU (compute) or the CPU (per fragment)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "voxel_cone_benchmark.png"), dpi=110)


if __name__ == "__main__":
    main()
