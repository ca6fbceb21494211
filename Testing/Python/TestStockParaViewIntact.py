"""Loading the plugin must not break stock ParaView. The plugin adds the "Particles" entry to the
representations of datasets and its own properties to them; none of them may replace a stock
property (ParaView then warns "An exposed property with the name ... already exists. It will be
replaced." and the stock representation silently loses it -- which happened to Point Gaussian's
OpacityArray). With the plugin loaded:
- showing data as Point Gaussian (and Surface, Points) logs no warning;
- Point Gaussian's Opacity By Array still changes the picture: the same spheres with
  OpacityByArray on (opacity from the 'speed' array) differ from the picture with it off by a
  mean of more than 10/255 with opacities 0.05-0.3 from the 'speed' array (it changes nothing
  when the plugin has replaced the property), and the picture with it off equals a second render with it off
  (max difference 0).

usage: pvpython TestStockParaViewIntact.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

args = pr.parse_arguments()
report = []
ok = True
with pr.captured_messages() as messages:  # (reported after the block)
    pr.load_plugin(args)
    atoms, _ = pr.open_particles(args, "lj_droplets.vtp")
    view = pr.setup_view(simple.CreateView("RenderView"), size=(400, 300))
    display = simple.Show(atoms, view)
    for representation in ("Surface", "Points", "Point Gaussian"):
        display.SetRepresentationType(representation)
        simple.Render(view)
    display.ShaderPreset = "Sphere"
    display.GaussianRadius = 0.45
    display.ScaleByArray = 0
    pr.set_camera(view, position=(95.0, 20.0, 95.0), focal_point=(40.0, 40.0, 40.0),
                  view_up=(0, 1, 0))
    display.OpacityByArray = 0
    off = pr.capture(view, os.path.join(args.temp_dir, "TestStockParaViewIntact_off.png"))
    off_again = pr.capture(view, os.path.join(args.temp_dir, "TestStockParaViewIntact_off2.png"))
    display.OpacityArray = ["POINTS", "speed"]
    # an opacity of 0.05 (slowest) to 0.3 (fastest): the droplets turn see-through
    speed = atoms.PointData["speed"].GetRange()
    opacity = simple.GetOpacityTransferFunction("speed")
    opacity.Points = [speed[0], 0.05, 0.5, 0.0, speed[1], 0.3, 0.5, 0.0]
    display.OpacityTransferFunction = opacity
    display.OpacityByArray = 1
    on = pr.capture(view, os.path.join(args.temp_dir, "TestStockParaViewIntact_on.png"))

text = messages.GetOutput().strip()
print("\n".join(report))
if text:
    print("FAIL: messages were logged with the plugin loaded:\n" + text)
    ok = False
worst_same, _ = pr.difference(off, off_again)
_, mean_change = pr.difference(off, on)
print("Point Gaussian: Opacity By Array changes the picture by a mean of %.2f/255; "
      "two renders without it differ by at most %s/255" % (mean_change, worst_same))
if worst_same != 0:
    print("FAIL: two renders of the same picture differ")
    ok = False
if not mean_change > 10.0:
    print("FAIL: Point Gaussian's Opacity By Array does not change the picture")
    ok = False
pr.finish(ok)
