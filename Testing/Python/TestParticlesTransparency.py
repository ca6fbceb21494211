"""Translucent particles in ParaView (vtkTransparentSphereMapper through the Particles
representation): the LAMMPS droplets (Testing/Data/lj_droplets.vtp, 11033 atoms) with the
maximum opacity from the atoms' speed (Use Opacity Array, the fastest atoms opaque), one
baseline image per density model -- Constant, and Squared Distance with a hollow core -- and
the same images with ParaView's depth peeling switched off (VTK's order-independent pass then
drives the translucent stage; the particles composite themselves either way). Also checks the
properties the panel exposes and their defaults.

Criteria of the baseline comparisons: the GPU's own image on the same platform matches to
rounding; the test is about the translucent shading (density model, hollow core), so at most
0.1 % of the pixels may differ by more than 2/255 and the mean by 0.5/255. Must-fail cases:
swapped-models (each baseline compared with the other model's picture) and solid (the Squared
Distance baseline compared with the picture without the hollow core).

usage: pvpython TestParticlesTransparency.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR [--must-fail swapped-models|solid]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.SAME_PLATFORM  # tolerance 2/255, 0.1 % of the pixels, mean 0.5/255

args = pr.parse_arguments()
pr.load_plugin(args)

atoms, from_file = pr.open_particles(args, "lj_droplets.vtp")
view = pr.setup_view(simple.CreateView("RenderView"), size=(500, 400))
display = pr.show_particles(atoms, view, use_radius_array=False)
display.Radius = 0.42

ok = True
defaults = {"DensityModel": "Constant", "HollowFraction": 0.0, "VolumeMix": 0.5,
            "UseOpacityArray": 0, "EarlyTermination": 0}
for name, value in defaults.items():
    if display.GetPropertyValue(name) != value:
        print("FAIL: %s is %r, expected %r" % (name, display.GetPropertyValue(name), value))
        ok = False

# the baselines are of the paper's opacity (of one particle's densest chord)
display.OpacityReference = "One Particle"
display.UseOpacityArray = 1
# the default range follows the chosen array (Data Range): radius first, then speed
for array in ("radius", "speed"):
    display.ParticleOpacityArray = ["POINTS", array]
    simple.Render(view)
    display.SMProxy.UpdatePropertyInformation()
    got = list(display.GetPropertyValue("OpacityArrayDataRange"))
    expected = list(atoms.PointData[array].GetRange())
    print("Data Range of %s: %s (array range %s)" % (array, got, expected))
    if display.OpacityArrayRangeMode != "Data Range" or \
            max(abs(a - b) for a, b in zip(got, expected)) > 1e-6 * max(1.0, abs(expected[1])):
        print("FAIL: the opacity range does not follow the array %s" % array)
        ok = False
display.OpacityArrayRangeMode = "Custom"
display.OpacityArrayRange = [0.0, 3.0]
pr.set_camera(view, position=(95.0, 20.0, 95.0), focal_point=(40.0, 40.0, 40.0),
              view_up=(0, 1, 0), view_angle=30.0)

suffix = "" if from_file else "_synthetic"
MODELS = (("Constant", 0.0, 0.5), ("Squared Distance", 0.4, 0.3))


def show_model(model, hollow, mix):
    display.DensityModel = model
    display.HollowFraction = hollow
    display.VolumeMix = mix


def baseline_name(model):
    return "TestParticlesTransparency_" + model.replace(" ", "") + suffix


view.EnableRenderOnInteraction = 0
if pr.must_fail(args, "swapped-models"):
    # each baseline against the picture of the other density model
    for (model, _, _), (other, hollow, mix) in zip(MODELS, reversed(MODELS)):
        show_model(other, hollow, mix)
        ok = pr.capture_and_compare(view, baseline_name(model), args, CRITERIA)[0] and ok
elif pr.must_fail(args, "solid"):
    model, _, mix = MODELS[1]
    show_model(model, 0.0, mix)
    ok = pr.capture_and_compare(view, baseline_name(model), args, CRITERIA)[0]
else:
    for model, hollow, mix in MODELS:
        show_model(model, hollow, mix)
        view.DepthPeeling = 1
        peeled_ok, peeled = pr.capture_and_compare(view, baseline_name(model), args, CRITERIA)
        ok = peeled_ok and ok
        view.DepthPeeling = 0
        unpeeled = pr.capture(view, os.path.join(args.temp_dir,
                                                 baseline_name(model) + "_nopeeling.png"))
        difference = pr.max_abs_difference(peeled, unpeeled)
        print("%s: max |depth peeling - no depth peeling| = %s/255" % (model, difference))
        if difference is None or difference > 1:
            print("FAIL: %s differs with and without depth peeling" % model)
            ok = False
        view.DepthPeeling = 1

pr.finish(ok)
