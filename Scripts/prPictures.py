"""Shared pieces of the README picture scripts (voxel_cone_picture.py, pointao_picture.py,
render_samples.py): the RGB of a window, an RGB image written as a PNG, and a row of panels
written as one PNG."""
import numpy as np

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter


def window_rgb(window, size=None, finalize=True, rerender=True):
    """The RGB of a window after its last render, rows bottom-up as VTK's, shaped (height, width,
    3): a size x size window when size is given, else the image's own size. finalize: the window
    is finalized afterwards; rerender: the window renders once more before the read-back (off for
    a progressive view, whose next render changes the picture)."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetShouldRerender(rerender)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    width, height, _ = image.GetDimensions()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3]
    if finalize:
        window.Finalize()
    return rgb.reshape((size, size, 3) if size else (height, width, 3))


def write_png(rgb, path):
    """Write an RGB image (height, width, 3; rows bottom-up; any number type, rounded and clamped
    to 0..255) as an 8-bit PNG."""
    data = np.clip(np.rint(rgb), 0, 255).astype(np.uint8)
    out = vtkImageData()
    out.SetDimensions(data.shape[1], data.shape[0], 1)
    out.GetPointData().SetScalars(numpy_to_vtk(np.ascontiguousarray(data.reshape(-1, 3)),
                                               deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(out)
    writer.Write()


def write_panels(panels, path):
    """Write the panels (window_rgb images) side by side, left to right, as one PNG."""
    write_png(np.concatenate(panels, axis=1), path)
