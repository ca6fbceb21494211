"""Oriented ellipsoids in the sphere core (vtkParticleSphereMapper, Shape Ellipsoid), plain VTK.

1. Equal axes give the sphere core's picture: the same particles drawn as spheres of radius r and
   as ellipsoids of semi-axes (r, r, r) in random orientations, perspective and parallel, with a
   uniformly scaled actor; colour and depth compared pixel by pixel.
2. Against vtkParticleReferenceRenderer (double-precision ray casting of the same ellipsoids):
   axis ratios 1:1:1 to 1:1:100, random orientations, perspective and parallel, intersecting
   particles; depth, coverage, normals and colour.
3. Closed forms: an ellipsoid of semi-axes (a, b, c) in parallel projection seen along each of its
   axes covers the ellipse pi * (the other two) -- pixel count and extent.
4. Extremes: the scene scaled by 1e-6 and 1e6 (axes of 1e-6 and 1e6) gives the unit scene's
   picture; the camera 1e7 largest axes away and inside an ellipsoid, against the reference;
   quaternions at the singular cases (180-degree turns, w = 0, tiny w), q and -q identical; all
   particles in one point.
5. Bad input: zero, negative and NaN axes skip the particle, zero and non-unit quaternions are
   axis-aligned and normalised, an unusable axes array gives spheres; each with its warning.
   Tensors (TensorArrayName, as ParaView's Tensor Glyph takes them): the absolute eigenvalues are
   the axes, the picture is that of the axes and quaternions; a flat tensor is skipped.
6. Occlusion culling and picking work on ellipsoids; S-NDF on sub-pixel rods converges towards
   their super-sampled picture; the baseline picture (with its must-fail pictures) and the
   repeat of every frame.

usage: python3 TestEllipsoids.py --baseline B.png --temp DIR [--data D]
"""
import argparse
import math
import os
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import (Messages, actor_view, check, compare, finish, grab_image, particles_from,
                          picked_ids, quaternion_rotations, random_quaternions)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

parser = argparse.ArgumentParser()
parser.add_argument("--baseline")
parser.add_argument("--temp", default=".")
parser.add_argument("--data")
args = parser.parse_args()


def ellipsoid_view(xyz, axes, quats, size=(240, 240), diameters=False):
    """Ellipsoids with the point arrays 'axes' and 'quat': (mapper, actor, renderer, window)."""
    data = particles_from(np.asarray(xyz, dtype=np.float64),
                          axes=np.asarray(axes, dtype=np.float64),
                          quat=np.asarray(quats, dtype=np.float64))
    mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(data)
    mapper.SetShapeToEllipsoid()
    mapper.SetAxesArrayName("axes")
    mapper.SetOrientationArrayName("quat")
    mapper.SetAxesAreDiameters(diameters)
    actor, renderer, window = actor_view(mapper, size)
    actor.GetProperty().SetColor(0.85, 0.55, 0.3)
    actor.GetProperty().SetSpecular(0.3)
    actor.GetProperty().SetSpecularPower(20)
    renderer.SetBackground(0.1, 0.1, 0.15)
    return mapper, actor, renderer, window


def look(renderer, position, parallel=False, focal=None):
    camera = renderer.GetActiveCamera()
    camera.SetParallelProjection(parallel)
    camera.SetFocalPoint(*(focal if focal is not None else (0.0, 0.0, 0.0)))
    camera.SetPosition(*position)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCamera()
    if focal is not None:
        camera.SetFocalPoint(*focal)


def depth_buffer(window):
    from vtkmodules.vtkCommonCore import vtkFloatArray
    width, height = window.GetSize()
    z = vtkFloatArray()
    window.GetZbufferData(0, 0, width - 1, height - 1, z)
    return vtk_to_numpy(z).astype(np.float64)


def covered(window):
    return depth_buffer(window) < 1.0


rng = np.random.default_rng(44)

# ---- 1. equal axes: the sphere core's picture
grid = np.mgrid[0:4, 0:4, 0:4].reshape(3, -1).T.astype(np.float64)
xyz = grid + rng.uniform(-0.15, 0.15, size=grid.shape)
radius = 0.42  # neighbours intersect
quats = random_quaternions(len(xyz), rng)
for label, parallel, scale in (("perspective", False, 1.0), ("parallel", True, 1.0),
                               ("scaled actor x2.5", False, 2.5)):
    mapper, actor, renderer, window = ellipsoid_view(xyz, np.full((len(xyz), 3), radius), quats)
    actor.SetScale(scale)
    look(renderer, (9.0 * scale, 6.0 * scale, 12.0 * scale), parallel)
    ellipsoid_image = grab_image(window)[:, :3].astype(int)
    ellipsoid_depth = depth_buffer(window)
    check(mapper.GetDrawsEllipsoids(), label + ": drawn as ellipsoids")
    mapper.SetShapeToSphere()
    mapper.SetRadius(radius)
    sphere_image = grab_image(window)[:, :3].astype(int)
    sphere_depth = depth_buffer(window)
    check(not mapper.GetDrawsEllipsoids(), label + ": drawn as spheres")
    diff = np.abs(ellipsoid_image - sphere_image).max(axis=1)
    both = (ellipsoid_depth < 1) & (sphere_depth < 1)
    coverage = int(np.sum((ellipsoid_depth < 1) != (sphere_depth < 1)))
    # the depth away from silhouettes and intersection curves (where a grazing ray's depth is
    # ill-conditioned): pixels whose neighbours' window depths are within 1e-2 of their own
    side = int(math.sqrt(len(sphere_depth)))
    grid_depth = np.pad(sphere_depth.reshape(side, side), 1, mode="edge")
    jump = np.zeros((side, side))
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            jump = np.maximum(jump, np.abs(grid_depth[1 + dy:1 + dy + side, 1 + dx:1 + dx + side] -
                                           grid_depth[1:1 + side, 1:1 + side]))
    smooth = both & (jump.ravel() < 1e-2)
    depth_diff = np.abs(ellipsoid_depth - sphere_depth)
    depth = depth_diff[smooth].max()
    print("  window depth differences: all covered pixels max %.1f steps (p99.9 %.1f), "
          "%d smooth pixels max %.1f" % (depth_diff[both].max() * 2 ** 24,
                                         np.percentile(depth_diff[both], 99.9) * 2 ** 24,
                                         smooth.sum(), depth * 2 ** 24))
    print("equal axes, %s: %d covered pixels, colour differs in %d (%d by more than 1/255, "
          "largest %d/255), coverage in %d, window depth by %.1f steps of 2^-24"
          % (label, both.sum(), np.sum(diff > 0), np.sum(diff > 1), diff.max(), coverage,
             depth * 2 ** 24))
    check(both.sum() > 5000, label + ": particles drawn")
    check(np.sum(diff > 1) <= 2e-4 * both.sum(), label + ": %d pixels differ from the spheres by "
          "more than 1/255" % np.sum(diff > 1))
    check(coverage <= 2e-4 * both.sum(), label + ": coverage differs in %d pixels" % coverage)
    check(depth <= 16 * 2.0 ** -24, label + ": depth differs by %.1f steps" % (depth * 2 ** 24))

# ---- 2. against the reference: axis ratios 1:1:1 to 1:1:100
shapes = np.array([[1.0, 1.0, 1.0], [1.0, 0.5, 0.25], [1.0, 1.0, 0.1], [0.05, 0.05, 5.0],
                   [0.6, 0.2, 0.2], [0.3, 0.9, 0.45]])
xyz = rng.uniform(-3.0, 3.0, size=(60, 3))
axes = shapes[np.arange(len(xyz)) % len(shapes)] * 0.8
quats = random_quaternions(len(xyz), rng)
for label, parallel in (("perspective", False), ("parallel", True)):
    mapper, actor, renderer, window = ellipsoid_view(xyz, axes, quats, size=(300, 300))
    look(renderer, (8.0, 5.0, 14.0), parallel)
    window.Render()
    r = compare(window, renderer, actor, 0.8, normals=True)
    ref_rgb = vtk_to_numpy(r["reference"].GetColorImage().GetPointData().GetScalars())[:, :3]
    gpu_rgb = grab_image(window)[:, :3].astype(float)
    colour = np.abs(ref_rgb * 255.0 - gpu_rgb).max(axis=1)[r["smooth"]]
    print("reference, %s: %d covered, depth error mean %.2e max %.2e (largest axis 0.8 = 1) "
          "outside %d silhouette pixels, window depth %.1f steps, coverage differs in %d + %d, "
          "normals %.3f deg mean (p99 %.2f), colour mean %.3f max %.1f /255"
          % (label, r["covered"], r["mean"], r["max_smooth"], r["silhouette"],
             r["max_window"] * 2 ** 24, r["only_gpu"], r["only_ref"], r["normal_mean"],
             r["normal_p99"], colour.mean(), colour.max()))
    check(r["covered"] > 3000, label + ": ellipsoids drawn")
    check(r["max_smooth"] <= 1e-4, label + ": depth error %.2e" % r["max_smooth"])
    check(r["only_gpu"] + r["only_ref"] <= 2e-3 * r["covered"],
          label + ": coverage differs in %d pixels" % (r["only_gpu"] + r["only_ref"]))
    check(r["normal_mean"] <= 0.5, label + ": normals %.2f deg off" % r["normal_mean"])
    check(colour.mean() <= 0.5 and np.percentile(colour, 99.9) <= 2.0,
          label + ": colour %.2f/255 off on average" % colour.mean())
    if not parallel:
        # a wrong picture must fail the same criteria: the needles 1:1:2 instead of 1:1:100
        wrong_axes = axes.copy()
        wrong_axes[3::len(shapes)] = [0.05 * 0.8, 0.05 * 0.8, 0.1 * 0.8]
        wmapper, wactor, wrenderer, wwindow = ellipsoid_view(xyz, wrong_axes, quats, (300, 300))
        look(wrenderer, (8.0, 5.0, 14.0), parallel)
        wrenderer.SetActiveCamera(renderer.GetActiveCamera())
        wwindow.Render()
        wrong_cover = covered(wwindow)
        reference_cover = vtk_to_numpy(
            r["reference"].GetViewDepthImage().GetPointData().GetScalars()) >= 0
        wrong = int(np.sum(wrong_cover != reference_cover))
        print("must fail: short needles differ from the reference in %d pixels" % wrong)
        check(wrong > 2e-3 * r["covered"], "must fail: short needles pass the coverage criterion")

# ---- 3. closed form: the silhouette seen along each body axis (parallel projection)
a_b_c = np.array([60.0, 35.0, 20.0])  # semi-axes in pixels (parallel scale set below)
turn = np.array([math.cos(0.35), 0.0, 0.0, math.sin(0.35)])  # about z by 0.7 rad
rotation = quaternion_rotations(turn[None])[0]
size = 200
for axis in range(3):
    mapper, actor, renderer, window = ellipsoid_view([[0.0, 0.0, 0.0]], [a_b_c], [turn],
                                                     size=(size, size))
    body_axis = rotation[:, axis]
    up = rotation[:, (axis + 1) % 3]
    camera = renderer.GetActiveCamera()
    camera.SetParallelProjection(True)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(*(400.0 * body_axis))
    camera.SetViewUp(*up)
    camera.SetParallelScale(size / 2.0)  # one pixel = one unit
    camera.SetClippingRange(100.0, 700.0)
    window.Render()
    count = int(np.sum(covered(window)))
    others = [a_b_c[k] for k in range(3) if k != axis]
    area = math.pi * others[0] * others[1]
    # Gauss circle problem: the lattice count differs from the area by far less than the
    # perimeter (here < 1 %); the wrong axes (the other pair) are 30 % and more away
    mask = covered(window).reshape(size, size)
    rows = np.nonzero(mask.any(axis=1))[0]
    cols = np.nonzero(mask.any(axis=0))[0]
    extent = (cols[-1] - cols[0] + 1, rows[-1] - rows[0] + 1)
    # up is the next body axis: it runs along the window's y
    expected = (2 * a_b_c[(axis + 2) % 3], 2 * a_b_c[(axis + 1) % 3])
    print("along body axis %d: %d pixels, pi a b = %.1f (%.3f %%), extent %s, expected %s"
          % (axis, count, area, 100.0 * (count - area) / area, extent, expected))
    check(abs(count - area) <= 0.005 * area, "axis %d: silhouette area %d, expected %.1f"
          % (axis, count, area))
    check(abs(extent[0] - expected[0]) <= 1 and abs(extent[1] - expected[1]) <= 1,
          "axis %d: extent %s, expected %s" % (axis, extent, expected))

# ---- 4. extremes
# scaled scenes: the picture does not depend on the units
xyz = rng.uniform(-2.0, 2.0, size=(40, 3))
axes = shapes[np.arange(len(xyz)) % len(shapes)] * 0.6
quats = random_quaternions(len(xyz), rng)
images = {}
for scale in (1.0, 1e-6, 1e6):
    mapper, actor, renderer, window = ellipsoid_view(xyz * scale, axes * scale, quats)
    look(renderer, (6.0 * scale, 4.0 * scale, 10.0 * scale))
    images[scale] = grab_image(window)[:, :3].astype(int)
for scale in (1e-6, 1e6):
    diff = np.abs(images[scale] - images[1.0]).max(axis=1)
    print("scene x %g: %d pixels differ by more than 1/255 from the unit scene (largest %d)"
          % (scale, np.sum(diff > 1), diff.max()))
    check(np.sum(diff > 1) <= 20, "scene x %g: %d pixels differ" % (scale, np.sum(diff > 1)))

# camera 1e7 largest axes away, a narrow view: two intersecting needles and a disc
xyz = np.array([[0.0, 0.0, 0.0], [0.3, 0.1, 0.0], [-0.2, -0.3, 0.1]])
axes = np.array([[0.1, 0.1, 2.0], [0.1, 2.0, 0.1], [1.0, 1.0, 0.2]])
quats = random_quaternions(3, np.random.default_rng(5))
for label, distance in (("camera 1e7 axes away", 2.0e7), ("camera at 5 axes", 10.0)):
    mapper, actor, renderer, window = ellipsoid_view(xyz, axes, quats)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(0.3 * distance, 0.2 * distance, distance)
    camera.SetViewAngle(math.degrees(2 * math.atan(2.5 / distance)))
    renderer.ResetCameraClippingRange()
    window.Render()
    r = compare(window, renderer, actor, 2.0)
    print("%s: %d covered, coverage differs in %d + %d, depth error max %.2e axes, window depth "
          "%.1f steps of 2^-24 outside silhouettes" % (label, r["covered"], r["only_gpu"],
                                                       r["only_ref"], r["max_smooth"],
                                                       r["max_window"] * 2 ** 24))
    check(r["covered"] > 3000, label + ": drawn")
    check(r["only_gpu"] + r["only_ref"] <= 5e-3 * r["covered"],
          label + ": coverage differs in %d pixels" % (r["only_gpu"] + r["only_ref"]))
    # which surface is in front along the intersection curves: the window depth (its 24 bits
    # resolve only ~1e-2 axes at 1e7 axes: the depth buffer, not the ellipsoids, limits it)
    check(r["max_window"] <= 8 * 2.0 ** -24,
          label + ": window depth %.1f steps off" % (r["max_window"] * 2 ** 24))

# inside an ellipsoid: the inner side of its back surface, as the reference
mapper, actor, renderer, window = ellipsoid_view([[0.0, 0.0, 0.0], [0.0, 0.0, -4.0]],
                                                 [[3.0, 1.5, 5.0], [1.0, 1.0, 1.0]],
                                                 [np.array([0.9, 0.1, 0.3, 0.2]) / math.sqrt(0.95),
                                                  [1.0, 0, 0, 0]])
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(0, 0, -1)
camera.SetPosition(0.3, 0.2, 1.0)
camera.SetViewAngle(60)
camera.SetClippingRange(0.01, 50)
window.Render()
r = compare(window, renderer, actor, 1.0, normals=True)
inside = vtk_to_numpy(r["reference"].GetInsideImage()) != 0
print("inside an ellipsoid: %d covered (%d inside), coverage differs in %d + %d, depth error max "
      "%.2e (window depth %.1f steps), normals %.2f deg"
      % (r["covered"], inside.sum(), r["only_gpu"], r["only_ref"], r["max_smooth"],
         r["max_window"] * 2 ** 24, r["normal_mean"]))
check(inside.sum() > 0.5 * 240 * 240, "inside: the reference sees the inner surface")
check(r["only_gpu"] + r["only_ref"] <= 20, "inside: coverage differs")
check(r["max_window"] <= 8 * 2.0 ** -24,
      "inside: window depth %.1f steps off" % (r["max_window"] * 2 ** 24))
check(r["normal_mean"] <= 0.5, "inside: normals %.2f deg" % r["normal_mean"])

# quaternions at the singular cases; q and -q are the same turn, bit for bit
singular = np.array([[0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0],
                     [1e-7, 0.6, 0.8, 0.0], [-1.0, 0.0, 0.0, 0.0], [0.0, 0.6, 0.0, 0.8]])
xyz = np.array([[2.0 * i, 0.0, 0.0] for i in range(len(singular))])
axes = np.tile([0.8, 0.4, 0.15], (len(singular), 1))
pictures = []
for sign in (1.0, -1.0):
    mapper, actor, renderer, window = ellipsoid_view(xyz, axes, sign * singular, size=(360, 120))
    look(renderer, (5.0, 3.0, 6.0), focal=(5.0, 0.0, 0.0))
    pictures.append(grab_image(window)[:, :3])
    if sign > 0:
        r = compare(window, renderer, actor, 0.8, normals=True)
        print("singular quaternions: coverage differs in %d + %d of %d, depth error max %.2e, "
              "normals %.2f deg" % (r["only_gpu"], r["only_ref"], r["covered"], r["max_smooth"],
                                    r["normal_mean"]))
        check(r["only_gpu"] + r["only_ref"] <= 5e-3 * r["covered"] + 4,
              "singular quaternions: coverage")
        check(r["max_smooth"] <= 1e-4 and r["normal_mean"] <= 0.5,
              "singular quaternions: depth %.2e, normals %.2f" % (r["max_smooth"],
                                                                  r["normal_mean"]))
check(np.array_equal(pictures[0], pictures[1]), "q and -q draw different pictures")

# all particles in one point, in different orientations: a star of needles
count = 12
mapper, actor, renderer, window = ellipsoid_view(np.zeros((count, 3)), np.tile([0.1, 0.1, 2.0],
                                                                               (count, 1)),
                                                 random_quaternions(count, rng))
look(renderer, (3.0, 2.0, 5.0))
window.Render()
r = compare(window, renderer, actor, 2.0, normals=True)
print("one point: coverage differs in %d + %d of %d, depth error max %.2e, normals %.2f deg"
      % (r["only_gpu"], r["only_ref"], r["covered"], r["max_smooth"], r["normal_mean"]))
check(r["only_gpu"] + r["only_ref"] <= 5e-3 * r["covered"] + 4, "one point: coverage")
check(r["max_smooth"] <= 1e-4, "one point: depth error %.2e" % r["max_smooth"])

# ---- 5. bad input
xyz = np.array([[i * 1.5, 0.0, 0.0] for i in range(8)])
axes = np.tile([0.5, 0.3, 0.2], (8, 1))
axes[1, 0] = 0.0
axes[2, 1] = -0.3
axes[3, 2] = np.nan
quats = np.tile([1.0, 0.0, 0.0, 0.0], (8, 1))
quats[4] = 0.0
quats[5] = [np.inf, 0, 0, 0]
quats[6] = [2.0, 0.0, 0.0, 0.0]
mapper, actor, renderer, window = ellipsoid_view(xyz, axes, quats)
messages = Messages(mapper)
look(renderer, (5.0, 3.0, 10.0), focal=(5.0, 0.0, 0.0))
image = grab_image(window)
text = " ".join(messages.warnings)
print("bad input warnings: " + text)
check(mapper.GetNumberOfSkippedParticles() == 3, "bad axes: %d skipped, expected 3"
      % mapper.GetNumberOfSkippedParticles())
check("3 of 8 particles have a semi-axis" in text, "bad axes: warning")
check("2 of 8 particles have a zero, NaN or infinite orientation" in text,
      "bad quaternions: warning")
check("1 of 8 particles have an orientation quaternion whose length is not 1" in text,
      "non-unit quaternion: warning")
orientations = vtk_to_numpy(mapper.GetParticleOrientations())
check(np.allclose(orientations[4:7], [[1, 0, 0, 0]] * 3), "bad quaternions: axis-aligned")
check(np.all(vtk_to_numpy(mapper.GetParticleAxes())[1:4] == 0), "skipped: axes 0")
check(np.isfinite(image).all(), "bad input: finite picture")
for name, first, expect in (("nope", 0, "is not a point array"), ("axes", 1, "components 1 to 3")):
    mapper.SetAxesArrayName(name)
    mapper.SetAxesArrayComponent(first)
    window.Render()
    text = mapper.GetLastInputWarning()
    check(expect in text and "drawing spheres" in text and not mapper.GetDrawsEllipsoids(),
          "axes array %s[%d]: %s" % (name, first, text))
mapper.SetAxesArrayName("axes")
mapper.SetAxesArrayComponent(0)
mapper.SetOrientationArrayComponent(1)
window.Render()
text = mapper.GetLastInputWarning()
check("drawing the ellipsoids axis-aligned" in text and mapper.GetDrawsEllipsoids(),
      "orientation components: " + text)

# diameters (LAMMPS's shapex/y/z) are halved
mapper, actor, renderer, window = ellipsoid_view([[0.0, 0.0, 0.0]], [[1.0, 0.6, 0.4]],
                                                 [[1.0, 0.0, 0.0, 0.0]], diameters=True)
window.Render()
check(np.allclose(vtk_to_numpy(mapper.GetParticleAxes())[0], [0.5, 0.3, 0.2]),
      "diameters are halved")
check(abs(mapper.GetBounds()[1] - 0.5) < 1e-6, "bounds grow by the largest semi-axis")

# tensors (as ParaView's Tensor Glyph takes them): T = R diag(a) R^T, one eigenvalue negated
# for some (the same ellipsoid: |eigenvalue|), one flat tensor (an eigenvalue 0: skipped)
count = 30
tensor_rng = np.random.default_rng(99)  # (the scenes below keep their random numbers)
xyz = tensor_rng.uniform(-2.0, 2.0, size=(count, 3))
quats = random_quaternions(count, tensor_rng)
axes = tensor_rng.uniform(0.15, 0.8, size=(count, 3))
turns = quaternion_rotations(quats)
signs = np.ones((count, 3))
signs[::3, 0] = -1.0
tensors = np.einsum("nij,nj,nkj->nik", turns, axes * signs, turns).reshape(count, 9)
flat = tensors.copy()
flat[0] = np.einsum("ij,j,kj->ik", turns[0], [0.5, 0.3, 0.0], turns[0]).reshape(9)
pictures = []
for label, use_tensor in (("axes and quaternions", False), ("tensors", True)):
    data = particles_from(xyz, axes=axes, quat=quats, tensor=tensors, flat=flat)
    mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(data)
    mapper.SetShapeToEllipsoid()
    if use_tensor:
        mapper.SetTensorArrayName("tensor")
    else:
        mapper.SetAxesArrayName("axes")
        mapper.SetOrientationArrayName("quat")
    actor, renderer, window = actor_view(mapper, (240, 240))
    look(renderer, (6.0, 4.0, 10.0))
    pictures.append(grab_image(window)[:, :3].astype(int))
    if use_tensor:
        drawn = np.sort(vtk_to_numpy(mapper.GetParticleAxes()), axis=1)
        error = np.abs(drawn - np.sort(axes, axis=1)).max()
        print("tensors: eigenvalue semi-axes within %.1e of the axes" % error)
        check(error < 1e-5, "tensor eigenvalues: axes off by %.1e" % error)
        mapper.SetTensorArrayName("flat")
        window.Render()
        check(mapper.GetNumberOfSkippedParticles() == 1 and
              "semi-axis" in mapper.GetLastInputWarning(),
              "flat tensor: skipped with a warning (%s)" % mapper.GetLastInputWarning())
diff = np.abs(pictures[0] - pictures[1]).max(axis=1)
print("tensors vs axes and quaternions: %d pixels differ by more than 1/255 (largest %d)"
      % (np.sum(diff > 1), diff.max()))
check(np.sum(diff > 1) <= 10, "tensors draw another picture (%d pixels)" % np.sum(diff > 1))

# ---- 6. occlusion culling, picking, baseline
xyz = rng.uniform(0.0, 12.0, size=(20000, 3))
axes = shapes[np.arange(len(xyz)) % len(shapes)] * 0.5
axes[3::len(shapes)] *= 0.4  # needles 1:1:100 of length 2
quats = random_quaternions(len(xyz), rng)
mapper, actor, renderer, window = ellipsoid_view(xyz, axes, quats, size=(300, 300))
look(renderer, (30.0, 24.0, 36.0), focal=(6.0, 6.0, 6.0))
renderer.ResetCamera()
culled = grab_image(window)[:, :3]
drawn = mapper.GetOcclusionCuller().GetLastNumberOfDrawnParticles()
mapper.SetOcclusionCulling(False)
plain = grab_image(window)[:, :3]
diff = np.abs(culled.astype(int) - plain.astype(int)).max(axis=1)
print("occlusion culling: %d of %d ellipsoids drawn, %d pixels differ from the unculled picture"
      % (drawn, len(xyz), np.sum(diff > 0)))
check(0 < drawn < len(xyz), "occlusion culling skips hidden ellipsoids (%d drawn)" % drawn)
check(np.sum(diff > 0) == 0, "occlusion culling changes %d pixels" % np.sum(diff > 0))

mapper, actor, renderer, window = ellipsoid_view([[0.0, 0.0, 0.0], [3.0, 0.0, 0.0]],
                                                 [[0.05, 0.05, 2.0], [1.0, 1.0, 1.0]],
                                                 [[math.cos(0.4), 0.0, math.sin(0.4), 0.0],
                                                  [1.0, 0.0, 0.0, 0.0]])
look(renderer, (1.5, 0.0, 10.0), focal=(1.5, 0.0, 0.0))
window.Render()
mask = covered(window).reshape(240, 240)
ys, xs = np.nonzero(mask[:, :120])
centre = (int(np.median(xs)), int(np.median(ys)))
ids = picked_ids(renderer, (centre[0], centre[1], centre[0], centre[1]))
print("picking the needle at pixel %s: %s" % (centre, sorted(ids)))
check(ids == {0}, "picking the needle gives %s" % sorted(ids))

# S-NDF (scale-consistent shading) samples the ellipsoids' normals through the core's hooks: the
# converged picture of a block of sub-pixel rods approaches their 8x8 super-sampled picture
def rod_block(size, sndf=None):
    from prVTKTesting import crystal_view
    g = np.arange(14, dtype=np.float64)
    xyz = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1).reshape(-1, 3)
    block_rng = np.random.default_rng(14)
    rgb = (block_rng.uniform(0.3, 1.0, size=(len(xyz), 3)) * 255).astype(np.uint8)
    renderer, window, actor = crystal_view(xyz, rgb, size, sndf=sndf, position=(70, 50, 90),
                                           focal_point=(6.5, 6.5, 6.5))
    data = actor.GetMapper().GetInput()
    for name, values in (("axes", np.tile([0.15, 0.15, 0.45], (len(xyz), 1))),
                         ("quat", random_quaternions(len(xyz), block_rng))):
        from vtkmodules.util.numpy_support import numpy_to_vtk
        array = numpy_to_vtk(np.ascontiguousarray(values), deep=True)
        array.SetName(name)
        data.GetPointData().AddArray(array)
    mapper = actor.GetMapper()
    mapper.SetShapeToEllipsoid()
    mapper.SetAxesArrayName("axes")
    mapper.SetOrientationArrayName("quat")
    renderer.GetActiveCamera().SetViewAngle(12.0)
    return window


W, H, S = 160, 120, 8
from prVTKTesting import image_error, window_pixels  # noqa: E402
window = rod_block((W * S, H * S))
window.Render()
supersampled = window_pixels(window, W * S, H * S).reshape(H, S, W, S, 3).mean(axis=(1, 3))
window = rod_block((W, H))
window.Render()
plain = window_pixels(window, W, H)
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(32)
window = rod_block((W, H), sndf)
renders = 0
while not sndf.GetConverged() and renders < 200:
    window.Render()
    renders += 1
window.Render()
converged = window_pixels(window, W, H)
plain_error = image_error(plain, supersampled)
sndf_error = image_error(converged, supersampled)
print("S-NDF on sub-pixel rods: plain vs 8x8 super-sampled mean %.2f p99 %.1f /255; S-NDF (%d "
      "samples) mean %.2f p99 %.1f /255" % (plain_error[0], plain_error[1],
                                           sndf.GetNumberOfSamples(), sndf_error[0],
                                           sndf_error[1]))
check(sndf.GetConverged(), "S-NDF converges on ellipsoids")
check(sndf_error[0] < 0.5 * plain_error[0],
      "S-NDF does not bring the rods nearer the super-sampled picture (%.2f vs plain %.2f)"
      % (sndf_error[0], plain_error[0]))

if args.baseline:
    xyz = rng.uniform(-2.5, 2.5, size=(45, 3))
    axes = shapes[np.arange(len(xyz)) % len(shapes)] * 0.7
    axes[3::len(shapes)] *= 0.5
    quats = random_quaternions(len(xyz), rng)
    rgb = (rng.uniform(0.3, 1.0, size=(len(xyz), 3)) * 255).astype(np.uint8)
    mapper, actor, renderer, window = ellipsoid_view(xyz, axes, quats, size=(300, 300))
    colours = particles_from(xyz, c=rgb).GetPointData().GetArray("c")
    mapper.GetInput().GetPointData().SetScalars(colours)
    mapper.SetColorModeToDirectScalars()
    look(renderer, (7.0, 5.0, 11.0))
    renderer.GetActiveCamera().Zoom(1.8)
    renderer.ResetCameraClippingRange()
    renderer.SetBackground(0.95, 0.95, 0.92)
    window.Render()
    grab_image(window)
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    comparison = pr.vtkParticleImageComparison()
    name = os.path.splitext(os.path.basename(args.baseline))[0]
    check(comparison.TestImage(grab.GetOutput(), args.baseline, args.temp, name),
          "the picture differs from the baseline (see %s)" % args.temp)

sys.exit(finish())
