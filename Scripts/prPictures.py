"""Shared pieces of the README picture scripts (voxel_cone_picture.py, pointao_picture.py):
the RGB of an off-screen window and a row of panels written as one PNG."""
import numpy as np

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter


def window_rgb(window, size):
    """The RGB of a size x size window after its last render (rows bottom-up, as VTK's); the
    window is finalized."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3]
    window.Finalize()
    return rgb.reshape(size, size, 3)


def write_panels(panels, path):
    """Write the panels (window_rgb images) side by side, left to right, as one PNG."""
    image = np.concatenate(panels, axis=1)
    out = vtkImageData()
    out.SetDimensions(image.shape[1], image.shape[0], 1)
    out.GetPointData().SetScalars(numpy_to_vtk(np.ascontiguousarray(image.reshape(-1, 3)),
                                               deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(out)
    writer.Write()
