"""Long columns of overlapping translucent spheres with mixed opacities and colours
(vtkTransparentSphereMapper's EXACT_OVERLAP, vtkParticleFragmentLists) against the
double-precision reference, and split into two clip boxes along the view (what distributed
rendering composites) against the whole.

Scene: 1 000 spheres of radius 0.9-1.5 at a mean spacing of 0.9 in a 6 x 6 x 20 block seen end
on, 64 x 64 (about 70 segments per pixel list, every pixel to the second pass; more than 15 at
one point on about a third of them, which go to the third), two colours, Theta from a
per-particle array (0.2-1.0) times 0.7 of the column (COLUMN_OPACITY: 37 layers, the whole depth
stays translucent, so the back of every list counts), both density models; and the
squared-distance density with Theta 0.5 of one particle.

This is where the squared-distance density went wrong: the colour weights' quadrature, written as
a loop over the segments inside the loop over the nodes, came out of Mesa's llvmpipe (Mesa 22)
with wrong opacities on the long lists (here 30/255 on 298 of 4 096 pixels, different in the
next frame; the two boxes 29/255 off the whole), although nothing in it writes what the opacity
reads. The weights are now three moments of the transmittance (FragmentListResolve.glsl).

Criteria (8-bit, each image rounded once): RGB and alpha within 2/255 of the reference on every
pixel; the two boxes composited "over" within 2/255 of the whole; the lists' second and third
passes ran, nothing incomplete; the frame repeats bit for bit (once: the squared-distance density
with the column opacity, where the frames differed; a frame costs 5-7 s on Mesa 25 and 26). Must
fail: the sorted spheres on the particle-opacity scene are more than 10/255 off the reference
(measured 29/255: the test tells the two apart).

usage: python3 TestDeepOverlapColumns.py   (PYTHONPATH: the build's python3/dist-packages)
"""
import sys

import numpy as np

import particlerendering as pr
from vtkmodules.vtkCommonCore import vtkSMPTools
from prVTKTesting import check, check_repeatable, composite_over, finish, particles_from
from prVTKTesting import transparent_view
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

M = pr.vtkTransparentSphereMapper
vtkSMPTools.SetBackend("STDThread")  # the reference's rows in parallel where VTK has threads
SIZE = (64, 64)
rng = np.random.default_rng(11)
N = 1000
XYZ = rng.uniform((0.0, 0.0, 0.0), (6.0, 6.0, 20.0), size=(N, 3))
RADII = rng.uniform(0.9, 1.5, size=N)
KIND = rng.integers(0, 2, size=N).astype(float)
SPEED = rng.uniform(0.2, 1.0, size=N)
SPLIT = 9.7  # a plane z = SPLIT across the view
COLUMN_THETA = 0.7  # of the column (COLUMN_OPACITY)
PARTICLE_THETA = 0.5  # of one particle (PARTICLE_OPACITY)


def scene(model, mode, reference_kind, opacity):
    data = particles_from(XYZ, radius=RADII, kind=KIND, speed=SPEED)
    mapper = M()
    mapper.SetInputData(data)
    mapper.SetRadiusArrayName("radius")
    mapper.SetDensityModel(model)
    mapper.SetOverlapCompositing(mode)
    mapper.SetOpacityReference(reference_kind)
    mapper.SetOpacityArrayName("speed")
    colours = vtkColorTransferFunction()
    colours.AddRGBPoint(0.0, 0.2, 0.4, 0.9)
    colours.AddRGBPoint(1.0, 0.9, 0.35, 0.2)
    mapper.SetLookupTable(colours)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("kind")
    mapper.ScalarVisibilityOn()
    actor, renderer, window = transparent_view(mapper, SIZE)
    actor.GetProperty().SetOpacity(opacity)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(3.0, 3.0, 10.0)
    camera.SetPosition(4.0, 3.5, 34.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetViewAngle(20.0)
    camera.SetClippingRange(5.0, 60.0)
    return mapper, actor, renderer, window


def gpu_image(window):
    """The window's RGBA pixels (alpha: the particles' accumulated opacity)."""
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGBA()
    grab.ReadFrontBufferOff()
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float)


def reference_image(renderer, actor):
    reference = pr.vtkParticleReferenceRenderer()
    reference.SetRenderer(renderer)
    reference.SetActor(actor)
    check(reference.Render(), "the reference renders")
    rgba = vtk_to_numpy(reference.GetColorImage().GetPointData().GetScalars())
    return np.round(np.clip(rgba, 0.0, 1.0) * 255.0)


def check_against_reference(name, model, reference_kind, opacity, repeat=False):
    """The exact lists against the reference (and, with `repeat`, the frame drawn twice);
    returns the scene and the reference image."""
    mapper, actor, renderer, window = scene(model, M.EXACT_OVERLAP, reference_kind, opacity)
    whole = gpu_image(window)
    if repeat:
        check_repeatable(window, name)
    lists = mapper.GetFragmentLists()
    reference = reference_image(renderer, actor)
    error = np.abs(whole - reference).max(axis=1)
    covered = int(np.count_nonzero(reference[:, 3] > 0))
    print("%s: %d fragments, %d pixels in the second pass, %d in the third, %d incomplete; %.1f"
          " column layers; max %d/255 against the reference (alpha %d), %d pixels over 2/255, %d"
          " covered" % (name, lists.GetLastNumberOfFragments(),
                        lists.GetLastNumberOfDeferredPixels(), lists.GetLastNumberOfDeepPixels(),
                        lists.GetLastNumberOfIncompletePixels(), mapper.GetEffectiveColumnLayers(),
                        error.max(), np.abs(whole[:, 3] - reference[:, 3]).max(),
                        np.count_nonzero(error > 2), covered))
    check(covered > error.size // 2, "%s: the block covers %d pixels only" % (name, covered))
    deferred = lists.GetLastNumberOfDeferredPixels()
    check(deferred > covered // 2, "%s: the long lists' pass ran on %d pixels only"
          % (name, deferred))
    check(lists.GetLastNumberOfDeepPixels() > 0, "%s: the third pass did not run" % name)
    check(lists.GetLastNumberOfIncompletePixels() == 0, "%s: incomplete pixels" % name)
    check(error.max() <= 2.0, "%s: max %d/255 against the reference" % (name, error.max()))
    return (mapper, actor, renderer, window), whole, reference


def check_split(name, objects, whole):
    """The block in two boxes along the view (the same mapper clipped to each in turn),
    composited "over", against the whole."""
    mapper, window = objects[0], objects[3]
    big = 1e3
    images = []
    for box in ((-big, big, -big, big, SPLIT, big), (-big, big, -big, big, -big, SPLIT)):
        mapper.SetClipBox(box)
        images.append(gpu_image(window))
    mapper.SetClipBox([1.0, -1.0, 1.0, -1.0, 1.0, -1.0])  # off again
    split = np.abs(composite_over(images[0], images[1]) - whole).max(axis=1)
    print("%s: two boxes composited: max %d/255 against the whole, %d pixels over 2/255"
          % (name, split.max(), np.count_nonzero(split > 2)))
    check(split.max() <= 2.0, "%s: the two boxes are %d/255 off the whole" % (name, split.max()))


# the column opacity (the back of every list counts): both models, whole and in two boxes
for model, name in ((M.SQUARED_DISTANCE_DENSITY, "squared"), (M.CONSTANT_DENSITY, "constant")):
    label = "%s density, column opacity" % name
    objects, whole, _ = check_against_reference(label, model, M.COLUMN_OPACITY, COLUMN_THETA,
                                                repeat=model == M.SQUARED_DISTANCE_DENSITY)
    check_split(label, objects, whole)

# Theta of one particle (denser spheres: the order matters), and the sorted spheres rejected
label = "squared density, particle opacity"
objects, _, reference = check_against_reference(label, M.SQUARED_DISTANCE_DENSITY,
                                                M.PARTICLE_OPACITY, PARTICLE_THETA)
objects[0].SetOverlapCompositing(M.SORTED_SPHERES)
sorted_error = np.abs(gpu_image(objects[3]) - reference).max(axis=1).max()
print("%s: sorted spheres max %d/255 against the reference" % (label, sorted_error))
check(sorted_error > 10.0, "%s: the sorted spheres are not rejected (max %d/255)"
      % (label, sorted_error))

sys.exit(finish())
