"""The Particles representation in ParaView's standard Render View: the LAMMPS FCC block
(Testing/Data/fcc_block.vtp: 32000 atoms, a z-cylinder of type 2) with radii from the 'radius'
point array -- picked by the default radius source, Automatic -- coloured by atom type through a
categorical lookup table. Baseline-image test.

usage: pvpython TestParticlesRepresentation.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR [--must-fail darker]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.SAME_PLATFORM  # tolerance 2/255, 0.1 % of the pixels, mean 0.5/255

args = pr.parse_arguments()
pr.load_plugin(args)

atoms, from_file = pr.open_particles(args, "fcc_block.vtp")
view = pr.setup_view(simple.CreateView("RenderView"))
# the radius source left at its default (Automatic): the data's "radius" array must be used,
# which the baseline (radii from 'radius') checks
display = pr.show_particles(atoms, view, use_radius_array=None)
pr.set_camera(view, position=(84.0, -52.0, 62.0), focal_point=(15.1, 15.1, 13.5))
if pr.must_fail(args, "darker"):
    display.Diffuse = 0.9  # the spheres' diffuse light 10 % darker: must be rejected

ok = True
# the representation's properties as the panel exposes them
expected = {"UseRadiusArray": "Automatic", "RadiusScaleFactor": 1.0}
for name, value in expected.items():
    if display.GetPropertyValue(name) != value:
        print("FAIL: %s is %r, expected %r" % (name, display.GetPropertyValue(name), value))
        ok = False
if display.RadiusArray[1] != "radius":
    print("FAIL: RadiusArray is %r" % (display.RadiusArray[:],))
    ok = False
if "Particles" not in display.Representation.Available:
    print("FAIL: 'Particles' is not a representation type")
    ok = False

name = "TestParticlesRepresentation" + ("" if from_file else "_synthetic")
ok = pr.capture_and_compare(view, name, args, CRITERIA)[0] and (ok or bool(args.must_fail))
pr.finish(ok)
