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
from prVTKTesting import crystal_view, window_pixels
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter

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
    renderer, window, actor = crystal_view(
        xyz, rgb, (W, H), sndf, position=(2.3 * CELLS, 1.7 * CELLS, 3.1 * CELLS),
        focal_point=(CELLS / 2, CELLS / 2 - 2, CELLS / 2), background=(0.12, 0.12, 0.14),
        specular=0.3)
    window.Render()
    if sndf is not None:
        while not sndf.GetConverged():
            window.Render()
        samples.append(sndf.GetNumberOfSamples())
    return window_pixels(window, W, H).astype(np.uint8)


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
