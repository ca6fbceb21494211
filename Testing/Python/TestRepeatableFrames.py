"""Every technique of the plugin gives the same picture each time the same frame is drawn, in
ParaView with its default settings (FXAA on), on a scene of 10^5 particles: a dense FCC slab
between two layers of gas (prVTKTesting.gas_and_slab, written to a .vtp and opened as a user
would). For each technique the view is rendered and saved three times (pr.capture, then once
more) at 1024 x 768: all three pictures must be identical, bit for bit
(vtkParticleImageComparison.TestIdentical). The techniques: opaque spheres; translucent spheres
(Opacity 0.5); the particle ambient occlusion choices Density Volume, Voxel Cone Tracing,
PointAO and PointAO at half resolution; metaballs (Vicinity); S-NDF scale-consistent shading
with Converge Still Renders (the picture converged to 32 samples per pixel). Each picture must also differ from the
opaque one (a technique that silently did nothing would pass the repeat check).

This is the test of the issue "PointAO gives a different picture each time": before the fix,
PointAO differed by up to 146/255 here (tile-shaped blocks); the other techniques did not.

usage: pvpython TestRepeatableFrames.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "VTKPython"))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402
from prVTKTesting import gas_and_slab, particles_from  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402

args = pr.parse_arguments()
pr.load_plugin(args)

path = os.path.join(args.temp_dir, "TestRepeatableFrames_gas_and_slab.vtp")
xyz, radius, kinds = gas_and_slab()
writer = vtkXMLPolyDataWriter()
writer.SetInputData(particles_from(xyz, radius=radius, type=kinds))
writer.SetFileName(path)
writer.Write()

view = simple.CreateView("ParticleRenderView")
view.ViewSize = [1024, 768]
view.OrientationAxesVisibility = 0
simple.GetSettingsProxy("RenderViewSettings").UseFXAA = 1
view.UseFXAA = 1  # ParaView's default: the renderer's FXAA runs inside the pass's delegate
source = simple.XMLPolyDataReader(FileName=[path])
display = pr.show_particles(source, view)
pr.set_camera(view, position=(95.0, -40.0, 70.0), focal_point=(32.0, 32.0, 8.0))


def rgb(image):
    return vtk_to_numpy(image.GetPointData().GetScalars()).astype(int)[:, :3]


def frames(name):
    """Three renders of the unchanged view: capture's two (identical, or a repeat failure that
    finish() reports) and a third compared with the first."""
    base = os.path.join(args.temp_dir, "TestRepeatableFrames_%s" % name)
    first = pr.capture(view, base + ".png")
    third = pr.capture(view, base + "_3.png", repeat=False)
    same = pr.particlerendering.vtkParticleImageComparison.TestIdentical(
        first, third, name + " (third render)")
    return rgb(first), same


ok = True
opaque, same = frames("opaque")
ok &= same
cases = [
    ("translucent", lambda: setattr(display, "Opacity", 0.5), lambda: setattr(display, "Opacity", 1.0)),
    ("density_volume", lambda: setattr(view, "ParticleAmbientOcclusion", "Density Volume"), None),
    ("voxel_cones", lambda: setattr(view, "ParticleAmbientOcclusion", "Voxel Cone Tracing"), None),
    ("pointao", lambda: setattr(view, "ParticleAmbientOcclusion", "PointAO"), None),
    ("pointao_half", lambda: setattr(view, "PointAOHalfResolution", 1),
     lambda: (setattr(view, "PointAOHalfResolution", 0),
              setattr(view, "ParticleAmbientOcclusion", "None"))),
    ("metaballs", lambda: setattr(display, "Technique", "Metaballs"),
     lambda: setattr(display, "Technique", "Spheres")),
    ("sndf", lambda: (setattr(view, "ScaleConsistentShading", 1),
                      setattr(view, "SNDFTargetSamples", 32),
                      setattr(view, "SNDFConvergeStillRenders", 1)),
     lambda: setattr(view, "ScaleConsistentShading", 0)),
]
for name, on, off in cases:
    on()
    picture, same = frames(name)
    changed = int((np.abs(picture - opaque).max(axis=1) > 4).sum())
    print("%s: %s; %d pixels differ from the opaque spheres by more than 4/255"
          % (name, "three identical renders" if same else "RENDERS DIFFER", changed))
    if changed < 2000:
        print("FAIL: %s does not change the picture" % name)
        ok = False
    ok &= same
    if off:
        off()
pr.finish(ok)
