"""Shared parts of the distributed-rendering tests (TestParticlesMPI, TestParticlesPvserver):
the LAMMPS film split into interleaved pieces per rank, the cases, the comparison helpers.

Note: a ProgrammableSource's script runs in the __main__ namespace of pvpython/pvbatch in a
builtin session and replaces globals there (e.g. `split`, `max`, `sum` from
numpy_interface.algorithms): the test scripts keep their work inside functions.
"""
import os
import sys

from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

CASES = {
    # name: (opacity, density model, ambient occlusion, technique)
    "opaque": (1.0, 0, "None", "Spheres"),
    "translucent": (0.7, 0, "None", "Spheres"),
    "translucent-squared": (0.7, 1, "None", "Spheres"),
    "ao": (1.0, 0, "Density Volume", "Spheres"),
    "ao-translucent": (0.7, 0, "Density Volume", "Spheres"),
    "voxel-cone": (1.0, 0, "Voxel Cone Tracing", "Spheres"),
    "voxel-cone-translucent": (0.7, 0, "Voxel Cone Tracing", "Spheres"),
    # screen space: the processes' G-buffers are composited before the occlusion
    "pointao": (1.0, 0, "PointAO", "Spheres"),
    "metaballs": (1.0, 0, "None", "Metaballs"),
    # Opacity is not applied to metaballs (opaque; its baseline is the metaballs picture): a
    # partial alpha blended the surface with what each process had drawn before it
    "metaballs-opacity": (0.7, 0, "None", "Metaballs"),
    # Scale-Consistent Shading, converged (SNDF_SAMPLES per pixel): each sample pass's G-buffer
    # is composited over the processes before it enters the S-NDFs
    "sndf": (1.0, 0, "None", "Spheres"),
    # translucent with the actor turned (35 degrees about z, 20 about x, about the film's centre):
    # the boxes are cut in data coordinates, the compositing order comes from them
    "translucent-turned": (0.7, 1, "None", "Spheres"),
}

# S-NDF samples per pixel of the sndf case (a converged, antialiased picture; 256 is the default)
SNDF_SAMPLES = 64

# share of the pixels that may be one 8-bit step over the tolerance (per-process rounding)
OVER_TOLERANCE_SHARE = 1e-4


def single_process_criteria(pr, tolerance=2.0):
    """The distributed criterion against the single-process picture (pr.Criteria): at most
    OVER_TOLERANCE_SHARE of the pixels over `tolerance` (8-bit steps), none more than one step
    over it, mean 0.5/255. pr: prParaViewTesting."""
    # 8-bit images: errors are whole steps; half a step above each bound keeps float rounding
    # of k/255 away from them ("over 2" means 3 or more)
    return pr.Criteria(tolerance=tolerance + 0.5, max_share=OVER_TOLERANCE_SHARE, max_mean=0.5,
                       max_error=tolerance + 1.5)


def compare_with_single_process(pr, image, reference_path, temp_dir, name, tolerance=2.0):
    """Compare a distributed rendering with the single-process image at reference_path through
    the suite's comparison (vtkParticleImageComparison.TestImage, which also checks that the
    criteria reject the reference darkened by 10 % and shifted by one pixel). Criteria: at most
    OVER_TOLERANCE_SHARE of the pixels over `tolerance` (8-bit steps), none more than one step
    over it (IceT composites the processes' 8-bit images, each rounded once), mean 0.5/255.
    Prints the measured maximum, mean and pixels over the tolerance. Returns (ok, maximum).
    pr: prParaViewTesting."""
    reference = pr.read_png(reference_path)
    worst, mean = pr.difference(image, reference)
    if worst is None:
        print("FAIL: %s: the image cannot be compared with %s" % (name, reference_path))
        return False, 0.0
    criteria = single_process_criteria(pr, tolerance)
    counter = criteria.comparison()
    counter.CompareImages(image, reference)
    print("%s: max %.0f/255, mean %.3f/255, %d of %d pixels over %.0f/255"
          % (name, worst, mean, counter.GetNumberOfPixelsOverTolerance(),
             counter.GetNumberOfComparedPixels(), tolerance))
    return criteria.comparison().TestImage(image, reference_path, temp_dir, name), worst


def rgb(image):
    return vtk_to_numpy(image.GetPointData().GetScalars()).astype(int)[:, :3]


SPLIT_SCRIPT = """
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk
info = self.GetOutputInformation(0)
piece = info.Get(sddp.UPDATE_PIECE_NUMBER())
pieces = info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
reader = vtkXMLPolyDataReader()
reader.SetFileName(%(path)r)
reader.Update()
full = reader.GetOutput()
n = full.GetNumberOfPoints()
if 0 < %(keep)d < n:  # (not min(): this script's namespace has numpy_interface's)
    n = %(keep)d
owner = numpy.arange(n) %% pieces
if %(empty_rank)r and pieces > 1:
    owner[owner == pieces - 1] = 0
keep = numpy.nonzero(owner == piece)[0]
from vtkmodules.vtkCommonCore import vtkIdList
ids = vtkIdList()
ids.SetNumberOfIds(len(keep))
for k, i in enumerate(keep):
    ids.SetId(k, int(i))
from vtkmodules.vtkCommonCore import vtkPoints
out = self.GetPolyDataOutput()
points = vtkPoints()
points.SetDataType(full.GetPoints().GetDataType())
full.GetPoints().GetPoints(ids, points)
# bad points on the last rank: NaN, and a huge point with an infinite coordinate (not drawn;
# they must neither stretch the bounds nor break the partition)
bad = %(bad)r and piece == pieces - 1
if bad:
    points.InsertNextPoint(float("nan"), 0.0, 0.0)
    points.InsertNextPoint(1e30, 1e30, float("inf"))
out.SetPoints(points)
for a in range(full.GetPointData().GetNumberOfArrays()):
    src = full.GetPointData().GetArray(a)
    dst = src.NewInstance()
    dst.SetName(src.GetName())
    dst.SetNumberOfComponents(src.GetNumberOfComponents())
    dst.SetNumberOfTuples(len(keep))
    src.GetTuples(ids, dst)
    if bad:
        for copy in range(2):
            dst.InsertNextTuple(src.GetTuple(0))
    out.GetPointData().AddArray(dst)
"""

SPLIT_INFORMATION_SCRIPT = """
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
self.GetOutputInformation(0).Set(vtkAlgorithm.CAN_HANDLE_PIECE_REQUEST(), 1)
"""



SCENE_CAMERAS = {  # position, focal point: the slab obliquely; the deep block from the front
    "gas": ((80.0, -40.0, 30.0), (16.0, 16.0, 4.0)),
    "reproducer": ((110.0, -70.0, 60.0), (25.0, 25.0, 22.0)),
    "deep": ((12.0, -40.0, 22.0), (12.0, 12.0, 5.0)),
    "ellipsoids": ((12.0, -40.0, 22.0), (12.0, 12.0, 5.0)),
}


def write_scene(name, path, seed=1):
    """Write the seeded scene `name` (points, radius, type, speed) to the .vtp file `path`:
    gas (a dense fcc slab of 8 000 atoms, radius 0.5, in 16 000 atoms of hot gas), deep (6 000
    spheres of radius 0.9-1.5 at mean spacing 0.9), mixed (gas, and also its slab and its gas
    alone in <path>_type1.vtp and <path>_type2.vtp), ellipsoids (3 000 oriented ellipsoids of
    semi-axes 0.25-1.2 in the deep scene's box, point arrays semi_axes and orientation as the
    LAMMPS Dump Reader writes them), reproducer (issue 61's: 100 000 atoms uniformly at random
    in a 30 x 30 x 40 box from z = -5, radius 0.5, speed uniform in [0.5, 4), type 2 within 6 of
    (15, 15, 15); numpy's default_rng(seed), default 1). Benchmarks/mpi_partition_accuracy.py,
    TestParticlesMPI --deep / --ellipsoids, TestTranslucencyMPIExact."""
    import numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    vtk_python = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                              "VTKPython")
    if vtk_python not in sys.path:
        sys.path.append(vtk_python)
    from prVTKTesting import particles_from
    if name == "reproducer":
        rng = numpy.random.default_rng(seed)
        xyz = rng.random((100000, 3)) * [30.0, 30.0, 40.0] - [0.0, 0.0, 5.0]
        speed = 0.5 + 3.5 * rng.random(100000)
        kind = numpy.where(numpy.linalg.norm(xyz - [15.0, 15.0, 15.0], axis=1) < 6.0, 2.0, 1.0)
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(path)
        writer.SetInputData(particles_from(
            xyz.astype(numpy.float32), radius=numpy.full(100000, 0.5, numpy.float32),
            type=kind.astype(numpy.float32), speed=speed.astype(numpy.float32)))
        writer.Write()
        return
    rng = numpy.random.default_rng(20261127)
    if name in ("gas", "mixed"):
        a = 1.5874  # fcc at number density 1
        cells = numpy.stack(numpy.meshgrid(numpy.arange(20), numpy.arange(20), numpy.arange(5),
                                           indexing="ij"), -1).reshape(-1, 1, 3)
        basis = numpy.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
        slab = ((cells + basis[None]).reshape(-1, 3)) * a
        gas = rng.random((16000, 3)) * [20 * a, 20 * a, 5 * a + 16.0] - [0.0, 0.0, 8.0]
        xyz = numpy.vstack([slab, gas])
        kind = numpy.r_[numpy.ones(len(slab)), numpy.full(len(gas), 2.0)]
        speed = numpy.where(kind == 2, 0.3 + 0.7 * rng.random(len(xyz)),
                            0.05 + 0.1 * rng.random(len(xyz)))
        radius = numpy.full(len(xyz), 0.5)
    elif name == "ellipsoids":
        xyz = rng.random((3000, 3)) * [24.0, 24.0, 10.0]
        kind = 1.0 + (rng.random(3000) < 0.3)
        speed = 0.2 + 0.8 * rng.random(3000)
        radius = numpy.full(3000, 0.5)
        axes = 0.25 + 0.95 * rng.random((3000, 3))
        quaternions = rng.normal(size=(3000, 4))
        quaternions /= numpy.linalg.norm(quaternions, axis=1)[:, None]
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(path)
        writer.SetInputData(particles_from(
            xyz.astype(numpy.float32), radius=radius.astype(numpy.float32),
            type=kind.astype(numpy.float32), speed=speed.astype(numpy.float32),
            semi_axes=axes.astype(numpy.float32), orientation=quaternions.astype(numpy.float32)))
        writer.Write()
        return
    else:
        xyz = rng.random((6000, 3)) * [24.0, 24.0, 10.0]
        kind = 1.0 + (rng.random(6000) < 0.3)
        speed = 0.2 + 0.8 * rng.random(6000)
        radius = 0.9 + 0.6 * rng.random(6000)
    f32 = numpy.float32
    parts = [("", numpy.ones(len(xyz), bool))]
    if name == "mixed":  # also the slab (type 1) and the gas (type 2) alone
        parts += [("_type%d" % t, kind == t) for t in (1, 2)]
    for suffix, keep in parts:
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(path[:-len(".vtp")] + suffix + ".vtp")
        writer.SetInputData(particles_from(xyz[keep].astype(f32), radius=radius[keep].astype(f32),
                                           type=kind[keep].astype(f32),
                                           speed=speed[keep].astype(f32)))
        writer.Write()


def make_film_pieces(args, empty_rank=False, keep=0, bad_points=False, path=None):
    """A ProgrammableSource that reads Testing/Data/lj_film.vtp (19360 atoms; or the .vtp file
    `path`) on every rank and keeps particle i on rank i mod N (with empty_rank: the last rank's
    go to rank 0; keep > 0: only the first `keep` particles; bad_points: 2 non-finite points more
    on the last rank)."""
    source = simple.ProgrammableSource()
    source.OutputDataSetType = "vtkPolyData"
    source.Script = SPLIT_SCRIPT % {"path": path or os.path.join(args.data, "lj_film.vtp"),
                                    "empty_rank": empty_rank, "keep": keep, "bad": bad_points}
    source.ScriptRequestInformation = SPLIT_INFORMATION_SCRIPT
    source.UpdatePipeline()
    return source


def show_film(source, pr):
    """The Particle Render View (400x300) of the tests with the film as Particles coloured by
    type, radii from 'radius'; returns (view, display). pr: prParaViewTesting."""
    view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=(400, 300))
    display = pr.show_particles(source, view)
    pr.set_camera(view, position=(95.0, -60.0, 70.0), focal_point=(19.7, 19.7, 9.0))
    return view, display


def apply_case(view, display, case):
    opacity, model, ao, technique = CASES[case]
    display.Technique = technique
    display.Opacity = opacity
    display.DensityModel = model
    view.ParticleAmbientOcclusion = ao
    if case.endswith("turned"):
        bounds = display.Input.GetDataInformation().GetBounds()
        display.Origin = [0.5 * (bounds[2 * a] + bounds[2 * a + 1]) for a in range(3)]
        display.Orientation = [20.0, 0.0, 35.0]
    else:
        display.Orientation = [0.0, 0.0, 0.0]
    sndf = 1 if case.startswith("sndf") else 0
    view.ScaleConsistentShading = sndf
    view.SNDFConvergeStillRenders = sndf
    view.SNDFTargetSamples = SNDF_SAMPLES
