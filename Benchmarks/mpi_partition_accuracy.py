"""Distributed translucency against the single-process picture on scenes the tests never saw
(issue 42): per case, how many pixels of the np N picture differ from the np 1 picture by more
than 2/255 and 3/255, and the largest difference.

Scenes (seeded, written to <out>/<scene>.vtp and split as TestParticlesMPI splits the film:
particle i on rank i mod N; the tests' view, colours and camera set-up):
  gas   a dense fcc slab (8 000 atoms, radius 0.5) in hot gas (16 000 atoms spread through and
        around it: deep penetrations), opacity from a 'speed' array (gas fast, slab slow)
  deep  6 000 spheres of radius 0.9-1.5 at mean spacing 0.9 (up to ~10 overlapping at a point)
  reproducer  issue 61's: 100 000 atoms at random in a 30 x 30 x 40 box, radius 0.5, opacity
        from 'speed' (uniform 0.5-4) over the custom range 1-3.5 ('custom'), seen at 480 x 360
        (--size 480 360, as run_mpi_partition_accuracy.sh runs its cases)
Cases: <scene>:<settings>:<compositing>, settings from {speed (opacity array), squared
(Squared Distance density), hollow (HollowFraction 0.5), one (Opacity Of One Particle), opaque
(Opacity 1), dvao / vcao / pointao (Density Volume / Voxel Cone Tracing / PointAO), sndf
(Scale-Consistent Shading, converged), far (the camera 3x farther away), fxaa (ParaView's FXAA
on, as in a new view; off otherwise), custom (the opacity array's custom range 1-3.5), metaballs,
neighbours (metaballs' Maximum Neighbours 255, the largest: no neighbour list cut), rotated (the
actor turned 35 degrees about z and 20 about x: the boxes are cut in data coordinates)}: the rows of the
outside report of issue 42 (opaque, each AO, metaballs, translucent, translucent with AO).
Scene 'mixed' (one view, several representations; issue 42's "one partition per view"): the gas
scene with settings surface (its particles translucent, squared density, opacity array, and a
translucent sphere surface, Opacity 0.4, through the slab), opaque-surface (the particles opaque,
the same surface), opaque-translucent (the slab atoms and the gas atoms as two Particles
representations, the slab opaque, the gas translucent), two-translucent (both translucent, the
slab at Opacity 0.5, the gas at 0.7), two-same (both translucent with the same settings, Opacity
0.7), merged (one Particles representation of all the atoms with those settings: the exact
reference of two-same, which the comparison also gets; mpi_partition_accuracy_compare.py),
two-opaque-dvao / two-opaque-vcao (both opaque, with Density Volume / Voxel Cone Tracing AO:
the AO volume of several Particles representations) and merged-opaque-dvao / -vcao (one
representation of all the atoms, their exact reference).

This pvbatch script renders one rank count; Benchmarks/run_mpi_partition_accuracy.sh runs
np 1, 2, 3 and compares (mpi_partition_accuracy_compare.py).
usage: PYTHONPATH=<build>/lib/python3/dist-packages
       mpiexec -np N pvbatch mpi_partition_accuracy.py --plugin SO --out DIR [--size W H]
           [--cases scene:settings:compositing,... | reproducer]
"""
import argparse
import os
import sys

from paraview import servermanager, simple

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path[:0] = [os.path.join(TOP, "Testing", "Python"), os.path.join(TOP, "Testing", "VTKPython")]
import prMPITesting  # noqa: E402  (the split of TestParticlesMPI: particle i on rank i mod N)
import prParaViewTesting as pr  # noqa: E402  (the tests' view, display and camera set-up)
from prMPITesting import write_scene  # noqa: E402  (the seeded gas, deep and mixed scenes)


CAMERAS = dict(prMPITesting.SCENE_CAMERAS)  # position, focal point
CAMERAS["mixed"] = CAMERAS["gas"]

CASES = ["gas:opaque:Automatic", "gas:opaque-dvao:Automatic", "gas:opaque-vcao:Automatic",
         "gas:opaque-pointao:Automatic", "deep:opaque-pointao:Automatic",
         "gas:metaballs:Automatic", "gas:metaballs-neighbours:Automatic",
         "gas:speed-squared-dvao:Automatic",
         "gas:speed-squared-vcao:Automatic", "deep:opaque:Automatic",
         "deep:opaque-vcao:Automatic", "gas:speed-squared:Automatic", "gas:speed-squared:Exact Overlap",
         "gas:speed-hollow:Sorted Spheres", "gas:one-speed:Automatic",
         "gas:one:Sorted Spheres", "gas:one:Exact Overlap",
         "deep:speed-squared:Automatic", "deep:speed-squared:Exact Overlap",
         "deep:speed-hollow:Sorted Spheres", "deep:one-speed:Automatic",
         "deep:one:Sorted Spheres", "deep:one:Exact Overlap",
         "gas:opaque-sndf:Automatic", "gas:opaque-sndf-far:Automatic",
         "deep:opaque-sndf:Automatic",
         "gas:speed-squared-rotated:Automatic", "deep:speed-squared-rotated:Automatic",
         "mixed:surface:Automatic", "mixed:opaque-surface:Automatic",
         "mixed:opaque-translucent:Automatic", "mixed:two-translucent:Automatic",
         "mixed:two-same:Automatic", "mixed:merged:Automatic",
         "mixed:two-opaque-dvao:Automatic", "mixed:merged-opaque-dvao:Automatic",
         "mixed:two-opaque-vcao:Automatic", "mixed:merged-opaque-vcao:Automatic"]
# issue 61's reproducer and its variants with ParaView's FXAA (--cases reproducer, 480 x 360:
# Benchmarks/run.py mpi-reproducer): every AO method, and the ellipsoids scene
REPRODUCER_CASES = ["reproducer:speed-custom-squared:Automatic",
                    "reproducer:speed-custom-squared-fxaa:Automatic",
                    "reproducer:speed-custom-fxaa:Exact Overlap",
                    "reproducer:speed-custom-squared-dvao-fxaa:Automatic",
                    "reproducer:speed-custom-squared-vcao-fxaa:Automatic",
                    "reproducer:speed-custom-squared-pointao:Automatic",
                    "reproducer:speed-custom-squared-pointao-fxaa:Automatic",
                    "reproducer:opaque-vcao:Automatic", "reproducer:opaque-vcao-fxaa:Automatic",
                    "ellipsoids:speed-squared-fxaa:Automatic",
                    "ellipsoids:speed-squared-dvao-fxaa:Automatic"]


def split_source(path):
    """The particles of the .vtp file `path`, particle i on rank i mod N."""
    source = simple.ProgrammableSource()
    source.OutputDataSetType = "vtkPolyData"
    source.Script = prMPITesting.SPLIT_SCRIPT % {"path": path, "empty_rank": False, "keep": 0,
                                                 "bad": False}
    source.ScriptRequestInformation = prMPITesting.SPLIT_INFORMATION_SCRIPT
    source.UpdatePipeline()
    return source


def show_mixed(settings, path, view):
    """Scene 'mixed': the representations of `settings` in `view`; returns the proxies to
    delete, displays first."""
    def particles(source, opacity):
        display = pr.show_particles(source, view)
        display.DensityModel = 1
        display.OpacityReference = 1
        display.UseOpacityArray = 1 if opacity < 1.0 else 0
        display.ParticleOpacityArray = ["POINTS", "speed"]
        display.Opacity = opacity
        return display
    if settings.endswith("surface"):
        source = split_source(path)
        sphere = simple.Sphere(Center=[16.0, 16.0, 4.0], Radius=9.0, ThetaResolution=96,
                               PhiResolution=48)
        surface = simple.Show(sphere, view)
        surface.ColorArrayName = ["POINTS", ""]
        surface.DiffuseColor = [0.9, 0.9, 0.3]
        surface.Opacity = 0.4
        opacity = 1.0 if settings.startswith("opaque") else 0.7
        return [particles(source, opacity), surface, sphere, source]
    view.ParticleAmbientOcclusion = ("Density Volume" if "dvao" in settings else
                                     "Voxel Cone Tracing" if "vcao" in settings else "None")
    if settings.startswith("merged"):
        source = split_source(path)
        return [particles(source, 1.0 if "opaque" in settings else 0.7), source]
    slab = split_source(path[:-len(".vtp")] + "_type1.vtp")
    gas = split_source(path[:-len(".vtp")] + "_type2.vtp")
    opacity = {"opaque-translucent": 1.0, "two-same": 0.7}.get(settings, 0.5)
    if settings.startswith("two-opaque"):  # both opaque, with ambient occlusion
        return [particles(slab, 1.0), particles(gas, 1.0), slab, gas]
    return [particles(slab, opacity), particles(gas, 0.7), slab, gas]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", type=int, nargs=2, default=(400, 300))
    parser.add_argument("--cases", default=",".join(CASES),
                        help="a comma-separated subset ('reproducer': REPRODUCER_CASES)")
    args, _ = parser.parse_known_args()
    if args.cases == "reproducer":
        args.cases = ",".join(REPRODUCER_CASES)
    simple.LoadPlugin(args.plugin, remote=False)
    ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    os.makedirs(args.out, exist_ok=True)
    for scene in sorted({case.split(":")[0] for case in args.cases.split(",")}):
        path = os.path.join(args.out, scene + ".vtp")
        write_scene(scene, path)  # (this script runs on the first rank; the pieces read it)
        if scene == "mixed":
            for case in args.cases.split(","):
                case_scene, settings, compositing = case.split(":")
                if case_scene != scene:
                    continue
                view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=args.size)
                proxies = show_mixed(settings, path, view)
                pr.set_camera(view, *CAMERAS[scene])
                simple.Render(view)
                name = "%s_%s_%s_np%d.png" % (scene, settings, compositing.split()[0].lower(),
                                              ranks)
                simple.SaveScreenshot(os.path.join(args.out, name), view,
                                      ImageResolution=list(args.size))
                for proxy in proxies:
                    simple.Delete(proxy)
                simple.Delete(view)
            continue
        source = split_source(path)
        view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=args.size)
        display = pr.show_particles(source, view)
        pr.set_camera(view, *CAMERAS[scene])
        for case in args.cases.split(","):
            case_scene, settings, compositing = case.split(":")
            if case_scene != scene:
                continue
            display.DensityModel = 1 if "squared" in settings else 0
            display.HollowFraction = 0.5 if "hollow" in settings else 0.0
            display.OpacityReference = 0 if "one" in settings else 1
            display.UseOpacityArray = 1 if "speed" in settings else 0
            display.ParticleOpacityArray = ["POINTS", "speed"]
            display.OpacityArrayRangeMode = 1 if "custom" in settings else 0
            display.OpacityArrayRange = [1.0, 3.5]
            display.Opacity = (1.0 if "opaque" in settings or "custom" in settings else
                               0.5 if "one" in settings else 0.7)
            # (UseFXAA is linked to the settings: both)
            fxaa = 1 if "fxaa" in settings else 0
            simple.GetSettingsProxy("RenderViewSettings").UseFXAA = fxaa
            view.UseFXAA = fxaa
            display.Technique = "Metaballs" if "metaballs" in settings else "Spheres"
            if "neighbours" in settings:
                display.MaximumNumberOfNeighbors = 255
            view.ParticleAmbientOcclusion = ("Density Volume" if "dvao" in settings else
                                             "Voxel Cone Tracing" if "vcao" in settings else
                                             "PointAO" if "pointao" in settings else "None")
            display.OverlapCompositing = compositing
            display.Orientation = [20.0, 0.0, 35.0] if "rotated" in settings else [0.0, 0.0, 0.0]
            display.Origin = list(CAMERAS[scene][1])  # (turned about the view's focal point)
            sndf = 1 if "sndf" in settings else 0
            view.ScaleConsistentShading = sndf
            view.SNDFConvergeStillRenders = sndf  # (the screenshot converges)
            position, focal = CAMERAS[scene]
            if "far" in settings:  # spheres of a pixel or less: what S-NDF is for
                position = [f + 3.0 * (p - f) for p, f in zip(position, focal)]
            view.CameraPosition = list(position)
            simple.Render(view)
            name = "%s_%s_%s_np%d.png" % (scene, settings, compositing.split()[0].lower(), ranks)
            simple.SaveScreenshot(os.path.join(args.out, name), view,
                                  ImageResolution=list(args.size))
        simple.Delete(display)
        simple.Delete(view)
        simple.Delete(source)


if __name__ == "__main__":
    main()
