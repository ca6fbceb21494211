"""vtkVoxelConeAOPass in a context without compute shaders (issue: voxel-cone AO, "Bad input":
a context without compute shaders). CTest runs it with MESA_GL_VERSION_OVERRIDE=3.3, so that
Mesa gives an OpenGL 3.3 context. Checked there: the ambient volume says once, by a warning, that
it voxelises on the CPU; the build does not run on the GPU; the opaque spheres still get their
ambient occlusion (the side of a probe facing a slab of spheres is darker than without the pass)
and the picture equals, to 1/255, the one this script renders in an OpenGL 4.3+ context with the
GPU voxelisation (passed in by CTest as a second run with --reference-out / --reference-in).

usage: python3 TestVoxelConeAONoCompute.py --reference-out FILE   (in a 4.3+ context)
       python3 TestVoxelConeAONoCompute.py --reference-in FILE    (under a 3.3 override)
"""
import argparse
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import Messages, check, finish, grab_image, offscreen_window, particles_from
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

parser = argparse.ArgumentParser()
parser.add_argument("--reference-out")
parser.add_argument("--reference-in")
args = parser.parse_args()


def render(ao):
    g = np.arange(12) - 5.5
    x, y = np.meshgrid(g, g)
    xyz = np.vstack([np.stack([x.ravel(), y.ravel(), np.zeros(x.size)], axis=1),
                     [[0.0, 0.0, 1.6]]])
    radii = np.concatenate([np.full(x.size, 0.5), [1.0]])
    mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(particles_from(xyz, radius=radii))
    mapper.SetRadiusArrayName("radius")
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    aopass = None
    messages = None
    if ao:
        aopass = pr.vtkVoxelConeAOPass()
        aopass.SetDelegatePass(vtkRenderStepsPass())
        messages = Messages(aopass.GetAmbientVolume())
        renderer.SetPass(aopass)
    window = offscreen_window(renderer, (200, 200))
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.0, 0.0, 1.6)
    camera.SetPosition(0.0, -12.0, 2.2)
    camera.SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    return grab_image(window)[:, :3], aopass, messages, window


plain, _, _, _ = render(False)
image, aopass, messages, window = render(True)
volume = aopass.GetAmbientVolume()
check(aopass.GetNumberOfVolumeBuilds() == 1, "the volume is built")
# the probe's underside (rows below its centre) is darker with AO
rows = image.reshape(200, 200, 3)[100 - 40:100 - 20, 90:110].mean()
rows_plain = plain.reshape(200, 200, 3)[100 - 40:100 - 20, 90:110].mean()
check(rows < 0.85 * rows_plain, "the probe's side facing the slab is darker (%.1f -> %.1f)"
      % (rows_plain, rows))
check(np.isfinite(image).all(), "no NaN")
if args.reference_out:
    check(volume.GetLastBuildOnGPU(), "reference run: voxelised on the GPU")
    np.save(args.reference_out, image)
if args.reference_in:
    check(not volume.GetLastBuildOnGPU(), "no compute shaders: voxelised on the CPU")
    warned = [t for t in messages.warnings if "voxelised on the CPU" in t]
    check(len(warned) == 1 and "4.3" in warned[0],
          "one warning that says why (OpenGL 4.3) and what happens: %s" % messages.text)
    # a second build (a colour change) does not repeat it
    aopass.Modified()
    for actor in window.GetRenderers().GetFirstRenderer().GetActors():
        actor.GetProperty().SetColor(0.8, 0.9, 1.0)
    window.Render()
    check(aopass.GetNumberOfVolumeBuilds() == 2, "rebuilt after the colour change")
    check(len([t for t in messages.warnings if "voxelised on the CPU" in t]) == 1,
          "the warning is not repeated")
    reference = np.load(args.reference_in)
    difference = int(np.abs(reference - image).max())
    check(difference <= 1, "the same picture as with the GPU voxelisation (max %d/255)"
          % difference)
sys.exit(finish())
