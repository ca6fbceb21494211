"""Metaballs in ParaView: the Particles representation with "Draw Particles As" Metaballs
(vtkMetaballMapper, Mueller et al. 2007) on the LAMMPS droplets
(Testing/Data/lj_droplets.vtp, 11033 atoms, radii from 'radius', coloured by type) in the
Particle Render View, compared with a baseline.

Also checked: the settings reach the mapper (a lower Iso Value grows the shapes: more pixels
covered), the shapes cover more than the spheres of the same atoms (Particles) and switching
back gives the baseline picture again; the view's ambient occlusion (Density Volume) darkens the
metaballs and nowhere brightens them; Metaball Method "Walking Depth Plane" (walked to convergence) under the
view's ambient occlusion gives the vicinity method's occluded picture (mean 1/255, at most 1 %
of the pixels over 4/255), darker than the picture without occlusion; still frames of the
walking depth plane with the default limits, the camera turning, end converged or stalled with at
most 1 % of the pixels unfinished, never at the pass limit; no error or warning is printed.

Criteria of the baseline comparison: the GPU's own image on the same platform matches to
rounding; the spheres differ from the metaballs over much of the droplets, so a mean of 1/255 or
1 % of the pixels over 4/255 rejects them. Must-fail case: spheres (the spheres' picture
against the metaballs' baseline).

usage: pvpython TestMetaballsParaView.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR [--must-fail spheres]
"""
import os
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.Criteria(tolerance=4.0, max_share=1e-2, max_mean=1.0)

args = pr.parse_arguments()
pr.load_plugin(args)
ok = True

atoms, from_file = pr.open_particles(args, "lj_droplets.vtp")
view = pr.setup_view(simple.CreateView("ParticleRenderView"))
display = pr.show_particles(atoms, view)
spheres = pr.must_fail(args, "spheres")
display.Technique = "Spheres" if spheres else "Metaballs"
pr.set_camera(view, position=(-20.0, -45.0, 75.0), focal_point=(33.0, 40.0, 40.0))
name = "TestMetaballsParaView" + ("" if from_file else "_synthetic")


def walking_plane(view):
    """The walking depth plane of the view's metaball mapper."""
    actors = view.GetClientSideObject().GetRenderer().GetActors()
    actors.InitTraversal()
    for _ in range(actors.GetNumberOfItems()):
        mapper = actors.GetNextActor().GetMapper()
        if mapper is not None and mapper.IsA("vtkMetaballMapper"):
            return mapper.GetWalkingPlane()
    raise RuntimeError("no metaball mapper in the view")


def rgb(image):
    return vtk_to_numpy(image.GetPointData().GetScalars()).astype(int)[:, :3]


def covered(image):
    background = [round(255 * c) for c in view.Background]
    return int((abs(rgb(image) - background).max(axis=1) > 2).sum())


with pr.captured_messages() as messages:
    image_ok, image = pr.capture_and_compare(view, name, args, CRITERIA)
ok = image_ok and ok
printed = messages.GetOutput()

if not args.must_fail:
    base = covered(image)
    display.IsoValue = 0.7
    grown = covered(pr.capture(view, os.path.join(args.temp_dir, name + "_iso07.png")))
    display.IsoValue = 1.0
    print("covered pixels: iso 1 %d, iso 0.7 %d" % (base, grown))
    if not grown > base * 1.02:
        print("FAIL: a lower Iso Value did not grow the shapes")
        ok = False

    display.Technique = "Spheres"
    plain = covered(pr.capture(view, os.path.join(args.temp_dir, name + "_spheres.png")))
    display.Technique = "Metaballs"
    again = pr.capture(view, os.path.join(args.temp_dir, name + "_again.png"))
    worst = pr.max_abs_difference(again, image)
    print("spheres cover %d pixels, metaballs %d; back to metaballs: %s/255" % (plain, base, worst))
    if not base > plain:
        print("FAIL: the metaballs do not cover more than the spheres")
        ok = False
    if worst is None or worst > 1:
        print("FAIL: switching back to Metaballs changed the picture")
        ok = False

    view.ParticleAmbientOcclusion = "Density Volume"
    occluded = pr.capture(view, os.path.join(args.temp_dir, name + "_ao.png"))
    view.ParticleAmbientOcclusion = "None"
    a = rgb(image).sum(axis=1)
    b = rgb(occluded).sum(axis=1)
    shaded = a > 0
    darker = float((a - b)[shaded].mean()) / 3.0
    brighter = int((b - a).max())
    print("ambient occlusion darkens the metaballs by %.2f/255 on average, brightens by at "
          "most %d/765" % (darker, brighter))
    if not (darker > 1.0 and brighter <= 6):
        print("FAIL: the view's ambient occlusion does not reach the metaballs")
        ok = False

    # the walking depth plane draws the same surface (to its tolerance) without lists
    display.MetaballMethod = "Walking Depth Plane"
    # to convergence whatever the machine's load (no wall-clock limit in a test)
    display.MetaballTimeBudget = 1000.0
    display.MetaballMaximumPasses = 1000
    # (with the view's ambient occlusion: compared with the vicinity method's occluded picture,
    # and darker than its picture without)
    view.ParticleAmbientOcclusion = "Density Volume"
    walking = pr.capture(view, os.path.join(args.temp_dir, name + "_walking_ao.png"))
    view.ParticleAmbientOcclusion = "None"
    display.MetaballMethod = "Vicinity"
    difference = abs(rgb(walking) - rgb(occluded)).max(axis=1)
    share = float((difference > 4).mean())
    walking_darker = float((rgb(image).sum(axis=1) - rgb(walking).sum(axis=1))[shaded].mean())
    print("walking depth plane vs vicinity (both with ambient occlusion): mean %.2f/255, "
          "%.2f %% of the pixels over 4/255; darker than without occlusion by %.2f/255"
          % (difference.mean(), 100.0 * share, walking_darker / 3.0))
    if not (difference.mean() <= 1.0 and share <= 1e-2):
        print("FAIL: the walking depth plane's picture differs from the vicinity method's")
        ok = False
    if not walking_darker / 3.0 > 1.0:
        print("FAIL: the view's ambient occlusion does not reach the walking depth plane")
        ok = False

    # still frames with the default limits (Time Budget 1 s, Maximum Passes 1000), the camera
    # turned 2 degrees before each: every walk ends converged, or stalled with its last few
    # pixels (at most 1 % of the covered ones, oscillating about a surface the ray grazes);
    # never at the pass limit (a frame of 1000 passes), never by the time budget, and no warning
    display.MetaballMethod = "Walking Depth Plane"
    display.MetaballTimeBudget = 1.0
    display.MetaballMaximumPasses = 1000
    simple.Render(view)
    plane = walking_plane(view)
    endings = []
    with pr.captured_messages() as walk_messages:
        for _ in range(8):
            view.GetActiveCamera().Azimuth(2.0)
            simple.Render(view)
            endings.append((plane.GetNumberOfPasses(),
                            plane.GetTerminationAsString(plane.GetTermination()),
                            plane.GetActivePixels(), plane.GetCoveredPixels()))
    display.MetaballMethod = "Vicinity"
    print("still walks with the default limits (passes, end, active of covered): %s" % endings)
    for passes, end, active, covered_pixels in endings:
        if end not in ("converged", "stalled") or active > max(1, 1e-2 * covered_pixels):
            print("FAIL: a still walk ended by %s with %d of %d pixels active"
                  % (end, active, covered_pixels))
            ok = False
    if walk_messages.GetOutput().strip():
        print("FAIL: messages of the still walks: %r" % walk_messages.GetOutput())
        ok = False

    if printed.strip():
        print("FAIL: messages: %r" % printed)
        ok = False

pr.finish(ok)
