"""Progress of long rendering work in plain VTK: vtkTransparentSphereMapper (an algorithm, so
UpdateProgress/GetProgressText) and vtkDensityVolumeAOPass (a render pass: ProgressEvent with the
fraction as call data and GetProgressText()). 1.1 million random particles, opacity 0.5, AO on,
400x300. Checked:
- the mapper's upload reports 0, 0.15, 0.3, 1 and the depth sort 0, 1/p, ..., 1 over its p radix
  passes, with the texts "Uploading N particles" / "Sorting N translucent particles", and no text
  afterwards;
- the pass's volume build reports 0, 0.5 (particles gathered), 0.5 + 0.5 j/16 for the 16 splat
  blocks, 1, with the text "Ambient occlusion: density volume of N particles", on the CPU and on
  the GPU (GenerationMode), and no text afterwards;
- a camera move reports one sort, no upload, no build;
- ProgressThreshold above the particle count: nothing is reported; the defaults are 2^20.

usage: python3 TestProgressEvents.py
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import check, finish
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.util.vtkConstants import VTK_DOUBLE
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

N = 1100000
rng = np.random.default_rng(7)
points = vtkPoints()
points.SetData(numpy_to_vtk((rng.random((N, 3)) * 100.0).astype(np.float32), deep=True))
particles = vtkPolyData()
particles.SetPoints(points)

mapper = pr.vtkTransparentSphereMapper()
mapper.SetInputData(particles)
mapper.SetRadius(0.5)
actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetOpacity(0.5)
# the random points overlap: keep the sorted path, whose sort's progress this test is about
mapper.SetOverlapCompositing(pr.vtkTransparentSphereMapper.SORTED_SPHERES)
renderer = vtkRenderer()
renderer.AddActor(actor)
ao = pr.vtkDensityVolumeAOPass()
ao.SetDelegatePass(vtkRenderStepsPass())
renderer.SetPass(ao)
window = vtkRenderWindow()
window.SetSize(400, 300)
window.SetMultiSamples(0)
window.AddRenderer(renderer)

check(mapper.GetProgressThreshold() == 1 << 20, "mapper threshold %d" % mapper.GetProgressThreshold())
check(ao.GetProgressThreshold() == 1 << 20, "pass threshold %d" % ao.GetProgressThreshold())

reports = {}


def on_mapper(obj, event):
    text = obj.GetProgressText()
    if text:
        reports.setdefault(text, []).append(round(obj.GetProgress(), 6))


@calldata_type(VTK_DOUBLE)
def on_pass(obj, event, fraction):
    reports.setdefault(obj.GetProgressText(), []).append(round(fraction, 6))


mapper.AddObserver("ProgressEvent", on_mapper)
ao.AddObserver("ProgressEvent", on_pass)

upload = "Uploading %d particles" % N
sort = "Sorting %d translucent particles" % N
volume = "Ambient occlusion: density volume of %d particles" % N
expected_volume = [0.0, 0.5, 0.5] + [round(0.5 + 0.5 * j / 16, 6) for j in range(1, 17)] + [1.0]


def check_sort(values):
    passes = len(values) - 1
    check(1 <= passes <= 8 and values == [round(i / passes, 6) for i in range(passes + 1)],
          "sort reports %s are not 0, 1/p, ..., 1" % values)


renderer.ResetCamera()
window.Render()
print(reports)
check(sorted(reports) == sorted([upload, sort, volume]), "first frame reported %s" % sorted(reports))
check(reports.get(upload) == [0.0, 0.15, 0.3, 1.0], "upload reports %s" % reports.get(upload))
check_sort(reports.get(sort, []))
check(reports.get(volume) == expected_volume, "CPU volume reports %s" % reports.get(volume))
check(not mapper.GetProgressText() and ao.GetProgressText() == "",
      "texts left after the frame: %r %r" % (mapper.GetProgressText(), ao.GetProgressText()))

reports.clear()
renderer.GetActiveCamera().Azimuth(20)
window.Render()
print(reports)
check(sorted(reports) == [sort], "after a camera move reported %s" % sorted(reports))
check_sort(reports.get(sort, []))

reports.clear()
ao.SetGenerationMode(ao.GPU_GENERATION)
window.Render()
print(reports)
check(reports.get(volume) == expected_volume, "GPU volume reports %s" % reports.get(volume))
check(ao.GetLastGenerationMode() == ao.GPU_GENERATION, "the GPU did not build the volume")

reports.clear()
mapper.SetProgressThreshold(N + 1)
ao.SetProgressThreshold(N + 1)
mapper.SetRadius(0.45)  # new radii: upload, sort and volume build again
renderer.GetActiveCamera().Azimuth(20)
window.Render()
print(reports)
check(not reports, "above the threshold reported %s" % sorted(reports))
check(ao.GetNumberOfVolumeBuilds() == 3, "volume builds: %d" % ao.GetNumberOfVolumeBuilds())

sys.exit(finish())
