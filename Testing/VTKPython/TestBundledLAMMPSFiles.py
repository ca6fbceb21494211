"""The bundled LAMMPS-format files hold the bundled .vtp runs exactly.

Testing/Data/lj_droplets.lammpstrj.gz (a dump, 5 snapshots) and fcc_block.data.gz (a data file)
are what Scripts/render_samples.sh opens through vtkLAMMPSDumpReader and vtkLAMMPSDataReader;
Testing/Data/Generators/make_lammps_data.py writes them from the same runs as the .vtp files.
Read through the plugin's readers with Type Radii 1 -> 0.5 and 2 -> 0.4, every snapshot must give
the .vtp file's points, ids, types, velocities and radii bit for bit, and its time step; the box
must be the .vtp's BoxBounds. Fails when either file is regenerated from other runs, rounded
differently, or read differently.

usage: python3 TestBundledLAMMPSFiles.py --data Testing/Data
"""
import argparse
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

import particlerendering as pr

parser = argparse.ArgumentParser()
parser.add_argument("--data", required=True)
args = parser.parse_args()
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL: " + what)


def vtp(name):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(args.data, name))
    reader.Update()
    return reader.GetOutput()


def array(data, name):
    values = data.GetPointData().GetArray(name)
    return None if values is None else vtk_to_numpy(values)


def compare(label, got, expected):
    check(got.GetNumberOfPoints() == expected.GetNumberOfPoints(),
          "%s: %d atoms, the .vtp has %d" % (label, got.GetNumberOfPoints(),
                                             expected.GetNumberOfPoints()))
    if got.GetNumberOfPoints() != expected.GetNumberOfPoints():
        return
    points = vtk_to_numpy(got.GetPoints().GetData()).astype(np.float64)
    check(np.array_equal(points, vtk_to_numpy(expected.GetPoints().GetData())),
          "%s: positions differ (max %g)" % (label, np.abs(
              points - vtk_to_numpy(expected.GetPoints().GetData())).max()))
    for name in ("id", "type", "velocity", "radius"):
        values = array(got, name)
        check(values is not None and np.array_equal(values, array(expected, name)),
              "%s: array %s missing or different" % (label, name))
    box = got.GetFieldData().GetArray("BoxBounds")
    check(box is not None and np.array_equal(
        vtk_to_numpy(box).reshape(-1)[:6],
        vtk_to_numpy(expected.GetFieldData().GetArray("BoxBounds")).reshape(-1)),
        "%s: the box differs from the .vtp's BoxBounds" % label)


# the droplets' trajectory: five snapshots, timesteps 0 ... 2000
dump = pr.vtkLAMMPSDumpReader()
dump.SetFileName(os.path.join(args.data, "lj_droplets.lammpstrj.gz"))
dump.SetTypeRadius(1, 0.5)
dump.SetTypeRadius(2, 0.4)
dump.UpdateInformation()
steps = dump.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
check(steps is not None and list(steps) == [0.0, 500.0, 1000.0, 1500.0, 2000.0],
      "the dump's time steps are %s, not 0, 500, ..., 2000" % (steps,))
for i, step in enumerate(steps or ()):
    dump.UpdateTimeStep(step)
    expected = vtp("lj_droplets_t%d.vtp" % i)
    compare("dump step %d" % i, dump.GetOutputDataObject(0), expected)
    time_value = expected.GetFieldData().GetArray("TimeValue").GetValue(0)
    check(abs(step * 0.005 - time_value) < 1e-9,
          "dump step %d: timestep %g is not the .vtp's time %g / 0.005" % (i, step, time_value))

# the crystal as a data file
data = pr.vtkLAMMPSDataReader()
data.SetFileName(os.path.join(args.data, "fcc_block.data.gz"))
data.SetTypeRadius(1, 0.5)
data.SetTypeRadius(2, 0.4)
data.Update()
compare("data file", data.GetOutputDataObject(0), vtp("fcc_block.vtp"))

print("%s: the dump (%d snapshots) and the data file against the .vtp files"
      % ("FAILED" if failures else "passed", len(steps or ())))
sys.exit(1 if failures else 0)
