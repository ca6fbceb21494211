"""PointAO (vtkPointAOPass, Eichelbaum et al. 2013) in ParaView: the Particle Render View's
"Particle Ambient Occlusion" choice "PointAO" puts the screen-space pass into the view's chain.
The LAMMPS FCC block (32000 atoms, radii from 'radius', coloured by type) is compared with a
baseline; PointAO must darken the block and brighten nothing, use four mean radii by default,
follow its settings (strength 0 is the plain picture, a larger radius darkens more, fewer
directions change the picture a little), leave the background alone, leave translucent
particles alone with a warning, and give way to another
AO choice (one pass in the chain). With scale-consistent shading on, the S-NDF pass warns and
shows PointAO's picture (S-NDF samples need per-fragment occlusion).

Criteria of the baseline comparison as in TestParticleRenderViewAO: a mean of 1/255 or 1 % of
the pixels over 4/255 rejects a picture whose occlusion is off or another method's.
Must-fail cases: ao-off (no AO), density-volume (the density-volume AO's picture).

usage: pvpython TestPointAOParaView.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR [--must-fail ao-off|density-volume]
"""
import os
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.Criteria(tolerance=4.0, max_share=1e-2, max_mean=1.0)

args = pr.parse_arguments()
pr.load_plugin(args)
ok = True

atoms, from_file = pr.open_particles(args, "fcc_block.vtp")
view = pr.setup_view(simple.CreateView("ParticleRenderView"))
display = pr.show_particles(atoms, view)
pr.set_camera(view, position=(84.0, -52.0, 62.0), focal_point=(15.1, 15.1, 13.5))
name = "TestPointAOParaView" + ("" if from_file else "_synthetic")


def info(property_name):
    view.SMProxy.UpdatePropertyInformation()
    return view.GetPropertyValue(property_name)


def rgb(image):
    return vtk_to_numpy(image.GetPointData().GetScalars()).astype(int)[:, :3]


def shot(tag):
    return pr.capture(view, os.path.join(args.temp_dir, "TestPointAOParaView_%s.png" % tag))


def full_test():
    ok = True
    plain = shot("off")
    view.ParticleAmbientOcclusion = 'PointAO'
    if info("NumberOfParticlePasses") != 1:
        print("FAIL: PointAO on, but %s passes in the chain" % info("NumberOfParticlePasses"))
        ok = False
    image_ok, occluded = pr.capture_and_compare(view, name, args, CRITERIA)
    ok = image_ok and ok
    radius = info("PointAOEffectiveRadius")
    print("automatic radius %.4f" % radius)
    # fcc_block.vtp: radii 0.5 (type 1) and 0.4 (type 2); four mean radii lie between
    if not 1.6 <= radius <= 2.0:
        print("FAIL: the automatic radius %s is not four mean particle radii" % radius)
        ok = False

    background = (rgb(plain) == rgb(plain)[0]).all(axis=1)
    a = rgb(plain).sum(axis=1)
    b = rgb(occluded).sum(axis=1)
    darker = int((b < a - 3).sum())
    brighter = int((b > a + 3).sum())
    print("PointAO: %d pixels darker, %d brighter; background changed: %d"
          % (darker, brighter, int((b != a)[background].sum())))
    if darker < 5000 or brighter > 0 or (b != a)[background].any():
        print("FAIL: PointAO should darken the block, brighten nothing, leave the background")
        ok = False

    # the settings reach the pass
    view.PointAOStrength = 0.0
    if pr.max_abs_difference(plain, shot("strength0")) > 1:
        print("FAIL: strength 0 is not the plain picture")
        ok = False
    view.PointAOStrength = 1.4
    view.PointAORadius = 2.0 * radius
    wide = rgb(shot("wide")).sum(axis=1)
    view.PointAORadius = 0.0
    print("radius x2: mean darkening %.2f against %.2f" % ((a - wide).mean(), (a - b).mean()))
    if not (a - wide).mean() > 1.02 * (a - b).mean():
        print("FAIL: a radius twice as large does not darken more")
        ok = False
    view.PointAODirections = 2
    worst, mean = pr.difference(occluded, shot("directions2"))
    view.PointAODirections = 4
    print("2 directions instead of 4: max %s, mean %.2f /255" % (worst, mean))
    if not (mean is not None and 0.05 < mean < 6.0):
        print("FAIL: the direction count does not reach the pass (or changes too much)")
        ok = False
    view.PointAOHalfResolution = 1
    worst, mean = pr.difference(occluded, shot("half"))
    view.PointAOHalfResolution = 0
    print("half resolution: max %s, mean %.2f /255" % (worst, mean))
    if not (mean is not None and 0.05 < mean < 8.0):
        print("FAIL: half resolution does not reach the pass (or changes too much)")
        ok = False
    if pr.max_abs_difference(occluded, shot("again")) != 0:
        print("FAIL: back to the defaults does not give the same picture")
        ok = False

    # S-NDF shading with PointAO inside: a warning, and PointAO's picture
    view.ScaleConsistentShading = 1
    view.SNDFConvergeStillRenders = 1
    with pr.captured_messages() as messages:
        with_sndf = shot("sndf")
    text = messages.GetOutput()
    view.ScaleConsistentShading = 0
    print("S-NDF with PointAO: difference max %s" % pr.max_abs_difference(occluded, with_sndf))
    if "vtkPointAOPass" not in text or pr.max_abs_difference(occluded, with_sndf) > 1:
        print("FAIL: S-NDF with PointAO should warn and show PointAO's picture; messages: %s"
              % text.strip())
        ok = False

    # translucent particles: not darkened (no depth in the G-buffer), with a warning
    display.Opacity = 0.5
    view.ParticleAmbientOcclusion = 'None'
    see_through = shot("translucent_off")
    view.ParticleAmbientOcclusion = 'PointAO'
    with pr.captured_messages() as messages:
        translucent = shot("translucent")
    display.Opacity = 1.0
    print("translucent particles: difference to no AO max %s"
          % pr.max_abs_difference(see_through, translucent))
    if "translucent particles" not in messages.GetOutput() or \
            pr.max_abs_difference(see_through, translucent) > 1:
        print("FAIL: translucent particles should be left alone with a warning; messages: %s"
              % messages.GetOutput().strip())
        ok = False

    # one AO choice: the density volume replaces PointAO, and back
    view.ParticleAmbientOcclusion = 'Density Volume'
    if info("NumberOfParticlePasses") != 1 or pr.max_abs_difference(occluded, shot("dv")) < 8:
        print("FAIL: the density volume should replace PointAO")
        ok = False
    view.ParticleAmbientOcclusion = 'PointAO'
    if pr.max_abs_difference(occluded, shot("back")) != 0:
        print("FAIL: back to PointAO does not give its picture")
        ok = False
    view.ParticleAmbientOcclusion = 'None'
    if info("NumberOfParticlePasses") != 0 or pr.max_abs_difference(plain, shot("off2")) != 0:
        print("FAIL: AO off should empty the chain and restore the picture")
        ok = False
    return ok


if pr.must_fail(args, "ao-off"):
    pr.finish(pr.capture_and_compare(view, name, args, CRITERIA)[0])
elif pr.must_fail(args, "density-volume"):
    view.ParticleAmbientOcclusion = 'Density Volume'
    pr.finish(pr.capture_and_compare(view, name, args, CRITERIA)[0])
else:
    pr.finish(full_test() and ok)
