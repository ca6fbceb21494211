"""vtkMetaballMapper's walking depth plane (Mueller et al. 2007, Sec. 3.2; issue: metaballs)
against the exact metaball surface of vtkParticleReferenceRenderer (metaball mode):

1. Isolated particles: depth error at most 0.5 % of R outside silhouettes (also with the data
   1e6 from the origin; with the camera 1e7 radii away, where a depth-buffer step is 6e-7 R,
   the window depth within 4 steps), coverage as the reference's.
2. The droplet with vapour, coloured by type: depth error at most 0.5 % of R outside
   silhouettes (the issue's goal), coverage differing in at most 0.1 % of the pixels, normals
   within 1 degree and colours within 2/255 on average; no neighbour list is built.
3. The error falls with WalkingTolerance; the walk ends by each of its criteria (converged,
   MaximumPasses, TimeBudget, FinishedShare) and says which; TimeBudget only in interactive
   frames (a still frame with TimeBudget 0 converges), a still frame cut by MaximumPasses warns
   once; fewer passes leave more pixels unfinished; the paper's oracle reaches the same surface
   in more passes.
4. The paper's thin neck (two particles 0.1 % short of the largest connecting distance):
   shown wherever the reference shows it.
5. Switching the method back and forth gives each method's picture to 0/255.
6. Bad input: empty input, NaN and non-positive radii, one particle; picking.

With --gl33 (CTest runs it under MESA_GL_VERSION_OVERRIDE=3.3, where the vicinity method has
no shader storage): the walking depth plane draws the droplet without an error, as exactly as
under OpenGL 4.5.
"""
import sys

import numpy as np

import particlerendering as pr
from prMetaballTesting import (compare, droplet, isolated_views, metaball_view, thin_neck,
                               type_lookup_table)
from prVTKTesting import Messages, check, finish, grab_image, picked_ids
from vtkmodules.util.numpy_support import vtk_to_numpy

GL33 = "--gl33" in sys.argv
Plane = pr.vtkMetaballWalkingPlane


def walking_view(xyz, size=(300, 300), radius=1.0, **arrays):
    mapper, actor, renderer, window = metaball_view(xyz, size, radius, **arrays)
    mapper.SetMethodToWalkingDepthPlane()
    # to convergence whatever the machine's load (no wall-clock limit in a test)
    mapper.SetTimeBudget(1000.0)
    mapper.SetMaximumPasses(1000)
    return mapper, actor, renderer, window


def walk(mapper):
    plane = mapper.GetWalkingPlane()
    return plane.GetNumberOfPasses(), Plane.GetTerminationAsString(plane.GetTermination())


def droplet_view(size=(400, 400)):
    xyz, kind = droplet()
    mapper, actor, renderer, window = walking_view(xyz, size, kind=kind)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("kind")
    mapper.SetLookupTable(type_lookup_table(0, 1))
    mapper.SetScalarRange(0, 1)
    renderer.GetActiveCamera().SetPosition(30, 20, 40)
    renderer.ResetCamera()
    return xyz, mapper, actor, renderer, window


def check_droplet(mapper, actor, renderer, window, label):
    messages = Messages(mapper)
    window.Render()
    r = compare(window, renderer, actor, 1.0, normals=True)
    ref_rgb = vtk_to_numpy(r["reference"].GetColorImage().GetPointData().GetScalars())[:, :3]
    gpu_rgb = grab_image(window)[:, :3].astype(float)
    color_error = np.abs(ref_rgb * 255.0 - gpu_rgb).max(axis=1)[r["both"]]
    passes, why = walk(mapper)
    print("%s: %d passes (%s), covered %d, depth error mean %.2e R, max %.2e R outside %d "
          "silhouette pixels, coverage differs in %d + %d, normals %.2f deg, colour %.2f/255"
          % (label, passes, why, r["covered"], r["mean"], r["max_smooth"], r["silhouette"],
             r["only_gpu"], r["only_ref"], r["normal_mean"], color_error.mean()))
    check(not messages.errors, label + ": no error, got %r" % messages.errors)
    check(r["covered"] > 0.05 * np.prod(window.GetSize()), label + ": the droplet is drawn")
    check(r["max_smooth"] <= 5e-3, label + ": depth error %.2e R > 0.5 %% R" % r["max_smooth"])
    check(r["only_gpu"] + r["only_ref"] <= 1e-3 * r["covered"],
          label + ": coverage differs in %d pixels" % (r["only_gpu"] + r["only_ref"]))
    check(r["normal_mean"] <= 1.0, label + ": normals %.2f deg off" % r["normal_mean"])
    check(color_error.mean() <= 2.0, label + ": colours %.2f/255 off" % color_error.mean())
    check(why == "converged", label + ": the walk converged (%s)" % why)
    return r


if GL33:
    xyz, mapper, actor, renderer, window = droplet_view((300, 300))
    check_droplet(mapper, actor, renderer, window, "OpenGL 3.3 droplet")
    sys.exit(finish())

# ---- 1. isolated particles
for name, distance, mapper, actor, renderer, window in isolated_views(walking=True):
    r = compare(window, renderer, actor, 1.0)
    print("isolated, %s: %d passes (%s), covered %d, depth error mean %.2e R, max %.2e R, "
          "coverage differs in %d + %d" % ((name,) + walk(mapper) + (
              r["covered"], r["mean"], r["max_smooth"], r["only_gpu"], r["only_ref"])))
    check(r["covered"] > 300, name + ": spheres drawn")
    if distance:
        # 1e7 R away, a step of the 24-bit depth buffer is 6e-7 R, finer than the view depth
        # the comparison converts it to: the window depth itself is compared
        print("  window depth within %.1f steps of 2^-24" % (r["max_window"] * 2 ** 24))
        check(r["max_window"] <= 4 * 2.0 ** -24,
              name + ": window depth %.1f steps off" % (r["max_window"] * 2 ** 24))
    else:
        check(r["max_smooth"] <= 5e-3, name + ": depth error %.2e R" % r["max_smooth"])
        check(r["mean"] <= 1e-3, name + ": mean depth error %.2e R" % r["mean"])
    check(r["only_gpu"] + r["only_ref"] <= 0.01 * r["covered"] + 4,
          name + ": coverage differs in %d pixels" % (r["only_gpu"] + r["only_ref"]))

# ---- 2. the droplet
xyz, mapper, actor, renderer, window = droplet_view()
r = check_droplet(mapper, actor, renderer, window, "droplet")
check(mapper.GetNumberOfListBuilds() == 0, "no neighbour list is built")
default_mean = r["mean"]
vapour_pixels = np.sum(np.abs(grab_image(window)[:, :3] - [31, 120, 204]).max(axis=1)[r["both"]]
                       < 40)
check(vapour_pixels > 50, "droplet: the vapour's colour is seen (%d pixels)" % vapour_pixels)
ids = picked_ids(renderer, (198, 198, 202, 202))
check(len(ids) > 0 and all(0 <= i < len(xyz) for i in ids), "picking: ids %r" % ids)

# ---- 3. tolerance and termination
mapper.SetWalkingTolerance(1e-5)
window.Render()
fine = compare(window, renderer, actor, 1.0)
print("WalkingTolerance 1e-5: %d passes (%s), depth error mean %.2e R (1e-3: %.2e R)"
      % (walk(mapper) + (fine["mean"], default_mean)))
check(fine["mean"] < 0.2 * default_mean, "a 100x finer tolerance: mean error %.2e R, not below "
      "a fifth of %.2e R" % (fine["mean"], default_mean))
mapper.SetWalkingTolerance(1e-3)

plane = mapper.GetWalkingPlane()
window.Render()
converged_passes = plane.GetNumberOfPasses()
covered = plane.GetCoveredPixels()
# the time budget bounds interactive frames only (level 0 of the frame budget); a still frame
# (this window: nobody set an update rate) walks to convergence whatever the budget, and one that
# MaximumPasses cuts warns
budget = mapper.GetFrameBudget()
for setting, value, expected, quality in (
        ("SetMaximumPasses", 4, "pass limit", pr.vtkParticleFrameBudget.ADAPTIVE),
        ("SetTimeBudget", 0.0, "time budget", pr.vtkParticleFrameBudget.INTERACTIVE),
        ("SetFinishedShare", 0.5, "finished share", pr.vtkParticleFrameBudget.ADAPTIVE)):
    getattr(mapper, setting)(value)
    budget.SetQuality(quality)
    cut_messages = Messages(mapper)
    window.Render()
    passes, why = walk(mapper)
    active = plane.GetActivePixels()
    print("%s(%g): %d passes, %s, %d of %d pixels active" % (setting, value, passes, why, active,
                                                            covered))
    check(why == expected, "%s(%g) ends by %s, not %s" % (setting, value, expected, why))
    check(passes < converged_passes and active > 0, "%s(%g): an unfinished walk" %
          (setting, value))
    check(np.isfinite(grab_image(window)).all(), "%s(%g): a finite picture" % (setting, value))
    warned = [w for w in cut_messages.warnings if "Maximum Passes" in w]
    check(len(warned) == (1 if setting == "SetMaximumPasses" else 0),
          "%s(%g): %d warnings about Maximum Passes (a still frame cut by it warns, once): %s"
          % (setting, value, len(warned), warned))
    budget.SetQuality(pr.vtkParticleFrameBudget.ADAPTIVE)
    if setting == "SetTimeBudget":
        window.Render()  # a still frame with the same budget: walks to convergence
        passes, why = walk(mapper)
        print("SetTimeBudget(0), still frame: %d passes, %s" % (passes, why))
        check(why == "converged" and passes == converged_passes,
              "SetTimeBudget(0): a still frame walks to convergence (%d passes, %s)"
              % (passes, why))
    getattr(mapper, setting)({"SetMaximumPasses": 1000, "SetTimeBudget": 1000.0,
                              "SetFinishedShare": 1.0}[setting])
mapper.SetMaximumPasses(8)
window.Render()
r8 = compare(window, renderer, actor, 1.0)
mapper.SetMaximumPasses(1000)
check(r8["only_ref"] > r["only_ref"] + 100, "8 passes leave pixels empty (%d)" % r8["only_ref"])

mapper.SetStepOracle(mapper.PAPER_ORACLE)
mapper.SetMaximumPasses(1000)
window.Render()
paper = compare(window, renderer, actor, 1.0)
print("paper's oracle: %d passes (%s), depth error mean %.2e R, max %.2e R, coverage differs "
      "in %d + %d" % (walk(mapper) + (paper["mean"], paper["max_smooth"], paper["only_gpu"],
                                     paper["only_ref"])))
check(walk(mapper)[0] > converged_passes, "the paper's oracle needs more passes")
check(paper["max_smooth"] <= 2e-2, "paper's oracle: depth error %.2e R" % paper["max_smooth"])
mapper.SetStepOracle(mapper.BRACKETING_ORACLE)

# ---- 5. switching methods
window.Render()
walking_image = grab_image(window)
mapper.SetMethodToVicinity()
window.Render()
vicinity_image = grab_image(window)
mapper.SetMethodToWalkingDepthPlane()
window.Render()
check(np.abs(grab_image(window) - walking_image).max() == 0, "walking plane again: same picture")
mapper.SetMethodToVicinity()
window.Render()
check(np.abs(grab_image(window) - vicinity_image).max() == 0, "vicinity again: same picture")
print("the two methods' pictures differ by %.2f/255 on average" %
      np.abs(walking_image - vicinity_image)[:, :3].mean())

# ---- 4. the thin neck
neck, neck_ref, neck_gpu, r = thin_neck(walking=True)
print("thin neck: reference %d pixels, walking plane %d of them, depth error max %.2e R" %
      (neck_ref, neck_gpu, r["max_smooth"]))
check(neck_ref > 0 and neck_gpu == neck_ref, "the neck has holes: %d of %d" % (neck_gpu, neck_ref))

# ---- 6. bad input
mapper, actor, renderer, window = walking_view(np.zeros((0, 3)))
messages = Messages(mapper)
window.Render()
check(any("no points" in w for w in messages.warnings), "empty input: a warning")
check(not messages.errors, "empty input: no error")

xyz = np.array([[0, 0, 0], [1.5, 0, 0], [0, 1.5, 0], [np.nan, 0, 0], [3, 0, 0]], dtype=float)
mapper, actor, renderer, window = walking_view(xyz, (200, 200),
                                               r=np.array([1, 1, 0, 1, -1], float))
mapper.SetRadiusArrayName("r")
messages = Messages(mapper)
renderer.ResetCamera()
window.Render()
check(mapper.GetNumberOfSkippedParticles() == 3, "bad radii and positions skipped")
image = grab_image(window)
check(np.isfinite(image).all() and image[:, :3].max() > 0, "bad input: a sane picture")
r = compare(window, renderer, actor, 1.0)
check(r["max_smooth"] <= 5e-3, "bad input: the valid particles' surface (%.2e R)" % r["max_smooth"])

mapper, actor, renderer, window = walking_view([[0.0, 0.0, 0.0]], (200, 200), radius=1e-6)
renderer.ResetCamera()
window.Render()
r = compare(window, renderer, actor, 1e-6)
print("one particle of radius 1e-6: %d passes (%s), depth error max %.2e R" %
      (walk(mapper) + (r["max_smooth"],)))
check(r["covered"] > 300 and r["max_smooth"] <= 5e-3, "one particle of radius 1e-6")

sys.exit(finish())
