"""Values too large for single precision are named as such (issue 17, section 6).

A radius of 1e38 used to be reported as "zero, negative, NaN or infinite", a position of 1e300 as
"NaN or infinite". Checked on 100 particles (double-precision points and radii): 2 with a radius of
1e38, 3 with a coordinate of 1e300, 1 with a NaN coordinate and 1 with radius 0 give one warning
with the four counts, each named for what it is, and 93 particles are drawn.

usage: python3 TestLargeValueMessages.py
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import Messages, check, finish, offscreen_window, particles_from
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

xyz = np.random.default_rng(4).random((100, 3)) * 10.0
radius = np.full(100, 0.3)
radius[[1, 2]] = 1e38
xyz[[10, 11, 12], 0] = 1e300
xyz[20, 1] = np.nan
radius[30] = 0.0
data = particles_from(xyz, radius=radius)

mapper = pr.vtkParticleSphereMapper()
mapper.SetInputData(data)
mapper.SetRadiusArrayName("radius")
messages = Messages(mapper)
actor = vtkActor()
actor.SetMapper(mapper)
renderer = vtkRenderer()
renderer.AddActor(actor)
window = offscreen_window(renderer, (100, 100))
renderer.ResetCamera()
window.Render()
window.Render()
text = " ".join(messages.warnings)
print(mapper.GetLastInputWarning())
check(len(messages.warnings) == 1, "%d warnings, expected one" % len(messages.warnings))
for expected in ("1 of 100 particles have a NaN or infinite position",
                 "3 of 100 particles have a coordinate of 1e37 or more, too large for single "
                 "precision",
                 "1 of 100 particles have a zero, negative, NaN or infinite radius",
                 "2 of 100 particles have a radius of 1e37 or more, too large for single precision"):
    check(expected in text, "missing: %r" % expected)
check(mapper.GetNumberOfSkippedParticles() == 7,
      "%d particles skipped, expected 7" % mapper.GetNumberOfSkippedParticles())
sys.exit(finish())
