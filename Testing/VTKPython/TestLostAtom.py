"""One lost atom far away does not spoil the rest (issue 17, section 1).

A 3x3 cluster near (1000, 1000, 0) plus one particle at x = 1e8: with VTK's single float
shift/scale over the 1e8 extent the cluster snapped onto a grid of several radii (here 4232 of
40000 pixels wrong opaque, 6360 translucent). The mapper now switches its default shift/scale to
VTK's focal-point shift when one origin cannot keep a thousandth of the smallest radius, and says
so once. Checked, against the cluster rendered alone (and the far atom alone), 200x200:
- opaque and translucent (opacity 0.5): the same picture (no pixel off by more than 2/255) from the
  cluster's view, after an orbit with a dolly, and looking at the lost atom itself; also with a
  NaN particle in the data;
- one warning naming the extent (besides the one for the NaN particle); camera moves re-upload
  nothing while the focal point stays;
- data without an outlier keeps VTK's default method and warns nothing.

A lone small particle (or a tight group) away from the origin: radius 1e-6 at (1, 2, 3). VTK's
automatic shift leaves a single point (or a group of small extent) unshifted, and the float view
translation resolved 2^-23 of |(1, 2, 3)|: the depth was off by 0.48 R. Checked, opaque and
translucent, one particle and four within 3e-6: the same picture as the scene moved to the origin
(no pixel off by more than 2/255), and the opaque depth within 1e-3 R of the reference renderer.

usage: python3 TestLostAtom.py
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import Messages, check, finish, grab_image, offscreen_window, particles_from
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

CLUSTER = np.array([[1000.0 + i, 1000.0 + j, 0.0] for i in range(3) for j in range(3)])
FAR = np.array([[1e8, 0.0, 0.0]])
LOST = np.vstack([CLUSTER, FAR, [[np.nan, 0.0, 0.0]]])
FOCAL_POINT_SHIFT_SCALE = 6


def scene(xyz, translucent, radius=0.4):
    """(mapper, renderer, window, messages) of the particles xyz, opaque or translucent, with
    the cluster's camera."""
    mapper = (pr.vtkTransparentSphereMapper if translucent else pr.vtkParticleSphereMapper)()
    mapper.SetInputData(particles_from(xyz))
    mapper.SetRadius(radius)
    messages = Messages(mapper)
    actor = vtkActor()
    actor.SetMapper(mapper)
    if translucent:
        actor.GetProperty().SetOpacity(0.5)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    window = offscreen_window(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(1001.0, 1001.0, 0.0)
    camera.SetPosition(1001.0, 1001.0, 10.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetClippingRange(1.0, 30.0)
    return mapper, renderer, window, messages


def wrong(a, b):
    return int((np.abs(grab_image(a) - grab_image(b)).max(axis=1) > 2).sum())


for translucent in (False, True):
    kind = "translucent" if translucent else "opaque"
    reference = scene(CLUSTER, translucent)
    lost = scene(LOST, translucent)
    for step in range(3):
        for mapper, renderer, window, _ in (reference, lost):
            if step:
                renderer.GetActiveCamera().Azimuth(25.0)
                renderer.GetActiveCamera().Dolly(1.2)
            window.Render()
        bad = wrong(reference[2], lost[2])
        print("%s, view %d: %d pixels wrong" % (kind, step, bad))
        check(bad == 0, "%s, view %d: the cluster is off in %d pixels" % (kind, step, bad))
    check(lost[0].GetNumberOfUploads() == 1,
          "%s: %d uploads for camera moves" % (kind, lost[0].GetNumberOfUploads()))
    check(lost[0].GetVBOShiftScaleMethod() == FOCAL_POINT_SHIFT_SCALE,
          "%s: the method is %d" % (kind, lost[0].GetVBOShiftScaleMethod()))
    precision = [w for w in lost[3].warnings if "beyond single precision" in w]
    check(len(precision) == 1, "%s: %d precision warnings" % (kind, len(precision)))
    check(not reference[3].warnings and reference[0].GetVBOShiftScaleMethod() != FOCAL_POINT_SHIFT_SCALE,
          "%s: the cluster alone changed its method or warned" % kind)
    # look at the lost atom itself
    far = scene(FAR, translucent)
    for mapper, renderer, window, _ in (far, lost):
        camera = renderer.GetActiveCamera()
        camera.SetFocalPoint(1e8, 0.0, 0.0)
        camera.SetPosition(1e8 + 0.3, 0.2, 3.0)
        camera.SetClippingRange(0.1, 10.0)
        window.Render()
    bad = wrong(far[2], lost[2])
    print("%s, at the lost atom: %d pixels wrong" % (kind, bad))
    check(bad == 0, "%s: the lost atom itself is off in %d pixels" % (kind, bad))

# ---- a lone small particle (or a tight group) away from the origin
from prVTKTesting import compare  # noqa: E402

TINY = 1e-6
GROUPS = {"one particle": np.array([[0.0, 0.0, 0.0]]),
          "four within 3e-6": np.array([[0.0, 0.0, 0.0], [2e-6, 0.0, 0.0], [0.0, 1.5e-6, 0.5e-6],
                                        [1e-6, 1e-6, -1.5e-6]])}
for name, group in GROUPS.items():
    for translucent in (False, True):
        kind = "translucent" if translucent else "opaque"
        views = []
        for origin in (np.zeros(3), np.array([1.0, 2.0, 3.0])):
            mapper, renderer, window, _ = scene(group + origin, translucent, TINY)
            camera = renderer.GetActiveCamera()
            camera.SetFocalPoint(*(origin + [0.5e-6, 0.5e-6, 0.0]))
            camera.SetPosition(*(origin + [3e-6, -2e-6, 8e-6]))
            camera.SetClippingRange(1e-6, 2e-5)
            window.Render()
            views.append((window, renderer, renderer.GetActors().GetLastActor()))
        bad = wrong(views[0][0], views[1][0])
        covered = int((grab_image(views[0][0]).max(axis=1) > 0).sum())
        print("tiny %s, %s: %d of %d covered pixels differ from the scene at the origin"
              % (name, kind, bad, covered))
        check(covered > 500 and bad == 0,
              "tiny %s, %s: %d pixels off (covered %d)" % (name, kind, bad, covered))
        if not translucent:
            r = compare(*views[1], TINY)
            print("tiny %s at (1, 2, 3): depth error max %.2e R outside silhouettes, coverage "
                  "differs in %d + %d" % (name, r["max_smooth"], r["only_gpu"], r["only_ref"]))
            check(r["max_smooth"] <= 1e-3, "tiny %s: depth off by %.2e R" % (name, r["max_smooth"]))

sys.exit(finish())
