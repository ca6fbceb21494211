"""vtkParticleSphereMapper::SetClipBox (distributed rendering, Shaders/Core/ClipBox.glsl) without MPI:
the particles drawn into two boxes that split their bounds, each image with a transparent
background, composited "over" front to back, must equal the image of all particles -- what
IceT does with the processes' images.

Scene: a random cluster of 3000 overlapping spheres (radii 0.3-0.7 in a 12^3 box), split by a
plane through its middle that cuts many spheres, seen from above the plane (the upper box is in
front). Cases: translucent (opacity 0.7; Constant and Squared Distance density models, the
chord integrated inside each box with the whole sphere's colour), the same 1e7 radii away from
the origin (box and particles shifted), and opaque spheres (the visible point decides).
Criteria (8-bit RGBA images, each rounded once): translucent max 2/255 per channel; opaque at
most 0.1 % of the pixels over 2/255 (a hit exactly on the plane may round to either side).
Also: without the clip box the composite of the same data (each box's particles drawn whole,
ghosts included) is rejected -- the test can fail.

usage: python3 TestClipBox.py   (PYTHONPATH: the build's python3/dist-packages)
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import check, check_repeatable, composite_over, finish, particles_from
from prVTKTesting import transparent_view
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

SIZE = (300, 240)
rng = np.random.default_rng(7)
N = 3000
XYZ = rng.uniform(-6.0, 6.0, size=(N, 3))
RADII = rng.uniform(0.3, 0.7, size=N)
SPLIT = 0.13  # a plane z = SPLIT through the middle


def render(xyz, offset, opacity, model, box, drawn=None):
    """RGBA floats of the particles (those with drawn[i], all by default) clipped to box."""
    keep = np.ones(len(xyz), bool) if drawn is None else drawn
    data = particles_from(xyz[keep] + offset, radius=RADII[keep])
    mapper = pr.vtkTransparentSphereMapper()
    mapper.SetInputData(data)
    mapper.SetRadiusArrayName("radius")
    mapper.SetDensityModel(model)
    if box is not None:
        mapper.SetClipBox([box[0] + offset[0], box[1] + offset[0], box[2] + offset[1],
                           box[3] + offset[1], box[4] + offset[2], box[5] + offset[2]])
    actor, renderer, window = transparent_view(mapper, SIZE)
    actor.GetProperty().SetColor(0.85, 0.45, 0.2)
    actor.GetProperty().SetOpacity(opacity)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(offset[0], offset[1], offset[2])
    camera.SetPosition(offset[0] + 14.0, offset[1] - 18.0, offset[2] + 22.0)
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.SetClippingRange(5.0, 80.0)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGBA()
    grab.ReadFrontBufferOff()
    grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float)
    check_repeatable(window)
    return pixels


def run(label, offset, opacity, model, opaque):
    big = 1e3
    upper = (-big, big, -big, big, SPLIT, big)
    lower = (-big, big, -big, big, -big, SPLIT)
    full = render(XYZ, offset, opacity, model, None)
    both = composite_over(render(XYZ, offset, opacity, model, upper),
                     render(XYZ, offset, opacity, model, lower))
    error = np.abs(both - full).max(axis=1)
    over = int(np.count_nonzero(error > 2.0))
    covered = int(np.count_nonzero(full[:, 3] > 0))
    print("%s: max %.0f/255, %d of %d pixels over 2/255 (%d covered)"
          % (label, error.max(), over, error.size, covered))
    check(covered > error.size // 4, "%s: the scene covers %d pixels only" % (label, covered))
    if opaque:
        check(over <= 1e-3 * error.size, "%s: %d pixels over 2/255" % (label, over))
    else:
        check(error.max() <= 2.0, "%s: max %.0f/255 > 2/255" % (label, error.max()))
    return full


full = run("translucent, constant density", (0.0, 0.0, 0.0), 0.7, 0, False)
run("translucent, squared-distance density", (0.0, 0.0, 0.0), 0.7, 1, False)
run("translucent, 1e7 radii from the origin", (1e7 * 0.5, 0.0, 0.0), 0.7, 0, False)
run("opaque", (0.0, 0.0, 0.0), 1.0, 0, True)

# must fail: each box's particles (centre in it, plus the spheres reaching into it) drawn whole
upper_set = XYZ[:, 2] + RADII >= SPLIT
lower_set = XYZ[:, 2] - RADII < SPLIT
unclipped = composite_over(render(XYZ, (0.0, 0.0, 0.0), 0.7, 0, None, upper_set),
                      render(XYZ, (0.0, 0.0, 0.0), 0.7, 0, None, lower_set))
wrong = np.abs(unclipped - full).max(axis=1).max()
print("without the clip box (ghosts drawn whole): max %.0f/255" % wrong)
check(wrong > 10.0, "the composite without clipping is not rejected (max %.0f/255)" % wrong)
sys.exit(finish())
