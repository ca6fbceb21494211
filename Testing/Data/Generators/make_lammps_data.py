#!/usr/bin/env python3
"""Regenerate the LAMMPS molecular-dynamics test data sets of ParticleRendering.

Runs LAMMPS (Debian package ``lammps``, binary ``lmp``) on the input scripts
next to this file (``in.<scene>``), parses the text dumps it writes and
converts them to VTK XML PolyData (``.vtp``) files:

=================  =====================================================
scene              output files
=================  =====================================================
``lj_droplets``    ``lj_droplets.vtp`` (last frame) and the time series
                   ``lj_droplets_t0.vtp`` ... ``lj_droplets_t4.vtp``
                   (``lj_droplets_t4.vtp`` is identical to
                   ``lj_droplets.vtp``); the five frames as one LAMMPS
                   dump, ``lj_droplets.lammpstrj.gz``
``lj_film``        ``lj_film.vtp``
``fcc_block``      ``fcc_block.vtp``; the same as a LAMMPS data file,
                   ``fcc_block.data.gz``
``gb_ellipsoids``  ``gb_ellipsoids.lammpstrj.gz``: Gay-Berne ellipsoids
                   (atom_style ellipsoid), 3 frames, the dump as LAMMPS
                   wrote it with its c_shape[1..7] columns renamed to
                   shapex ... quatk (no .vtp)
=================  =====================================================

The LAMMPS-format files (write_lammps_dump, write_lammps_data) hold the
rounded values of the ``.vtp`` files, without radii (the readers' Type
Radii give them); the samples command opens them through the plugin's
readers. ``--lammps-files-only`` rewrites them from the ``.vtp`` files.

Every ``.vtp`` file holds one vertex cell per point and these point arrays:

* ``type``     int32   LAMMPS atom type (1 or 2)
* ``id``       int32   LAMMPS atom id (points are sorted by id)
* ``velocity`` float32 3 components, LJ units (sigma/tau)
* ``speed``    float32 magnitude of ``velocity``
* ``radius``   float32 rendering radius in sigma (the LJ length unit),
                       derived from the type, see ``TYPE_RADIUS``:
                       type 1 -> 0.5, type 2 -> 0.4

Points are float32 positions in sigma (wrapped into the periodic box, as
written by LAMMPS). Field data: ``TimeValue`` (float64, LJ time tau =
timestep * 0.005 of the run that wrote the frame) and ``BoxBounds`` (float64,
xmin xmax ymin ymax zmin zmax of the simulation box).

To keep the committed files small, positions are rounded to multiples of
2^-10 sigma (~0.001 sigma) and velocities/speeds to multiples of 2^-8
sigma/tau (~0.004) before the float32 conversion; the zeroed low mantissa
bits compress much better. ``--no-quantize`` writes full float32 precision.

The files are written by vtkXMLPolyDataWriter with zlib compression (level 9),
UInt32 block headers and Int32 vertex connectivity/offsets, in *inline binary*
(base64) data mode, NOT in appended mode: Debian 12's libexpat
(2.5.0-1+deb12uN) carries the backported "reparse deferral" change of expat
2.6, which breaks VTK <= 9.3's reading of ``<AppendedData>`` sections
(https://gitlab.kitware.com/vtk/vtk/-/issues/19258); the reader of the Debian
ParaView 5.11 / VTK 9.2 packages then fails with "not well-formed (invalid
token)" on any appended file larger than one parser buffer. Inline base64 data
is plain, valid XML and is read correctly everywhere.

All LJ interactions are identical (epsilon = sigma = 1, cut-off 2.5 sigma);
the atom type is only a label. The radius convention "half the LJ diameter"
(0.5 sigma) for type 1 is the contact radius of touching atoms; type 2 is
drawn smaller (0.4 sigma) so that the two types are easy to tell apart.

Runs are reproducible: velocity seeds are fixed in the input scripts (and
``velocity ... loop geom`` / ``set type/fraction`` do not depend on the
number of MPI ranks). Bit-for-bit identical trajectories additionally need
the same LAMMPS build and the same number of MPI ranks (``--np``, default 2,
which is what the committed files were made with).

Usage::

    /usr/bin/python3 Testing/Data/Generators/make_lammps_data.py \\
        [--out DIR] [--scene NAME ...] [--np N] [--lmp PATH] [--keep DIR]
        [--no-quantize] [--dumps DIR]

Only numpy and VTK (``vtkmodules``, e.g. Debian ``python3-paraview``) are
needed; LAMMPS scratch files go to a temporary directory.
"""

import argparse
import glob
import gzip
import io
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints, vtkTypeInt32Array
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

HERE = os.path.dirname(os.path.abspath(__file__))
REPO_DATA = os.path.normpath(os.path.join(HERE, ".."))  # Testing/Data

#: Rendering radius per LAMMPS atom type, in sigma (LJ length unit).
TYPE_RADIUS = {1: 0.5, 2: 0.4}

#: LJ time step used by all input scripts (for the TimeValue field data).
TIMESTEP = 0.005

#: Rounding quanta (see module docstring); None disables the rounding.
POS_QUANTUM = 2.0 ** -10
VEL_QUANTUM = 2.0 ** -8

#: scene name -> (LAMMPS input script, dump file glob relative to the run dir)
SCENES = {
    "lj_droplets": ("in.lj_droplets", "lj_droplets.*.dump"),
    "lj_film": ("in.lj_film", "lj_film.dump"),
    "fcc_block": ("in.fcc_block", "fcc_block.dump"),
    "gb_ellipsoids": ("in.gb_ellipsoids", "gb_ellipsoids.dump"),
}

#: the compute property/atom columns of in.gb_ellipsoids and the names newer LAMMPS versions
#: write for them in dump custom (Debian 12's LAMMPS has no such dump keywords)
ELLIPSOID_COLUMNS = ("c_shape[1] c_shape[2] c_shape[3] c_shape[4] c_shape[5] c_shape[6] "
                     "c_shape[7]", "shapex shapey shapez quatw quati quatj quatk")


# --------------------------------------------------------------------------- LAMMPS
def find_lammps(explicit=None):
    if explicit:
        return explicit
    for name in ("lmp", "lmp_serial", "lmp_stable", "lmp_mpi"):
        path = shutil.which(name)
        if path:
            return path
    sys.exit("error: no LAMMPS executable (lmp) found on PATH; install the 'lammps' package "
             "or pass --lmp")


def lammps_command(lmp, script, run_dir, scene, np_ranks):
    cmd = [lmp, "-in", script, "-var", "outdir", run_dir,
           "-log", os.path.join(run_dir, "log." + scene), "-screen", "none", "-nocite"]
    if np_ranks > 1:
        mpirun = shutil.which("mpirun") or shutil.which("mpiexec")
        if mpirun is None:
            return None
        pre = [mpirun]
        if hasattr(os, "geteuid") and os.geteuid() == 0:
            pre.append("--allow-run-as-root")  # Open MPI refuses to run as root otherwise
        pre += ["-np", str(np_ranks)]
        cmd = pre + cmd
    return cmd


def run_lammps(lmp, scene, run_dir, np_ranks):
    script = os.path.join(HERE, SCENES[scene][0])
    env = dict(os.environ, OMP_NUM_THREADS="1")
    attempts = [np_ranks] if np_ranks == 1 else [np_ranks, 1]
    for n in attempts:
        cmd = lammps_command(lmp, script, run_dir, scene, n)
        if cmd is None:
            print("  mpirun not found, running serially", flush=True)
            continue
        print("  $ " + " ".join(cmd), flush=True)
        t0 = time.perf_counter()
        proc = subprocess.run(cmd, cwd=run_dir, env=env,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        dt = time.perf_counter() - t0
        if proc.returncode == 0:
            print("  LAMMPS %s: %.1f s on %d rank(s)" % (scene, dt, n), flush=True)
            return dt, n
        print(proc.stdout[-3000:], file=sys.stderr)
        log = os.path.join(run_dir, "log." + scene)
        if os.path.exists(log):
            with open(log) as f:
                print("".join(f.readlines()[-30:]), file=sys.stderr)
        if n > 1:
            print("  warning: LAMMPS with %d MPI ranks failed (rc=%d), retrying serially; the "
                  "trajectory will differ from the committed data" % (n, proc.returncode),
                  file=sys.stderr, flush=True)
    sys.exit("error: LAMMPS failed for scene %s" % scene)


# --------------------------------------------------------------------------- dumps
def read_dump(path):
    """Read a single-frame LAMMPS text dump ('dump custom' / 'write_dump custom').

    Returns (timestep, box_bounds[3x2], {column name: numpy array}).
    """
    with open(path) as f:
        timestep = natoms = None
        box = []
        columns = None
        while columns is None:
            line = f.readline()
            if not line:
                raise ValueError("%s: no ITEM: ATOMS section" % path)
            if line.startswith("ITEM: TIMESTEP"):
                timestep = int(f.readline())
            elif line.startswith("ITEM: NUMBER OF ATOMS"):
                natoms = int(f.readline())
            elif line.startswith("ITEM: BOX BOUNDS"):
                if "xy" in line.split()[3:]:
                    raise ValueError("%s: triclinic boxes are not supported" % path)
                box = [[float(v) for v in f.readline().split()[:2]] for _ in range(3)]
            elif line.startswith("ITEM: ATOMS"):
                columns = line.split()[2:]
        data = np.loadtxt(f, dtype=np.float64, max_rows=natoms, ndmin=2)
    if data.shape != (natoms, len(columns)):
        raise ValueError("%s: expected %d x %d values, got %s"
                         % (path, natoms, len(columns), data.shape))
    cols = {name: data[:, i] for i, name in enumerate(columns)}
    for required in ("id", "type", "x", "y", "z", "vx", "vy", "vz"):
        if required not in cols:
            raise ValueError("%s: column %r missing" % (path, required))
    return timestep, np.array(box, dtype=np.float64), cols


# --------------------------------------------------------------------------- VTK
def _vtk_array(values, name):
    arr = numpy_support.numpy_to_vtk(np.ascontiguousarray(values), deep=1)
    arr.SetName(name)
    return arr


def _round(values, quantum):
    if quantum:
        values = np.round(values / quantum) * quantum
    return values.astype(np.float32)


def _int32_array(values):
    arr = vtkTypeInt32Array()
    arr.DeepCopy(numpy_support.numpy_to_vtk(np.ascontiguousarray(values, dtype=np.int32)))
    return arr


def dump_to_polydata(timestep, box, cols, quantize=True):
    order = np.argsort(cols["id"], kind="stable")
    n = order.size
    ids = cols["id"][order].astype(np.int32)
    types = cols["type"][order].astype(np.int32)
    pq, vq = (POS_QUANTUM, VEL_QUANTUM) if quantize else (None, None)
    pos = _round(np.column_stack([cols[c][order] for c in ("x", "y", "z")]), pq)
    vel = _round(np.column_stack([cols[c][order] for c in ("vx", "vy", "vz")]), vq)
    v64 = vel.astype(np.float64)
    speed = _round(np.sqrt(np.einsum("ij,ij->i", v64, v64)), vq)
    unknown = set(np.unique(types).tolist()) - set(TYPE_RADIUS)
    if unknown:
        raise ValueError("no radius defined for atom type(s) %s" % sorted(unknown))
    lut = np.zeros(max(TYPE_RADIUS) + 1, dtype=np.float32)
    for t, r in TYPE_RADIUS.items():
        lut[t] = r
    radius = lut[types]

    pd = vtkPolyData()
    points = vtkPoints()
    points.SetData(_vtk_array(pos, "Points"))
    pd.SetPoints(points)

    # one vertex cell per point; 32-bit storage keeps the file small
    verts = vtkCellArray()
    verts.SetData(_int32_array(np.arange(n + 1)), _int32_array(np.arange(n)))
    pd.SetVerts(verts)

    pdata = pd.GetPointData()
    for name, values in (("type", types), ("id", ids), ("velocity", vel),
                         ("radius", radius), ("speed", speed)):
        pdata.AddArray(_vtk_array(values, name))
    pdata.SetScalars(pdata.GetArray("type"))

    fd = pd.GetFieldData()
    tv = vtkDoubleArray()
    tv.SetName("TimeValue")
    tv.InsertNextValue(timestep * TIMESTEP)
    fd.AddArray(tv)
    fd.AddArray(_vtk_array(box.reshape(1, 6), "BoxBounds"))
    return pd


def write_vtp(pd, path):
    w = vtkXMLPolyDataWriter()
    w.SetFileName(path)
    w.SetInputData(pd)
    # Inline base64 instead of appended raw data: see the module docstring (expat bug).
    w.SetDataModeToBinary()
    w.SetCompressorTypeToZLib()
    w.SetCompressionLevel(9)
    w.SetBlockSize(1 << 16)
    w.SetHeaderTypeToUInt32()
    w.SetIdTypeToInt32()
    if not w.Write():
        raise RuntimeError("writing %s failed" % path)


def _exact(values):
    """Shortest decimal strings that read back to exactly these values (the rounded positions
    and velocities are multiples of 2^-10 and 2^-8: a few digits each)."""
    return [np.format_float_positional(v, trim="-") for v in values]


def _polydata_columns(pd):
    pdata = pd.GetPointData()
    pos = numpy_support.vtk_to_numpy(pd.GetPoints().GetData()).astype(np.float64)
    vel = numpy_support.vtk_to_numpy(pdata.GetArray("velocity")).astype(np.float64)
    ids = numpy_support.vtk_to_numpy(pdata.GetArray("id"))
    types = numpy_support.vtk_to_numpy(pdata.GetArray("type"))
    box = numpy_support.vtk_to_numpy(pd.GetFieldData().GetArray("BoxBounds")).reshape(6)
    time_value = pd.GetFieldData().GetArray("TimeValue").GetValue(0)
    return ids, types, pos, vel, box, int(round(time_value / TIMESTEP))


def _gzip_text(path):
    """A text file written gzip-compressed (level 9) without a time stamp or name in the gzip
    header, so that the same content gives the same bytes."""
    raw = open(path, "wb")
    return io.TextIOWrapper(gzip.GzipFile(filename="", mode="wb", compresslevel=9, fileobj=raw,
                                          mtime=0), encoding="ascii", newline="\n")


def write_lammps_dump(frames, path):
    """The frames (vtkPolyData of dump_to_polydata) as one gzipped LAMMPS text dump in the
    layout of ``dump custom ... id type x y z vx vy vz`` (periodic box "pp pp pp"), one snapshot
    per frame: what a user's trajectory file looks like, for vtkLAMMPSDumpReader (the radius comes
    from the reader's Type Radii, like for a user's atoms)."""
    with _gzip_text(path) as f:
        for pd in frames:
            ids, types, pos, vel, box, step = _polydata_columns(pd)
            f.write("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\n" % (step, len(ids)))
            f.write("ITEM: BOX BOUNDS pp pp pp\n")
            for k in range(3):
                f.write("%s %s\n" % tuple(_exact(box[2 * k:2 * k + 2])))
            f.write("ITEM: ATOMS id type x y z vx vy vz\n")
            columns = [_exact(pos[:, k]) for k in range(3)] + [_exact(vel[:, k]) for k in range(3)]
            for i in range(len(ids)):
                f.write("%d %d %s\n" % (ids[i], types[i], " ".join(c[i] for c in columns)))


def write_lammps_data(pd, path):
    """One frame as a gzipped LAMMPS data file in the layout of ``write_data`` (atom style
    atomic: Masses, Atoms with image flags 0, Velocities), for vtkLAMMPSDataReader."""
    ids, types, pos, vel, box, step = _polydata_columns(pd)
    with _gzip_text(path) as f:
        f.write("LAMMPS data file via make_lammps_data.py, timestep = %d, units = lj\n\n" % step)
        f.write("%d atoms\n%d atom types\n\n" % (len(ids), int(types.max())))
        for k, axis in enumerate("xyz"):
            f.write("%s %s %slo %shi\n" % (*_exact(box[2 * k:2 * k + 2]), axis, axis))
        f.write("\nMasses\n\n")
        for t in range(1, int(types.max()) + 1):
            f.write("%d 1\n" % t)
        f.write("\nAtoms # atomic\n\n")
        columns = [_exact(pos[:, k]) for k in range(3)]
        for i in range(len(ids)):
            f.write("%d %d %s 0 0 0\n" % (ids[i], types[i], " ".join(c[i] for c in columns)))
        f.write("\nVelocities\n\n")
        columns = [_exact(vel[:, k]) for k in range(3)]
        for i in range(len(ids)):
            f.write("%d %s\n" % (ids[i], " ".join(c[i] for c in columns)))


#: scene -> the LAMMPS-format file written beside its .vtp files (see write_lammps_files)
LAMMPS_FILES = {"lj_droplets": "lj_droplets.lammpstrj.gz", "fcc_block": "fcc_block.data.gz"}


def write_lammps_files(scene, out_dir):
    """The time series of lj_droplets as one dump and fcc_block as a data file, from the .vtp
    files just written (the same rounded values), so that the samples open them through the
    plugin's own readers."""
    if scene not in LAMMPS_FILES:
        return []
    path = os.path.join(out_dir, LAMMPS_FILES[scene])

    def read(name):
        r = vtkXMLPolyDataReader()
        r.SetFileName(os.path.join(out_dir, name))
        r.Update()
        return r.GetOutput()

    if scene == "lj_droplets":
        write_lammps_dump([read("lj_droplets_t%d.vtp" % i) for i in range(5)], path)
    else:
        write_lammps_data(read(scene + ".vtp"), path)
    return [path]


def describe(path):
    if not path.endswith(".vtp"):
        return "%-22s %8.1f kB" % (os.path.basename(path), os.path.getsize(path) / 1024.0)
    r = vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    pd = r.GetOutput()
    pdata = pd.GetPointData()
    names = [pdata.GetArrayName(i) for i in range(pdata.GetNumberOfArrays())]
    b = pd.GetBounds()
    return ("%-22s %7d atoms %7d verts %8.1f kB  bounds (%.1f..%.1f, %.1f..%.1f, %.1f..%.1f)"
            "  arrays %s" % (os.path.basename(path), pd.GetNumberOfPoints(),
                             pd.GetNumberOfVerts(), os.path.getsize(path) / 1024.0,
                             *b, ",".join(names)))


# --------------------------------------------------------------------------- main
def convert_ellipsoids(dump, out_dir):
    """The Gay-Berne dump as the bundled gb_ellipsoids.lammpstrj.gz: LAMMPS's text with the
    compute property/atom columns named as newer LAMMPS's dump custom names them."""
    path = os.path.join(out_dir, "gb_ellipsoids.lammpstrj.gz")
    old, new = ELLIPSOID_COLUMNS
    with open(dump) as f, _gzip_text(path) as out:
        for line in f:
            if line.startswith("ITEM: ATOMS"):
                if old not in line:
                    sys.exit("error: %s has no columns %s" % (dump, old))
                line = line.replace(old, new)
            out.write(line)
    return [path]


def convert(scene, run_dir, out_dir, quantize=True):
    pattern = SCENES[scene][1]
    dumps = glob.glob(os.path.join(run_dir, pattern))
    if not dumps:
        sys.exit("error: LAMMPS wrote no dump matching %s" % pattern)
    if scene == "gb_ellipsoids":
        return convert_ellipsoids(dumps[0], out_dir)

    def step_of(p):
        m = re.search(r"\.(\d+)\.dump$", p)
        return int(m.group(1)) if m else 0

    dumps.sort(key=step_of)
    written = []
    if len(dumps) > 1:  # time series (lj_droplets)
        for i, d in enumerate(dumps):
            pd = dump_to_polydata(*read_dump(d), quantize=quantize)
            path = os.path.join(out_dir, "%s_t%d.vtp" % (scene, i))
            write_vtp(pd, path)
            written.append(path)
    last = dump_to_polydata(*read_dump(dumps[-1]), quantize=quantize)
    path = os.path.join(out_dir, scene + ".vtp")
    write_vtp(last, path)
    written.append(path)
    return written


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default=REPO_DATA,
                    help="output directory for the .vtp files (default: Testing/Data)")
    ap.add_argument("--scene", action="append", choices=sorted(SCENES) + ["all"],
                    help="scene to generate (repeatable; default: all)")
    ap.add_argument("--np", type=int, default=2, dest="np_ranks",
                    help="MPI ranks for LAMMPS (default 2; 1 = serial, no mpirun). If the MPI "
                         "run fails the scene is rerun serially.")
    ap.add_argument("--lmp", help="LAMMPS executable (default: lmp on PATH)")
    ap.add_argument("--keep", metavar="DIR",
                    help="keep the LAMMPS scratch files (logs, dumps) in DIR instead of a "
                         "temporary directory")
    ap.add_argument("--dumps", metavar="DIR",
                    help="do not run LAMMPS; convert the dumps of an earlier --keep DIR run")
    ap.add_argument("--lammps-files-only", action="store_true",
                    help="only write the LAMMPS-format files (%s) from the .vtp files in --out"
                    % ", ".join(sorted(LAMMPS_FILES.values())))
    ap.add_argument("--no-quantize", dest="quantize", action="store_false",
                    help="write full float32 precision (larger files)")
    args = ap.parse_args(argv)

    scenes = args.scene or ["all"]
    scenes = list(SCENES) if "all" in scenes else list(dict.fromkeys(scenes))
    if args.lammps_files_only:
        for scene in scenes:
            for path in write_lammps_files(scene, args.out):
                print("  " + describe(path))
        return 0
    lmp = None if args.dumps else find_lammps(args.lmp)
    os.makedirs(args.out, exist_ok=True)

    total = 0.0
    written = []
    for scene in scenes:
        print("[%s]" % scene, flush=True)
        if args.dumps:
            dt = 0.0
            written += convert(scene, os.path.join(args.dumps, scene), args.out, args.quantize)
        elif args.keep:
            run_dir = os.path.abspath(os.path.join(args.keep, scene))
            os.makedirs(run_dir, exist_ok=True)
            for old in glob.glob(os.path.join(run_dir, "*.dump")):
                os.remove(old)
            dt, _ = run_lammps(lmp, scene, run_dir, args.np_ranks)
            written += convert(scene, run_dir, args.out, args.quantize)
        else:
            with tempfile.TemporaryDirectory(prefix="pr_lammps_%s_" % scene) as run_dir:
                dt, _ = run_lammps(lmp, scene, run_dir, args.np_ranks)
                written += convert(scene, run_dir, args.out, args.quantize)
        written += write_lammps_files(scene, args.out)
        total += dt

    print("LAMMPS total: %.1f s" % total)
    print("wrote:")
    size = 0
    for path in written:
        print("  " + describe(path))
        size += os.path.getsize(path)
    print("total size: %.2f MB" % (size / 1e6))
    return 0


if __name__ == "__main__":
    sys.exit(main())
