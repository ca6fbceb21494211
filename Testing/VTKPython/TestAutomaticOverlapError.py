"""AUTOMATIC overlap compositing by estimated error (vtkTransparentSphereMapper,
vtkParticleOverlapError), checked against the exact picture: on each scene the sorted spheres
(SORTED_SPHERES) and the exact lists (EXACT_OVERLAP) are drawn and the pixels where they differ
by more than 2/255 counted; AUTOMATIC must take the lists wherever that count exceeds the
criterion (0.01 % of the viewport): when it chooses the sort, the sorted picture meets the
criterion against the exact one. Scenes, 400 x 300:

- a molecule-like chain (60 spheres, neighbours 0.9 radii apart, red and blue alternating, Theta
  0.9): the estimate says exact, and the sorted picture is far off (what the lists fix);
- faint gas (3000 spheres of radius 0.5 in a 16^3 box, many penetrating by more than the 0.25
  floor, Theta 0.05): the estimate says sorted (no lens can be 2/255 off), and the sorted picture
  is within the criterion;
- the same gas at Theta 0.3 and 0.6, and one colour for all at 0.6: whatever the estimate says,
  a "sorted" must meet the criterion (the estimate is a bound; printed with the measured count);
- the chain 100 units beside the view, which shows a lattice of spheres that do not touch (Theta
  0.9): the chain's lenses lie outside the view frustum and count nothing, so the estimate says
  sorted (it said exact before lenses beside the view were left out), and the sorted picture is
  the exact one within the criterion.
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import check, finish, grab_image, offscreen_window, particles_from
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

M = pr.vtkTransparentSphereMapper
SIZE = (400, 300)
SHARE = 1e-4


def chain():
    rng = np.random.default_rng(3)
    xyz = [np.zeros(3)]
    for _ in range(59):
        step = rng.normal(size=3)
        xyz.append(xyz[-1] + 0.9 * step / np.linalg.norm(step))
    rgb = np.array([[230, 40, 40] if i % 2 else [40, 60, 230] for i in range(60)], np.uint8)
    return np.array(xyz), rgb, 1.0


def gas(seed=5):
    rng = np.random.default_rng(seed)
    xyz = rng.random((3000, 3)) * 16.0
    rgb = np.array([[230, 120, 40] if i % 3 else [60, 160, 230] for i in range(3000)], np.uint8)
    return xyz, rgb, 0.5


def chain_beside_lattice():
    """The chain, and 100 units beside it a lattice of spheres that do not touch (radius 1,
    spacing 2.5): the view shows the lattice only."""
    xyz, rgb, _ = chain()
    grid = np.stack(np.meshgrid(*[np.arange(5) * 2.5] * 3, indexing="ij"), -1).reshape(-1, 3)
    lattice_rgb = np.array([[230, 40, 40] if i % 2 else [40, 60, 230] for i in range(len(grid))],
                           np.uint8)
    return (np.concatenate([xyz, grid + [100.0, 0.0, 0.0]]),
            np.concatenate([rgb, lattice_rgb]), 1.0)


LATTICE_VIEW = ((105.0, 5.0, 5.0), (105.0, -15.0, 30.0))  # focal point, position


def draw(xyz, rgb, radius, opacity, mode, view=None):
    data = particles_from(xyz, rgb=rgb)
    mapper = M()
    mapper.SetInputData(data)
    mapper.SetRadius(radius)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("rgb")
    mapper.SetColorModeToDirectScalars()
    mapper.SetOverlapCompositing(mode)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetOpacity(opacity)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.1, 0.1, 0.1)
    window = offscreen_window(renderer, SIZE)
    camera = renderer.GetActiveCamera()
    if view:
        camera.SetFocalPoint(*view[0])
        camera.SetPosition(*view[1])
        camera.SetViewUp(0, 0, 1)
    else:
        renderer.ResetCamera()
        camera.Azimuth(30)
        camera.Elevation(20)
    renderer.ResetCameraClippingRange()
    image = grab_image(window)[:, :3]
    return mapper, image


scenes = [("chain", chain(), 0.9, "exact", None), ("faint gas", gas(), 0.05, "sorted", None),
          ("gas 0.3", gas(), 0.3, None, None), ("gas 0.6", gas(), 0.6, None, None),
          ("chain beside the view", chain_beside_lattice(), 0.9, "sorted", LATTICE_VIEW)]
one_colour = gas()
one_colour = (one_colour[0], np.full_like(one_colour[1], 200), one_colour[2])
scenes.append(("gas 0.6, one colour", one_colour, 0.6, None, None))
for name, (xyz, rgb, radius), opacity, expected, view in scenes:
    _, sorted_image = draw(xyz, rgb, radius, opacity, M.SORTED_SPHERES, view)
    _, exact_image = draw(xyz, rgb, radius, opacity, M.EXACT_OVERLAP, view)
    auto, auto_image = draw(xyz, rgb, radius, opacity, M.AUTOMATIC, view)
    drawn = int((np.abs(exact_image - exact_image[0]).max(axis=1) > 0).sum())
    check(drawn > 0.05 * SIZE[0] * SIZE[1], "%s: the view shows the particles (%d px)"
          % (name, drawn))
    over = np.abs(sorted_image - exact_image).max(axis=1) > 2
    measured = int(over.sum())
    limit = SHARE * SIZE[0] * SIZE[1]
    chose_exact = auto.GetExactOverlapInUse()
    print("%-20s estimate %9.1f px (largest bound %6.1f/255) -> %s; measured sorted vs exact: "
          "%d px over 2/255 (criterion %.0f px), max %d/255"
          % (name, auto.GetEstimatedOverlapErrorPixels(), auto.GetLargestOverlapErrorBound(),
             "exact" if chose_exact else "sorted", measured, limit,
             np.abs(sorted_image - exact_image).max()))
    if not chose_exact:
        check(measured <= limit, "%s: the estimate chose the sort, which meets the criterion"
              % name)
        check(np.array_equal(auto_image, sorted_image), "%s: ... and drew the sorted picture"
              % name)
    else:
        check(np.array_equal(auto_image, exact_image), "%s: the exact picture when chosen" % name)
    if expected:
        check(chose_exact == (expected == "exact"), "%s: the estimate says %s" % (name, expected))
    if expected == "exact":
        check(measured > limit, "%s: ... and the sorted picture misses the criterion" % name)

sys.exit(finish())
