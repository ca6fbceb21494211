"""A ParaView state file keeps everything of the plugin: a Particle Render View with voxel-cone
AO and translucent Particles (non-default radius array and scale, opacity, density model, hollow
fraction, AO strength and cone count) is saved with SaveState, the session is reset, the plugin
loaded again and the state loaded:
- every property of the representation and every property of the view that the plugin adds has
  the value it had (compared one by one, proxies by their XML name);
- the picture of the loaded state is identical to the picture before saving (max difference 0),
  and the picture before saving passes the baseline comparison (with its built-in must-fail
  pictures);
- must fail: a state that lost the AO setting (the loaded view with AO off) differs from the
  saved picture by a mean of more than 2/255, so the identity check can see a lost setting.
The same file is written and read on ParaView 5.11, 5.13 and 6.1.

usage: pvpython TestParticlesStateFile.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import servermanager, simple  # noqa: E402

CRITERIA = pr.SAME_PLATFORM
# Stock Point Gaussian properties of the same composite representation: with no opacity or scale
# array chosen, ParaView saves the array component as '' and loads it as 0 (ParaView's own
# behaviour, the same meaning), in 5.11 as in 6.1.
STOCK_EXCEPTIONS = ("OpacityArrayComponent", "ScaleArrayComponent")
VIEW_PROPERTY_PREFIXES = ("Particle", "PointAO", "SNDF", "DensityVolume", "VoxelCone", "Metaball",
                          "ScaleConsistent", "AmbientOcclusion")


def values(proxy, names):
    """name -> comparable value: proxies by XML name, everything else by its Python value."""
    out = {}
    for name in names:
        try:
            value = proxy.GetPropertyValue(name)
        except Exception:  # (information-only or write-only properties)
            continue
        if isinstance(value, servermanager.Proxy):
            value = value.GetXMLName()
        elif hasattr(value, "__iter__") and not isinstance(value, str):
            value = [v.GetXMLName() if isinstance(v, servermanager.Proxy) else v for v in value]
        out[name] = repr(value)
    return out


def plugin_view_properties(view):
    return [name for name in view.ListProperties() if name.startswith(VIEW_PROPERTY_PREFIXES)]


def build_scene(args):
    atoms, _ = pr.open_particles(args, "lj_droplets.vtp")
    view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=(400, 300))
    display = pr.show_particles(atoms, view)
    display.RadiusScaleFactor = 0.9
    display.Opacity = 0.6
    display.DensityModel = "Squared Distance"
    display.HollowFraction = 0.3
    view.ParticleAmbientOcclusion = "Voxel Cone Tracing"
    view.VoxelConeCount = 6
    view.AmbientOcclusionStrength = 1.3
    pr.set_camera(view, position=(95.0, 20.0, 95.0), focal_point=(40.0, 40.0, 40.0),
                  view_up=(0, 1, 0))
    return view, display


args = pr.parse_arguments()
pr.load_plugin(args)
ok = True
view, display = build_scene(args)
before = pr.capture(view, os.path.join(args.temp_dir, "TestParticlesStateFile_saved.png"))
saved_display = values(display, [n for n in display.ListProperties() if n not in STOCK_EXCEPTIONS])
saved_view = values(view, plugin_view_properties(view))
state = os.path.join(args.temp_dir, "TestParticlesStateFile.pvsm")
simple.SaveState(state)
print("saved %d representation and %d view properties to %s" % (
    len(saved_display), len(saved_view), state))

simple.ResetSession()
pr.load_plugin(args)
simple.LoadState(state)
views = [v for v in simple.GetViews() if v.GetXMLName() == "ParticleRenderView"]
if len(views) != 1:
    print("FAIL: the loaded state has %d Particle Render Views, not 1" % len(views))
    pr.finish(False)
view = views[0]
simple.SetActiveView(view)
pr.setup_view(view, size=(400, 300))
sources = list(simple.GetSources().values())
display = simple.GetDisplayProperties(sources[0], view)
loaded_display = values(display, display.ListProperties())
loaded_view = values(view, plugin_view_properties(view))
for what, saved, loaded in (("representation", saved_display, loaded_display),
                            ("view", saved_view, loaded_view)):
    changed = ["%s: saved %s, loaded %s" % (name, saved[name], loaded.get(name, "(missing)"))
               for name in sorted(saved) if loaded.get(name) != saved[name]]
    print("%s: %d properties compared, %d differ" % (what, len(saved), len(changed)))
    if changed:
        print("FAIL: the state file changed %s properties:\n  %s" % (what, "\n  ".join(changed)))
        ok = False
if display.Representation != "Particles" or view.ParticleAmbientOcclusion != "Voxel Cone Tracing":
    print("FAIL: loaded as %s with AO %s" % (display.Representation, view.ParticleAmbientOcclusion))
    ok = False

after = pr.capture(view, os.path.join(args.temp_dir, "TestParticlesStateFile_loaded.png"))
worst, mean = pr.difference(before, after)
print("loaded state vs saved: max %s/255, mean %.3f/255" % (worst, mean))
if worst != 0:
    print("FAIL: the picture of the loaded state differs from the saved one")
    ok = False

view.ParticleAmbientOcclusion = "None"
lost = pr.capture(view, os.path.join(args.temp_dir, "TestParticlesStateFile_mustfail_ao-lost.png"),
                  repeat=False)
_, lost_mean = pr.difference(before, lost)
print("MUST-FAIL TestParticlesStateFile (AO setting lost): mean difference %.2f/255 (> 2 to be seen)"
      % lost_mean)
if not lost_mean > 2.0:
    print("FAIL: a state without its AO setting would look the same")
    ok = False
view.ParticleAmbientOcclusion = "Voxel Cone Tracing"

compared, _ = pr.capture_and_compare(view, "TestParticlesStateFile", args, CRITERIA)
pr.finish(ok and compared)
