"""The speed/accuracy trade in ParaView (vtkParticleFrameBudget through the Particles
representation and the Particle Render View):

- a still render (SaveScreenshot, Render) draws every technique exact, and says so
  (QualityText, AmbientOcclusionQualityText);
- an interactive render (what the GUI issues while the mouse moves) gets ParaView's 200 ms, or
  the view's Interactive Frame Budget: with 0.001 ms nothing fits and the translucent particles
  are drawn as sorted spheres at half resolution, PointAO at half resolution;
- the still render after interactive ones is the first still render, bit for bit;
- Interactive Quality 'Interactive' draws the cheap level in a still render, 'Exact' the exact
  level in an interactive one, on the representation and on the view.

usage: pvpython TestInteractiveQualityParaView.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import particlerendering  # noqa: E402
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

args = pr.parse_arguments()
pr.load_plugin(args)
ok = True


def check(condition, what):
    global ok
    if not condition:
        print("FAIL: " + what)
        ok = False
    return condition


def text(proxy, name):
    proxy.SMProxy.UpdatePropertyInformation()
    return proxy.GetPropertyValue(name)


def interactive_render(view):
    view.SMProxy.InteractiveRender()


atoms, _ = pr.open_particles(args, "lj_droplets.vtp")
view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=(480, 360))
display = pr.show_particles(atoms, view)
display.Opacity = 0.6
simple.ResetCamera(view)
shot = os.path.join(args.temp_dir, "TestInteractiveQualityParaView_%s.png")

first = pr.capture(view, shot % "still")
said = text(display, "QualityText")
print("still: " + said)
check(said.startswith("exact") and "(still frame)" in said, "a still render is exact")

interactive_render(view)
said = text(display, "QualityText")
print("interactive, ParaView's rate: " + said)
check("(interactive frame of 200 ms)" in said, "ParaView's interactive renders have 200 ms")

view.InteractiveFrameBudget = 0.001
interactive_render(view)
said = text(display, "QualityText")
print("interactive, 0.001 ms: " + said)
check(said.startswith("half resolution, sorted spheres") and
      "(interactive frame of 0.001 ms)" in said,
      "nothing fits 0.001 ms: the sorted spheres at half resolution")
interactive_render(view)

again = pr.capture(view, shot % "still_again")
check(particlerendering.vtkParticleImageComparison.TestIdentical(first, again, "still again"),
      "the still render after interactive ones is the first one, bit for bit")
check(text(display, "QualityText").startswith("exact"), "... and exact")

display.InteractiveQuality = "Interactive"
simple.Render(view)
said = text(display, "QualityText")
check(said.startswith("half resolution, sorted spheres") and
      "(interactive quality asked for)" in said,
      "Interactive Quality 'Interactive': the cheap level in a still render (%s)" % said)
display.InteractiveQuality = "Exact"
interactive_render(view)
said = text(display, "QualityText")
check(said.startswith("exact") and "(exact quality asked for)" in said,
      "Interactive Quality 'Exact': exact in a 0.001 ms interactive render (%s)" % said)
display.InteractiveQuality = "Adaptive"

display.Opacity = 1.0
view.ParticleAmbientOcclusion = "PointAO"
simple.Render(view)
said = text(view, "AmbientOcclusionQualityText")
print("PointAO, still: " + said)
check(said.startswith("full resolution (still frame)"), "PointAO still: full resolution")
interactive_render(view)
said = text(view, "AmbientOcclusionQualityText")
print("PointAO, interactive: " + said)
check(said.startswith("half resolution (interactive frame of 0.001 ms)"),
      "PointAO in a 0.001 ms interactive render: half resolution")
view.InteractiveQuality = "Exact"
interactive_render(view)
check(text(view, "AmbientOcclusionQualityText").startswith("full resolution (exact quality"),
      "the view's Interactive Quality 'Exact': PointAO at full resolution")
view.InteractiveQuality = "Interactive"
simple.Render(view)
check(text(view, "AmbientOcclusionQualityText").startswith("half resolution (interactive qual"),
      "the view's Interactive Quality 'Interactive': PointAO at half resolution")

pr.finish(ok)
