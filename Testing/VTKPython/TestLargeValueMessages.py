"""Values too large for single precision are named as such (issue 17, section 6), and data
beyond double precision for VTK's matrices is reported (section 2).

A radius of 1e38 used to be reported as "zero, negative, NaN or infinite", a position of 1e300 as
"NaN or infinite". Checked on 100 particles (double-precision points and radii): 2 with a radius of
1e38, 3 with a coordinate of 1e300, 1 with a NaN coordinate and 1 with radius 0 give one warning
with the four counts, each named for what it is, and 93 particles are drawn.

A sphere of radius 1e-6 at 1e8 from the origin (1e14 radii; VTK's double matrices resolve 2.2 %
of the radius there) gives the double-precision warning, with the eye inside it too (drawn, not
culled: the view is covered); at 1e6 (1e12 radii) there is none.

usage: python3 TestLargeValueMessages.py
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import Messages, actor_view, check, finish, grab_image, particles_from
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
actor, renderer, window = actor_view(mapper, (100, 100))
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
# beyond double precision (section 2)
for centre, expected in ((1e8, True), (1e6, False)):
    tiny = particles_from(np.array([[centre, 0.0, 0.0]]))
    tiny_mapper = pr.vtkParticleSphereMapper()
    tiny_mapper.SetInputData(tiny)
    tiny_mapper.SetRadius(1e-6)
    tiny_messages = Messages(tiny_mapper)
    _, tiny_renderer, tiny_window = actor_view(tiny_mapper, (64, 64))
    camera = tiny_renderer.GetActiveCamera()
    camera.SetPosition(centre + 2e-7, 1e-7, 3e-7)  # the eye inside the sphere
    camera.SetFocalPoint(centre - 5e-7, 0.0, -1e-6)
    tiny_renderer.ResetCameraClippingRange()
    tiny_window.Render()
    said = any("beyond double precision" in w for w in tiny_messages.warnings)
    print("centre %g: %s" % (centre, tiny_messages.warnings))
    check(said == expected, "centre %g, radius 1e-6: double-precision warning %s"
          % (centre, "given" if expected else "not given"))
    covered = (grab_image(tiny_window)[:, :3].max(axis=1) > 0).sum()
    check(covered == 64 * 64, "centre %g: the eye inside the sphere sees it everywhere (%d px)"
          % (centre, covered))

sys.exit(finish())

