"""Every ParticleRendering technique on the bundled LAMMPS data, through ParaView (pvpython with
the plugin), with each picture's cost and error measured in the same run.

usage: pvpython render_samples.py --plugin ParticleRendering.so --data Testing/Data --out DIR
           [--quick | --full] [--size WxH] [--frames N] [--ao-rays N] [--only NAME,...]
           [--results DIR]
       pvpython render_samples.py --check [--self-test] --out DIR
(PYTHONPATH must hold <build>/lib/python3/dist-packages for the reference renderer;
Scripts/render_samples.sh sets everything up.) Exit status 1 when a picture failed (it is
reported, and the others are still made) or, with --check, when the output is incomplete.

Data, opened the way a user opens it: the droplet trajectory lj_droplets.lammpstrj.gz (5 steps,
11 033 atoms) through the LAMMPS Dump Reader, the crystal fcc_block.data.gz (32 000 atoms) through
the LAMMPS Data Reader, both with Type Radii 1 -> 0.5, 2 -> 0.4 sigma; the film lj_film.vtp (19 360
atoms, the AO scene) through ParaView's XML reader; the Gay-Berne rods gb_ellipsoids.lammpstrj.gz
(1440 ellipsoids, atom_style ellipsoid, last of 3 steps) through the LAMMPS Dump Reader, drawn as
oriented ellipsoids by Shape Automatic. Every picture is a Particle Render View with one Particles
representation, coloured by atom type; the space-filling ("molecule-like") scene and the rods are
coloured by speed, so that overlapping neighbours differ in colour.

Per picture (DIR/<name>.png, one tile of DIR/contact_sheet.png, one row of DIR/samples.csv and
DIR/samples.md):
- frame_s: the median wall-clock time of still renders (simple.Render) with the camera turned by
  2 degrees before each (what a user waits for after letting go of the mouse), over `frames`
  renders (at least the mode's count, more until they took 0.5 s); vs_core: that over
  the opaque core's frame of the same scene at the same size, measured in this process;
- error_max, error_mean (1/255, over all pixels and RGB channels) and share_over_2 (pixels whose
  largest channel error exceeds 2/255) against the reference: ParticleRendering's double-precision
  CPU ray caster (vtkParticleReferenceRenderer) on the same mapper, camera and lights --
  opaque, emission-absorption (the exact overlap integral), metaball surface, or ray-traced
  ambient occlusion applied as in Staib et al. Eq. 7 (one reference for the film serves its four
  AO pictures); for the crystal the plain core super-sampled S x S per pixel (S-NDF's target).
The reference images are written to DIR/reference/.
"""
import argparse
import collections
import csv
import math
import os
import platform
import statistics
import sys
import time

import numpy as np
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkSMPTools
from vtkmodules.vtkIOImage import vtkPNGReader

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from prPictures import window_rgb, write_png  # noqa: E402

# tile size; timed frames: at least `frames`, and more (up to 60) until they took `min_time`
# seconds (a 15 ms frame is timed over ~30 frames); AO reference rays per pixel; the S-NDF
# reference's super-sampling per axis
MODES = {
    "quick": dict(size=(240, 180), frames=1, min_time=0.0, ao_rays=32, supersample=4),
    "default": dict(size=(400, 300), frames=5, min_time=0.5, ao_rays=256, supersample=8),
    "full": dict(size=(640, 480), frames=9, min_time=1.0, ao_rays=1024, supersample=16),
}
TYPE_RADII = [1, 0.5, 2, 0.4]
BACKGROUND = [0.12, 0.12, 0.16]
TYPE_COLOURS = [0.85, 0.35, 0.20, 0.20, 0.55, 0.90]

# scene -> how it is opened and looked at: file, reader, type radii, time step (index), direction
# from the focal point to the camera, zoom
SCENES = {
    "droplets": dict(file="lj_droplets.lammpstrj.gz", reader="dump", step=-1,
                     direction=(1.0, -1.6, 0.9), zoom=2.2, what="LAMMPS dump, step 5 of 5"),
    "droplets, close": dict(file="lj_droplets.lammpstrj.gz", reader="dump", step=-1,
                            direction=(1.0, -1.6, 0.9), zoom=5.0, what="LAMMPS dump, step 5 of 5"),
    "droplets t0": dict(file="lj_droplets.lammpstrj.gz", reader="dump", step=0,
                        direction=(1.0, -1.6, 0.9), zoom=2.2, what="LAMMPS dump, step 1 of 5"),
    # space-filling radii (0.8 / 0.65 sigma at ~1.1 sigma spacing): every atom overlaps its
    # neighbours like the van der Waals spheres of a molecule
    # space-filling radii (0.8 / 0.65 sigma at ~1.1 sigma spacing): every atom overlaps its
    # neighbours like the van der Waals spheres of a molecule; coloured by speed so that
    # overlapping neighbours differ in colour (where sorting whole spheres is wrong)
    "molecule-like": dict(file="lj_droplets.lammpstrj.gz", reader="dump", step=-1,
                          radii=[1, 0.8, 2, 0.65], colour="speed", direction=(1.0, -1.6, 0.9),
                          zoom=4.0, what="LAMMPS dump, radii 0.8/0.65"),
    "film": dict(file="lj_film.vtp", reader="vtp", direction=(1.0, -1.8, 0.6), zoom=1.4,
                 what="VTK XML"),
    "crystal": dict(file="fcc_block.data.gz", reader="data", direction=(1.2, -1.5, 1.0),
                    zoom=0.8, what="LAMMPS data file"),
    # atom_style ellipsoid: Shape Automatic draws the reader's semi_axes and orientation
    "rods": dict(file="gb_ellipsoids.lammpstrj.gz", reader="dump", step=-1, colour="speed",
                 direction=(1.0, -1.6, 0.5), zoom=1.25, what="LAMMPS dump, ellipsoids"),
}

# name: the file name; label: what the picture shows; scene: a key of SCENES; settings: display.X
# and view.X properties; reference: "opaque", "transparent", "transparent exact" (the exact
# overlap integral whatever the mapper's mode), "metaballs", "ao" (ray-traced AO of the scene),
# "supersampled"; use: when to choose it (the table's last column)
Tile = collections.namedtuple("Tile", "name label scene settings reference use")
TILES = [
    Tile("core", "Spheres (opaque core)", "droplets", {}, "opaque",
         "any particle data: every atom an exact sphere with true depth"),
    Tile("translucent_constant", "Translucent, constant density", "droplets, close",
         {"display.Opacity": 0.5, "display.DensityModel": "Constant"}, "transparent",
         "see into a dense liquid; opacity per atom from an array"),
    Tile("translucent_squared", "Translucent, squared-distance density", "droplets, close",
         {"display.Opacity": 0.5, "display.DensityModel": "Squared Distance"}, "transparent",
         "glyphs densest at the rim: outlines of single atoms read better"),
    Tile("translucent_hollow", "Translucent, hollow (core 0.6 r)", "droplets, close",
         {"display.Opacity": 0.5, "display.DensityModel": "Constant",
          "display.HollowFraction": 0.6}, "transparent",
         "shells only: what lies behind a crowd of atoms stays visible"),
    Tile("overlap_sorted", "Overlapping, sorted spheres", "molecule-like",
         {"display.Opacity": 0.5, "display.OverlapCompositing": "Sorted Spheres"},
         "transparent exact", "translucent atoms that overlap little (what Automatic picks then)"),
    Tile("overlap_exact", "Overlapping, exact overlap", "molecule-like",
         {"display.Opacity": 0.5, "display.OverlapCompositing": "Exact Overlap"},
         "transparent exact", "space-filling models: deeply overlapping translucent atoms"),
    Tile("film_plain", "Film, no AO (against AO)", "film", {}, "ao",
         "(what AO adds: the same view without it)"),
    Tile("ao_density", "Density-volume AO", "film",
         {"view.ParticleAmbientOcclusion": "Density Volume"}, "ao",
         "contact shadows that show the shape of dense opaque clusters; the cheapest AO"),
    Tile("ao_voxel_cone", "Voxel-cone AO", "film",
         {"view.ParticleAmbientOcclusion": "Voxel Cone Tracing"}, "ao",
         "far-reaching occlusion that sees translucency; coloured ambient light"),
    Tile("ao_point", "PointAO (screen space)", "film",
         {"view.ParticleAmbientOcclusion": "PointAO"}, "ao",
         "any opaque geometry in view; nothing built per time step"),
    Tile("metaballs_vicinity", "Metaballs, vicinity", "droplets",
         {"display.Technique": "Metaballs", "display.MetaballMethod": "Vicinity"}, "metaballs",
         "smooth merged surfaces of droplets, clusters and molecules"),
    Tile("metaballs_walking", "Metaballs, walking depth plane", "droplets",
         {"display.Technique": "Metaballs", "display.MetaballMethod": "Walking Depth Plane"},
         "metaballs", "no neighbour lists, OpenGL 3.3; may miss a surface thinner than a step"),
    Tile("crystal_plain", "Crystal, one ray per pixel", "crystal", {}, "supersampled",
         "(the plain picture S-NDF improves on)"),
    Tile("crystal_sndf", "Crystal, S-NDF", "crystal",
         {"view.ScaleConsistentShading": 1, "view.SNDFConvergeStillRenders": 1}, "supersampled",
         "atoms near or below a pixel: alias-free shading, refined while the view holds still"),
    Tile("time_step", "Time series, step 1 of 5", "droplets t0", {}, "opaque",
         "trajectories: the LAMMPS readers' time steps, Play in ParaView"),
    Tile("ellipsoids", "Ellipsoids (Gay-Berne rods)", "rods", {}, "opaque",
         "aspherical particles (atom_style ellipsoid): exact oriented ellipsoids"),
    Tile("ellipsoids_translucent", "Ellipsoids, translucent", "rods",
         {"display.Opacity": 0.9, "display.DensityModel": "Squared Distance"}, "transparent",
         "see into a liquid crystal: each rod's opacity along its length"),
    Tile("ellipsoids_ao", "Ellipsoids, voxel-cone AO", "rods",
         {"view.ParticleAmbientOcclusion": "Voxel Cone Tracing"}, "ao",
         "the depth of a dense packing of rods"),
]
# the opaque core of each scene: the picture that is the scene's core, or a core measured
# without a picture
CORE_TILE = {"droplets": "core", "film": "film_plain", "crystal": "crystal_plain",
             "droplets t0": "time_step", "rods": "ellipsoids"}


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--plugin")
    parser.add_argument("--data")
    parser.add_argument("--out", required=True)
    parser.add_argument("--check", action="store_true",
                        help="render nothing: check that --out holds every picture (not blank), "
                             "the contact sheet and a table row with numbers per picture")
    parser.add_argument("--self-test", action="store_true",
                        help="with --check: also check that the check rejects a blank, a missing "
                             "and a wrong-sized picture and a table row without a number")
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--quick", dest="mode", action="store_const", const="quick",
                       help="small pictures, one timed frame, fewer reference rays (~1 min)")
    group.add_argument("--full", dest="mode", action="store_const", const="full",
                       help="640x480, 9 timed frames, 1024 AO reference rays (a few minutes)")
    parser.add_argument("--size", help="tile size WxH (overrides the mode's)")
    parser.add_argument("--frames", type=int, help="timed frames per picture")
    parser.add_argument("--ao-rays", type=int, help="rays per pixel of the AO reference")
    parser.add_argument("--only", help="comma-separated picture names (for debugging)")
    parser.add_argument("--results", metavar="DIR",
                        help="also write the table and the small contact sheet to DIR as "
                             "samples.csv, samples.md and samples.png (Benchmarks/results)")
    args = parser.parse_args()
    if not args.check and not (args.plugin and args.data):
        parser.error("--plugin and --data are required to render")
    args.mode = args.mode or "default"
    settings = dict(MODES[args.mode])
    if args.size:
        settings["size"] = tuple(int(v) for v in args.size.lower().split("x"))
    if args.frames:
        settings["frames"] = args.frames
    if args.ao_rays:
        settings["ao_rays"] = args.ao_rays
    args.settings = settings
    return args


class Samples:
    def __init__(self, args):
        self.args = args
        self.size = args.settings["size"]
        self.readers = {}
        self.core_s = {}
        self.ao_reference = {}
        self.supersampled = {}
        self.rows = []
        self.tiles = []
        self.failed = []  # (picture, error) of the pictures that could not be made
        self.frames_timed = 0
        self.renderer_string = ""
        os.makedirs(os.path.join(args.out, "reference"), exist_ok=True)

    # --- data -------------------------------------------------------------------------------
    def reader(self, scene):
        spec = SCENES[scene]
        key = (spec["file"], tuple(spec.get("radii", TYPE_RADII)))
        if key not in self.readers:
            path = os.path.join(self.args.data, spec["file"])
            if not os.path.exists(path):
                raise RuntimeError("missing sample data %s (a clone without Testing/Data?)" % path)
            if spec["reader"] == "dump":
                reader = simple.LAMMPSDumpReader(FileNames=[path])
            elif spec["reader"] == "data":
                reader = simple.LAMMPSDataReader(FileName=path)
            else:
                reader = simple.XMLPolyDataReader(FileName=[path])
            if spec["reader"] != "vtp":
                reader.TypeRadii = spec.get("radii", TYPE_RADII)
            self.readers[key] = reader
        return self.readers[key]

    def time_of(self, scene, reader):
        step = SCENES[scene].get("step")
        if step is None:
            return None
        return reader.TimestepValues[step]

    # --- one view -----------------------------------------------------------------------------
    def open_view(self, scene, settings):
        spec = SCENES[scene]
        reader = self.reader(scene)
        view = simple.CreateView("ParticleRenderView")
        view.ViewSize = list(self.size)
        view.OrientationAxesVisibility = 0
        view.UseColorPaletteForBackground = 0
        view.Background = BACKGROUND
        simple.GetSettingsProxy("RenderViewSettings").UseFXAA = 0
        view.UseFXAA = 0
        t = self.time_of(scene, reader)
        if t is not None:
            view.ViewTime = t
        display = simple.Show(reader, view)
        display.Representation = "Particles"
        display.UseRadiusArray = 1
        display.RadiusArray = ["POINTS", "radius"]
        display.Specular = 0.3
        if spec.get("colour") == "speed":
            simple.ColorBy(display, ("POINTS", "velocity", "Magnitude"))
            lut = simple.GetColorTransferFunction("velocity")
            lut.ApplyPreset("Jet", True)
            lut.RescaleTransferFunction(0.0, 3.0)
            lut.AutomaticRescaleRangeMode = "Never"
        else:
            simple.ColorBy(display, ("POINTS", "type"))
            lut = simple.GetColorTransferFunction("type")
            lut.InterpretValuesAsCategories = 1
            lut.Annotations = ["1", "type 1", "2", "type 2"]
            lut.IndexedColors = TYPE_COLOURS
        display.LookupTable = lut
        for key, value in settings.items():
            owner, name = key.split(".")
            setattr(display if owner == "display" else view, name, value)
        simple.Render(view)  # the first render resets the camera: place it afterwards
        view.ResetCamera()
        camera = view.GetActiveCamera()
        focal = camera.GetFocalPoint()
        distance = camera.GetDistance()
        direction = spec["direction"]
        norm = math.sqrt(sum(d * d for d in direction))
        camera.SetPosition(*[f + 1.2 * distance * d / norm for f, d in zip(focal, direction)])
        camera.SetViewUp(0, 0, 1)
        view.ResetCamera()
        camera.Zoom(spec["zoom"])
        simple.Render(view)
        if not self.renderer_string:
            window = view.GetClientSideObject().GetRenderWindow()
            for line in window.ReportCapabilities().splitlines():
                if "OpenGL renderer string" in line:
                    self.renderer_string = line.split(":", 1)[1].strip()
        return view, display

    @staticmethod
    def grab(view):
        window = view.GetClientSideObject().GetRenderWindow()
        return window_rgb(window, finalize=False, rerender=False).astype(np.float64)

    def timed_frame(self, view):
        times = []
        settings = self.args.settings
        while len(times) < settings["frames"] or (
                sum(times) < settings["min_time"] and len(times) < 60):
            view.GetActiveCamera().Azimuth(2.0)
            start = time.perf_counter()
            simple.Render(view)
            times.append(time.perf_counter() - start)
        self.frames_timed = len(times)
        return statistics.median(times)

    # --- references ---------------------------------------------------------------------------
    @staticmethod
    def particle_actor(view):
        actors = view.GetClientSideObject().GetRenderer().GetActors()
        actors.InitTraversal()
        for _ in range(actors.GetNumberOfItems()):
            actor = actors.GetNextActor()
            mapper = actor.GetMapper()
            if actor.GetVisibility() and mapper is not None and (
                    mapper.IsA("vtkParticleSphereMapper") or
                    mapper.IsA("vtkTransparentSphereMapper")):
                return actor
        raise RuntimeError("no visible particle mapper in the view")

    def reference(self, view, kind):
        import particlerendering as pr  # the plugin's classes, wrapped for Python

        actor = self.particle_actor(view)
        renderer = pr.vtkParticleReferenceRenderer()
        renderer.SetRenderer(view.GetClientSideObject().GetRenderer())
        renderer.SetActor(actor)
        mapper = actor.GetMapper()
        restore = None
        if kind == "transparent exact" and mapper.IsA("vtkTransparentSphereMapper"):
            restore = mapper.GetOverlapCompositing()
            mapper.SetOverlapCompositing(mapper.EXACT_OVERLAP)
        if kind == "ao":
            renderer.SetAmbientOcclusionSamples(self.args.settings["ao_rays"])
            renderer.SetApplyAmbientOcclusion(True)
        try:
            if not renderer.Render():
                raise RuntimeError("the reference renderer failed (see the messages above)")
        finally:
            if restore is not None:
                mapper.SetOverlapCompositing(restore)
        colour = vtk_to_numpy(renderer.GetColorImage().GetPointData().GetScalars())
        height, width = self.size[1], self.size[0]
        return np.clip(colour[:, :3], 0.0, 1.0).reshape(height, width, 3) * 255.0

    def supersampled_reference(self, view, name):
        s = self.args.settings["supersample"]
        path = os.path.join(self.args.out, "reference", name + "_%dx.png" % s)
        width, height = self.size
        simple.SaveScreenshot(path, view, ImageResolution=[width * s, height * s],
                              TransparentBackground=0)
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        big = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3]
        os.remove(path)  # large; the downsampled reference is kept
        big = big.astype(np.float64).reshape(height, s, width, s, 3)
        return big.mean(axis=(1, 3))

    # --- one picture --------------------------------------------------------------------------
    def render(self, index, tile):
        name, label, scene, settings, reference_kind = (
            tile.name, tile.label, tile.scene, tile.settings, tile.reference)
        n = len(self.tiles)
        reader = self.reader(scene)
        print("[%2d/%d] %-40s" % (index + 1, n, label + " (" + scene + ")"), end=" ", flush=True)
        start = time.perf_counter()
        if CORE_TILE.get(scene) != name and scene not in self.core_s:
            view, _ = self.open_view(scene, {})  # the scene's core, for the ratio
            self.timed_frame(view)
            self.core_s[scene] = self.timed_frame(view)
            simple.Delete(view)
        view, display = self.open_view(scene, settings)
        picture = self.grab(view)
        write_png(picture, os.path.join(self.args.out, name + ".png"))
        if reference_kind == "supersampled" and scene not in self.supersampled:
            self.supersampled[scene] = self.supersampled_reference(view, scene)
        picture_s = time.perf_counter() - start

        start = time.perf_counter()
        if reference_kind == "supersampled":
            reference = self.supersampled[scene]
        elif reference_kind == "ao":
            if scene not in self.ao_reference:
                self.ao_reference[scene] = self.reference(view, "ao")
            reference = self.ao_reference[scene]
        else:
            reference = self.reference(view, reference_kind)
        write_png(reference, os.path.join(self.args.out, "reference", name + ".png"))
        reference_s = time.perf_counter() - start

        note = ""
        if "view.ScaleConsistentShading" in settings:
            view.SMProxy.UpdatePropertyInformation()
            samples = view.GetPropertyValue("SNDFNumberOfSamples")
            view.SNDFConvergeStillRenders = 0  # time one refinement frame
            note = "picture: %d samples per pixel; frame: one refinement frame" % samples
        self.timed_frame(view)  # first frames after the change: shader compiles, volumes, sorts
        frame_s = self.timed_frame(view)
        if CORE_TILE.get(scene) == name:
            self.core_s[scene] = frame_s
        difference = np.abs(picture - reference)
        row = {
            "picture": name, "technique": label, "scene": scene,
            "data": SCENES[scene]["what"],
            "particles": reader.GetDataInformation().GetNumberOfPoints(),
            "width": self.size[0], "height": self.size[1],
            "frame_s": round(frame_s, 4), "frames": self.frames_timed,
            "vs_core": round(frame_s / self.core_s[scene], 2),
            "error_max": round(float(difference.max()), 1),
            "error_mean": round(float(difference.mean()), 2),
            "share_over_2": round(float(np.mean(difference.max(axis=2) > 2.0)), 4),
            "reference": REFERENCE_TEXT[reference_kind].format(**self.args.settings),
            "note": note, "use": tile.use,
        }
        self.rows.append(row)
        print("picture %5.1f s, reference %5.1f s | frame %6.3f s = %5.2fx core | error max %5.1f"
              " mean %5.2f /255" % (picture_s, reference_s, frame_s, row["vs_core"],
                                    row["error_max"], row["error_mean"]), flush=True)
        simple.Delete(display)
        simple.Delete(view)

    def run(self):
        only = set(self.args.only.split(",")) if self.args.only else None
        self.tiles = [t for t in TILES if only is None or t.name in only]
        for index, tile in enumerate(self.tiles):
            try:
                self.render(index, tile)
            except Exception as error:  # report, go on with the next picture
                print("FAILED: %s" % error, flush=True)
                self.failed.append((tile.name, str(error)))
                self.rows.append({"picture": tile.name, "technique": tile.label,
                                  "scene": tile.scene, "note": "FAILED: %s" % error,
                                  "use": tile.use})


REFERENCE_TEXT = {
    "opaque": "ray-cast particles (double)",
    "transparent": "emission-absorption integral (double)",
    "transparent exact": "exact overlap integral (double)",
    "metaballs": "exact metaball surface (double)",
    "ao": "ray-traced AO, {ao_rays} rays per pixel",
    "supersampled": "core super-sampled {supersample}x{supersample}",
}


def machine_text(renderer_string):
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    from paraview import servermanager
    version = servermanager.vtkSMProxyManager.GetParaViewSourceVersion().replace(
        "paraview version ", "")
    return "%s, %d cores; %s; ParaView %s" % (cpu, os.cpu_count() or 0, renderer_string,
                                              version)


def contact_sheet(samples, path):
    """All pictures in a grid, each labelled with its technique, scene, cost and error."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = samples.rows
    columns = 5
    lines = math.ceil(len(rows) / columns)
    width, height = samples.size
    scale = 400.0 / width  # the sheet has the same layout in every mode
    figure = plt.figure(figsize=(columns * 4.0, lines * (4.0 * height / width + 0.55)), dpi=100)
    for i, row in enumerate(rows):
        axes = figure.add_subplot(lines, columns, i + 1)
        axes.set_xticks([])
        axes.set_yticks([])
        if "vs_core" not in row:  # the picture failed
            axes.text(0.5, 0.5, row["note"], ha="center", va="center", wrap=True, fontsize=8)
            axes.set_title("%s\n%s | FAILED" % (row["technique"], row["scene"]), fontsize=9)
            continue
        image = plt.imread(os.path.join(samples.args.out, row["picture"] + ".png"))
        axes.imshow(image, interpolation="nearest")
        axes.set_title("%s\n%s | %.2fx core | error mean %.2f, max %.0f"
                       % (row["technique"], row["scene"], row["vs_core"], row["error_mean"],
                          row["error_max"]), fontsize=9 * min(1.0, scale * 1.2))
    figure.suptitle("ParticleRendering on the bundled LAMMPS data (Scripts/render_samples.sh): "
                    "frame time over the opaque core, error against the reference in 1/255",
                    fontsize=11)
    figure.text(0.5, 0.005, samples.machine, ha="center", fontsize=8)
    figure.tight_layout(rect=(0, 0.015, 1, 0.97))
    figure.savefig(path)
    plt.close(figure)
    try:  # a lighter copy for web pages (the README's): 1500 pixels wide, 256 colours
        from PIL import Image
    except ImportError:
        return None
    sheet = Image.open(path).convert("RGB")
    small = sheet.resize((1500, round(sheet.height * 1500 / sheet.width)), Image.LANCZOS)
    small_path = os.path.splitext(path)[0] + "_small.png"
    small.quantize(256).save(small_path, optimize=True)
    return small_path


CSV_FIELDS = ["picture", "technique", "scene", "data", "particles", "width", "height", "frame_s",
              "frames", "vs_core", "error_max", "error_mean", "share_over_2", "reference", "note",
              "use", "machine"]
COLUMNS_MD = [("technique", "picture"), ("scene", "scene"), ("particles", "particles"),
              ("frame_s", "frame (s)"), ("vs_core", "× core"), ("error_mean", "error mean"),
              ("error_max", "error max"), ("share_over_2", "pixels > 2/255"),
              ("reference", "reference"), ("use", "use it for")]


def markdown(samples):
    width, height = samples.size
    lines = ["| " + " | ".join(title for _, title in COLUMNS_MD) + " |",
             "|" + "---|" * len(COLUMNS_MD)]
    for row in samples.rows:
        cells = []
        for key, _ in COLUMNS_MD:
            value = row.get(key, "—")
            if value == "—":
                pass
            elif key == "share_over_2":
                value = "%.2f %%" % (100.0 * value)
            elif key == "frame_s":
                value = "%.3f" % value
            elif key == "technique" and row["note"]:
                value = "%s (%s)" % (value, row["note"])
            cells.append(str(value))
        lines.append("| " + " | ".join(cells) + " |")
    lines.append("")
    lines.append("%d×%d pixels per picture; frame: the median of at least %d still frames (and "
                 "of at least %.1f s); errors in 1/255 over all pixels and RGB channels. "
                 "Machine: %s." % (width, height, samples.args.settings["frames"],
                                   samples.args.settings["min_time"], samples.machine))
    return "\n".join(lines) + "\n"


# --- the smoke test's check (--check) ---------------------------------------------------------
NUMBER_COLUMNS = ("particles", "width", "height", "frame_s", "vs_core", "error_max",
                  "error_mean", "share_over_2")


def read_rgb(path):
    reader = vtkPNGReader()
    if not os.path.exists(path) or not reader.CanReadFile(path):
        return None
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[:, :, :3].astype(np.float64)


def blank(rgb):
    """True when fewer than 1 % of the pixels differ by more than 8/255 from the most common
    colour (the background): a picture with nothing drawn."""
    flat = rgb.reshape(-1, 3)
    packed = np.rint(flat).astype(np.int64) @ np.array([65536, 256, 1])
    values, counts = np.unique(packed, return_counts=True)
    common = values[np.argmax(counts)]
    background = np.array([common >> 16, (common >> 8) & 255, common & 255], dtype=np.float64)
    drawn = np.abs(flat - background).max(axis=1) > 8.0
    return drawn.mean() < 0.01


def check_output(out, names):
    """The problems of a render_samples output directory, [] when it is complete."""
    problems = []
    rows = {}
    csv_path = os.path.join(out, "samples.csv")
    if not os.path.exists(csv_path):
        return ["no table %s" % csv_path]
    with open(csv_path, newline="") as f:
        for row in csv.DictReader(f):
            rows[row.get("picture", "")] = row
    markdown_text = ""
    md_path = os.path.join(out, "samples.md")
    if os.path.exists(md_path):
        with open(md_path) as f:
            markdown_text = f.read()
    else:
        problems.append("no Markdown table %s" % md_path)
    for name in names:
        row = rows.get(name)
        if row is None:
            problems.append("%s: no row in samples.csv" % name)
            continue
        for column in NUMBER_COLUMNS:
            try:
                value = float(row.get(column, ""))
            except ValueError:
                value = float("nan")
            if not math.isfinite(value) or value < 0 or (
                    column in ("particles", "width", "height", "frame_s", "vs_core")
                    and value <= 0):
                problems.append("%s: %s is %r, not a number" % (name, column, row.get(column)))
        if "| %s" % row.get("technique", "?") not in markdown_text:
            problems.append("%s: no row in samples.md" % name)
        for path in (os.path.join(out, name + ".png"),
                     os.path.join(out, "reference", name + ".png")):
            rgb = read_rgb(path)
            if rgb is None:
                problems.append("%s: missing or unreadable" % path)
            elif blank(rgb):
                problems.append("%s: blank (nothing drawn)" % path)
            elif row is not None and (str(rgb.shape[1]), str(rgb.shape[0])) != (
                    row.get("width"), row.get("height")):
                problems.append("%s: %dx%d, the table says %sx%s" % (
                    path, rgb.shape[1], rgb.shape[0], row.get("width"), row.get("height")))
    sheet = read_rgb(os.path.join(out, "contact_sheet.png"))
    if sheet is None or blank(sheet):
        problems.append("contact_sheet.png missing or blank")
    return problems


def self_test(out, names):
    """The check must reject each of these damages of a good output (a copy is damaged)."""
    import shutil
    import tempfile


    def blank_picture(d):
        rgb = read_rgb(os.path.join(d, names[0] + ".png"))
        write_png(np.zeros_like(rgb) + 30.0, os.path.join(d, names[0] + ".png"))

    def remove_picture(d):
        os.remove(os.path.join(d, names[-1] + ".png"))

    def resize_picture(d):
        rgb = read_rgb(os.path.join(d, names[1] + ".png"))
        write_png(rgb[: rgb.shape[0] // 2], os.path.join(d, names[1] + ".png"))

    def rewrite_table(d, change):
        path = os.path.join(d, "samples.csv")
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        fields = list(rows[0].keys())
        rows = change(rows)
        with open(path, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=fields)
            writer.writeheader()
            writer.writerows(rows)

    def empty_cell(d):
        rewrite_table(d, lambda rows: [dict(r, frame_s="") if i == 2 else r
                                       for i, r in enumerate(rows)])

    def nan_cell(d):
        rewrite_table(d, lambda rows: [dict(r, error_mean="nan") if i == 3 else r
                                       for i, r in enumerate(rows)])

    def drop_row(d):
        rewrite_table(d, lambda rows: rows[:-1])

    failures = []
    for damage in (blank_picture, remove_picture, resize_picture, empty_cell, nan_cell,
                   drop_row):
        with tempfile.TemporaryDirectory() as copy:
            target = os.path.join(copy, "samples")
            shutil.copytree(out, target)
            damage(target)
            problems = check_output(target, names)
            print("self-test %-15s rejected: %s" % (damage.__name__, "; ".join(problems) or
                                                     "NOT REJECTED"))
            if not problems:
                failures.append(damage.__name__)
    return failures


def check_main(args):
    names = [t.name for t in TILES]
    problems = check_output(args.out, names)
    for problem in problems:
        print("FAIL: " + problem)
    if not problems:
        print("check: %d pictures, their references, the contact sheet and %d table rows with "
              "numbers in %s" % (len(names), len(names), args.out))
    failures = self_test(args.out, names) if args.self_test and not problems else []
    for name in failures:
        print("FAIL: the check accepted the damage %s" % name)
    return 1 if problems or failures else 0


def main():
    args = parse_arguments()
    if args.check:
        return check_main(args)
    total = time.perf_counter()
    simple.LoadPlugin(args.plugin, remote=False)
    vtkSMPTools.SetBackend("STDThread")  # the reference renderer's rows in parallel
    samples = Samples(args)
    print("Rendering %d pictures (%s mode, %dx%d) into %s" % (
        len(TILES) if not args.only else len(args.only.split(",")), args.mode,
        args.settings["size"][0], args.settings["size"][1], os.path.abspath(args.out)),
        flush=True)
    samples.run()
    samples.machine = machine_text(samples.renderer_string)

    csv_path = os.path.join(args.out, "samples.csv")
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=CSV_FIELDS)
        writer.writeheader()
        for row in samples.rows:
            writer.writerow(dict(row, machine=samples.machine))
    md_path = os.path.join(args.out, "samples.md")
    table = markdown(samples)
    with open(md_path, "w") as f:
        f.write(table)
    sheet_path = os.path.join(args.out, "contact_sheet.png")
    small_path = contact_sheet(samples, sheet_path)

    if args.results:
        import shutil
        os.makedirs(args.results, exist_ok=True)
        for source, target in ((csv_path, "samples.csv"), (md_path, "samples.md"),
                               (small_path or sheet_path, "samples.png")):
            shutil.copyfile(source, os.path.join(args.results, target))

    print()
    print(table)
    print("Done in %.0f s. Written:" % (time.perf_counter() - total))
    print("  contact sheet   %s%s" % (os.path.abspath(sheet_path), (
        " (1500 pixels wide: %s)" % os.path.basename(small_path)) if small_path else ""))
    print("  table           %s (CSV), %s (Markdown)" % (os.path.abspath(csv_path),
                                                          os.path.abspath(md_path)))
    print("  pictures        %s/<picture>.png (%d)" % (
        os.path.abspath(args.out), len(samples.rows) - len(samples.failed)))
    print("  references      %s/reference/<picture>.png" % os.path.abspath(args.out))
    if args.results:
        print("  results copy    %s/samples.{csv,md,png}" % os.path.abspath(args.results))
    for name, error in samples.failed:
        print("FAILED: %s: %s" % (name, error))
    return 1 if samples.failed else 0


if __name__ == "__main__":
    sys.exit(main())
