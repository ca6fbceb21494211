"""vtkParticleSphereMapper::SetPositionBounds (distributed rendering of opaque spheres) without
MPI: the particles split into pieces (particle i in piece i mod N, as TestParticlesMPI splits the
film), each piece drawn alone with the bounds of all centres, composited by depth as IceT does,
must equal the picture of all particles exactly (0/255, every pixel).

Why: VTK's automatic vertex-buffer shift and scale comes from the uploaded positions' own range.
A piece has another range than the whole, so a centre rounds to another float, and a ray that
grazes a sphere within that rounding hits it in one and misses it in the other (found on the
gas-plus-slab scene of Benchmarks/mpi_partition_accuracy.py: one pixel 53-66/255 off at np 2).
With the bounds of all centres every piece rounds as the whole does.

Scene: the benchmark's gas scene (an fcc slab of 8 000 atoms in 16 000 gas atoms, radius 0.5,
seeded), 400x300, its camera. Checks: with the bounds, the depth composite of 2 and of 3 pieces
equals the whole picture in every pixel (colour and depth); without them the 2-piece composite
differs in at least one pixel (this scene does expose the rounding: the test can fail); setting
the bounds of the piece's own centres changes nothing against not setting them (the rule is
VTK's AUTO_SHIFT_SCALE).

usage: python3 TestPositionBounds.py   (PYTHONPATH: the build's python3/dist-packages)
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import actor_view, check, finish, grab_image, particles_from
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.util.numpy_support import vtk_to_numpy

SIZE = (400, 300)


def gas_scene():
    """The gas scene of Benchmarks/mpi_partition_accuracy.py (same seed and construction)."""
    rng = np.random.default_rng(20261127)
    a = 1.5874
    cells = np.stack(np.meshgrid(np.arange(20), np.arange(20), np.arange(5), indexing="ij"),
                     -1).reshape(-1, 1, 3)
    basis = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
    slab = ((cells + basis[None]).reshape(-1, 3)) * a
    gas = rng.random((16000, 3)) * [20 * a, 20 * a, 5 * a + 16.0] - [0.0, 0.0, 8.0]
    return np.vstack([slab, gas]).astype(np.float32)


XYZ = gas_scene()
ALL_BOUNDS = [float(v) for k in range(3) for v in (XYZ[:, k].min(), XYZ[:, k].max())]


def render(keep, bounds):
    """(rgb, depth) of the particles XYZ[keep], with SetPositionBounds(bounds) unless None."""
    mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(particles_from(XYZ[keep]))
    mapper.SetRadius(0.5)
    if bounds is not None:
        mapper.SetPositionBounds(bounds)
    actor, renderer, window = actor_view(mapper, SIZE)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(80.0, -40.0, 30.0)
    camera.SetFocalPoint(16.0, 16.0, 4.0)
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.SetClippingRange(36.8, 154.8)
    window.Render()
    rgb = grab_image(window)[:, :3].astype(int)
    depth = vtkFloatArray()
    window.GetZbufferData(0, 0, SIZE[0] - 1, SIZE[1] - 1, depth)
    return rgb, vtk_to_numpy(depth).copy()


def composite(pieces, bounds):
    """Depth composite of the pieces i mod `pieces`, each drawn with `bounds`."""
    ids = np.arange(len(XYZ))
    rgb, depth = render(ids % pieces == 0, bounds)
    for piece in range(1, pieces):
        piece_rgb, piece_depth = render(ids % pieces == piece, bounds)
        nearer = piece_depth < depth
        rgb[nearer] = piece_rgb[nearer]
        depth[nearer] = piece_depth[nearer]
    return rgb, depth


whole_rgb, whole_depth = render(slice(None), None)
check(np.count_nonzero(whole_depth < 1.0) > 0.3 * len(whole_depth), "the scene covers the view")

# the bounds of the whole data's own centres: the same picture as VTK's automatic shift/scale
same_rgb, same_depth = render(slice(None), ALL_BOUNDS)
check(np.array_equal(same_rgb, whole_rgb) and np.array_equal(same_depth, whole_depth),
      "the whole data with its own bounds: not VTK's AUTO_SHIFT_SCALE picture")

for pieces in (2, 3):
    rgb, depth = composite(pieces, ALL_BOUNDS)
    colour = np.abs(rgb - whole_rgb).max(axis=1)
    print("%d pieces with the bounds of all centres: %d pixels differ in colour (max %d/255), "
          "%d in depth" % (pieces, np.count_nonzero(colour), colour.max(),
                           np.count_nonzero(depth != whole_depth)))
    check(colour.max() == 0 and np.array_equal(depth, whole_depth),
          "%d pieces with the bounds of all centres: not the whole picture" % pieces)

rgb, depth = composite(2, None)
colour = np.abs(rgb - whole_rgb).max(axis=1)
print("2 pieces, each with its own shift/scale: %d pixels differ in colour (max %d/255), "
      "%d in depth" % (np.count_nonzero(colour), colour.max(),
                       np.count_nonzero(depth != whole_depth)))
check(np.count_nonzero(depth != whole_depth) > 0,
      "2 pieces with their own shift/scale give the whole picture: the scene no longer shows the "
      "rounding this test is about")

sys.exit(finish())
