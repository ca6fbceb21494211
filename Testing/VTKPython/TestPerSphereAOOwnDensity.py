"""Per-sphere ambient occlusion does not count a sphere's own density (issue 17, section 4).

vtkDensityVolumeAOPass's PER_SPHERE retrieval fetches the density at the centre +- eps along the
world axes. The volume holds every sphere's own volume around its centre, so before the fix an
isolated sphere darkened itself (brightness 0.967 of the picture without AO here) and with voxels
finer than the spheres the whole picture darkened (a 12^3 lattice at Resolution 128: 0.794, while
per-fragment retrieval stays at 1.000). The fetches now subtract the sphere's own splat share
(Shaders/AmbientOcclusion/DensityVolumeOwn.glsl). Checked, brightness = sum of RGB relative to no AO, 200x200:
- a single sphere, per sphere: >= 0.998 (nearest-voxel and trilinear splats);
- the lattice at Resolution 64 and 128, per sphere: within 0.02 of per fragment;
- the lattice at the default resolution still shows occlusion (per sphere < 0.95): the
  subtraction removes the sphere's own share only.

usage: python3 TestPerSphereAOOwnDensity.py
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import check, finish, grab_image, offscreen_window, particles_from
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

PER_FRAGMENT, PER_SPHERE = 0, 1


def brightness(xyz, ao=True, mode=PER_SPHERE, resolution=0, splat=1):
    mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(particles_from(np.asarray(xyz, dtype=np.float64)))
    mapper.SetRadius(0.5)
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    if ao:
        aopass = pr.vtkDensityVolumeAOPass()
        aopass.SetDelegatePass(vtkRenderStepsPass())
        aopass.SetRetrievalMode(mode)
        aopass.GetDensityVolume().SetResolution(resolution)
        aopass.GetDensityVolume().SetSplatMode(splat)
        renderer.SetPass(aopass)
    window = offscreen_window(renderer)
    renderer.ResetCamera()
    window.Render()
    return float(grab_image(window)[:, :3].sum())


single = np.zeros((1, 3))
lattice = np.stack(np.meshgrid(*(np.arange(12),) * 3, indexing="ij"), -1).reshape(-1, 3)
plain_single = brightness(single, ao=False)
plain_lattice = brightness(lattice, ao=False)
for splat, name in ((0, "nearest-voxel"), (1, "trilinear")):
    b = brightness(single, splat=splat) / plain_single
    print("single sphere, %s splat, per sphere: %.4f" % (name, b))
    check(b >= 0.998, "a single sphere darkens itself (%s splat): %.4f" % (name, b))
for resolution in (64, 128):
    sphere = brightness(lattice, resolution=resolution) / plain_lattice
    fragment = brightness(lattice, mode=PER_FRAGMENT, resolution=resolution) / plain_lattice
    print("lattice, resolution %d: per sphere %.4f, per fragment %.4f" % (resolution, sphere, fragment))
    check(abs(sphere - fragment) <= 0.02,
          "fine volume: per sphere %.4f vs per fragment %.4f" % (sphere, fragment))
default = brightness(lattice) / plain_lattice
print("lattice, default resolution: per sphere %.4f" % default)
check(default < 0.95, "the lattice shows no occlusion per sphere: %.4f" % default)
sys.exit(finish())
