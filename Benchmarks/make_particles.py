#!/usr/bin/env python3
"""Synthetic particle data sets for ParticleRendering scaling benchmarks.

Kinds (``count`` = N particles, ``R`` = ``radius`` argument, default 0.5):

``lattice``
    Simple cubic lattice with spacing 1 filling a cube of side ceil(N^(1/3))
    (the last layer is partially filled when N is not a cube), starting at the
    origin, in x-fastest order. ``type`` alternates 1/2 in a 3D checkerboard.
    With the default R = 0.5 the largest spheres just touch.
``gas``
    Uniformly random positions in a cube of side (N / 0.1)^(1/3), i.e. number
    density 0.1; random order. ``type`` 1 (80 %) or 2 (20 %).
``clustered``
    Clumpy distribution in the same cube as ``gas`` (same mean density):
    90 % of the particles in N/1000 isotropic Gaussian clusters with uniformly
    random centres, log-normally distributed populations (sigma 0.75) and
    widths chosen for a central density of ~1 (log-normal scatter), plus 10 %
    uniform background. Cluster particles are stored cluster by cluster.
    ``type`` is 1 for background particles and 2..5 (cluster index mod 4) for
    cluster members.

Point arrays (all kinds): ``radius`` float32, uniform in [0.6 R, R] (0.3..0.5
for R = 0.5); ``type`` int32; ``speed`` float32, Maxwell-Boltzmann magnitude
(chi distribution with 3 degrees of freedom, unit thermal velocity). One vertex
cell per point (32-bit cell storage when N < 2^31). Points are float32.
Everything is deterministic for a given (kind, count, seed, radius).

Python use (e.g. from a pvpython benchmark driver, no file round trip)::

    sys.path.insert(0, "<repo>/Benchmarks")
    import make_particles
    pd = make_particles.make("clustered", 10**6, seed=1)   # -> vtkPolyData

CLI::

    /usr/bin/python3 Benchmarks/make_particles.py --kind gas --count 1000000 \\
        --out gas_1M.vtp [--seed S] [--radius R] [--format binary|appended]

File format: vtkXMLPolyDataWriter, no compression. ``--format appended`` (raw
appended binary) is the fastest to write and read, but Debian 12's ParaView
5.11 / VTK 9.2 cannot read appended files with the patched system libexpat
(https://gitlab.kitware.com/vtk/vtk/-/issues/19258), so the default is
``binary`` (inline base64), which every reader handles.

Memory: about 20 bytes per particle for the data set itself plus temporaries,
~0.5 GB peak for N = 10^7.
"""

import argparse
import math
import os
import sys
import time

import numpy as np

from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints, vtkTypeInt32Array, vtkTypeInt64Array
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

KINDS = ("lattice", "gas", "clustered")

#: number density of the ``gas`` and ``clustered`` kinds (particles per unit volume)
GAS_DENSITY = 0.1
#: mean number of particles per cluster of the ``clustered`` kind
PER_CLUSTER = 1000
#: fraction of uniformly distributed background particles in ``clustered``
BACKGROUND = 0.1


# --------------------------------------------------------------------------- numpy
def _lattice(n, rng, rng_type):
    side = max(1, int(math.ceil(round(n ** (1.0 / 3.0), 9))))
    while side ** 3 < n:  # guard against floating point cube-root errors
        side += 1
    i = np.arange(n, dtype=np.int64)
    pos = np.empty((n, 3), dtype=np.float32)
    x = i % side
    pos[:, 0] = x
    i //= side
    y = i % side
    pos[:, 1] = y
    i //= side  # z
    pos[:, 2] = i
    x += y
    x += i
    types = (x & 1).astype(np.int32)
    types += 1
    return pos, types


def _cube_side(n):
    return (n / GAS_DENSITY) ** (1.0 / 3.0)


def _gas(n, rng, rng_type):
    side = _cube_side(n)
    pos = rng.random((n, 3), dtype=np.float32)
    pos *= np.float32(side)
    types = np.where(rng_type.random(n, dtype=np.float32) < 0.2, 2, 1).astype(np.int32)
    return pos, types


def _clustered(n, rng, rng_type):
    side = _cube_side(n)
    n_bg = int(round(n * BACKGROUND)) if n > 1 else 0
    n_cl = n - n_bg
    k = max(1, n // PER_CLUSTER)
    centres = rng.random((k, 3)) * side
    weights = rng.lognormal(0.0, 0.75, k)
    counts = rng.multinomial(n_cl, weights / weights.sum())
    # Gaussian width for a central density rho0: counts / ((2 pi)^1.5 sigma^3) = rho0
    rho0 = rng.lognormal(0.0, 0.5, k)
    sigma = np.cbrt(np.maximum(counts, 1) / ((2.0 * math.pi) ** 1.5 * rho0))
    sigma = np.maximum(sigma, 0.5).astype(np.float32)

    pos = np.empty((n, 3), dtype=np.float32)
    types = np.empty(n, dtype=np.int32)
    member = np.repeat(np.arange(k, dtype=np.int32), counts)
    cl = pos[:n_cl]
    rng.standard_normal((n_cl, 3), dtype=np.float32, out=cl)
    cl *= sigma[member][:, None]
    cl += centres.astype(np.float32)[member]
    types[:n_cl] = member % 4 + 2
    del member
    if n_bg:
        bg = pos[n_cl:]
        bg[...] = rng.random((n_bg, 3), dtype=np.float32)
        bg *= np.float32(side)
        types[n_cl:] = 1
    return pos, types


def make_arrays(kind, count, seed=0, radius=0.5):
    """Return a dict of numpy arrays: points (N,3) float32, radius, type, speed."""
    if kind not in KINDS:
        raise ValueError("kind must be one of %s, not %r" % (", ".join(KINDS), kind))
    count = int(count)
    if count < 1:
        raise ValueError("count must be >= 1")
    # independent random streams per kind and per quantity
    seeds = np.random.SeedSequence([int(seed), KINDS.index(kind)]).spawn(4)
    rng_pos, rng_type, rng_radius, rng_speed = (np.random.default_rng(s) for s in seeds)
    make_kind = {"lattice": _lattice, "gas": _gas, "clustered": _clustered}[kind]
    pos, types = make_kind(count, rng_pos, rng_type)
    r = rng_radius.random(count, dtype=np.float32)
    r *= np.float32(0.4 * radius)
    r += np.float32(0.6 * radius)
    speed = np.sqrt(rng_speed.chisquare(3, count)).astype(np.float32)
    return {"points": pos, "radius": r, "type": types, "speed": speed}


# --------------------------------------------------------------------------- VTK
# All VTK arrays own their memory (numpy data is copied in). Zero-copy
# numpy_to_vtk(deep=0) arrays are not safe here: vtkCellArray.SetData() may keep
# only a shallow copy of the wrapper array, which drops the numpy reference and
# leaves VTK pointing at freed memory (segfaults at 10^7 points).
def _to_vtk(values, name=None):
    arr = numpy_support.numpy_to_vtk(np.ascontiguousarray(values), deep=1)
    if name:
        arr.SetName(name)
    return arr


def _iota(count, array_type):
    """VTK-owned integer array 0..count-1, filled through a numpy view."""
    arr = array_type()
    arr.SetNumberOfValues(count)
    view = numpy_support.vtk_to_numpy(arr)
    view[:] = np.arange(count, dtype=view.dtype)
    return arr


def vertex_cells(n):
    """vtkCellArray with one vertex cell per point, built from numpy (no Python loop)."""
    array_type = vtkTypeInt32Array if n + 1 < 2 ** 31 else vtkTypeInt64Array
    cells = vtkCellArray()
    # SetData returns a bool in VTK 9.2 and 9.6 but nothing in ParaView 5.13's VTK 9.3 snapshot:
    # the cell count tells in every version.
    ok = cells.SetData(_iota(n + 1, array_type), _iota(n, array_type))
    if ok is False or cells.GetNumberOfCells() != n:
        raise RuntimeError("vtkCellArray.SetData failed")
    return cells


def to_polydata(arrays):
    """Convert a make_arrays() dict to vtkPolyData (empties the dict to free memory)."""
    pd = vtkPolyData()
    points = vtkPoints()
    points.SetData(_to_vtk(arrays.pop("points").astype(np.float32, copy=False)))
    pd.SetPoints(points)
    pd.SetVerts(vertex_cells(points.GetNumberOfPoints()))
    pdata = pd.GetPointData()
    for name in ("radius", "type", "speed"):
        pdata.AddArray(_to_vtk(arrays.pop(name), name))
    pdata.SetActiveScalars("radius")
    return pd


def make(kind, count, seed=0, radius=0.5):
    """Build a ``kind`` particle set with ``count`` points as a vtkPolyData."""
    return to_polydata(make_arrays(kind, count, seed, radius))


def write(pd, path, fmt="binary"):
    """Write ``pd`` uncompressed with vtkXMLPolyDataWriter.

    fmt: "binary" (inline base64; readable by every VTK) or "appended" (raw
    appended binary; fastest, but see the module docstring about Debian 12).
    """
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    w = vtkXMLPolyDataWriter()
    w.SetFileName(path)
    w.SetInputData(pd)
    w.SetCompressorTypeToNone()
    w.SetHeaderTypeToUInt64()
    if fmt == "appended":
        w.SetDataModeToAppended()
        w.EncodeAppendedDataOff()
    elif fmt == "binary":
        w.SetDataModeToBinary()
    else:
        raise ValueError("fmt must be 'binary' or 'appended'")
    if not w.Write():
        raise RuntimeError("writing %s failed" % path)


# --------------------------------------------------------------------------- CLI
def main(argv=None):
    ap = argparse.ArgumentParser(description="Generate synthetic particle data (.vtp) for "
                                             "ParticleRendering benchmarks.")
    ap.add_argument("--kind", required=True, choices=KINDS)
    ap.add_argument("--count", required=True, type=float,
                    help="number of particles (1e6 style accepted)")
    ap.add_argument("--out", required=True, help="output .vtp file")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--radius", type=float, default=0.5,
                    help="maximum particle radius R; radii are uniform in [0.6R, R]")
    ap.add_argument("--format", choices=("binary", "appended"), default="binary",
                    help="binary = inline base64 (default, readable everywhere); appended = "
                         "raw appended (fast, unreadable by Debian 12's ParaView 5.11)")
    args = ap.parse_args(argv)

    count = int(round(args.count))
    t0 = time.perf_counter()
    pd = make(args.kind, count, args.seed, args.radius)
    t1 = time.perf_counter()
    out_dir = os.path.dirname(os.path.abspath(args.out))
    os.makedirs(out_dir, exist_ok=True)
    write(pd, args.out, args.format)
    t2 = time.perf_counter()
    b = pd.GetBounds()
    print("%s: %s %d particles, bounds (%.3g..%.3g, %.3g..%.3g, %.3g..%.3g), "
          "generate %.2f s, write %.2f s, %.1f MB"
          % (args.out, args.kind, pd.GetNumberOfPoints(), *b, t1 - t0, t2 - t1,
             os.path.getsize(args.out) / 1e6))
    return 0


if __name__ == "__main__":
    sys.exit(main())
