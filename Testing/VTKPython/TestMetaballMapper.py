"""vtkMetaballMapper (issue: metaballs, Mueller et al. 2007) against the exact metaball surface of
vtkParticleReferenceRenderer (metaball mode, double precision):

1. Isolated particles are their spheres (the core's exact imposter path): window depth within
   4 steps of the 24-bit depth buffer of the exact value and colours within 2/255 outside
   silhouettes, also with the camera 1e7 radii away and the data 1e6 from the origin; near the
   data that is a depth error below 1e-5 R beyond the buffer's resolution.
2. A droplet of 291 jittered particles with 60 vapour atoms, coloured by type: depth error at
   most 0.5 % of R outside silhouettes (goal of the issue), mean <= 1e-4 R; at most 0.1 % of the
   covered pixels covered by one picture only; normals within 1 degree on average; colours
   within 2/255 on average (blended by field share). Drawn with the depth pre-pass (default) and
   without it: both meet these bounds and agree with each other in depth to 1e-3 R away from
   silhouettes. A multisampled window declines the pre-pass.
3. The paper's thin-neck situation (its Fig. 11 holes): two particles 0.1 % short of the largest
   distance at which they connect; the GPU shows the neck wherever the reference does.
4. Coincident particles: one sphere of the closed-form radius k R sqrt(1 - sqrt(1 / (n c))).
5. The neighbour lists are rebuilt only when positions, radii, RadiusScaleFactor or
   InfluenceFactor change (not for the camera, IsoValue or colours).
6. Bad input: no points, NaN and non-positive radii (warned, skipped), a huge InfluenceFactor
   (every particle a neighbour of every other: lists cut to MaximumNumberOfNeighbors with a
   warning, bounded time), IterationLimit 1 (terminates). No NaN reaches the picture.
7. Picking returns a particle of the cluster.

With --no-storage (CTest runs it under MESA_GL_VERSION_OVERRIDE=3.3): one error says metaballs
need shader storage buffers and the particles are drawn as their spheres.
"""
import sys
import time

import numpy as np

import particlerendering as pr
from prMetaballTesting import (compare, droplet, isolated_views, metaball_view, thin_neck,
                               type_lookup_table)
from prVTKTesting import Messages, check, finish, grab_image, picked_ids
from vtkmodules.util.numpy_support import vtk_to_numpy

NO_STORAGE = "--no-storage" in sys.argv


if NO_STORAGE:
    xyz, kind = droplet()
    mapper, actor, renderer, window = metaball_view(xyz)
    messages = Messages(mapper)
    renderer.ResetCamera()
    window.Render()
    window.Render()
    errors = [e for e in messages.errors if "shader storage" in e]
    check(len(errors) == 1, "one error about shader storage buffers, got %r" % messages.errors)
    # drawn as spheres: the picture equals the plain core's
    spheres = pr.vtkParticleSphereMapper()
    spheres.SetInputData(mapper.GetInput())
    spheres.SetRadius(1.0)
    actor.SetMapper(spheres)
    window.Render()
    plain = grab_image(window)[:, :3].astype(int)
    actor.SetMapper(mapper)
    window.Render()
    image = grab_image(window)[:, :3].astype(int)
    check(np.abs(image - plain).max() <= 1, "not the spheres' picture: max diff %d" %
          np.abs(image - plain).max())
    sys.exit(finish())

# ---- 1. isolated particles are exact
for name, _, mapper, actor, renderer, window in isolated_views():
    check(mapper.GetNumberOfIsolatedParticles() == 3, name + ": three isolated particles")
    r = compare(window, renderer, actor, 1.0)
    ref_rgb = vtk_to_numpy(r["reference"].GetColorImage().GetPointData().GetScalars())[:, :3]
    grid = r["both"].reshape(window.GetSize()[1], -1)
    inner = grid.copy()
    inner[1:, :] &= grid[:-1, :]
    inner[:-1, :] &= grid[1:, :]
    inner[:, 1:] &= grid[:, :-1]
    inner[:, :-1] &= grid[:, 1:]
    inner = inner.ravel()
    color = np.abs(ref_rgb * 255.0 - grab_image(window)[:, :3]).max(axis=1)[inner]
    print("isolated, %s: covered %d, depth error max %.2e R (window depth %.1f steps of 2^-24), "
          "colour max %.2f/255 inside, coverage differs in %d + %d pixels"
          % (name, r["covered"], r["max_smooth"], r["max_window"] * 2 ** 24, color.max(),
             r["only_gpu"], r["only_ref"]))
    check(r["covered"] > 100, name + ": spheres drawn")
    check(r["max_window"] <= 4 * 2.0 ** -24,
          name + ": window depth %.1f steps off" % (r["max_window"] * 2 ** 24))
    check(color.max() <= 2.0, name + ": colour %.2f/255 off" % color.max())
    check(r["only_gpu"] + r["only_ref"] <= 0.01 * r["covered"] + 4,
          name + ": coverage differs in %d pixels" % (r["only_gpu"] + r["only_ref"]))

# ---- 2. a droplet with vapour, coloured by type
xyz, kind = droplet()
mapper, actor, renderer, window = metaball_view(xyz, (400, 400), kind=kind)
mapper.SetScalarModeToUsePointFieldData()
mapper.SelectColorArray("kind")
lut = type_lookup_table(0, 1)
mapper.SetLookupTable(lut)
mapper.SetScalarRange(0, 1)
camera = renderer.GetActiveCamera()
camera.SetPosition(30, 20, 40)
renderer.ResetCamera()
window.Render()
r = compare(window, renderer, actor, 1.0, normals=True)
ref_color = r["reference"].GetColorImage().GetPointData().GetScalars()
ref_rgb = vtk_to_numpy(ref_color)[:, :3] * 255.0
gpu_rgb = grab_image(window)[:, :3].astype(float)
color_error = np.abs(ref_rgb - gpu_rgb).max(axis=1)[r["both"]]
print("droplet: covered %d, depth error mean %.2e R, max %.2e R outside %d silhouette pixels "
      "(%.2e R there), coverage differs in %d + %d, normals %.2f deg mean, colour %.2f/255 mean"
      % (r["covered"], r["mean"], r["max_smooth"], r["silhouette"], r["max"], r["only_gpu"],
         r["only_ref"], r["normal_mean"], color_error.mean()))
check(r["max_smooth"] <= 5e-3, "droplet: depth error %.2e R > 0.5 %% R" % r["max_smooth"])
check(r["mean"] <= 1e-4, "droplet: mean depth error %.2e R" % r["mean"])
check(r["only_gpu"] + r["only_ref"] <= 1e-3 * r["covered"],
      "droplet: coverage differs in %d pixels" % (r["only_gpu"] + r["only_ref"]))
check(r["normal_mean"] <= 1.0, "droplet: normals %.2f deg off on average" % r["normal_mean"])
check(color_error.mean() <= 2.0, "droplet: colours %.2f/255 off on average" % color_error.mean())
check(np.isfinite(gpu_rgb).all(), "droplet: finite picture")
# colour by type shows both types, blended where they meet
vapour_pixels = np.sum(np.abs(gpu_rgb - [31, 120, 204]).max(axis=1)[r["both"]] < 40)
check(vapour_pixels > 50, "droplet: the vapour's colour is seen (%d pixels)" % vapour_pixels)
check(mapper.GetLastDrawUsedDepthPrePass(), "droplet: the depth pre-pass was used")

# the same without the depth pre-pass
mapper.SetDepthPrePass(False)
window.Render()
check(not mapper.GetLastDrawUsedDepthPrePass(), "droplet: the depth pre-pass is off")
r_one = compare(window, renderer, actor, 1.0, normals=True)
print("droplet, one pass: depth error mean %.2e R, max %.2e R outside silhouettes, coverage "
      "differs in %d + %d, normals %.2f deg mean"
      % (r_one["mean"], r_one["max_smooth"], r_one["only_gpu"], r_one["only_ref"],
         r_one["normal_mean"]))
check(r_one["max_smooth"] <= 5e-3 and r_one["mean"] <= 1e-4,
      "droplet, one pass: depth error %.2e R" % r_one["max_smooth"])
both = r["smooth"] & r_one["smooth"]
agree = np.abs(r["gpu_depth"] - r_one["gpu_depth"])[both].max()
print("droplet: with and without the pre-pass the depths agree to %.2e R" % agree)
check(agree <= 1e-3, "droplet: pre-pass changes the depth by %.2e R" % agree)
mapper.SetDepthPrePass(True)

# the actor scaled, turned and moved, the radii scaled: the kernels are gathered in list
# (model) coordinates, the reference forms the scene in view coordinates
actor.SetScale(1.7)
actor.RotateZ(30.0)
actor.RotateX(-20.0)
actor.SetPosition(3.0, -2.0, 1.0)
mapper.SetRadiusScaleFactor(1.1)
renderer.ResetCamera()
window.Render()
r_moved = compare(window, renderer, actor, 1.7 * 1.1, normals=True)
print("droplet, actor scaled 1.7 and turned, radii 1.1: depth error mean %.2e R, max %.2e R "
      "outside silhouettes, coverage differs in %d + %d, normals %.2f deg mean"
      % (r_moved["mean"], r_moved["max_smooth"], r_moved["only_gpu"], r_moved["only_ref"],
         r_moved["normal_mean"]))
check(r_moved["max_smooth"] <= 5e-3 and r_moved["mean"] <= 1e-4 and r_moved["covered"] > 1000,
      "droplet, actor transformed: depth error %.2e R" % r_moved["max_smooth"])
check(r_moved["only_gpu"] + r_moved["only_ref"] <= 1e-3 * r_moved["covered"],
      "droplet, actor transformed: coverage differs in %d pixels"
      % (r_moved["only_gpu"] + r_moved["only_ref"]))
check(r_moved["normal_mean"] <= 1.0,
      "droplet, actor transformed: normals %.2f deg off" % r_moved["normal_mean"])
actor.SetScale(1.0)
actor.SetOrientation(0.0, 0.0, 0.0)
actor.SetPosition(0.0, 0.0, 0.0)
mapper.SetRadiusScaleFactor(1.0)
renderer.ResetCamera()
window.Render()
# a multisampled window: the pre-pass's depth copy cannot read it, one pass is drawn
ms_mapper, _, _, ms_window = metaball_view(xyz, (200, 200))
ms_window.SetMultiSamples(4)
ms_window.Render()
samples = ms_window.GetMultiSamples()
check(not ms_mapper.GetLastDrawUsedDepthPrePass() and np.isfinite(grab_image(ms_window)).all(),
      "multisampled (%d): the pre-pass is declined" % samples)

# ---- 7. picking: a particle of the cluster
ids = picked_ids(renderer, (198, 198, 202, 202))
check(len(ids) > 0 and all(0 <= i < len(xyz) for i in ids), "picking: ids %r" % ids)

# ---- 5. what rebuilds the lists
builds = mapper.GetNumberOfListBuilds()
camera.Azimuth(20)
window.Render()
mapper.SetIsoValue(0.8)
window.Render()
lut.SetTableValue(0, 0.2, 0.8, 0.2)
window.Render()
check(mapper.GetNumberOfListBuilds() == builds,
      "camera, IsoValue and colours rebuilt the lists (%d builds)" %
      (mapper.GetNumberOfListBuilds() - builds))
mapper.SetRadiusScaleFactor(1.1)
window.Render()
check(mapper.GetNumberOfListBuilds() == builds + 1, "RadiusScaleFactor: one rebuild")
mapper.SetInfluenceFactor(2.5)
window.Render()
check(mapper.GetNumberOfListBuilds() == builds + 2, "InfluenceFactor: one rebuild")
mapper.GetInput().GetPoints().Modified()
window.Render()
check(mapper.GetNumberOfListBuilds() == builds + 3, "new positions: one rebuild")
print("list build: %.4f s for %d particles, %d entries" %
      (mapper.GetLastListBuildSeconds(), len(xyz), mapper.GetNumberOfListEntries()))

# a particle lost 1e6 radii away: the others keep their lists (the neighbour search bins only
# occupied cells, so the lost one neither changes nor slows the others' search)
plain, _, _, plain_window = metaball_view(xyz, (100, 100))
plain_window.Render()
lost, _, _, lost_window = metaball_view(np.vstack([xyz, [[1.0e6, 0.0, 0.0]]]), (100, 100))
lost_window.Render()
print("lists with a particle 1e6 away: %d entries, %d isolated (without it %d, %d)" %
      (lost.GetNumberOfListEntries(), lost.GetNumberOfIsolatedParticles(),
       plain.GetNumberOfListEntries(), plain.GetNumberOfIsolatedParticles()))
check(lost.GetNumberOfListEntries() == plain.GetNumberOfListEntries() > 0 and
      lost.GetNumberOfIsolatedParticles() == plain.GetNumberOfIsolatedParticles() + 1,
      "a lost particle changed the others' lists")

# ---- 3. the thin neck: two particles just short of the largest connecting distance
neck, neck_ref, neck_gpu, r = thin_neck()
print("thin neck (radius %.3f R): reference %d pixels, GPU %d of them" % (neck, neck_ref, neck_gpu))
check(neck_ref > 0 and neck_gpu == neck_ref, "the neck has holes: %d of %d" % (neck_gpu, neck_ref))

# ---- 4. coincident particles
k, c = 2.0, 16.0 / 9.0
n = 10
mapper, actor, renderer, window = metaball_view(np.zeros((n, 3)) + [1.0, 2.0, 3.0], (200, 200))
renderer.ResetCamera()
window.Render()
r = compare(window, renderer, actor, 1.0)
expected = k * np.sqrt(1.0 - np.sqrt(1.0 / (n * c)))
bounds = mapper.GetBounds()
print("coincident: depth error max %.2e R; expected radius %.4f R" % (r["max_smooth"], expected))
check(r["max_smooth"] <= 5e-3 and r["covered"] > 100, "coincident: depth error %.2e R" %
      r["max_smooth"])
check(abs((bounds[1] - bounds[0]) / 2 - k) < 1e-9, "coincident: bounds reach k R")

# ---- 6. bad input
mapper, actor, renderer, window = metaball_view(np.zeros((0, 3)))
messages = Messages(mapper)
window.Render()
check(any("no points" in w for w in messages.warnings), "empty input: a warning")

xyz = np.array([[0, 0, 0], [1.5, 0, 0], [0, 1.5, 0], [np.nan, 0, 0], [3, 0, 0]], dtype=float)
mapper, actor, renderer, window = metaball_view(xyz, (200, 200),
                                                r=np.array([1, 1, 0, 1, -1], float))
mapper.SetRadiusArrayName("r")
messages = Messages(mapper)
renderer.ResetCamera()
window.Render()
check(mapper.GetNumberOfSkippedParticles() == 3, "bad radii and positions skipped: %d" %
      mapper.GetNumberOfSkippedParticles())
check(mapper.GetNumberOfListEntries() == 2, "two valid particles are each other's neighbours")
check(len(messages.warnings) >= 1, "bad input warned")
image = grab_image(window)
check(np.isfinite(image).all() and image[:, :3].max() > 0, "bad input: a sane picture")

rng = np.random.default_rng(5)
crowd = rng.uniform(-10, 10, (8000, 3))
mapper, actor, renderer, window = metaball_view(crowd, (100, 100), radius=0.3)
mapper.SetInfluenceFactor(10.0)
messages = Messages(mapper)
renderer.ResetCamera()
start = time.time()
window.Render()
seconds = time.time() - start
print("huge influence: %d of %d lists cut, %d entries, list build %.2f s, frame %.1f s" %
      (mapper.GetNumberOfTruncatedLists(), len(crowd), mapper.GetNumberOfListEntries(),
       mapper.GetLastListBuildSeconds(), seconds))
check(mapper.GetNumberOfTruncatedLists() > len(crowd) // 2, "huge influence: lists cut")
check(mapper.GetNumberOfListEntries() <= len(crowd) * mapper.GetMaximumNumberOfNeighbors(),
      "huge influence: lists bounded")
check(any("MaximumNumberOfNeighbors" in w for w in messages.warnings),
      "huge influence: a warning, got %r" % messages.warnings)

# colours with alpha below 1, and an actor opacity below 1 with ForceOpaque: the opaque surface,
# the same picture (a partial alpha would blend it with what was drawn before it: order-
# dependent, and under MPI partition-dependent). An actor opacity below 1 alone: VTK's
# translucent pass, with a warning that names the opacity and how to get the opaque surface.
for method in (pr.vtkMetaballMapper.VICINITY, pr.vtkMetaballMapper.WALKING_DEPTH_PLANE):
    xyz, kind = droplet()
    mapper, actor, renderer, window = metaball_view(xyz, (200, 200), kind=kind)
    mapper.SetMethod(method)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("kind")
    mapper.SetScalarRange(0, 1)
    renderer.SetBackground(0.9, 0.1, 0.1)
    renderer.ResetCamera()
    pictures = {}
    for alpha in (1.0, 0.3):
        lut = type_lookup_table(0, 1)
        for i in range(2):
            lut.SetTableValue(i, *(lut.GetTableValue(i)[:3] + (alpha,)))
        mapper.SetLookupTable(lut)
        window.Render()
        pictures[alpha] = grab_image(window)[:, :3].astype(int)
    check(actor.HasOpaqueGeometry() and not actor.HasTranslucentPolygonalGeometry(),
          "method %d: colours with alpha: still opaque geometry" % method)
    messages = Messages(mapper)
    actor.GetProperty().SetOpacity(0.5)
    window.Render()
    translucent = grab_image(window)
    warned = [w for w in messages.warnings if "opacity 0.5" in w and "ForceOpaque" in w]
    check(len(warned) == 1, "method %d: one warning about the opacity, got %r"
          % (method, messages.warnings))
    check(np.isfinite(translucent).all() and np.abs(translucent[:, :3] - pictures[0.3]).max() > 8,
          "method %d: opacity 0.5 is drawn translucent" % method)
    actor.ForceOpaqueOn()
    window.Render()
    pictures["forced"] = grab_image(window)[:, :3].astype(int)
    check(len(messages.warnings) == 1, "method %d: no warning once forced opaque" % method)
    for name in (0.3, "forced"):
        diff = np.abs(pictures[name] - pictures[1.0]).max(axis=1)
        print("method %d, %s against the opaque colours: max %d/255, %d px over 2/255"
              % (method, name if name == "forced" else "colour alpha 0.3", diff.max(),
                 (diff > 2).sum()))
        check(diff.max() <= 1, "method %d, %s: not the opaque picture (max %d/255)"
              % (method, name, diff.max()))

mapper, actor, renderer, window = metaball_view(droplet()[0], (200, 200))
mapper.SetIterationLimit(1)
renderer.ResetCamera()
window.Render()
check(np.isfinite(grab_image(window)).all(), "IterationLimit 1: terminates")

sys.exit(finish())
