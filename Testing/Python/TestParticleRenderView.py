"""The Particle Render View with an empty pass chain renders exactly like ParaView's standard
Render View: the scene of TestParticlesRepresentation (LAMMPS FCC block, radii from 'radius',
coloured by type) is rendered in both views and the images must agree to 1/255 in every
channel; the Particle Render View's image is also compared with a baseline.

A second scene exercises what the chain's inner pass (vtkPVDefaultPass) must keep working:
a translucent surface (depth peeling) intersecting the particles, with the renderer's own
ambient occlusion (UseSSAO) on; again both views must agree. The view's pass chain must stay
installed through FXAA, tone mapping and SSAO switching (ParaView rebuilds its pass tree then).

usage: pvpython TestParticleRenderView.py --plugin ParticleRendering.so --data DIR
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


def chain_installed(view):
    view.SMProxy.UpdatePropertyInformation()
    return view.GetPropertyValue("ParticlePassChainInstalled") == 1


def check_installed(view, when):
    global ok
    if not chain_installed(view):
        print("FAIL: the particle pass chain is not installed %s" % when)
        ok = False


def compare_views(image_standard, image_particle, what):
    global ok
    diff = pr.max_abs_difference(image_standard, image_particle)
    print("%s: max abs difference Render View vs Particle Render View = %s/255" % (what, diff))
    if diff is None or diff > 1:
        print("FAIL: %s: the Particle Render View differs from the Render View" % what)
        ok = False


atoms, from_file = pr.open_particles(args, "fcc_block.vtp")


def make_views():
    standard = pr.setup_view(simple.CreateView("RenderView"))
    particle = pr.setup_view(simple.CreateView("ParticleRenderView"))
    return standard, particle


# --- scene 1: the TestParticlesRepresentation scene -----------------------------------------
standard, particle = make_views()
check_installed(particle, "after the view was created")
if particle.GetPropertyValue("NumberOfParticlePasses") != 0:
    print("FAIL: the pass chain is not empty")
    ok = False
images = {}
for view, key in ((standard, "standard"), (particle, "particle")):
    pr.show_particles(atoms, view)
    pr.set_camera(view, position=(84.0, -52.0, 62.0), focal_point=(15.1, 15.1, 13.5))
images["standard"] = pr.capture(
    standard, os.path.join(args.temp_dir, "TestParticleRenderView-standard.png"))
name = "TestParticleRenderView" + ("" if from_file else "_synthetic")
matched, images["particle"] = pr.capture_and_compare(particle, name, args, CRITERIA)
ok = matched and ok
compare_views(images["standard"], images["particle"], "scene 1")
check_installed(particle, "after rendering")

# ParaView rebuilds the renderer's pass tree when these change: the chain must survive.
for prop, on, off in (("UseFXAA", 1, 0), ("UseToneMapping", 1, 0), ("UseSSAO", 1, 0)):
    particle.SetPropertyWithName(prop, on)
    simple.Render(particle)
    check_installed(particle, "with %s on" % prop)
    particle.SetPropertyWithName(prop, off)
    simple.Render(particle)
    check_installed(particle, "after %s off" % prop)
simple.Delete(standard)
simple.Delete(particle)

# --- scene 2: translucent surface through the particles, renderer SSAO ----------------------
standard, particle = make_views()
ball = simple.Sphere(Center=[15.1, 15.1, 30.5], Radius=9.0, ThetaResolution=48,
                     PhiResolution=48)
for view in (standard, particle):
    view.UseAmbientOcclusion = 1
    view.UseSSAODefaultPresets = 1
    pr.show_particles(atoms, view)
    surface = simple.Show(ball, view)
    surface.Representation = "Surface"
    surface.ColorArrayName = ["POINTS", ""]
    surface.DiffuseColor = [0.9, 0.9, 0.3]
    surface.Opacity = 0.45
    pr.set_camera(view, position=(60.0, -30.0, 75.0), focal_point=(15.1, 15.1, 20.0))
images["standard2"] = pr.capture(
    standard, os.path.join(args.temp_dir, "TestParticleRenderView-scene2-standard.png"))
images["particle2"] = pr.capture(
    particle, os.path.join(args.temp_dir, "TestParticleRenderView-scene2-particle.png"))
compare_views(images["standard2"], images["particle2"], "scene 2 (translucency, SSAO)")
# and SSAO really ran in the Particle Render View
particle.UseAmbientOcclusion = 0
images["particle2-nossao"] = pr.capture(
    particle, os.path.join(args.temp_dir, "TestParticleRenderView-scene2-nossao.png"))
ssao_effect = pr.max_abs_difference(images["particle2"], images["particle2-nossao"])
print("scene 2: SSAO on vs off in the Particle Render View: max abs difference %s/255" % ssao_effect)
if not ssao_effect or ssao_effect < 10:
    print("FAIL: turning SSAO off does not change the Particle Render View's image")
    ok = False
check_installed(particle, "at the end")

pr.finish(ok)
