"""Strong scaling of distributed rendering (pvbatch under mpiexec; one run per process count).

Scene: the LAMMPS film of Testing/Data/lj_film.vtp (19 360 atoms, periodic in x and y) repeated
REPEAT x REPEAT times over its periodic box (REPEAT 2: 77 440 atoms, 7: 948 640), radii from
`radius`, coloured by type, in a WIDTH x HEIGHT Particle Render View seen obliquely from above.
Every rank generates its piece itself: particle i on rank i mod N (interleaved: the worst case
for the exchange, every rank's particles spread over the whole film).

Measured per process count N, with the wall clock of rank 0 (the render call returns after
IceT has composited):
- frame_s for opaque spheres (no partition), translucent (opacity 0.7, partitioned) and
  translucent with density-volume AO: the mean of FRAMES frames, each after a camera rotation
  (nothing but drawing and compositing);
- step_s: a time step (every particle moved a little, the source executes again) rendered
  translucent with AO: source (source_s: the ProgrammableSource generating the pieces, not our
  code), partition, volume sum and frame;
- partition_s: the partition's own time in that step (the slowest rank, from the
  representation's ParticleDistribution), bytes: bytes sent by all ranks, ghosts: ghost copies
  drawn by all ranks.

usage: mpiexec -np N pvbatch Benchmarks/mpi_scaling.py --plugin ParticleRendering.so
           --data Testing/Data [--repeat R] [--size W H] [--frames F] [--csv FILE]
Appends one row per run to the CSV (default Benchmarks/results/mpi_scaling.csv); see
Benchmarks/run_mpi_scaling.sh for the whole table and Benchmarks/plot_mpi_scaling.py for the plot.
"""
import argparse
import os
import time


SCRIPT = """
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.util.numpy_support import vtk_to_numpy, numpy_to_vtk
import numpy
info = self.GetOutputInformation(0)
piece = info.Get(sddp.UPDATE_PIECE_NUMBER())
pieces = info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
reader = vtkXMLPolyDataReader()
reader.SetFileName(%(path)r)
reader.Update()
film = reader.GetOutput()
xyz = vtk_to_numpy(film.GetPoints().GetData()).astype(numpy.float32)
b = film.GetBounds()
period = numpy.array([b[1] - b[0], b[3] - b[2]], numpy.float32)
repeat = %(repeat)d
n = xyz.shape[0]
copies = numpy.arange(repeat * repeat)
ids = numpy.arange(n * repeat * repeat)
mine = ids[ids %% pieces == piece]
copy = mine // n
atom = mine %% n
pos = xyz[atom].copy()
pos[:, 0] += (copy %% repeat) * period[0]
pos[:, 1] += (copy // repeat) * period[1]
# the time step: a small deterministic displacement
step = %(step)d
pos += 0.05 * step * numpy.sin(pos[:, ::-1] + step).astype(numpy.float32)
out = self.GetPolyDataOutput()
from vtkmodules.vtkCommonCore import vtkPoints
points = vtkPoints()
points.SetData(numpy_to_vtk(pos, deep=True))
out.SetPoints(points)
for name in ("radius", "type"):
    values = vtk_to_numpy(film.GetPointData().GetArray(name))[atom]
    array = numpy_to_vtk(numpy.ascontiguousarray(values), deep=True)
    array.SetName(name)
    out.GetPointData().AddArray(array)
"""

INFORMATION_SCRIPT = """
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
self.GetOutputInformation(0).Set(vtkAlgorithm.CAN_HANDLE_PIECE_REQUEST(), 1)
"""


def main():
    from paraview import servermanager, simple

    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--repeat", type=int, default=2)
    parser.add_argument("--size", type=int, nargs=2, default=[800, 600])
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--csv", default=os.path.join(here, "results", "mpi_scaling.csv"))
    args, _ = parser.parse_known_args()
    simple.LoadPlugin(args.plugin, remote=False)
    ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    path = os.path.join(args.data, "lj_film.vtp")

    source = simple.ProgrammableSource()
    source.OutputDataSetType = "vtkPolyData"
    source.ScriptRequestInformation = INFORMATION_SCRIPT
    source.Script = SCRIPT % {"path": path, "repeat": args.repeat, "step": 0}
    source.UpdatePipeline()
    particles = source.GetDataInformation().GetNumberOfPoints()

    view = simple.CreateView("ParticleRenderView")
    view.ViewSize = list(args.size)
    view.OrientationAxesVisibility = 0
    display = simple.Show(source, view)
    display.Representation = "Particles"
    display.UseRadiusArray = 1
    display.RadiusArray = ["POINTS", "radius"]
    simple.ColorBy(display, ("POINTS", "type"))
    simple.Render(view)
    view.CameraFocalPoint = [19.7 * args.repeat, 19.7 * args.repeat, 9.0]
    view.CameraPosition = [19.7 * args.repeat + 60.0 * args.repeat, -40.0 * args.repeat,
                           50.0 * args.repeat]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    simple.ResetCamera(view)

    def frames():
        simple.Render(view)  # warm: shaders, uploads, volumes
        camera = simple.GetActiveCamera()
        start = time.time()
        for _ in range(args.frames):
            camera.Azimuth(2.0)
            simple.Render(view)
        return (time.time() - start) / args.frames

    def distribution():
        display.SMProxy.UpdatePropertyInformation()
        values = list(display.GetProperty("ParticleDistribution"))
        return [values[5 * r:5 * r + 5] for r in range(len(values) // 5)]

    row = {"particles": particles, "ranks": ranks, "width": args.size[0], "height": args.size[1]}
    display.Opacity = 1.0
    view.ParticleAmbientOcclusion = "None"
    row["opaque_frame_s"] = frames()
    display.Opacity = 0.7
    row["translucent_frame_s"] = frames()
    view.ParticleAmbientOcclusion = "Density Volume"
    row["translucent_ao_frame_s"] = frames()
    # a time step
    source.Script = SCRIPT % {"path": path, "repeat": args.repeat, "step": 1}
    start = time.time()
    source.UpdatePipeline()
    row["source_s"] = time.time() - start
    simple.Render(view)
    row["step_s"] = time.time() - start
    per_rank = distribution()
    row["partition_s"] = float(numpy_max([r[4] for r in per_rank]))
    row["bytes"] = int(sum_values([r[3] for r in per_rank]))
    row["ghosts"] = int(sum_values([r[2] for r in per_rank]))
    row["owned_min"] = int(numpy_min([r[1] for r in per_rank]))
    row["owned_max"] = int(numpy_max([r[1] for r in per_rank]))
    print(row)

    columns = ["particles", "ranks", "width", "height", "opaque_frame_s", "translucent_frame_s",
               "translucent_ao_frame_s", "source_s", "step_s", "partition_s", "bytes", "ghosts",
               "owned_min", "owned_max"]
    new = not os.path.exists(args.csv)
    with open(args.csv, "a") as f:
        if new:
            f.write(",".join(columns) + "\n")
        f.write(",".join(("%.4f" % row[c]) if isinstance(row[c], float) else str(row[c])
                         for c in columns) + "\n")


# (the ProgrammableSource's script runs in __main__ and replaces builtins such as max and sum)
def numpy_max(values):
    import numpy
    return numpy.max(numpy.array(values, dtype=float))


def numpy_min(values):
    import numpy
    return numpy.min(numpy.array(values, dtype=float))


def sum_values(values):
    import numpy
    return numpy.sum(numpy.array(values, dtype=float))


main()
