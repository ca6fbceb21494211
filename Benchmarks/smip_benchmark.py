"""The S-MIP of vtkSNDFRenderPass (paper Sec. 6, Table 2 style; llvmpipe, one run per scene).

Scenes, seen whole in parallel projection at WIDTHxHEIGHT (1280x720), headlight:
- crystal: an fcc crystal of two species (CELLS^3 unit cells, 4 atoms each, radius 0.36 lattice
  constants; CELLS 63: 1 000 188 atoms);
- liquid: the LAMMPS LJ liquid film of Testing/Data/lj_film.vtp (19 360 atoms, periodic in x and
  y) repeated REPEAT x REPEAT times over its periodic box (REPEAT 8: 1 239 040 atoms), radius
  from its `radius` array, coloured by type, seen obliquely from above.

Measured in the same run, per scene:
- plain: a frame of the core without the pass (mean of 3);
- sample pass: a refinement frame with one sample (mean over the samples of the first view);
- level 0 over the 2 x 2 views around the centre: each converged to SAMPLES samples (pans by
  half a view: whole pixels);
- zoom out: the parallel scale doubled about the centre: the frame that averages level 1 from
  the cached level 0 (no sample: every texel's finer texels are there), against re-sampling
  level 1 to the same SAMPLES samples (SAMPLES sample passes of a pass started at level 1, timed)
  and the accuracy of the averaged level against that directly rendered one (mean, p99, max /255);
- pan back: the parallel scale halved again and a pan to one of the four views: the frame that
  shows the cached tiles, against a restart's frame;
- re-light: a light change at level 1 (table, tiles rebaked, shade);
- the cache: its slots, tiles and MB.

usage: Scripts/with_xvfb.sh /usr/bin/python3 Benchmarks/smip_benchmark.py [CELLS REPEAT WIDTH HEIGHT SAMPLES]
(PYTHONPATH=build/lib/python3/dist-packages:Testing/VTKPython); appends to
Benchmarks/results/smip_timings.csv and draws smip_timings.png from all its rows.
(another directory: PR_BENCHMARK_RESULTS=DIR; Benchmarks/run.py --out sets it)
"""
import os
import sys
import time

import numpy as np

import particlerendering as pr
from prVTKTesting import crystal_view, fcc_crystal, image_error, pan_camera, window_pixels
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import vtkLight

here = os.path.dirname(os.path.abspath(__file__))
# PR_BENCHMARK_RESULTS (set by Benchmarks/run.py --out) overrides the results directory
results = os.environ.get("PR_BENCHMARK_RESULTS") or os.path.join(here, "results")


def liquid(n):
    """lj_film.vtp repeated n x n times over its periodic box: positions, colours, radii."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(here, "..", "Testing", "Data", "lj_film.vtp"))
    reader.Update()
    data = reader.GetOutput()
    xyz = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
    kind = vtk_to_numpy(data.GetPointData().GetArray("type"))
    radius = vtk_to_numpy(data.GetPointData().GetArray("radius"))
    box = vtk_to_numpy(data.GetFieldData().GetArray("BoxBounds")).reshape(-1)
    lx, ly = box[1] - box[0], box[3] - box[2]
    shifts = np.array([(i * lx, j * ly, 0.0) for i in range(n) for j in range(n)])
    xyz = (xyz[None, :, :] + shifts[:, None, :]).reshape(-1, 3)
    palette = np.array([[70, 130, 200], [230, 150, 60]], np.uint8)
    rgb = np.tile(palette[np.clip(kind - 1, 0, 1)], (n * n, 1))
    return xyz, rgb, np.tile(radius, n * n).astype(np.float32)


def timed(window):
    t = time.perf_counter()
    window.Render()
    window.GetRGBACharPixelData(0, 0, 0, 0, 0)  # wait for the GPU
    return time.perf_counter() - t


def make_view(scene, sndf, size=None, zoom=1.0):
    """The scene in a window of `size` (default width x height) with its parallel scale divided by
    `zoom` (a window of half the size with zoom 2 shows the centre of the full view at the same
    pixel size)."""
    xyz, rgb, radii, position, focal, scale = scene
    renderer, window, actor = crystal_view(xyz, rgb, size or (width, height), sndf,
                                           position=position, focal_point=focal)
    if radii is not None:
        mapper = actor.GetMapper()
        array = numpy_to_vtk(radii, deep=True)
        array.SetName("radius")
        mapper.GetInput().GetPointData().AddArray(array)
        mapper.SetRadiusArrayName("radius")
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetParallelScale(scale / zoom)
    renderer.ResetCameraClippingRange()
    return renderer, window


def pan(camera, right, up, view_height=None):
    pan_camera(camera, right, up, view_height or height)


def converge(sndf, window):
    times = [timed(window)]  # (GetConverged() speaks of the view before the change until then)
    while not sndf.GetConverged():
        times.append(timed(window))
    return times


def measure(name, scene, samples):
    renderer, window = make_view(scene, None)
    timed(window)
    plain = np.mean([timed(window) for _ in range(3)])

    sndf = pr.vtkSNDFRenderPass()
    sndf.SetSamplesPerFrame(1)
    sndf.SetTargetSamples(samples)
    sndf.SetMaximumMemory(4000)  # level 0 over four views and level 1: five views of tiles
    renderer, window = make_view(scene, sndf)
    camera = renderer.GetActiveCamera()
    timed(window)  # the frame of the change
    # level 0 over the 2 x 2 views around the centre (the first one times the sample pass)
    offsets = [(-width // 2, -height // 2), (width, 0), (0, height), (-width, 0)]
    sample = None
    for k, (dx, dy) in enumerate(offsets):
        pan(camera, dx, dy)
        times = converge(sndf, window)
        if k == 0:
            sample = np.mean(times[2:])  # (the first: the change, the second builds programs)
    pan(camera, width // 2, -height // 2)  # back to the centre
    cache = sndf.GetTileCache()
    averaged = cache.GetNumberOfDownsampledTiles()
    camera.SetParallelScale(2.0 * camera.GetParallelScale())
    passes = sndf.GetNumberOfSamplePasses()
    zoom = timed(window)
    averaged = cache.GetNumberOfDownsampledTiles() - averaged
    assert sndf.GetNumberOfSamplePasses() == passes and sndf.GetConverged(), "the zoom sampled"
    zoomed = window_pixels(window, width, height)
    tiles, slots, memory = cache.GetNumberOfTiles(), cache.GetNumberOfSlots(), cache.GetBytes() / 2**20

    light = vtkLight()
    light.SetLightTypeToCameraLight()
    light.SetPosition(1, 0.5, 0.4)
    renderer.RemoveAllLights()
    renderer.AddLight(light)
    relight = timed(window)

    camera.SetParallelScale(0.5 * camera.GetParallelScale())
    pan(camera, -width // 2, -height // 2)
    passes = sndf.GetNumberOfSamplePasses()
    back = timed(window)
    assert sndf.GetNumberOfSamplePasses() == passes, "the pan back sampled"
    camera.Azimuth(1)
    restart = timed(window)

    # level 1 rendered directly: re-sampling to the same quality
    direct = pr.vtkSNDFRenderPass()
    direct.SetSamplesPerFrame(1)
    direct.SetTargetSamples(samples)
    direct_renderer, direct_window = make_view(scene, direct)
    direct_camera = direct_renderer.GetActiveCamera()
    direct_camera.SetParallelScale(2.0 * direct_camera.GetParallelScale())
    timed(direct_window)
    resample = sum(converge(direct, direct_window))
    level1 = window_pixels(direct_window, width, height)
    accuracy = image_error(zoomed, level1)
    return [name, len(scene[0]), width, height, samples, plain, sample, averaged, zoom, resample,
            resample / zoom, accuracy[0], accuracy[1], accuracy[2], back, restart, relight,
            tiles, slots, memory]


def make_scenes(cells, repeat):
    """[(name, (xyz, rgb, radii, camera position, focal point, parallel scale))]: the crystal
    and the liquid seen whole (the parallel scale for a view `height` pixels high)."""
    scenes = []
    xyz, rgb = fcc_crystal(cells)
    scenes.append(("crystal", (xyz, rgb, None, (2.5 * cells, 1.9 * cells, 3.4 * cells),
                               (cells / 2, cells / 2, cells / 2), 0.6 * cells)))
    lxyz, lrgb, lradii = liquid(repeat)
    centre = 0.5 * (lxyz.min(axis=0) + lxyz.max(axis=0))
    extent = lxyz.max(axis=0) - lxyz.min(axis=0)
    scenes.append(("liquid", (lxyz, lrgb, lradii,
                              tuple(centre + np.array([0.3, -0.9, 1.0]) * extent[0]),
                              tuple(centre), 0.3 * extent[0])))
    return scenes


# the view size the helpers use (set by main(); smip_quality.py sets its own)
width, height = 1280, 720


def main():
    global width, height
    args = sys.argv[1:6] + ["63", "8", "1280", "720", "64"][len(sys.argv[1:6]):]
    cells, repeat, width, height, samples = (int(a) for a in args)
    run(make_scenes(cells, repeat), samples)


def run(scenes, samples):
    header = ("scene,particles,width,height,samples,plain_s,sample_pass_s,zoom_tiles_averaged,"
              "zoom_out_s,resample_level1_s,resample_over_zoom,zoom_mean_255,zoom_p99_255,"
              "zoom_max_255,pan_back_s,restart_s,relight_s,cache_tiles,cache_slots,cache_MB\n")
    path = os.path.join(results, "smip_timings.csv")
    for name, scene in scenes:
        row = measure(name, scene, samples)
        new = not os.path.exists(path)
        with open(path, "a") as f:
            if new:
                f.write(header)
            f.write(",".join("%.6g" % v if isinstance(v, (float, np.floating)) else str(v) for v in row) + "\n")
        print(header.strip())
        print(",".join(str(v) for v in row), flush=True)

    # the plot: per scene, the frame times of each operation (last row per scene)
    import csv

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            rows[r["scene"]] = r
    ops = [("plain frame", "plain_s"), ("one sample pass", "sample_pass_s"),
           ("zoom out (averaged)", "zoom_out_s"), ("re-sample level 1", "resample_level1_s"),
           ("pan back (cached)", "pan_back_s"), ("restart (plain)", "restart_s"),
           ("re-light", "relight_s")]
    fig, ax = plt.subplots(figsize=(9, 4.5))
    w = 0.8 / max(1, len(rows))
    for k, (name, r) in enumerate(rows.items()):
        ax.bar(np.arange(len(ops)) + k * w, [float(r[c]) for _, c in ops], w,
               label="%s (%s atoms)" % (name, r["particles"]))
    ax.set_xticks(np.arange(len(ops)) + w * (len(rows) - 1) / 2)
    ax.set_xticklabels([o for o, _ in ops], rotation=20, ha="right")
    ax.set_yscale("log")
    ax.set_ylabel("seconds (llvmpipe)")
    ax.set_title("S-MIP operations at %sx%s, %s samples per pixel" % (width, height, samples))
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(results, "smip_timings.png"), dpi=100)


if __name__ == "__main__":
    main()
