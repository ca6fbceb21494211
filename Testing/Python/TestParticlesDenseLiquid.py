"""Translucency that keeps the inside of dense data visible (issue: "on a thick liquid the
opacity settings give an opaque block"). The LAMMPS liquid film (Testing/Data/lj_film.vtp, 19360
atoms, ~17 sigma thick) seen from above through its top surface, Opacity 0.5, every atom white
except the middle third of the film's thickness, which is red. The interior's share of the light
= mean(R - G) / mean(R) over the film's pixels; a film one could see through evenly would give
the interior about its share of the thickness, 1/3.
- Opacity Of "One Particle" (the paper's Theta_i per particle): several layers of 0.5 lie in
  front of the interior, the white surface dominates (measured share 0.20; red shows only in the
  gaps between the top atoms).
- Opacity Of "Column Through The Data" (the default): each particle's opacity is the one whose
  compound over the estimated number of full chords across the film is 0.5: the interior shows
  (measured share 0.30). Required: share >= 0.27 (80 % of 1/3) and at least 0.07 above the other
  mode.
Baseline image of the default mode (viewed); criteria: the GPU's own picture on the same platform
(tolerance 2/255, 0.1 % of the pixels, mean 0.5/255).

usage: pvpython TestParticlesDenseLiquid.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR
"""
import os
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.SAME_PLATFORM  # tolerance 2/255, 0.1 % of the pixels, mean 0.5/255

args = pr.parse_arguments()
pr.load_plugin(args)
ok = True

film, _ = pr.open_particles(args, "lj_film.vtp")
film.UpdatePipeline()
bounds = film.GetDataInformation().GetBounds()
# the film's slab: the z range of the densest part (the liquid), from a histogram of z
positions = vtk_to_numpy(simple.servermanager.Fetch(film).GetPoints().GetData())
heights = positions[:, 2]
lo, hi = numpy.percentile(heights, [5, 95])
third = (hi - lo) / 3.0
interior = simple.Calculator(Input=film, ResultArrayName="interior",
                             Function="(coordsZ > %.6f) * (coordsZ < %.6f)" % (lo + third, hi - third))
view = pr.setup_view(simple.CreateView("RenderView"), size=(400, 400))
view.Background = [0.0, 0.0, 0.0]
display = simple.Show(interior, view)
display.Representation = "Particles"
display.UseRadiusArray = 1
display.RadiusArray = ["POINTS", "radius"]
simple.ColorBy(display, ("POINTS", "interior"))
lut = simple.GetColorTransferFunction("interior")
lut.InterpretValuesAsCategories = 1
lut.Annotations = ["0", "surface", "1", "interior"]
lut.IndexedColors = [1.0, 1.0, 1.0, 1.0, 0.0, 0.0]
display.Opacity = 0.5
centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (lo + hi) / 2]
pr.set_camera(view, position=(centre[0] + 2.0, centre[1] + 3.0, hi + 60.0),
              focal_point=centre, view_up=(0, 1, 0), view_angle=30.0)


def interior_share(image):
    rgb = vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)[:, :3]
    film_pixels = rgb.max(axis=1) > 20  # not the black background
    red, green = rgb[film_pixels, 0], rgb[film_pixels, 1]
    return float((red - green).mean() / red.mean())


if display.OpacityReference != "Column Through The Data":
    print("FAIL: the default Opacity Of is %r" % display.OpacityReference)
    ok = False
column = pr.capture(view, os.path.join(args.temp_dir, "TestParticlesDenseLiquid_column.png"))
display.OpacityReference = "One Particle"
particle = pr.capture(view, os.path.join(args.temp_dir, "TestParticlesDenseLiquid_particle.png"))
display.OpacityReference = "Column Through The Data"
share_column = interior_share(column)
share_particle = interior_share(particle)
print("the interior's share of the light: column %.3f, one particle %.3f (see-through: 1/3)"
      % (share_column, share_particle))
if not (share_column >= 0.27 and share_column >= share_particle + 0.07):
    print("FAIL: the interior of the dense film does not show with Opacity Of = Column")
    ok = False
ok = pr.capture_and_compare(view, "TestParticlesDenseLiquid", args, CRITERIA)[0] and ok
pr.finish(ok)
