"""Helpers of the metaball tests and benchmarks: scenes for vtkMetaballMapper; their depth and
normal errors against the exact surface of vtkParticleReferenceRenderer (metaball mode) come
from prVTKTesting.compare, re-exported here."""
import numpy as np

import particlerendering as pr
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable

from prVTKTesting import compare


def metaball_view(xyz, size=(300, 300), radius=1.0, **arrays):
    """A vtkMetaballMapper of the particles xyz with constant `radius` and point arrays, in an
    offscreen window: (mapper, actor, renderer, window)."""
    from prVTKTesting import actor_view, particles_from
    mapper = pr.vtkMetaballMapper()
    mapper.SetInputData(particles_from(np.asarray(xyz, dtype=np.float64), **arrays))
    mapper.SetRadius(radius)
    actor, renderer, window = actor_view(mapper, size)
    return mapper, actor, renderer, window


def isolated_views(walking=False):
    """The isolated-particle scenes of the metaball tests: three particles far apart, seen near,
    with the camera 1e7 R away, and with the data 1e6 from the origin. Yields (name, far camera,
    mapper, actor, renderer, window), rendered once."""
    for name, offset, distance in (("near", 0.0, None), ("camera 1e7 R away", 0.0, 1e7),
                                   ("data 1e6 from the origin", 1e6, None)):
        xyz = np.array([[0.0, 0.0, 0.0], [5.0, 0.3, -0.2], [-4.0, 3.0, 1.0]]) + offset
        mapper, actor, renderer, window = metaball_view(xyz, (200, 200))
        if walking:
            mapper.SetMethodToWalkingDepthPlane()
            mapper.SetTimeBudget(1000.0)  # to convergence whatever the load
            mapper.SetMaximumPasses(1000)
        renderer.ResetCamera()
        if distance:
            camera = renderer.GetActiveCamera()
            camera.SetPosition(offset, offset, offset + distance)
            camera.SetFocalPoint(offset, offset, offset)
            camera.SetViewAngle(6e-6 * 30)  # the spheres fill the view from 1e7 R away
            renderer.ResetCameraClippingRange()
        window.Render()
        yield name, bool(distance), mapper, actor, renderer, window


def thin_neck(walking=False):
    """The paper's thin-neck situation (its Fig. 10/11): two particles 0.1 % short of the
    largest distance at which they connect (k = 2), seen across the neck. Returns the neck's
    radius (R), the reference's pixels in the columns within a pixel of the mid-plane, how many
    of them the GPU shows too, and the comparison."""
    k, c = 2.0, 16.0 / 9.0
    d = 2.0 * k * np.sqrt(1.0 - np.sqrt(1.0 / (2.0 * c))) * 0.999
    neck = np.sqrt(k * k * (1.0 - np.sqrt(1.0 / (2.0 * c))) - d * d / 4.0)
    mapper, actor, renderer, window = metaball_view([[-d / 2, 0, 0], [d / 2, 0, 0]], (400, 200))
    if walking:
        mapper.SetMethodToWalkingDepthPlane()
        mapper.SetTimeBudget(1000.0)  # to convergence whatever the load
        mapper.SetMaximumPasses(1000)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 0, 20)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewAngle(15)
    renderer.ResetCameraClippingRange()
    window.Render()
    r = compare(window, renderer, actor, 1.0)
    width, height = window.GetSize()
    reference_t = vtk_to_numpy(r["reference"].GetViewDepthImage().GetPointData().GetScalars())
    mid = np.abs(np.arange(width * height) % width - (width - 1) / 2.0) <= 1
    return neck, int(np.sum((reference_t >= 0) & mid)), int(np.sum(r["both"] & mid)), r


def droplet(seed=3):
    """The tests' droplet: 291 particles on a jittered lattice within 6 R, and 60 vapour atoms
    in a 28 R box; returns the positions and the type (0 droplet, 1 vapour)."""
    rng = np.random.default_rng(seed)
    g = np.mgrid[-3:4, -3:4, -3:4].reshape(3, -1).T * 1.9
    g = g[np.linalg.norm(g, axis=1) < 6.0]
    g = g + rng.normal(0, 0.25, g.shape)
    vapour = rng.uniform(-14, 14, (60, 3))
    return np.vstack([g, vapour]), np.r_[np.zeros(len(g)), np.ones(len(vapour))]


def type_lookup_table(first, last):
    """The two-colour table of the metaball tests and benchmarks: orange for the type `first`,
    blue for `last`."""
    lut = vtkLookupTable()
    lut.SetNumberOfTableValues(2)
    lut.SetTableValue(0, 0.85, 0.33, 0.10)
    lut.SetTableValue(1, 0.12, 0.47, 0.80)
    lut.SetTableRange(first, last)
    lut.Build()
    return lut


