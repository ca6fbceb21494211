"""Occlusion culling of opaque particles (vtkParticleOcclusionCuller through
vtkParticleSphereMapper) changes nothing in the picture and skips hidden particles.

A dense block (a 40^3 simple cubic lattice with random radii 0.3-0.5, coloured by a random
scalar, 400x300, no multisampling) is rendered with culling on (threshold 0) and off, from
views that stress the conservative tests: the default view, an oblique orbit, a close-up, the eye
inside the block (and inside a sphere), a parallel projection, a scaled and rotated actor, and the
whole block moved 1e6 away from the origin with the camera following. Checked:
- the images with and without culling are equal (at most 0.02 % of the pixels may differ, where
  two touching spheres have the same depth to the last bit and the drawing order decides; every
  run so far: none);
- culling did its work: three depth read-backs, and in the oblique views fewer than half of
  the spheres leave the geometry stage (GL_PRIMITIVES_GENERATED: hidden cells and hidden single
  spheres skipped);
- a multisampled window (glReadPixels cannot read it) and picking fall back to the plain draw
  with the same results; the opaque particles of vtkTransparentSphereMapper are culled too.

usage: python3 TestOcclusionCulling.py
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import check, finish, grab_image, picked_ids
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkLookupTable, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkRenderer,
    vtkRenderWindow,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory overrides)

SIDE = 40
rng = np.random.default_rng(3)
grid = np.stack(np.meshgrid(*(np.arange(SIDE),) * 3, indexing="ij"), axis=-1).reshape(-1, 3)
N = grid.shape[0]


def block(offset=0.0):
    points = vtkPoints()
    points.SetDataTypeToDouble()
    points.SetData(numpy_to_vtk(grid.astype(np.float64) + np.array([offset, 0.0, 0.0]), deep=True))
    data = vtkPolyData()
    data.SetPoints(points)
    radius = numpy_to_vtk(rng.uniform(0.3, 0.5, N).astype(np.float32), deep=True)
    radius.SetName("radius")
    data.GetPointData().AddArray(radius)
    value = numpy_to_vtk(rng.random(N).astype(np.float32), deep=True)
    value.SetName("value")
    data.GetPointData().SetScalars(value)
    return data


def render(data, cull, view, mapper_class=pr.vtkParticleSphereMapper, samples=0, pick=False):
    renderer = vtkRenderer()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(samples)
    window.SetSize(400, 300)
    window.AddRenderer(renderer)
    mapper = mapper_class()
    mapper.SetInputData(data)
    mapper.SetRadiusArrayName("radius")
    lut = vtkLookupTable()
    lut.SetHueRange(0.0, 0.66)
    lut.Build()
    mapper.SetLookupTable(lut)
    mapper.SetScalarRange(0.0, 1.0)
    mapper.SetOcclusionCulling(cull)
    mapper.SetOcclusionCullingThreshold(0)
    mapper.GetOcclusionCuller().SetCountEmittedSpheres(True)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetSpecular(0.3)
    renderer.AddActor(actor)
    renderer.ResetCamera()
    view(renderer, actor)
    window.Render()
    image = grab_image(window)
    culler = mapper.GetOcclusionCuller()
    stats = (culler.GetLastNumberOfEmittedSpheres(), culler.GetLastNumberOfDepthReads())
    picked = None
    if pick:
        picked = picked_ids(renderer, (190, 140, 210, 160))
    window.Finalize()
    return image, stats, picked


def default(renderer, actor):
    pass


def orbit(renderer, actor):
    camera = renderer.GetActiveCamera()
    camera.Azimuth(30)
    camera.Elevation(20)
    renderer.ResetCameraClippingRange()


def closeup(renderer, actor):
    renderer.GetActiveCamera().Zoom(4.0)


def inside(renderer, actor):
    camera = renderer.GetActiveCamera()
    camera.SetPosition(20.0, 20.0, 20.0)  # the centre of a sphere
    camera.SetFocalPoint(30.0, 24.0, 21.0)
    renderer.ResetCameraClippingRange()


def parallel(renderer, actor):
    renderer.GetActiveCamera().ParallelProjectionOn()
    orbit(renderer, actor)


def transformed(renderer, actor):
    actor.SetScale(1.0, 2.0, 0.5)
    actor.RotateZ(30)
    renderer.ResetCamera()
    orbit(renderer, actor)


PIXELS = 400 * 300
near = block()
# (the views straight along the lattice rows and the stretched block look through the gaps
# between spheres of unequal radii into the block: much of it is visible there, so they only
# check the picture)
views = [("default", default, near, False), ("orbit", orbit, near, True),
         ("close-up", closeup, near, True), ("inside", inside, near, False),
         ("parallel", parallel, near, True), ("transformed", transformed, near, False),
         ("far from the origin", orbit, block(1.0e6), True)]
for name, view, data, outside in views:
    on, (drawn, reads), _ = render(data, True, view)
    off, (all_drawn, no_reads), _ = render(data, False, view)
    differing = int((np.abs(on - off).max(axis=1) > 0).sum())
    print("%-20s %7d of %d spheres drawn, %d read-backs, %d pixels differ" % (
        name, drawn, N, reads, differing))
    check(differing <= PIXELS * 0.0002, "%s: culling changes %d pixels" % (name, differing))
    check(reads == 3, "%s: %d depth read-backs, expected 3" % (name, reads))
    check(no_reads == 0 and all_drawn == N, "%s: culling off still culls" % name)
    if outside:
        check(drawn < 0.5 * N, "%s: %d of %d spheres drawn, culling skipped too few" % (
            name, drawn, N))
    check(int((on.max(axis=1) > 0).sum()) > PIXELS // 10, "%s: the image is empty" % name)

# multisampling: no read-back possible, plain draw, same picture as without culling
msaa_on, (drawn, reads), _ = render(near, True, orbit, samples=4)
msaa_off, _, _ = render(near, False, orbit, samples=4)
check(reads == 0 and drawn == N, "multisampled window: culled (%d reads) although it cannot" % reads)
check(np.array_equal(msaa_on, msaa_off), "multisampled window: the picture changed")

# picking: the same particles under the same pixels
_, _, picked_on = render(near, True, orbit, pick=True)
_, _, picked_off = render(near, False, orbit, pick=True)
check(picked_on == picked_off and len(picked_on) > 0,
      "picking with culling %s differs from without %s" % (sorted(picked_on)[:5], sorted(picked_off)[:5]))

# the opaque particles of the transparent mapper
t_on, (drawn, reads), _ = render(near, True, orbit, mapper_class=pr.vtkTransparentSphereMapper)
t_off, _, _ = render(near, False, orbit, mapper_class=pr.vtkTransparentSphereMapper)
check(reads == 3 and 0 <= drawn < 0.5 * N, "transparent mapper, opaque particles: not culled")
check(int((np.abs(t_on - t_off).max(axis=1) > 0).sum()) <= PIXELS * 0.0002,
      "transparent mapper, opaque particles: culling changes the picture")

sys.exit(finish())
