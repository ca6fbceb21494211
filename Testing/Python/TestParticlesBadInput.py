"""Bad input through ParaView: the Particles representation must render without crashing for
  (a) an empty polydata (with Use Radius Array on): nothing drawn, no warning (an empty local
      piece is normal in ParaView, the representation hides its actor);
  (b) points without the chosen radius array (RadiusArray names a missing array),
  (c) a 2-component array chosen as radius (a plane's TextureCoordinates).
(b) and (c) warn and fall back to the constant Radius: two 7x7 grids of equal spheres, (b)
grey-blue on the left, (c) yellow on the right. Baseline-image test. Each representation's own
warning (its ParticleInputWarning information property) must say what is wrong with its input:
none for (a), the missing 'radius' for (b), the 2-component TextureCoordinates for (c); and every
warning logged during the test must be one of those two -- in particular no "no points" warning
for the empty piece and no "already exists" warning (loading the plugin must not replace stock
ParaView properties). Switching representation and radius source back and forth on these inputs
must not crash either.

usage: pvpython TestParticlesBadInput.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.SAME_PLATFORM  # tolerance 2/255, 0.1 % of the pixels, mean 0.5/255

args = pr.parse_arguments()
pr.load_plugin(args)
ok = True

# collect the warnings (they are printed at the end)
with pr.captured_messages() as messages:  # (reported after the block)

    view = pr.setup_view(simple.CreateView("RenderView"))

    # (a) empty polydata
    empty = simple.ProgrammableSource(OutputDataSetType="vtkPolyData", Script="")
    shown_a = simple.Show(empty, view)
    shown_a.Representation = "Particles"
    shown_a.UseRadiusArray = 1
    shown_a.RadiusArray = ["POINTS", "radius"]

    # (b) no radius array
    plane_b = simple.Plane(Origin=[-6.0, -2.5, 0.0], Point1=[-1.0, -2.5, 0.0], Point2=[-6.0, 2.5, 0.0],
                           XResolution=6, YResolution=6)
    shown_b = simple.Show(plane_b, view)
    shown_b.Representation = "Particles"
    shown_b.Radius = 0.3
    shown_b.UseRadiusArray = 1
    shown_b.RadiusArray = ["POINTS", "radius"]
    shown_b.ColorArrayName = ["POINTS", ""]
    shown_b.DiffuseColor = [0.55, 0.65, 0.9]

    # (c) 2-component radius array
    plane_c = simple.Plane(Origin=[1.0, -2.5, 0.0], Point1=[6.0, -2.5, 0.0], Point2=[1.0, 2.5, 0.0],
                           XResolution=6, YResolution=6)
    shown_c = simple.Show(plane_c, view)
    shown_c.Representation = "Particles"
    shown_c.Radius = 0.3
    shown_c.UseRadiusArray = 1
    shown_c.RadiusArray = ["POINTS", "TextureCoordinates"]
    shown_c.ColorArrayName = ["POINTS", ""]
    shown_c.DiffuseColor = [0.95, 0.8, 0.25]

    pr.set_camera(view, position=(0.0, -14.0, 16.0), focal_point=(0.0, 0.0, 0.0), view_up=(0, 1, 0))
    simple.Render(view)

    # switching things back and forth on bad input must not crash either
    for display in (shown_a, shown_b, shown_c):
        display.Representation = "Surface"
        simple.Render(view)
        display.Representation = "Particles"
        display.UseRadiusArray = 0
        simple.Render(view)
        display.UseRadiusArray = 1
        simple.Render(view)

    name = "TestParticlesBadInput"
    ok = pr.capture_and_compare(view, name, args, CRITERIA)[0] and ok

text = messages.GetOutput()
print("---- warnings ----\n%s\n------------------" % text.strip())

# each representation's own warning
EXPECTED = {
    "(a)": (shown_a, ""),
    "(b)": (shown_b, "Radius array 'radius' is not a point array of the input"),
    "(c)": (shown_c, "Radius array 'TextureCoordinates' has 2 components"),
}
for case, (display, needle) in EXPECTED.items():
    display.SMProxy.UpdatePropertyInformation()
    warning = display.GetPropertyValue("ParticleInputWarning")
    print("%s: %r" % (case, warning))
    if (needle == "" and warning != "") or needle not in warning:
        print("FAIL: case %s warned %r, expected %s" % (case, warning,
                                                       repr(needle) if needle else "nothing"))
        ok = False

# every logged warning is one of the expected ones
blocks = [b.strip() for b in text.split("Warning: In ") if b.strip()]
unexpected = [b for b in blocks if not any(n and n in b for _, n in EXPECTED.values())]
print("%d warnings logged, %d unexpected" % (len(blocks), len(unexpected)))
for block in unexpected:
    print("FAIL: unexpected warning: %s" % block.replace("\n", " "))
ok = ok and not unexpected and len(blocks) > 0

pr.finish(ok)
