"""A density volume larger than the free memory is an error message, not an abort.

vtkDensityVolumeAOPass with Resolution 4096, MaximumResolution 4096 and MaximumVoxelCount lifted
asked for 34 GB on the CPU build (the grid is clamped to the GPU's largest 3D texture per axis,
2048 on llvmpipe) and aborted on an uncaught std::bad_alloc. Checked, for the CPU and the GPU
build: the render returns, the pass reports one error naming the grid and the sizes ("needs X GB,
Y GB free"), the particles are drawn (without ambient occlusion: the same picture as with no AO
pass), and a second render neither retries nor repeats the message. Then a sane resolution on the
same pass builds the volume again.

The reference renderer's images too: 200000 x 200000 pixels (about 4 TB) are an error naming the
size, Render() returns False with empty images, and a sane size renders afterwards.

usage: python3 TestDensityVolumeMemory.py
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import Messages, actor_view, check, finish, grab_image, particles_from
from vtkmodules.vtkCommonCore import VTK_ID_MAX
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

particles = particles_from(np.random.default_rng(2).random((5000, 3)) * 20.0)


def scene(with_ao, mode=0):
    mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(particles)
    mapper.SetRadius(0.6)
    _, renderer, window = actor_view(mapper)
    ao = None
    if with_ao:
        ao = pr.vtkDensityVolumeAOPass()
        ao.SetDelegatePass(vtkRenderStepsPass())
        ao.SetGenerationMode(mode)
        volume = ao.GetDensityVolume()
        volume.SetResolution(4096)
        volume.SetMaximumResolution(4096)
        volume.SetMaximumVoxelCount(VTK_ID_MAX)
        renderer.SetPass(ao)
    renderer.ResetCamera()
    return window, ao


window, _ = scene(False)
window.Render()
plain = grab_image(window)
for mode, name in ((0, "CPU"), (1, "GPU")):
    window, ao = scene(True, mode)
    messages = Messages(ao.GetDensityVolume())
    pass_messages = Messages(ao)
    window.Render()
    window.Render()  # the same input again: no retry, no second message
    errors = messages.errors + pass_messages.errors
    print("%s build: %s" % (name, [e.split("): ")[-1].strip() for e in errors]))
    check(len(errors) == 1, "%s build: %d errors, expected one" % (name, len(errors)))
    check(any("density volume" in e and " GB" in e and "free" in e and "no ambient occlusion" in e
              for e in errors), "%s build: the error does not name the sizes: %s" % (name, errors))
    image = grab_image(window)
    check(np.array_equal(image, plain), "%s build: the particles are not drawn as without AO" % name)
    # a sane resolution on the same pass: built
    ao.GetDensityVolume().SetResolution(64)
    ao.GetDensityVolume().SetMaximumResolution(256)
    window.Render()
    check(ao.GetNumberOfVolumeBuilds() == 1, "%s build: a sane resolution builds no volume" % name)

# the reference renderer's images
reference = pr.vtkParticleReferenceRenderer()
reference_messages = Messages(reference)
mapper = pr.vtkParticleSphereMapper()
mapper.SetInputData(particles)
mapper.SetRadius(0.3)
actor, renderer, window = actor_view(mapper, (64, 64))
renderer.ResetCamera()
window.Render()
reference.SetRenderer(renderer)
reference.SetActor(actor)
reference.SetImageSize(200000, 200000)
rendered = reference.Render()
print("reference at 200000 x 200000: %s %s" % (rendered, reference_messages.errors))
check(not rendered and reference.GetColorImage().GetNumberOfPoints() == 0,
      "reference: a huge image is refused")
check(any("200000 x 200000" in e and "free" in e for e in reference_messages.errors),
      "reference: the error names the size: %s" % reference_messages.errors)
reference.SetImageSize(32, 32)
check(reference.Render() and reference.GetColorImage().GetNumberOfPoints() == 32 * 32,
      "reference: a sane size renders afterwards")

sys.exit(finish())
