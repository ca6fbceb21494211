"""The README's before/after picture of vtkSNDFRenderPass (Plugin/Documentation/sndf-crystal.png):
an fcc crystal of 64^3 unit cells (1 048 576 atoms, radius 0.36 lattice constants) with a
spherical precipitate of a second species and 5 % of that species spread at random, seen whole at
about 1.5 pixels per atom. Left: the plain picture (one ray per pixel); right: the S-NDF picture
after 256 jittered samples per pixel.

usage: Scripts/with_xvfb.sh /usr/bin/python3 Scripts/sndf_picture.py [OUTPUT.png]
(PYTHONPATH=build/lib/python3/dist-packages:Testing/VTKPython)
"""
import os
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import offscreen_window, particles_from
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkWindowToImageFilter
from vtkmodules.vtkRenderingOpenGL2 import vtkCameraPass, vtkRenderStepsPass

CELLS, W, H = 64, 480, 360
out_path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    os.path.dirname(__file__), "..", "Plugin", "Documentation", "sndf-crystal.png")

g = np.arange(CELLS)
base = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1).reshape(-1, 3).astype(float)
offsets = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
xyz = (base[:, None, :] + offsets[None]).reshape(-1, 3)
centre = np.array([0.62, 0.55, 0.7]) * CELLS
second = (np.linalg.norm(xyz - centre, axis=1) < 0.22 * CELLS) | (
    np.random.default_rng(3).random(len(xyz)) < 0.05)
rgb = np.where(second[:, None], [235, 190, 60], [80, 120, 200]).astype(np.uint8)


def render(sndf):
    data = particles_from(xyz)
    colours = numpy_to_vtk(rgb, deep=True)
    data.GetPointData().SetScalars(colours)
    mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(data)
    mapper.SetRadius(0.36)
    mapper.SetColorModeToDirectScalars()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetSpecular(0.3)
    actor.GetProperty().SetSpecularPower(20)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.12, 0.12, 0.14)
    window = offscreen_window(renderer, (W, H))
    camera_pass = vtkCameraPass()
    if sndf is None:
        camera_pass.SetDelegatePass(vtkRenderStepsPass())
    else:
        camera_pass.SetDelegatePass(sndf)
        sndf.SetDelegatePass(vtkRenderStepsPass())
    renderer.SetPass(camera_pass)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(2.3 * CELLS, 1.7 * CELLS, 3.1 * CELLS)
    camera.SetFocalPoint(CELLS / 2, CELLS / 2 - 2, CELLS / 2)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCameraClippingRange()
    window.Render()
    if sndf is not None:
        while not sndf.GetConverged():
            window.Render()
        samples.append(sndf.GetNumberOfSamples())
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ShouldRerenderOff()
    grab.ReadFrontBufferOff()
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3].reshape(H, W, 3)


samples = []
plain = render(None)
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(32)
sndf.SetTargetSamples(256)
converged = render(sndf)
gap = np.full((H, 8, 3), 255, np.uint8)
both = np.concatenate([plain, gap, converged], axis=1)
image = vtkImageData()
image.SetDimensions(both.shape[1], both.shape[0], 1)
image.GetPointData().SetScalars(numpy_to_vtk(both.reshape(-1, 3).copy(), deep=True))
writer = vtkPNGWriter()
writer.SetFileName(out_path)
writer.SetInputData(image)
writer.Write()
print("wrote %s (%d atoms; left plain, right S-NDF with %d samples per pixel)"
      % (out_path, len(xyz), samples[0]))
