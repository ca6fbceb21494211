"""LAMMPS ellipsoids in ParaView, as a user opens them: OpenDataFile on the bundled Gay-Berne dump
(Testing/Data/gb_ellipsoids.lammpstrj.gz, atom_style ellipsoid, shapex ... quatk columns), Show.

- OpenDataFile picks the LAMMPS Dump Reader; Show gives the Particles representation with
  Shape Automatic, which draws oriented ellipsoids from the reader's "semi_axes" and
  "orientation" (the view's particle mapper GetDrawsEllipsoids), no warning logged;
- the opaque picture against its baseline (must-fail "spheres": Shape Sphere, the same data as
  spheres of the Radius);
- translucent (Opacity 0.9 of a column through the data, squared-distance density) against its
  baseline; still ellipsoids;
- the 2021 LAMMPS layout: the same step written with the columns c_shape[1..7] (what Debian 12's
  lmp writes through compute property/atom), Shape Ellipsoid with Axes Array c_shape, component
  0, Axes Are Diameters, Orientation Array c_shape, component 3: the same picture, bit for bit;
- tensors as the Tensor Glyph filter takes them (R diag(a) R^T): Shape Ellipsoid (Tensor) draws
  the picture of Shape Ellipsoid with the axes and quaternions, within 1/255.

usage: pvpython TestEllipsoidsParaView.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR [--must-fail spheres]
"""
import gzip
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.SAME_PLATFORM  # tolerance 2/255, 0.1 % of the pixels, mean 0.5/255

args = pr.parse_arguments()
ok = True
report = []
NAMES = "shapex shapey shapez quatw quati quatj quatk"
C_SHAPE = " ".join("c_shape[%d]" % k for k in range(1, 8))


def fail(text):
    global ok
    report.append("FAIL: " + text)
    ok = False


def draws_ellipsoids(view):
    return pr.particle_mapper(view).GetDrawsEllipsoids()


def last_step_as_2021_dump(path, out):
    """The last snapshot of a dump, its ellipsoid columns named as Debian 12's LAMMPS names them."""
    with gzip.open(path, "rt") as f:
        lines = f.read().splitlines()
    starts = [i for i, line in enumerate(lines) if line == "ITEM: TIMESTEP"]
    last = lines[starts[-1]:]
    with open(out, "w") as f:
        for line in last:
            f.write((line.replace(NAMES, C_SHAPE) if line.startswith("ITEM: ATOMS") else line)
                    + "\n")


def write_tensor_particles(path):
    """40 random ellipsoids as a .vtp: axes, quaternions and the tensors R diag(a) R^T."""
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    sys.path.append(os.path.join(os.path.dirname(HERE), "VTKPython"))
    from prVTKTesting import quaternion_rotations, random_quaternions
    rng = np.random.default_rng(8)
    n = 40
    q = random_quaternions(n, rng)
    a = rng.uniform(0.2, 1.0, size=(n, 3))
    r = quaternion_rotations(q)
    data = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(rng.uniform(-3.0, 3.0, size=(n, 3)), deep=True))
    data.SetPoints(points)
    for name, values in (("axes", a), ("quat", q),
                         ("tensor", np.einsum("nij,nj,nkj->nik", r, a, r).reshape(n, 9))):
        array = numpy_to_vtk(np.ascontiguousarray(values), deep=True)
        array.SetName(name)
        data.GetPointData().AddArray(array)
    writer = vtkXMLPolyDataWriter()
    writer.SetDataModeToBinary()
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.Write()


bundled = os.path.join(args.data, "gb_ellipsoids.lammpstrj.gz")
with pr.captured_messages() as messages:
    try:
        pr.load_plugin(args)
        reader = simple.OpenDataFile(bundled)
        if reader is None or reader.GetXMLName() != "LAMMPSDumpReader":
            raise RuntimeError("OpenDataFile picked %s" % (reader.GetXMLName() if reader else None))
        times = list(reader.TimestepValues)
        view = pr.setup_view(simple.CreateView("RenderView"), size=(500, 400))
        display = simple.Show(reader, view)
        simple.GetAnimationScene().UpdateAnimationUsingDataTimeSteps()
        simple.GetAnimationScene().AnimationTime = times[-1]
        if display.Representation != "Particles":
            fail("the dump is shown as %r, not as Particles" % display.Representation)
        if display.Shape != "Automatic":
            fail("Shape is %r, not Automatic" % display.Shape)
        simple.ColorBy(display, ("POINTS", "velocity", "Magnitude"))
        # (ParaView 6's default map is "Fast", 5.11's and 5.13's "Cool to Warm")
        pr.apply_preset(simple.GetColorTransferFunction("velocity"), "Cool to Warm")
        display.RescaleTransferFunctionToDataRange(True, False)
        pr.set_camera(view, position=(-40.0, -55.0, 50.0), focal_point=(7.5, 7.5, 16.5),
                      view_up=(0, 0, 1))
        if pr.must_fail(args, "spheres"):
            display.Shape = "Sphere"
        simple.Render(view)
        drawn = draws_ellipsoids(view)
        report.append("Shape Automatic: ellipsoids %s, time steps %s" % (drawn, times))
        if not drawn and not args.must_fail:
            fail("the ellipsoids are not drawn as ellipsoids")
        image_path = os.path.join(args.temp_dir, "TestEllipsoidsParaView_capture.png")
        opaque = pr.capture(view, image_path)
    except Exception as error:  # reported below, after the output window is restored
        fail("%s: %s" % (type(error).__name__, error))
print("\n".join(report))
text = messages.GetOutput().strip()
if text:
    print("FAIL: messages were logged:\n" + text)
    ok = False


def second_part():
    """The 2021 layout and the translucent picture (after the opaque one passed or not)."""
    ok = True
    report = []

    def fail(text):
        nonlocal ok
        report.append("FAIL: " + text)
        ok = False

    # the 2021 layout: components picked by hand give the same picture
    with pr.captured_messages() as messages:
        try:
            old = os.path.join(args.temp_dir, "TestEllipsoidsParaView_2021.lammpstrj")
            last_step_as_2021_dump(bundled, old)
            old_reader = simple.OpenDataFile(old)
            simple.Hide(reader, view)
            old_display = simple.Show(old_reader, view)
            simple.ColorBy(old_display, ("POINTS", "velocity", "Magnitude"))
            old_display.LookupTable = display.LookupTable
            old_display.Shape = "Ellipsoid"
            old_display.AxesArray = ["POINTS", "c_shape"]
            old_display.AxesArrayComponent = 0
            old_display.AxesAreDiameters = 1
            old_display.OrientationArray = ["POINTS", "c_shape"]
            old_display.OrientationArrayComponent = 3
            simple.Render(view)
            if not draws_ellipsoids(view):
                fail("c_shape: not drawn as ellipsoids")
            by_hand = pr.capture(
                view, os.path.join(args.temp_dir, "TestEllipsoidsParaView_2021.png"))
            largest, mean = pr.difference(opaque, by_hand)
            report.append("2021 layout, components by hand: largest difference %s/255" % largest)
            if largest != 0:
                fail("the c_shape components draw another picture (%s/255)" % largest)

            # tensors, as the Tensor Glyph filter takes them: Shape Ellipsoid (Tensor) draws the
            # picture of the axes and quaternions they were made from
            simple.Hide(old_reader, view)
            tensor_file = os.path.join(args.temp_dir, "TestEllipsoidsParaView_tensors.vtp")
            write_tensor_particles(tensor_file)
            tensor_reader = simple.OpenDataFile(tensor_file)
            tensor_display = simple.Show(tensor_reader, view)
            tensor_display.Representation = "Particles"
            pictures = []
            for shape in ("Ellipsoid", "Ellipsoid (Tensor)"):
                tensor_display.Shape = shape
                tensor_display.AxesArray = ["POINTS", "axes"]
                tensor_display.OrientationArray = ["POINTS", "quat"]
                tensor_display.TensorArray = ["POINTS", "tensor"]
                simple.Render(view)
                if not draws_ellipsoids(view):
                    fail("%s: not drawn as ellipsoids" % shape)
                pictures.append(pr.capture(view, os.path.join(
                    args.temp_dir, "TestEllipsoidsParaView_%s.png" % shape.split()[-1].strip("()"))))
            largest, mean = pr.difference(pictures[0], pictures[1])
            report.append("Ellipsoid (Tensor) vs axes and quaternions: largest difference %s/255"
                          % largest)
            if largest is None or largest > 1:
                fail("the tensors draw another picture (%s/255)" % largest)
            simple.Hide(tensor_reader, view)

            # translucent
            simple.Show(reader, view)
            display.Opacity = 0.9
            display.DensityModel = "Squared Distance"
            simple.Render(view)
            if not draws_ellipsoids(view):
                fail("translucent: not drawn as ellipsoids")
        except Exception as error:
            fail("%s: %s" % (type(error).__name__, error))
    print("\n".join(report))
    text = messages.GetOutput().strip()
    if text:
        print("FAIL: messages were logged:\n" + text)
        ok = False
    translucent = pr.capture_and_compare(view, "TestEllipsoidsParaView_translucent", args, CRITERIA)
    return translucent[0] and ok


if args.must_fail:
    pr.finish(pr.capture_and_compare(view, "TestEllipsoidsParaView", args, CRITERIA)[0])
else:
    ok = pr.capture_and_compare(view, "TestEllipsoidsParaView", args, CRITERIA)[0] and ok
    ok = second_part() and ok
    pr.finish(ok)

