"""vtkPointAOPass gives the same picture each time the same frame is drawn (issue: PointAO gave
a different picture each time, tile-shaped blocks up to 146/255, in ParaView where the
renderer's FXAA is on by default).

Scene: 10^5 particles, a dense FCC slab between two layers of gas (prVTKTesting.gas_and_slab),
1024 x 768 (many of llvmpipe's 64 x 64 tiles), a translucent box drawn over part of it with
dual depth peeling (its full-screen blend writes undefined values into the pass's G-buffer
targets, as ParaView's FXAA does: the pass must not read them). Before the fix, the four renders
differed. For PointAO at full and at half resolution,
with the renderer's FXAA off and on: four renders of the unchanged view are identical, bit for
bit (vtkParticleImageComparison.TestRepeatable), and PointAO does darken the slab (the check is
not passed by a pass that does nothing). With FXAA on the picture is PointAO's picture with
FXAA applied on top: FXAA changes it no more than it changes the picture without PointAO (its
edges; occlusion from undefined normals would change far more).
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import check, check_repeatable, finish, gas_and_slab, grab_image, offscreen_window
from prVTKTesting import particles_from
from vtkmodules.vtkFiltersSources import vtkCubeSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer
from vtkmodules.vtkRenderingOpenGL2 import (vtkCameraPass, vtkDualDepthPeelingPass,
                                            vtkRenderStepsPass, vtkTranslucentPass,
                                            vtkVolumetricPass)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)

xyz, radius, kinds = gas_and_slab()
data = particles_from(xyz, radius=radius, type=kinds.astype(np.float32))
mapper = pr.vtkParticleSphereMapper()
mapper.SetInputData(data)
mapper.SetRadiusArrayName("radius")
mapper.SetScalarModeToUsePointFieldData()
mapper.SelectColorArray("type")
mapper.SetScalarRange(1, 2)
actor = vtkActor()
actor.SetMapper(mapper)
actor.GetProperty().SetSpecular(0.3)

cube = vtkCubeSource()
cube.SetBounds(10, 40, 10, 40, 20, 30)
box = vtkActor()
box_mapper = vtkPolyDataMapper()
box_mapper.SetInputConnection(cube.GetOutputPort())
box.SetMapper(box_mapper)
box.GetProperty().SetOpacity(0.4)
box.GetProperty().SetColor(0.9, 0.9, 0.3)

renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.AddActor(box)
renderer.SetBackground(0.1, 0.1, 0.12)
renderer.SetUseDepthPeeling(1)
window = offscreen_window(renderer, (1024, 768))
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(32, 32, 8)
camera.SetPosition(95, -40, 70)
camera.SetViewUp(0, 0, 1)
renderer.ResetCameraClippingRange()
camera_pass = vtkCameraPass()
camera_pass.SetDelegatePass(vtkRenderStepsPass())
renderer.SetPass(camera_pass)
plain = grab_image(window)[:, :3]

ao = pr.vtkPointAOPass()
# the delegate draws translucent geometry with dual depth peeling, whose full-screen blend quad
# has one output: it leaves undefined values in the G-buffer's normal targets (as ParaView's
# depth peeling and the renderer's FXAA do)
steps = vtkRenderStepsPass()
peeling = vtkDualDepthPeelingPass()
peeling.SetTranslucentPass(vtkTranslucentPass())
peeling.SetVolumetricPass(vtkVolumetricPass())
steps.SetTranslucentPass(peeling)
ao.SetDelegatePass(steps)
camera_pass.SetDelegatePass(ao)
pictures = {}
for half in (False, True):
    for fxaa in (False, True):
        ao.SetHalfResolution(half)
        renderer.SetUseFXAA(fxaa)
        label = "PointAO %s resolution, FXAA %s" % ("half" if half else "full", "on" if fxaa else "off")
        window.Render()
        for k in range(3):
            check_repeatable(window, "%s, render %d" % (label, k + 2))
        pictures[(half, fxaa)] = grab_image(window, repeat=False)[:, :3]
        darker = int((pictures[(half, fxaa)].sum(axis=1) < plain.sum(axis=1) - 6).sum())
        print("%s: %d pixels darker than without PointAO" % (label, darker))
        check(darker > 50000, "%s: PointAO does not darken the slab" % label)

# FXAA runs on PointAO's composite: it changes the picture as much as it changes the picture
# without PointAO (its edges), not more (occlusion from undefined normals would)
# (the renderer's own rendering, no pass: vtkRenderStepsPass does not run the renderer's FXAA)
renderer.SetPass(None)
renderer.SetUseFXAA(False)
plain = grab_image(window)[:, :3]
renderer.SetUseFXAA(True)
plain_fxaa = grab_image(window)[:, :3]
reference = float((np.abs(plain_fxaa - plain).max(axis=1) > 8).mean())
print("without PointAO: FXAA changes %.2f %% of the pixels by more than 8/255" % (100 * reference))
for half in (False, True):
    share = float((np.abs(pictures[(half, True)] - pictures[(half, False)]).max(axis=1) > 8).mean())
    print("PointAO at %s resolution: FXAA changes %.2f %% of the pixels by more than 8/255"
          % ("half" if half else "full", 100 * share))
    check(share < 1.25 * reference + 0.005,
          "FXAA on PointAO changes more than FXAA alone (%.2f %%)" % (100 * share))
sys.exit(finish())
