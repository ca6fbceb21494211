"""vtkVoxelConeAOPass at the numerical extremes (issue: voxel-cone AO, "Numerical extremes").
Every case renders the scene without the pass and with it (per fragment, the defaults) and
checks a sane picture: the particles cover exactly the pixels they cover without AO (no hole, no
black frame, no extra pixel), AO never brightens a pixel (at most 1/255 of rounding), and the
pass reports no error. Cases:
- one particle: nothing occludes it (at most a few /255 from its own voxels);
- all particles in one plane, all at one point (the grid degenerates along an axis or all);
- radii from 1e-3 to 1e3 in one scene;
- Theta_i = 0 and 1 - 1e-7 (translucent mapper): the Theta = 0 particles are neither drawn nor
  occlude -- the picture equals the one without them;
- volume resolution 1 (one voxel), and a resolution beyond the memory bound and the GPU's 3D
  texture limit (4096): degraded with a warning, still drawn;
- the whole scene 1e6 from the origin: the picture of the scene at the origin (mean difference
  below 0.5/255).

usage: python3 TestVoxelConeAOExtremes.py
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import Messages, check, finish, grab_image, offscreen_window, particles_from
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

SIZE = 200


BACKGROUND = (0.1, 0.2, 0.3)


def render(xyz, radii, theta=None, ao=True, resolution=0, max_resolution=256, offset=(0, 0, 0),
           view=None):
    """(RGB image as an (N, 3) int array, pass messages, pass errors, volume dimensions); the
    camera frames the points `view` (default: xyz)."""
    xyz = np.asarray(xyz, dtype=np.float64) + np.asarray(offset, dtype=np.float64)
    view = xyz if view is None else np.asarray(view, dtype=np.float64) + np.asarray(offset)
    arrays = dict(radius=np.asarray(radii, dtype=np.float64))
    if theta is not None:
        arrays["opacity"] = np.asarray(theta, dtype=np.float64)
        mapper = pr.vtkTransparentSphereMapper()
        mapper.SetOpacityArrayName("opacity")
        mapper.SetOpacityRange(0.0, 1.0)
    else:
        mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(particles_from(xyz, **arrays))
    mapper.SetRadiusArrayName("radius")
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.9, 0.9, 0.9)
    renderer = vtkRenderer()
    renderer.SetBackground(*BACKGROUND)
    renderer.AddActor(actor)
    messages = None
    aopass = None
    if ao:
        aopass = pr.vtkVoxelConeAOPass()
        aopass.SetDelegatePass(vtkRenderStepsPass())
        aopass.GetAmbientVolume().SetMaximumResolution(max_resolution)
        aopass.GetAmbientVolume().SetResolution(resolution)
        messages = (Messages(aopass), Messages(aopass.GetAmbientVolume()))
        renderer.SetPass(aopass)
    window = offscreen_window(renderer, (SIZE, SIZE))
    b = np.array([view[:, 0].min(), view[:, 0].max(), view[:, 1].min(), view[:, 1].max(),
                  view[:, 2].min(), view[:, 2].max()])
    centre = np.array([(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2])
    extent = max(b[1] - b[0], b[3] - b[2], b[5] - b[4], 2 * max(radii)) + 2 * max(radii)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*(centre + extent * np.array([0.9, -1.4, 0.8])))
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    window.Render()
    image = grab_image(window)[:, :3]
    dims = aopass.GetAmbientVolume().GetDimensions() if aopass else None
    texts = (messages[0].text + messages[1].text) if messages else []
    errors = (messages[0].errors + messages[1].errors) if messages else []
    window.Finalize()
    return image, texts, errors, dims


def sane(name, xyz, radii, theta=None, max_darkening=255, **kw):
    plain, _, _, _ = render(xyz, radii, theta, ao=False, offset=kw.get("offset", (0, 0, 0)),
                            view=kw.get("view"))
    image, texts, errors, dims = render(xyz, radii, theta, **kw)
    background = np.round(np.array(BACKGROUND) * 255.0)
    covered_plain = np.abs(plain - background).max(axis=1) > 1
    covered = np.abs(image - background).max(axis=1) > 1
    brighter = int((image - plain).max())
    darker = (plain - image)[covered_plain].mean() if covered_plain.any() else 0.0
    print("%s: volume %s, %d pixels covered (%d without AO), darker by %.2f/255 on average, "
          "brighter by at most %d/255, messages %s"
          % (name, dims, covered.sum(), covered_plain.sum(), darker, brighter, texts))
    check(covered_plain.sum() > 0, "%s: the particles are visible" % name)
    # AO only scales the colour (the grey particles never look like the blue background)
    check(int((covered_plain != covered).sum()) == 0,
          "%s: AO covers the same pixels (%d lost, %d extra)"
          % (name, (covered_plain & ~covered).sum(), (covered & ~covered_plain).sum()))
    check(brighter <= 1, "%s: AO never brightens (max +%d)" % (name, brighter))
    check(darker <= max_darkening, "%s: darkening %.2f/255 at most %.2f"
          % (name, darker, max_darkening))
    check(not errors, "%s: no error (%s)" % (name, errors))
    return image, texts, dims


rng = np.random.default_rng(3)

# one particle
sane("one particle", [[0.0, 0.0, 0.0]], [1.0], max_darkening=3.0)

# all in one plane, all at one point
g = np.arange(12) - 5.5
x, y = np.meshgrid(g, g)
plane = np.stack([x.ravel(), y.ravel(), np.zeros(x.size)], axis=1)
sane("one plane", plane, np.full(len(plane), 0.5))
sane("one point", np.zeros((50, 3)), np.full(50, 1.0))

# radii spanning 1e-3 ... 1e3 in one scene: a huge sphere with small ones above its top
n = 300
radii = np.exp(rng.uniform(np.log(1e-3), np.log(3.0), n))
small = np.column_stack([rng.uniform(-20, 20, n), rng.uniform(-20, 20, n),
                         1000.0 + radii + rng.uniform(0.0, 10.0, n)])
huge = np.array([[0.0, 0.0, 0.0]])
sane("radii 1e-3..1e3", np.vstack([huge, small]), np.concatenate([[1000.0], radii]))

# Theta 0 and 1 - 1e-7: the clear half neither drawn nor occluding
blob = rng.uniform(-4, 4, (200, 3))
theta = np.where(np.arange(200) % 2 == 0, 1.0 - 1e-7, 0.0)
with_clear, _, _ = sane("Theta 0 and 1 - 1e-7", blob, np.full(200, 0.7), theta)
only_opaque, _, _ = sane("Theta 1 - 1e-7 alone", blob[::2], np.full(100, 0.7), theta[::2],
                         view=blob)
diff = int(np.abs(with_clear - only_opaque).max())
check(diff <= 1, "Theta = 0 particles change nothing (max %d/255)" % diff)

# resolution 1, and beyond the memory bound and the 3D texture limit
sane("resolution 1", blob, np.full(200, 0.7), resolution=1)
_, texts, dims = sane("resolution 4096", blob, np.full(200, 0.7), resolution=4096,
                      max_resolution=4096)
check(dims is not None and max(dims) < 4096 and len(texts) == 1,
      "resolution 4096: degraded (%s) with one message" % (dims,))

# 1e6 from the origin: the picture at the origin
lattice = np.stack(np.meshgrid(np.arange(6.0), np.arange(6.0), np.arange(6.0)), -1).reshape(-1, 3)
near, _, _ = sane("lattice at the origin", lattice, np.full(len(lattice), 0.5))
far, _, _ = sane("lattice 1e6 away", lattice, np.full(len(lattice), 0.5), offset=(1e6, 1e6, 1e6))
mean = float(np.abs(near - far).mean())
check(mean < 0.5, "1e6 from the origin: the same picture (mean difference %.3f/255, max %d)"
      % (mean, int(np.abs(near - far).max())))

sys.exit(finish())
