"""Shared helpers of the pvpython / pvbatch tests of ParticleRendering.

Every test script takes
    --plugin PATH        ParticleRendering.so
    --data DIR           Testing/Data
    --baseline-dir DIR   Testing/Data/Baseline
    --temp-dir DIR       where the rendered images go (<Test>.png, and on failure the
                         difference images of vtkTesting)
The rendered image of a test is always written to the temp dir, so a new baseline is made by
running the test once, looking at <temp-dir>/<Test>.png and copying it to the baseline dir.
A missing baseline fails the test.
"""
import argparse
import os
import sys

from paraview import simple
from vtkmodules.vtkCommonExecutionModel import vtkTrivialProducer
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkTestingRendering import vtkTesting

# vtkImageDifference's thresholded error (VTK 9.2), as the C++ tests of this project use.
IMAGE_THRESHOLD = 0.15

def parse_arguments():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--baseline-dir", required=True)
    parser.add_argument("--temp-dir", required=True)
    args, _ = parser.parse_known_args()
    os.makedirs(args.temp_dir, exist_ok=True)
    return args


def load_plugin(args):
    # builtin session (pvpython, pvbatch): client and server are this process
    simple.LoadPlugin(args.plugin, remote=False)


def open_particles(args, name):
    """A reader for Testing/Data/<name>, or a synthetic FCC block with the same point arrays
    (type, id, velocity, speed, radius) when the file does not exist. Returns (source, is_file).
    Tests name the image of the synthetic set <Test>_synthetic; no baselines are shipped for
    it (the LAMMPS files are in the repository), so a missing data file still fails the test,
    after rendering something to look at."""
    path = os.path.join(args.data, name)
    if os.path.exists(path):
        return simple.XMLPolyDataReader(FileName=[path]), True
    print("NOTE: %s missing, using a synthetic FCC block" % path)
    source = simple.ProgrammableSource()
    source.OutputDataSetType = "vtkPolyData"
    source.Script = SYNTHETIC_FCC_SCRIPT
    return source, False


SYNTHETIC_FCC_SCRIPT = """
# (ParaView runs this with numpy_interface.algorithms imported: no builtin sum/min/max here)
import math
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkIntArray, vtkPoints
out = self.GetPolyDataOutput()
n, a = 12, 1.5874
basis = ((0, 0, 0), (0.5, 0.5, 0), (0.5, 0, 0.5), (0, 0.5, 0.5))
points = vtkPoints()
types = vtkIntArray(); types.SetName("type")
ids = vtkIntArray(); ids.SetName("id")
radius = vtkFloatArray(); radius.SetName("radius")
speed = vtkFloatArray(); speed.SetName("speed")
velocity = vtkFloatArray(); velocity.SetName("velocity"); velocity.SetNumberOfComponents(3)
c = 0.5 * n * a
for i in range(n):
    for j in range(n):
        for k in range(n):
            for b in basis:
                x, y, z = (i + b[0]) * a, (j + b[1]) * a, (k + b[2]) * a
                t = 2 if (x - c) ** 2 + (y - c) ** 2 < (0.25 * n * a) ** 2 else 1
                points.InsertNextPoint(x, y, z)
                types.InsertNextValue(t)
                ids.InsertNextValue(points.GetNumberOfPoints())
                radius.InsertNextValue(0.5 if t == 1 else 0.4)
                v = (math.sin(x), math.cos(y), math.sin(z))
                velocity.InsertNextTuple3(*v)
                speed.InsertNextValue(math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]))
out.SetPoints(points)
for array in (types, ids, velocity, speed, radius):
    out.GetPointData().AddArray(array)
"""


def setup_view(view, size=(600, 400)):
    """Deterministic view settings: size, plain background, no annotations, no FXAA."""
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.32, 0.34, 0.43]
    # UseFXAA is linked to the RenderViewSettings: creating another view pushes the setting to
    # every view again, so switch it off in the settings too.
    simple.GetSettingsProxy("RenderViewSettings").UseFXAA = 0
    view.UseFXAA = 0
    return view


def type_lookup_table():
    """Categorical colours for the LAMMPS atom types 1 and 2."""
    lut = simple.GetColorTransferFunction("type")
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = ["1", "type 1", "2", "type 2"]
    lut.IndexedColors = [0.85, 0.35, 0.20, 0.20, 0.55, 0.90]
    return lut


def show_particles(source, view, color_by_type=True, use_radius_array=True):
    display = simple.Show(source, view)
    display.Representation = "Particles"
    if use_radius_array:
        display.UseRadiusArray = 1
        display.RadiusArray = ["POINTS", "radius"]
    if color_by_type:
        simple.ColorBy(display, ("POINTS", "type"))
        display.LookupTable = type_lookup_table()
    display.Specular = 0.4
    display.SpecularPower = 30.0
    return display


def set_camera(view, position, focal_point, view_up=(0, 0, 1), view_angle=30.0):
    """Set the camera. Renders once first: paraview.simple resets the camera at the first
    Render() of the process, which would otherwise override this camera."""
    simple.Render(view)
    view.CameraPosition = list(position)
    view.CameraFocalPoint = list(focal_point)
    view.CameraViewUp = list(view_up)
    view.CameraViewAngle = view_angle
    view.CameraParallelProjection = 0


def capture(view, path):
    """Render the view, save it to `path` (PNG, the view's size) and return the image read back
    (vtkImageData)."""
    simple.Render(view)
    simple.SaveScreenshot(path, view, ImageResolution=list(view.ViewSize), TransparentBackground=0)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def capture_and_compare(view, name, args):
    """Save the view to <temp>/<name>.png and compare it with <baseline-dir>/<name>.png.
    Returns (ok, image); a missing baseline is a failure."""
    test_png = os.path.join(args.temp_dir, name + ".png")
    image = capture(view, test_png)
    baseline = os.path.join(args.baseline_dir, name + ".png")
    if not os.path.exists(baseline):
        print("FAIL: baseline %s does not exist (the test image is %s)" % (baseline, test_png))
        return False, image
    testing = vtkTesting()
    for arg in ("-V", baseline, "-T", args.temp_dir):
        testing.AddArgument(arg)
    producer = vtkTrivialProducer()
    producer.SetOutput(image)
    result = testing.RegressionTest(producer, IMAGE_THRESHOLD)
    if result != vtkTesting.PASSED:
        print("FAIL: %s differs from the baseline %s (see %s)" % (test_png, baseline, args.temp_dir))
        return False, image
    print("image %s matches %s" % (test_png, baseline))
    return True, image


def max_abs_difference(image_a, image_b):
    """Largest per-channel difference (0..255) of two images of the same size, or None when
    the sizes or channel counts differ."""
    if image_a.GetDimensions() != image_b.GetDimensions():
        return None
    a = image_a.GetPointData().GetScalars()
    b = image_b.GetPointData().GetScalars()
    if a.GetNumberOfComponents() != b.GetNumberOfComponents():
        return None
    try:
        from vtkmodules.util.numpy_support import vtk_to_numpy
        import numpy

        return int(numpy.max(numpy.abs(vtk_to_numpy(a).astype(int) - vtk_to_numpy(b).astype(int))))
    except ImportError:
        worst = 0
        for i in range(a.GetNumberOfTuples()):
            for k in range(a.GetNumberOfComponents()):
                worst = max(worst, abs(a.GetComponent(i, k) - b.GetComponent(i, k)))
        return int(worst)


class TestFailure(RuntimeError):
    pass


def finish(ok):
    """End the test. Success: return, and let the script end normally. Failure: raise, which
    makes pvpython/pvbatch exit with a non-zero status. (sys.exit() must not be used: with
    Debian's ParaView 5.11 it skips ParaView's finalization and the process then crashes or
    fails with an X error while tearing down OpenGL, so even sys.exit(0) gives a non-zero
    status.)"""
    sys.stdout.flush()
    if not ok:
        raise TestFailure("FAILED (see the messages above)")
    print("PASSED")
    sys.stdout.flush()
