"""The Particles representation on the dataset types ParaView hands it: every point becomes a
sphere whatever the cells are.
  left:   image data (Wavelet, 5x5x5 points), coloured by the point array RTData;
  middle: an unstructured grid (the points of a sphere surface appended into a
          vtkUnstructuredGrid), solid green;
  right:  a multiblock of two planes (two leaves, flattened into one set of particles),
          solid orange, side by side at two heights.
Baseline-image test.

usage: pvpython TestParticlesInputTypes.py --plugin ParticleRendering.so --data DIR
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
view = pr.setup_view(simple.CreateView("RenderView"))

# image data: 5x5x5 points, spacing 1, centred on (-6, 0, 0)
wavelet = simple.Wavelet(WholeExtent=[-2, 2, -2, 2, -2, 2])
image = simple.Show(wavelet, view)
image.Representation = "Particles"
image.Radius = 0.3
pr.translate(image, (-6.0, 0.0, 0.0))
simple.ColorBy(image, ("POINTS", "RTData"))
pr.apply_preset(simple.GetColorTransferFunction("RTData"), "Cool to Warm")  # (6.1's default: Fast)
image.RescaleTransferFunctionToDataRange(True, False)

# unstructured grid: the points of a sphere
ball = simple.Sphere(Radius=2.5, ThetaResolution=16, PhiResolution=10)
grid = simple.AppendDatasets(Input=[ball])
unstructured = simple.Show(grid, view)
unstructured.Representation = "Particles"
unstructured.Radius = 0.25
unstructured.ColorArrayName = ["POINTS", ""]
unstructured.DiffuseColor = [0.35, 0.8, 0.4]

# multiblock of two planes
lower = simple.Plane(Origin=[3.5, -2.0, -1.0], Point1=[5.5, -2.0, -1.0], Point2=[3.5, 2.0, -1.0],
                     XResolution=2, YResolution=4)
upper = simple.Plane(Origin=[6.5, -2.0, 1.0], Point1=[8.5, -2.0, 1.0], Point2=[6.5, 2.0, 1.0],
                     XResolution=2, YResolution=4)
group = simple.GroupDatasets(Input=[lower, upper])
blocks = simple.Show(group, view)
blocks.Representation = "Particles"
blocks.Radius = 0.3
blocks.ColorArrayName = ["POINTS", ""]
blocks.DiffuseColor = [0.95, 0.55, 0.2]

for display, kind in ((image, "vtkImageData"), (unstructured, "vtkUnstructuredGrid"),
                      (blocks, "vtkMultiBlockDataSet")):
    info = display.Input.GetDataInformation()
    if info.GetDataSetTypeAsString() != kind:
        print("FAIL: expected a %s input, got %s" % (kind, info.GetDataSetTypeAsString()))
        ok = False

pr.set_camera(view, position=(0.5, -24.0, 17.0), focal_point=(0.5, 0.0, 0.0))
ok = pr.capture_and_compare(view, "TestParticlesInputTypes", args, CRITERIA)[0] and ok
pr.finish(ok)
