"""Translucent oriented ellipsoids (vtkTransparentSphereMapper, Shape Ellipsoid), plain VTK.

The emission-absorption model of the spheres through the affine map x = c + A u: the chord, the
impact parameter and the density profile are the unit sphere's, lengths are scaled by
1 / |A^-1 d| along each ray, and Theta_i is the opacity along the longest axis (the most opaque
ray of a physical density).
1. Closed form: one ellipsoid seen along each of its axes (parallel projection, emission only,
   black background): the centre pixel is 1 - (1 - Theta)^(a_k / a_max) for the constant
   density, 1 - (1 - Theta)^(a_k / (sqrt(2) a_max)) for the squared distance (whose most opaque
   chord has b^2 = 1/2), within 1/255.
2. Equal axes: translucent ellipsoids of semi-axes (r, r, r) in random orientations give the
   translucent spheres' picture (exact-overlap lists both), both density models and hollow.
3. Against the reference (its transparent mode integrates the same model in double): oriented
   ellipsoids of ratios 1:1:1 to 1:1:20, separate and intersecting, constant and squared-distance
   densities, solid and hollow, within 2/255; AUTOMATIC takes the exact lists for ellipsoids
   (the sort by centre is no visibility order for them); the sorted path, asked for, is off.
"""
import math
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import (Messages, check, finish, grab_image, offscreen_window, particles_from,
                          random_quaternions)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

M = pr.vtkTransparentSphereMapper
SIZE = 200


def scene(xyz, axes, quats, rgb, opacity=0.8, model=M.CONSTANT_DENSITY, hollow=0.0,
          mode=M.AUTOMATIC, size=SIZE, sphere_radius=None):
    data = particles_from(np.asarray(xyz, dtype=float), axes=np.asarray(axes, dtype=float),
                          quat=np.asarray(quats, dtype=float),
                          rgb=np.asarray(rgb, dtype=np.uint8))
    mapper = M()
    mapper.SetInputData(data)
    if sphere_radius is None:
        mapper.SetShapeToEllipsoid()
        mapper.SetAxesArrayName("axes")
        mapper.SetOrientationArrayName("quat")
    else:
        mapper.SetRadius(sphere_radius)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("rgb")
    mapper.SetColorModeToDirectScalars()
    mapper.SetDensityModel(model)
    mapper.SetHollowFraction(hollow)
    mapper.SetOverlapCompositing(mode)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetOpacity(opacity)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.1, 0.1, 0.1)
    window = offscreen_window(renderer, (size, size))
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(30)
    camera.Elevation(20)
    renderer.ResetCameraClippingRange()
    return mapper, actor, renderer, window, Messages(mapper)


def reference_image(renderer, actor):
    reference = pr.vtkParticleReferenceRenderer()
    reference.SetRenderer(renderer)
    reference.SetActor(actor)
    check(reference.Render(), "the reference renders")
    rgba = vtk_to_numpy(reference.GetColorImage().GetPointData().GetScalars())
    return np.round(np.clip(rgba[:, :3], 0.0, 1.0) * 255.0).astype(int)


def error(a, b):
    return np.abs(a.astype(int) - b.astype(int)).max(axis=1)


rng = np.random.default_rng(7)

# ---- 1. closed form: the opacity along each axis
axes = np.array([[1.0, 0.5, 0.25]])
theta = 0.8
for model, name in ((M.CONSTANT_DENSITY, "constant"), (M.SQUARED_DISTANCE_DENSITY, "squared")):
    for k in range(3):
        mapper, actor, renderer, window, _ = scene([[0.0, 0.0, 0.0]], axes, [[1.0, 0, 0, 0]],
                                                   [[255, 255, 255]], opacity=theta, model=model,
                                                   size=101)
        mapper.SetVolumeMix(1.0)  # the colour is the volume's: Theta * c
        renderer.SetBackground(0.0, 0.0, 0.0)
        camera = renderer.GetActiveCamera()
        camera.SetParallelProjection(True)
        direction = np.eye(3)[k]
        camera.SetFocalPoint(0, 0, 0)
        camera.SetPosition(*(10.0 * direction))
        camera.SetViewUp(*np.eye(3)[(k + 1) % 3])
        camera.SetParallelScale(1.2)
        camera.SetClippingRange(5.0, 15.0)
        window.Render()
        image = grab_image(window)[:, :3].reshape(101, 101, 3)
        centre = image[50, 50, 0]
        # the chord through the centre along axis k, in the unit frame I(0) scaled by a_k;
        # the most opaque ray: the longest axis at the model's most opaque impact parameter b*.
        # Constant: I(b) = 2 sqrt(1 - b^2), b* = 0. Squared distance: I(b) = (2/3) sqrt(1 - b^2)
        # (1 + 2 b^2), b*^2 = 1/2, I(b*) = 2 sqrt(2) / 3 = sqrt(2) I(0).
        ratio = 1.0 if model == M.CONSTANT_DENSITY else 1.0 / math.sqrt(2.0)
        expected = 1.0 - (1.0 - theta) ** (ratio * axes[0, k] / axes[0].max())
        print("%s density, along axis %d: centre %d/255, closed form %.2f/255"
              % (name, k, centre, expected * 255.0))
        check(abs(centre - expected * 255.0) <= 1.0,
              "%s, axis %d: centre %d/255, expected %.2f" % (name, k, centre, expected * 255.0))

# ---- 2. equal axes: the spheres' picture
xyz = rng.uniform(-2.0, 2.0, size=(25, 3))
quats = random_quaternions(len(xyz), rng)
rgb = (rng.uniform(0.2, 1.0, size=(len(xyz), 3)) * 255).astype(np.uint8)
for model, hollow, name in ((M.CONSTANT_DENSITY, 0.0, "constant"),
                            (M.SQUARED_DISTANCE_DENSITY, 0.0, "squared"),
                            (M.CONSTANT_DENSITY, 0.5, "hollow")):
    images = []
    for radius in (None, 0.7):
        mapper, actor, renderer, window, _ = scene(
            xyz, np.full((len(xyz), 3), 0.7), quats, rgb, model=model, hollow=hollow,
            mode=M.EXACT_OVERLAP, sphere_radius=radius)
        window.Render()
        images.append(grab_image(window)[:, :3])
        check(mapper.GetExactOverlapInUse(), name + ": exact lists")
    diff = error(images[0], images[1])
    print("equal axes, %s: %d pixels differ, largest %d/255" % (name, np.sum(diff > 0),
                                                                 diff.max()))
    check(diff.max() <= 1, "equal axes, %s: %d/255 from the spheres" % (name, diff.max()))

# ---- 3. against the reference
shapes = np.array([[1.0, 1.0, 1.0], [1.0, 0.5, 0.25], [0.15, 0.15, 3.0], [0.8, 0.8, 0.3]])
separate = np.array([[x, y, 0.0] for x in (-3.0, 0.0, 3.0) for y in (-3.0, 0.0, 3.0)])
crowded = rng.uniform(-1.2, 1.2, size=(14, 3))
for label, xyz in (("separate", separate), ("intersecting", crowded)):
    axes = shapes[np.arange(len(xyz)) % len(shapes)] * 0.6
    quats = random_quaternions(len(xyz), rng)
    rgb = (rng.uniform(0.2, 1.0, size=(len(xyz), 3)) * 255).astype(np.uint8)
    for model, hollow, name in ((M.CONSTANT_DENSITY, 0.0, "constant"),
                                (M.SQUARED_DISTANCE_DENSITY, 0.0, "squared"),
                                (M.SQUARED_DISTANCE_DENSITY, 0.5, "squared hollow")):
        mapper, actor, renderer, window, messages = scene(xyz, axes, quats, rgb, opacity=0.85,
                                                          model=model, hollow=hollow)
        window.Render()
        gpu = grab_image(window)[:, :3]
        expected = reference_image(renderer, actor)
        diff = error(gpu, expected)
        covered = int(np.sum(np.any(expected != 26, axis=1)))
        print("%s, %s: exact lists %s, %d covered pixels, error mean %.3f max %d/255 (%d over "
              "2/255)" % (label, name, mapper.GetExactOverlapInUse(), covered, diff.mean(),
                          diff.max(), np.sum(diff > 2)))
        check(mapper.GetExactOverlapInUse(), "%s, %s: AUTOMATIC takes the lists" % (label, name))
        check(covered > 800, "%s, %s: drawn" % (label, name))
        check(np.sum(diff > 2) <= 1e-3 * covered,
              "%s, %s: %d pixels over 2/255" % (label, name, np.sum(diff > 2)))
        check(not messages.text, "%s, %s: no warnings %s" % (label, name, messages.text))
        if label == "intersecting" and hollow == 0.0:
            # must fail: the sorted path composites each ellipsoid whole
            mapper.SetOverlapCompositing(M.SORTED_SPHERES)
            window.Render()
            sorted_diff = error(grab_image(window)[:, :3], expected)
            print("  sorted instead: %d pixels over 2/255, largest %d/255"
                  % (np.sum(sorted_diff > 2), sorted_diff.max()))
            check(np.sum(sorted_diff > 2) > 1e-3 * covered,
                  "must fail: the sorted path passes on intersecting ellipsoids")

# the data turns from spheres into ellipsoids (its axes array appears) while both the opaque and
# the translucent programs are in use (per-particle opacities 1 and 0.5): each is rebuilt for
# ellipsoids, the picture is a fresh mapper's
xyz = rng.uniform(-2.0, 2.0, size=(20, 3))
axes = shapes[np.arange(len(xyz)) % len(shapes)] * 0.6
quats = random_quaternions(len(xyz), rng)
rgb = (rng.uniform(0.2, 1.0, size=(len(xyz), 3)) * 255).astype(np.uint8)
alpha = np.where(np.arange(len(xyz)) % 2 == 0, 1.0, 0.5)
pictures = []
for late in (True, False):
    mapper, actor, renderer, window, messages = scene(xyz, axes, quats, rgb, opacity=1.0)
    data = mapper.GetInput()
    data.GetPointData().AddArray(particles_from(xyz, alpha=alpha).GetPointData().GetArray("alpha"))
    mapper.SetOpacityArrayName("alpha")
    mapper.SetOpacityRange(0.0, 1.0)
    mapper.SetRadius(0.5)
    if late:
        saved = data.GetPointData().GetArray("axes")
        data.GetPointData().RemoveArray("axes")
        window.Render()
        check(not mapper.GetDrawsEllipsoids(), "without the axes array: spheres")
        data.GetPointData().AddArray(saved)
        data.Modified()
    window.Render()
    check(mapper.GetDrawsEllipsoids(), "with the axes array: ellipsoids")
    pictures.append(grab_image(window)[:, :3])
diff = error(pictures[0], pictures[1])
print("spheres turned ellipsoids: %d pixels differ from a fresh mapper's picture (largest %d)"
      % (np.sum(diff > 0), diff.max()))
check(diff.max() == 0, "a program kept the sphere variant after the data became ellipsoids")

# the camera inside a translucent ellipsoid (its chord starts at the near plane)
mapper, actor, renderer, window, _ = scene([[0.0, 0.0, 0.0], [0.5, 0.3, -3.0]],
                                           [[3.0, 1.5, 5.0], [0.6, 0.6, 0.6]],
                                           [[math.cos(0.3), 0.0, math.sin(0.3), 0.0],
                                            [1.0, 0, 0, 0]],
                                           [[200, 120, 60], [60, 200, 220]])
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(0, 0, -1)
camera.SetPosition(0.3, 0.2, 1.0)
camera.SetViewAngle(60)
camera.SetClippingRange(0.01, 50)
window.Render()
diff = error(grab_image(window)[:, :3], reference_image(renderer, actor))
print("inside: error mean %.3f max %d/255" % (diff.mean(), diff.max()))
check(np.sum(diff > 2) <= 1e-3 * diff.size, "inside: %d pixels over 2/255" % np.sum(diff > 2))

sys.exit(finish())
