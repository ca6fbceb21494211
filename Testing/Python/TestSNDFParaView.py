"""Scale-consistent shading (vtkSNDFRenderPass, Ibrahim et al. 2017) in ParaView: the Particle
Render View's "Scale-Consistent Shading (S-NDF)" group. An fcc crystal of two atom types
(16^3 unit cells, 16 384 atoms, radius 0.36 lattice constants, coloured by type) is seen whole
at 200x150, about two pixels per atom, where one ray per pixel aliases. Checked:
- off by default (no pass in the chain); on puts one pass in the chain;
- progressive refinement: the render of the change is the plain image (0 samples), each
  further render adds S-NDF Samples Per Frame until S-NDF Target Samples (information property);
- the converged image against the 16x16 super-sampled plain view (a 3200x2400 screenshot of the
  same view box-filtered): mean < 1/255, 99th percentile < 6/255, max < 12/255, where the plain
  image is far off; and against the baseline (same platform);
- Converge Still Renders: after a camera change one Render() gives the converged image, equal
  to the progressively refined one; with Use FXAA on the same picture (FXAA is off under S-NDF);
- re-lighting: a light change re-shades without taking samples again; so do new colours of
  the two atom types, and the old colours back give the picture before; colour by speed, a
  new preset (Cool to Warm to Viridis) re-shades from the bins' moments, near sampling under it;
- parallel projection: a pan and back keeps the samples; a zoom by 1.25 samples anew, and keeps
  them with S-NDF Zoom Between Levels;
- the view's ambient occlusion is sampled with the particles (Density Volume: darker, nowhere
  brighter);
- translucent particles: the plain image and one warning.
Must-fail case: plain (the one-sample image against the S-NDF baseline).

usage: pvpython TestSNDFParaView.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR [--must-fail plain]
"""
import os
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

W, H, S = 200, 150, 16
CRITERIA = pr.SAME_PLATFORM

CRYSTAL_SCRIPT = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
cells = 16
g = np.arange(cells)
base = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1).reshape(-1, 3).astype(float)
offsets = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
xyz = (base[:, None, :] + offsets[None]).reshape(-1, 3)
kind = np.where(np.random.default_rng(1).random(len(xyz)) < 0.3, 2, 1).astype(np.int32)
out = self.GetPolyDataOutput()
points = vtkPoints()
points.SetData(numpy_to_vtk(xyz, deep=True))
out.SetPoints(points)
types = numpy_to_vtk(kind, deep=True)
types.SetName("type")
out.GetPointData().AddArray(types)
speed = numpy_to_vtk(np.random.default_rng(2).random(len(xyz)).astype(np.float32), deep=True)
speed.SetName("speed")
out.GetPointData().AddArray(speed)
"""


def rgb(image):
    return vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)[:, :3].reshape(
        image.GetDimensions()[1], image.GetDimensions()[0], 3)


def view_info(view, name):
    view.SMProxy.UpdatePropertyInformation()
    return view.GetPropertyValue(name)


def errors(a, b):
    d = numpy.abs(a - b)
    return d.mean(), numpy.percentile(d.max(axis=2), 99), d.max()


args = pr.parse_arguments()
pr.load_plugin(args)
ok = True


def check(condition, what):
    global ok
    if not condition:
        print("FAIL: " + what)
        ok = False


crystal = simple.ProgrammableSource()
crystal.OutputDataSetType = "vtkPolyData"
crystal.Script = CRYSTAL_SCRIPT
view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=(W, H))
display = pr.show_particles(crystal, view, use_radius_array=False)
display.Radius = 0.36
display.Specular = 0.0
pr.set_camera(view, position=(40.0, 30.0, 55.0), focal_point=(8.0, 8.0, 8.0), view_up=(0, 1, 0))
view.CameraParallelScale = 1.0  # (unused: perspective)

# --- off by default; the plain view and its super-sampled reference ---------------------------
check(view.ScaleConsistentShading == 0 and view_info(view, "NumberOfParticlePasses") == 0,
      "S-NDF off by default, no pass in the chain")
plain = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_plain.png")))
big_path = os.path.join(args.temp_dir, "TestSNDFParaView_reference_16x.png")
simple.SaveScreenshot(big_path, view, ImageResolution=[W * S, H * S], TransparentBackground=0)
big = rgb(pr.read_png(big_path))
reference = big.reshape(H, S, W, S, 3).mean(axis=(1, 3))

# --- progressive refinement --------------------------------------------------------------------
view.ScaleConsistentShading = 1
view.SNDFSamplesPerFrame = 64
view.SNDFTargetSamples = 256
check(view_info(view, "NumberOfParticlePasses") == 1, "S-NDF on: one pass in the chain")
simple.Render(view)
counts = [view_info(view, "SNDFNumberOfSamples")]
for _ in range(5):
    simple.Render(view)
    counts.append(view_info(view, "SNDFNumberOfSamples"))
print("samples after each render:", counts)
check(counts == [0, 64, 128, 192, 256, 256],
      "the render of the change is plain, then 64 samples per render up to 256 (%s)" % counts)
check(view_info(view, "SNDFActiveBins") == 8, "8 x 8 bins")

# --- the converged image: against the super-sampled view and the baseline ---------------------
# Converge Still Renders keeps the picture converged through the screenshot's own renders
view.SNDFConvergeStillRenders = 1
name = "TestSNDFParaView"
if pr.must_fail(args, "plain"):
    view.ScaleConsistentShading = 0
image_ok, converged_image = pr.capture_and_compare(view, name, args, CRITERIA)
check(image_ok, "the converged image against the baseline")
if not args.must_fail:
    converged = rgb(converged_image)
    plain_error = errors(plain, reference)
    sndf_error = errors(converged, reference)
    print("plain vs 16x16 super-sampled: mean %.2f p99 %.1f max %.1f /255" % plain_error)
    print("S-NDF vs 16x16 super-sampled: mean %.2f p99 %.1f max %.1f /255" % sndf_error)
    check(plain_error[0] > 2.0, "the plain image aliases (mean %.2f)" % plain_error[0])
    check(sndf_error[0] < 0.5 and sndf_error[1] < 4.5 and sndf_error[2] < 8.0,
          "S-NDF within mean 0.5, p99 4.5, max 8 /255 of the super-sampled view")

    # --- FXAA (ParaView's default in many settings) is off while S-NDF shading is on ----------
    view.UseFXAA = 1
    with_fxaa = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_fxaa.png")))
    view.UseFXAA = 0
    check(numpy.abs(with_fxaa - converged).max() <= 1.0,
          "Use FXAA on: the same S-NDF picture (max %.1f /255)" % numpy.abs(with_fxaa - converged).max())

    # --- Converge Still Renders: one Render() after a change converges -------------------------
    view.CameraPosition = [40.5, 30.0, 55.0]
    simple.Render(view)
    check(view_info(view, "SNDFNumberOfSamples") == 256,
          "Converge Still Renders: 256 samples in the render of a change (%d)"
          % view_info(view, "SNDFNumberOfSamples"))
    view.CameraPosition = [40.0, 30.0, 55.0]
    again = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_again.png")))
    check(numpy.abs(again - converged).max() <= 1.0,
          "back at the first camera, one render gives the refined picture (max %.1f /255)"
          % numpy.abs(again - converged).max())

    # --- re-lighting without sampling ------------------------------------------------------------
    view.SNDFConvergeStillRenders = 0
    simple.Render(view)
    samples = view_info(view, "SNDFNumberOfSamples")
    view.KeyLightIntensity = 0.4
    view.KeyLightElevation = 10.0
    view.KeyLightAzimuth = -40.0
    relit = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_relit.png")))
    print("re-lit: %d samples kept, mean change %.2f /255"
          % (view_info(view, "SNDFNumberOfSamples"), numpy.abs(relit - converged).mean()))
    check(samples == 256 and view_info(view, "SNDFNumberOfSamples") == 256
          and numpy.abs(relit - converged).mean() > 2.0,
          "a light change re-shades the 256 samples without taking new ones")
    view.KeyLightIntensity = 0.75
    view.KeyLightElevation = 50.0
    view.KeyLightAzimuth = 10.0

    # --- a new colour map re-shades the samples (two types: linear in the old colours) --------
    simple.Render(view)
    samples = view_info(view, "SNDFNumberOfSamples")
    recoloured = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_before_map.png")))
    lut = display.LookupTable
    old_colours = list(lut.IndexedColors)
    lut.IndexedColors = [0.95, 0.80, 0.20, 0.30, 0.70, 0.40]
    simple.Render(view)
    kept = view_info(view, "SNDFNumberOfSamples")
    remapped = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_new_map.png")))
    print("new colour map: %d samples before, %d after, mean change %.2f /255"
          % (samples, kept, numpy.abs(remapped - recoloured).mean()))
    check(samples == 256 and kept == 256 and numpy.abs(remapped - recoloured).mean() > 2.0,
          "new type colours re-shade the 256 samples without taking new ones")
    lut.IndexedColors = old_colours
    back_map = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_old_map.png")))
    check(view_info(view, "SNDFNumberOfSamples") == 256
          and numpy.abs(back_map - recoloured).max() <= 1.0,
          "the old colour map back: the picture before (max %.1f /255), no sample taken"
          % numpy.abs(back_map - recoloured).max())

    # --- colour by speed: another preset re-shades from the bins' moments of the speed ----------
    view.SNDFConvergeStillRenders = 1
    simple.ColorBy(display, ("POINTS", "speed"))
    speed_lut = simple.GetColorTransferFunction("speed")
    pr.apply_preset(speed_lut, "Cool to Warm")
    by_speed = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_speed.png")))
    view.SNDFConvergeStillRenders = 0
    simple.Render(view)
    samples = view_info(view, "SNDFNumberOfSamples")
    pr.apply_preset(speed_lut, "Viridis (matplotlib)")
    simple.Render(view)
    kept = view_info(view, "SNDFNumberOfSamples")
    viridis = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_viridis.png")))
    # sampled under the new preset: a camera change and back restarts, Converge Still Renders
    view.SNDFConvergeStillRenders = 1
    view.CameraPosition = [41.0, 30.0, 55.0]
    simple.Render(view)
    view.CameraPosition = [40.0, 30.0, 55.0]
    fresh = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_viridis_fresh.png")))
    d = numpy.abs(viridis - fresh)
    print("colour by speed, Cool to Warm -> Viridis: %d samples before, %d after, against sampling "
          "under Viridis mean %.3f p99 %.1f max %.1f /255 (the preset moved the picture by %.1f)"
          % (samples, kept, d.mean(), numpy.percentile(d, 99), d.max(),
             numpy.abs(viridis - by_speed).mean()))
    check(samples == 256 and kept == 256 and numpy.abs(viridis - by_speed).mean() > 2.0
          and d.mean() <= 0.1 and numpy.percentile(d, 99) <= 2.0,
          "a new preset for a continuous map re-shades the 256 samples without taking new ones, "
          "near sampling under it (mean %.3f <= 0.1, p99 %.1f <= 2 /255)"
          % (d.mean(), numpy.percentile(d, 99)))
    simple.ColorBy(display, ("POINTS", "type"))

    # --- the view's ambient occlusion is sampled -------------------------------------------------
    view.SNDFConvergeStillRenders = 1
    lit = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_lit.png")))
    view.ParticleAmbientOcclusion = "Density Volume"
    occluded = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_ao.png")))
    darker = (lit - occluded).sum(axis=2)
    print("density-volume AO under S-NDF: mean darkening %.2f /255, largest brightening %.1f"
          % (darker.mean() / 3.0, float(numpy.maximum(0.0, -darker.min()))))
    check(view_info(view, "NumberOfParticlePasses") == 2 and darker.mean() > 3.0
          and darker.min() > -3.0 * 2.0, "AO darkens the S-NDF picture, brightens nothing")
    view.ParticleAmbientOcclusion = "None"

    # --- the S-MIP through ParaView: a pan in parallel projection and back keeps the samples ---
    view.SNDFConvergeStillRenders = 0
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 16.0
    simple.Render(view)
    for _ in range(6):
        simple.Render(view)
    before_pan = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_smip0.png")))
    converged_samples = view_info(view, "SNDFNumberOfSamples")
    pixel = 2.0 * view.CameraParallelScale / H
    forward = numpy.array(view.CameraFocalPoint) - numpy.array(view.CameraPosition)
    up = numpy.array(view.CameraViewUp)
    right = numpy.cross(forward, up)
    right /= numpy.linalg.norm(right)
    move = 20 * pixel * right
    position, focal = numpy.array(view.CameraPosition), numpy.array(view.CameraFocalPoint)
    view.CameraPosition, view.CameraFocalPoint = list(position + move), list(focal + move)
    simple.Render(view)
    panned_samples = view_info(view, "SNDFNumberOfSamples")
    view.CameraPosition, view.CameraFocalPoint = list(position), list(focal)
    back = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestSNDFParaView_smip1.png")))
    print("parallel projection: %d samples, %d after a pan by 20 px, %d back, max change %.1f /255"
          % (converged_samples, panned_samples, view_info(view, "SNDFNumberOfSamples"),
             numpy.abs(back - before_pan).max()))
    check(converged_samples == 256 and panned_samples == 64
          and view_info(view, "SNDFNumberOfSamples") == 256
          and numpy.abs(back - before_pan).max() <= 1.0,
          "a pan in parallel projection samples only the uncovered texels; back: the cached tiles")
    # a zoom by 1.25 samples anew; with S-NDF Zoom Between Levels it keeps the samples
    view.CameraParallelScale = 20.0
    simple.Render(view)
    anew = view_info(view, "SNDFNumberOfSamples")
    view.CameraParallelScale = 16.0
    for _ in range(6):
        simple.Render(view)
    view.SNDFZoomBetweenLevels = 1
    view.CameraParallelScale = 20.0
    simple.Render(view)
    kept = view_info(view, "SNDFNumberOfSamples")
    print("parallel zoom by 1.25: %d samples after it, %d with S-NDF Zoom Between Levels"
          % (anew, kept))
    check(anew == 0 and kept == 64, "a zoom by 1.25 samples anew; with S-NDF Zoom Between "
          "Levels the frame after it shows the kept samples and samples the new texels")
    view.SNDFZoomBetweenLevels = 0
    view.CameraParallelScale = 16.0
    view.CameraParallelProjection = 0

    # --- an error target stops refinement early ------------------------------------------------
    view.SNDFErrorTarget = 2.0
    view.SNDFConvergeStillRenders = 1
    view.CameraPosition = [40.5, 30.0, 55.0]
    simple.Render(view)
    early = view_info(view, "SNDFNumberOfSamples")
    check(0 < early < 256, "S-NDF Error Target 2: refinement stops at %d samples" % early)
    view.SNDFErrorTarget = 0.0
    view.CameraPosition = [40.0, 30.0, 55.0]
    view.SNDFConvergeStillRenders = 0

    # --- translucent particles: plain image, one warning ----------------------------------------
    display.Opacity = 0.5
    with pr.captured_messages() as messages:
        simple.Render(view)
        simple.Render(view)
    text = messages.GetOutput()
    check("translucent" in text and text.count("S-NDF shading is off") == 1
          and view_info(view, "SNDFNumberOfSamples") == 0,
          "translucent particles: one warning, no samples (%s)" % text.strip()[:300])
    display.Opacity = 1.0

pr.finish(ok)
