"""Shared helpers of the pvpython / pvbatch tests of ParticleRendering.

Every test script takes
    --plugin PATH        ParticleRendering.so
    --data DIR           Testing/Data
    --baseline-dir DIR   Testing/Data/Baseline
    --temp-dir DIR       where the rendered images go (<Test>.png and <Test>.diff.png)
    --must-fail CASE     draw the named wrong picture instead of the right one: the test then
                         passes only when its baseline comparison rejects it (see must_fail())
The rendered image of a test is always written to the temp dir, so a new baseline is made by
running the test once, looking at <temp-dir>/<Test>.png and copying it to the baseline dir.
A missing baseline fails the test.

Images are compared by ParticleRendering's own vtkParticleImageComparison (the class every C++
and VTK Python image test uses too), imported from the Python-wrapped module `particlerendering`
(PYTHONPATH=<build>/lib/python3/dist-packages, set by CTest), under criteria each test states
(Criteria below).
"""
import argparse
import contextlib
import os
import sys

from paraview import simple
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader

import particlerendering  # ParticleRendering's Python-wrapped VTK module (the comparison)


class Criteria:
    """Criteria of an image test, in 8-bit steps (x/255): per-pixel tolerance, largest share of
    compared pixels over it, largest mean and largest single error of a channel, and the radius
    of the band around the baseline's colour edges that is not compared. Each test states its
    own (see vtkParticleImageComparison)."""

    def __init__(self, tolerance=2.0, max_share=1e-3, max_mean=0.5, max_error=255.0,
                 mask_radius=0):
        self.tolerance = tolerance
        self.max_share = max_share
        self.max_mean = max_mean
        self.max_error = max_error
        self.mask_radius = mask_radius

    def comparison(self):
        c = particlerendering.vtkParticleImageComparison()
        c.SetTolerance(self.tolerance / 255.0)
        c.SetMaximumOverToleranceFraction(self.max_share)
        c.SetMaximumMeanError(self.max_mean / 255.0)
        c.SetMaximumError(self.max_error / 255.0)
        c.SetMaskRadius(self.mask_radius)
        return c

# The criteria of the tests whose baseline is the GPU's own picture on the same platform (Mesa
# llvmpipe): it matches to rounding, so at most 0.1 % of the pixels may differ by more than 2/255
# and the mean by 0.5/255 -- a missing, extra, moved or recoloured sphere, or shading a tenth
# darker, is rejected.
SAME_PLATFORM = Criteria(tolerance=2.0, max_share=1e-3, max_mean=0.5)


@contextlib.contextmanager
def captured_messages():
    """Every VTK message (errors, warnings, text) while the block runs, in a vtkStringOutputWindow
    (its GetOutput()); they are not printed. pvpython routes Python's own output through VTK's
    output window too: print what the test reports after the block."""
    messages = vtkStringOutputWindow()
    previous_window = vtkOutputWindow.GetInstance()
    vtkOutputWindow.SetInstance(messages)
    try:
        yield messages
    finally:
        vtkOutputWindow.SetInstance(previous_window)


def parse_arguments():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--baseline-dir", required=True)
    parser.add_argument("--temp-dir", required=True)
    parser.add_argument("--must-fail", default="")
    args, _ = parser.parse_known_args()
    args.matched_must_fail = ""
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
    if use_radius_array is None:
        pass  # the default: Automatic (the "radius" array when there is one)
    elif use_radius_array:
        display.UseRadiusArray = 1
        display.RadiusArray = ["POINTS", "radius"]
    else:
        display.UseRadiusArray = 0  # the constant Radius
    if color_by_type:
        simple.ColorBy(display, ("POINTS", "type"))
        display.LookupTable = type_lookup_table()
    display.Specular = 0.4
    display.SpecularPower = 30.0
    return display


def translate(representation, offset):
    """Moves a representation by offset: the property is "Position" in ParaView 5.11's Python and
    "Translation" from 5.12 on (the same XML property, Position, renamed for Python)."""
    name = "Translation" if "Translation" in representation.ListProperties() else "Position"
    setattr(representation, name, list(offset))


# Colour-map presets renamed between ParaView versions: the name a test asks for -> the names
# ParaView 6 knows it by.
PRESET_NAMES = {"Viridis (matplotlib)": ("Viridis (matplotlib)", "Viridis")}


def apply_preset(lut, name):
    """Applies a colour-map preset by its ParaView 5.11 name, under whichever name this ParaView
    has it ("Viridis (matplotlib)" is "Viridis" in ParaView 6). Also for a test whose picture
    relies on the default map: ParaView 6's default is "Fast", 5.11's and 5.13's "Cool to Warm"."""
    for candidate in PRESET_NAMES.get(name, (name,)):
        try:
            lut.ApplyPreset(candidate, True)
            return
        except RuntimeError:
            continue
    raise TestFailure("no colour-map preset named %s in this ParaView" % name)


def set_camera(view, position, focal_point, view_up=(0, 0, 1), view_angle=30.0):
    """Set the camera. Renders once first: paraview.simple resets the camera at the first
    Render() of the process, which would otherwise override this camera."""
    simple.Render(view)
    view.CameraPosition = list(position)
    view.CameraFocalPoint = list(focal_point)
    view.CameraViewUp = list(view_up)
    view.CameraViewAngle = view_angle
    view.CameraParallelProjection = 0


# the captures whose frame, drawn once more, differed (see capture); finish() fails on any
REPEAT_FAILURES = []


def particle_mapper(view, visible=True):
    """The view's (first visible, with visible) particle mapper on this process: a
    vtkParticleSphereMapper or a subclass, with its Python methods."""
    actors = view.GetClientSideObject().GetRenderer().GetActors()
    actors.InitTraversal()
    for _ in range(actors.GetNumberOfItems()):
        actor = actors.GetNextActor()
        mapper = actor.GetMapper()
        if (actor.GetVisibility() or not visible) and mapper is not None and \
                mapper.IsA("vtkParticleSphereMapper"):
            return mapper
    raise RuntimeError("no particle mapper in the view")


def capture(view, path, repeat=True, size=None):
    """Render the view, save it to `path` (PNG, the view's size) and return the image read back
    (vtkImageData). With repeat (the default: every image test of the suite) the view is saved
    once more and the two pictures must be identical, bit for bit
    (vtkParticleImageComparison.TestIdentical), with no OpenGL error reported by the context's
    debug output while the second is drawn (vtkParticleGLDebugLog); finish() fails otherwise.
    repeat=False only for a progressive view whose next frame refines the picture (S-NDF while
    it converges). size: the saved image's size (default the view's; larger ones ParaView draws
    in tiles)."""
    size = list(size or view.ViewSize)
    simple.Render(view)
    simple.SaveScreenshot(path, view, ImageResolution=size, TransparentBackground=0)
    image = read_png(path)
    if repeat:
        again = os.path.splitext(path)[0] + "_repeat.png"
        name = os.path.splitext(os.path.basename(path))[0]
        # the second frame under the context's debug output (as TestRepeatable)
        log = particlerendering.vtkParticleGLDebugLog.GetInstance()
        log.StartFrame(view.GetRenderWindow())
        simple.SaveScreenshot(again, view, ImageResolution=size, TransparentBackground=0)
        if not log.EndFrame(name):
            REPEAT_FAILURES.append(name)
        if not particlerendering.vtkParticleImageComparison.TestIdentical(
                image, read_png(again), name):
            REPEAT_FAILURES.append(name)
        else:
            os.remove(again)
    return image


def must_fail(args, case):
    """True when the test was started with --must-fail CASE: it then draws that wrong picture
    instead of the right one, and capture_and_compare passes only when the picture is rejected."""
    if args.must_fail == case:
        args.matched_must_fail = case
        return True
    return False


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = vtkImageData()
    image.ShallowCopy(reader.GetOutput())
    return image


def capture_and_compare(view, name, args, criteria):
    """Save the view to <temp>/<name>.png and compare it with <baseline-dir>/<name>.png under
    the criteria (vtkParticleImageComparison.TestImage: report, difference image, built-in
    must-fail checks). Returns (ok, image); a missing baseline is a failure. In must-fail mode
    ok means that the (wrong) picture was rejected."""
    baseline = os.path.join(args.baseline_dir, name + ".png")
    comparison = criteria.comparison()
    if args.must_fail:
        image = capture(view, os.path.join(args.temp_dir, "%s_mustfail_%s.png"
                                           % (name, args.must_fail)))
        if args.matched_must_fail != args.must_fail:
            print("FAIL: unknown must-fail case %s" % args.must_fail)
            return False, image
        if not os.path.exists(baseline):
            print("FAIL: baseline %s does not exist" % baseline)
            return False, image
        return comparison.TestRejects(image, read_png(baseline), None,
                                      "%s_mustfail_%s" % (name, args.must_fail)), image
    image = capture(view, os.path.join(args.temp_dir, name + "_capture.png"))
    return comparison.TestImage(image, baseline, args.temp_dir, name), image


def difference(image_a, image_b):
    """(max, mean) per-channel difference in 8-bit steps of two images of the same size, RGB
    only, through vtkParticleImageComparison; (None, None) when they cannot be compared."""
    comparison = particlerendering.vtkParticleImageComparison()
    if not comparison.CompareImages(image_a, image_b) or comparison.GetNumberOfComparedPixels() == 0:
        return None, None
    return (comparison.GetMaxAbsError() * 255.0,
            max(comparison.GetChannelMeanAbsError()[:3]) * 255.0)


def max_abs_difference(image_a, image_b):
    """Largest per-channel difference (0..255, RGB) of two images of the same size, or None when
    they cannot be compared."""
    worst = difference(image_a, image_b)[0]
    return None if worst is None else int(round(worst))


class TestFailure(RuntimeError):
    pass


def finish(ok):
    """End the test. Success: return, and let the script end normally. Failure: raise, which
    makes pvpython/pvbatch exit with a non-zero status. (sys.exit() must not be used: with
    Debian's ParaView 5.11 it skips ParaView's finalization and the process then crashes or
    fails with an X error while tearing down OpenGL, so even sys.exit(0) gives a non-zero
    status.)"""
    sys.stdout.flush()
    if REPEAT_FAILURES:
        print("FAIL: the same frame drawn twice differs: %s" % ", ".join(REPEAT_FAILURES))
        ok = False
    if not ok:
        raise TestFailure("FAILED (see the messages above)")
    print("PASSED")
    sys.stdout.flush()
