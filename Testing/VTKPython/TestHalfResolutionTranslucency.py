"""The cheapest interactive level of vtkTransparentSphereMapper: the sorted spheres accumulated at
half the viewport's resolution (vtkParticleFrontToBackTarget::SetDownsampling(2)) and upsampled
bilinearly over the full-resolution opaque image.

Scene: three large overlapping translucent spheres (40-70 pixels radius) in front of, around and
behind an opaque sphere, 301 x 201 pixels (odd: the half-resolution buffer is 151 x 101 and must
still cover the view exactly). The half-resolution picture (Quality INTERACTIVE) against the exact
one (Quality EXACT, the same sorted spheres at full resolution):
- within 3/255 wherever the exact picture is smooth (no colour step of more than 8/255 within
  2 pixels: about 80 % of this view, away from silhouettes and from the translucent spheres'
  edges against the opaque one; bilinear upsampling is exact to first order, its error grows with
  the picture's curvature, steepest at a translucent sphere's rim); larger differences lie only
  at such steps;
- but not equal (the cheap picture is the cheaper one);
- the criterion rejects a wrong picture: the frame without the translucent spheres, and the
  translucent spheres shifted by 2 pixels (must-fail);
- the same in a multisampled window (4 samples: the opaque depth is resolved before it is
  reduced) and with VTK's dual depth peeling and a translucent polygon in the view (the opaque
  image saved by the peeling pass);
- every frame drawn twice is identical, with no OpenGL error (grab_image).
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import check, finish, grab_image, offscreen_window, particles_from
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)

B = pr.vtkParticleFrameBudget
WIDTH, HEIGHT = 301, 201
SMOOTH_STEP = 8  # 1/255: the largest colour step within 2 pixels of a "smooth" pixel
TOLERANCE = 3  # 1/255, at smooth pixels


def build(samples=0, peeling=False):
    renderer = vtkRenderer()
    renderer.SetBackground(0.15, 0.15, 0.2)
    opaque = pr.vtkParticleSphereMapper()
    opaque.SetInputData(particles_from(np.array([[0.3, 0.0, 0.0]]),
                                       radius=np.array([0.9], dtype=np.float32)))
    opaque.SetRadiusArrayName("radius")
    opaque_actor = vtkActor()
    opaque_actor.SetMapper(opaque)
    opaque_actor.GetProperty().SetColor(0.9, 0.8, 0.2)
    renderer.AddActor(opaque_actor)

    xyz = np.array([[-1.2, 0.2, 1.0], [0.0, -0.3, -0.5], [1.3, 0.4, 1.5]])
    translucent = pr.vtkTransparentSphereMapper()
    translucent.SetInputData(particles_from(
        xyz, radius=np.array([1.4, 1.1, 1.0], dtype=np.float32),
        type=np.array([0.0, 1.0, 2.0], dtype=np.float32)))
    translucent.SetRadiusArrayName("radius")
    translucent.SetScalarModeToUsePointFieldData()
    translucent.SelectColorArray("type")
    translucent.SetScalarRange(0, 2)
    actor = vtkActor()
    actor.SetMapper(translucent)
    actor.GetProperty().SetOpacity(0.5)
    renderer.AddActor(actor)
    if peeling:
        plane = vtkPlaneSource()
        plane.SetOrigin(-3.5, -2.5, -2.0)
        plane.SetPoint1(3.5, -2.5, -2.0)
        plane.SetPoint2(-3.5, 2.5, -2.0)
        plane_mapper = vtkPolyDataMapper()
        plane_mapper.SetInputConnection(plane.GetOutputPort())
        plane_actor = vtkActor()
        plane_actor.SetMapper(plane_mapper)
        plane_actor.GetProperty().SetColor(0.2, 0.7, 0.3)
        plane_actor.GetProperty().SetOpacity(0.4)
        renderer.AddActor(plane_actor)
        renderer.SetUseDepthPeeling(1)
        renderer.SetMaximumNumberOfPeels(8)
        renderer.SetOcclusionRatio(0.0)
    window = offscreen_window(renderer, (WIDTH, HEIGHT), samples)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.0, 0.0, 9.0)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    renderer.ResetCameraClippingRange()
    return window, renderer, translucent, actor


def picture(window, translucent, quality):
    translucent.GetFrameBudget().SetQuality(quality)
    return grab_image(window)[:, :3].reshape(HEIGHT, WIDTH, 3)


def steps(image):
    """Per pixel: the largest colour difference to any pixel within 2 pixels."""
    padded = np.pad(image, ((2, 2), (2, 2), (0, 0)), mode="edge")
    largest = np.zeros(image.shape[:2], dtype=int)
    for dy in range(5):
        for dx in range(5):
            shifted = padded[dy:dy + HEIGHT, dx:dx + WIDTH]
            largest = np.maximum(largest, np.abs(shifted - image).max(axis=2))
    return largest


def meets(cheap, exact):
    """The criterion: within TOLERANCE where the exact picture is smooth. Returns (meets, pixels
    over TOLERANCE at smooth pixels, largest difference there, pixels over 2/255 in all)."""
    difference = np.abs(cheap - exact).max(axis=2)
    smooth = steps(exact) <= SMOOTH_STEP
    bad = (difference > TOLERANCE) & smooth
    largest = int(difference[smooth].max()) if smooth.any() else 0
    return not bad.any(), int(bad.sum()), largest, int((difference > 2).sum())


for name, samples, peeling in (("plain", 0, False), ("4 samples", 4, False),
                               ("dual depth peeling", 0, True)):
    window, renderer, translucent, actor = build(samples, peeling)
    exact = picture(window, translucent, B.EXACT)
    cheap = picture(window, translucent, B.INTERACTIVE)
    budget = translucent.GetFrameBudget()
    check(budget.GetLastLevel() == 0 and
          budget.GetLastChoiceText(translucent.GetQualityLevelNames()).startswith(
              "half resolution, sorted spheres"),
          "%s: INTERACTIVE draws the half-resolution level" % name)
    ok, count, largest, over = meets(cheap, exact)
    print("%s: half resolution vs full: %d pixels over 2/255, %d over 3/255 at smooth pixels "
          "(largest there %d/255), max %d/255"
          % (name, over, count, largest, int(np.abs(cheap - exact).max())))
    check(ok, "%s: within 3/255 of the full-resolution picture wherever it is smooth" % name)
    check(over > 0, "%s: the half-resolution picture differs (at edges)" % name)

    # must-fail: the criterion rejects the frame without the translucent spheres ...
    actor.VisibilityOff()
    without = picture(window, translucent, B.EXACT)
    actor.VisibilityOn()
    rejected = meets(without, exact)
    check(not rejected[0], "%s: must-fail: the frame without the translucent spheres is rejected"
          " (%d pixels over 3/255 at smooth pixels)" % (name, rejected[1]))
    # ... and the translucent spheres 2 pixels off
    rejected = meets(np.roll(cheap, 2, axis=1), exact)
    check(not rejected[0], "%s: must-fail: the picture shifted by 2 pixels is rejected (%d pixels)"
          % (name, rejected[1]))
    print("%s: must-fail pictures: %d and %d pixels over 3/255 at smooth pixels"
          % (name, meets(without, exact)[1], rejected[1]))

    # back to exact: the full-resolution picture again, bit for bit
    check(np.array_equal(picture(window, translucent, B.EXACT), exact),
          "%s: the exact frame after the half-resolution one is the first, bit for bit" % name)

sys.exit(finish())
