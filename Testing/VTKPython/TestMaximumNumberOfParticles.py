"""More particles than the vertex buffers take: vtkParticleSphereMapper draws every k-th one with
one warning instead of failing (10^8 particles render on llvmpipe; 2.2 x 10^8 crashed it inside
its vertex fetch, whose buffers are limited to 2 GiB). Scaled down here: 40 000 particles with
MaximumNumberOfParticles 15 000, so k = 3. Checked:
- GetParticleStride() is 3, exactly one warning naming the counts, repeated renders warn no more;
- the picture is every third particle: equal to rendering that subset with no limit (also with
  vtkTransparentSphereMapper, whose per-particle opacities are thinned the same way);
- picking reports input point ids (multiples of 3), and the same ids as the subset rendering
  times 3;
- raising the limit draws everything again (stride 1, no warning).

usage: python3 TestMaximumNumberOfParticles.py
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import Messages, check, finish, grab_image, picked_ids
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkRenderer,
    vtkRenderWindow,
)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

N = 40000
LIMIT = 15000
rng = np.random.default_rng(5)
xyz = rng.random((N, 3)) * 40.0
radius = rng.uniform(0.3, 0.6, N)
value = rng.random(N)


def particles(step=1):
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz[::step]), deep=True))
    data = vtkPolyData()
    data.SetPoints(points)
    r = numpy_to_vtk(np.ascontiguousarray(radius[::step]), deep=True)
    r.SetName("radius")
    data.GetPointData().AddArray(r)
    v = numpy_to_vtk(np.ascontiguousarray(value[::step]), deep=True)
    v.SetName("value")
    data.GetPointData().SetScalars(v)
    return data


def render(data, limit, mapper_class=pr.vtkParticleSphereMapper, opacity=1.0, renders=1):
    renderer = vtkRenderer()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(300, 300)
    window.AddRenderer(renderer)
    mapper = mapper_class()
    mapper.SetInputData(data)
    mapper.SetRadiusArrayName("radius")
    mapper.SetScalarRange(0.0, 1.0)
    mapper.SetMaximumNumberOfParticles(limit)
    messages = Messages(mapper)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetOpacity(opacity)
    renderer.AddActor(actor)
    renderer.ResetCamera()
    renderer.GetActiveCamera().SetPosition(20.0, 20.0, 150.0)  # the same camera for both data
    renderer.GetActiveCamera().SetFocalPoint(20.0, 20.0, 20.0)
    renderer.ResetCameraClippingRange()
    for _ in range(renders):
        window.Render()
    image = grab_image(window)
    ids = picked_ids(renderer, (100, 100, 200, 200))
    stride = mapper.GetParticleStride()
    window.Finalize()
    return image, stride, messages.warnings, ids


full = particles()
subset = particles(3)
image, stride, warnings, ids = render(full, LIMIT, renders=3)
reference, _, _, subset_ids = render(subset, 10**9)
print("stride %d, warnings %s" % (stride, warnings))
check(stride == 3, "stride %d, expected 3" % stride)
check(len(warnings) == 1 and "40000 particles exceed MaximumNumberOfParticles (15000" in warnings[0]
      and "one particle in 3 (13334 of 40000)" in warnings[0], "warning: %s" % warnings)
differing = int((np.abs(image - reference).max(axis=1) > 0).sum())
check(differing == 0, "every third particle: %d pixels differ from the subset's picture" % differing)
check(int((image.max(axis=1) > 0).sum()) > 9000, "the picture is empty")
check(len(ids) > 0 and all(i % 3 == 0 for i in ids), "picked ids are not input ids: %s" % sorted(ids)[:8])
check(ids == {3 * i for i in subset_ids}, "picked ids differ from the subset's times 3")

t_image, t_stride, _, _ = render(full, LIMIT, pr.vtkTransparentSphereMapper, opacity=0.5)
t_reference, _, _, _ = render(subset, 10**9, pr.vtkTransparentSphereMapper, opacity=0.5)
t_diff = int((np.abs(t_image - t_reference).max(axis=1) > 1).sum())
check(t_stride == 3 and t_diff == 0, "transparent mapper: stride %d, %d pixels differ" % (t_stride, t_diff))

_, stride, warnings, _ = render(full, 10**9)
check(stride == 1 and not warnings, "no limit: stride %d, warnings %s" % (stride, warnings))

sys.exit(finish())
