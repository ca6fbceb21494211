"""Convert an X window dump (xwd, 24/32-bit TrueColor, as Xvfb gives) to PNG with numpy and
VTK's PNG writer (no ImageMagick needed); black margins right and below (screen not covered by
the window) are cut away. usage: xwd -root | python3 xwd_to_png.py OUT.png"""
import struct
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter

data = sys.stdin.buffer.read()
fields = struct.unpack(">25I", data[:100])
header_size, _, _, _, width, height = fields[:6]
byte_order, bits_per_pixel, bytes_per_line = fields[7], fields[11], fields[12]
red_mask, green_mask, blue_mask, ncolors = fields[14], fields[15], fields[16], fields[19]
if bits_per_pixel not in (24, 32):
    sys.exit("only 24 and 32 bits per pixel are handled, not %d" % bits_per_pixel)
offset = header_size + 12 * ncolors
raw = np.frombuffer(data, dtype=np.uint8, count=height * bytes_per_line, offset=offset)
raw = raw.reshape(height, bytes_per_line)[:, :width * (bits_per_pixel // 8)]
raw = raw.reshape(height, width, bits_per_pixel // 8).astype(np.uint32)
if byte_order == 1:  # MSBFirst
    raw = raw[:, :, ::-1]
rows = sum(raw[:, :, k] << (8 * k) for k in range(raw.shape[2]))  # pixel values, LSB first


def channel(mask):
    shift = (mask & -mask).bit_length() - 1
    return ((rows & mask) >> shift).astype(np.uint8)


rgb = np.dstack([channel(red_mask), channel(green_mask), channel(blue_mask)])
# the screen outside the window (black, right and bottom) is cut away
covered = rgb.any(axis=2)
rgb = rgb[:np.nonzero(covered.any(axis=1))[0].max() + 1, :np.nonzero(covered.any(axis=0))[0].max() + 1]
height, width = rgb.shape[:2]
image = vtkImageData()
image.SetDimensions(width, height, 1)
image.GetPointData().SetScalars(numpy_to_vtk(rgb[::-1].reshape(-1, 3).copy(), deep=True))
writer = vtkPNGWriter()
writer.SetFileName(sys.argv[1])
writer.SetInputData(image)
writer.Write()
