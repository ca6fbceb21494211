"""vtkParticleGBufferExchange under MPI (pvbatch, any number of ranks >= 2): after
CompositeNearest every rank holds, per pixel, the nearest depth over all ranks and the payload of
the rank that drew it, exactly (compared with a reference computed here from every rank's
inputs): equal depths go to the lowest rank, NaN counts as the background (1), depths are clamped
to [0, 1], -0 equals 0, one float step apart decides, large and negative payloads arrive
unchanged. Mismatched arrays are refused with an error; one process changes nothing. The pixels
are also composited in one block of 100 000 (MPI may segment large all-reduces).

usage: mpiexec -np 3 pvbatch TestGBufferExchangeMPI.py
"""
import math
import os
import struct
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                "VTKPython"))
import particlerendering as pr  # noqa: E402
from prVTKTesting import Messages, check, finish  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkParallelCore import vtkDummyController, vtkMultiProcessController  # noqa: E402

COMPONENTS = 5


def f32(x):
    """x rounded to float32 (as a Python float)."""
    return struct.unpack("f", struct.pack("f", x))[0]


def below(x):
    """The float32 just below x > 0."""
    bits = struct.unpack("I", struct.pack("f", x))[0]
    return struct.unpack("f", struct.pack("I", bits - 1))[0]


def depths_of(rank, ranks):
    """Rank `rank`'s depth per special pixel."""
    last = ranks - 1
    return [
        0.5,                                               # all equal: rank 0
        0.9 - 0.1 * rank,                                  # nearest: the last rank
        float("nan") if rank == 1 else 1.0,                # NaN is background: depth 1, rank 0
        -0.0 if rank == 0 else (0.0 if rank == 1 else 0.25),  # -0 == 0: rank 0
        2.0 if rank == last else 1.0,                      # clamped to 1: rank 0
        below(0.3) if rank == 1 else 0.3,                  # one float step: rank 1
        -5.0 if rank == last else 0.1,                     # negative clamps to 0: the last rank
        float("inf") if rank == 0 else 0.75,               # +inf clamps to 1: rank 1 (0.75)
    ]


def payloads_of(rank, pixels):
    """Rank `rank`'s payload (float32, pixels x COMPONENTS): large, negative, tiny values."""
    scale = np.array([1e30, -3.25, 1.0 / 3.0, -1e-30, 7.0]) * (rank + 1)
    return (scale[None, :] + 0.5 * np.arange(pixels)[:, None]).astype(np.float32)


def depths_with(rank, ranks, extra):
    """The special pixels, then `extra` pixels of a rank-dependent pattern (float32)."""
    extras = ((np.arange(extra) * 7919 + rank * 104729) % 1000) / 1000.0
    return np.concatenate([np.array(depths_of(rank, ranks)), extras]).astype(np.float32)


def arrays(rank, ranks, extra=0):
    depth = numpy_to_vtk(depths_with(rank, ranks, extra), deep=1)
    payload = numpy_to_vtk(payloads_of(rank, depth.GetNumberOfTuples()), deep=1)
    return depth, payload


def expected(ranks, extra=0):
    """The reference: per pixel the clamped nearest depth (NaN as 1) and the lowest rank at it."""
    keys = np.stack([np.clip(np.nan_to_num(depths_with(r, ranks, extra), nan=1.0), 0.0, 1.0)
                     for r in range(ranks)])
    # -0 is 0 (numpy 2 keeps -0 through clip, numpy 1.24 did not)
    keys = np.where(keys == 0.0, np.float32(0.0), keys).astype(np.float32)
    owner = np.argmin(keys, axis=0)  # the first (lowest rank) at the minimum
    pixels = keys.shape[1]
    payloads = np.stack([payloads_of(r, pixels) for r in range(ranks)])
    return keys[owner, np.arange(pixels)], payloads[owner, np.arange(pixels)], owner


def check_composite(controller, extra, label):
    rank = controller.GetLocalProcessId()
    ranks = controller.GetNumberOfProcesses()
    depth, payload = arrays(rank, ranks, extra)
    exchange = pr.vtkParticleGBufferExchange()
    exchange.SetController(controller)
    check(exchange.IsDistributed(), "%s: distributed with %d ranks" % (label, ranks))
    check(exchange.CompositeNearest(depth, payload), "%s: composited" % label)
    want_depth, want_payload, owner = expected(ranks, extra)
    got_depth = vtk_to_numpy(depth)
    got_payload = vtk_to_numpy(payload)
    # exact: bit patterns compared (0 and -0 would compare equal as numbers)
    wrong = np.flatnonzero((got_depth.view(np.uint32) != want_depth.view(np.uint32)) |
                           np.any(got_payload.view(np.uint32) != want_payload.view(np.uint32),
                                  axis=1))
    for i in wrong[:5]:
        print("rank %d %s pixel %d: depth %r payload %r, expected %r %r (rank %d)"
              % (rank, label, i, got_depth[i], got_payload[i], want_depth[i], want_payload[i],
                 owner[i]))
    check(len(wrong) == 0, "%s: rank %d: %d of %d pixels wrong" % (label, rank, len(wrong),
                                                                     len(got_depth)))
    if extra == 0:
        print("rank %d: special pixels' owners %s" % (rank, list(owner)))
        check(list(owner[:3]) == [0, ranks - 1, 0] and owner[5] == 1 and owner[7] == 1,
              "the reference's owners are the intended ones")


def main():
    controller = vtkMultiProcessController.GetGlobalController()
    ranks = controller.GetNumberOfProcesses() if controller else 1
    if not check(ranks >= 2, "run with at least 2 MPI ranks (has %d)" % ranks):
        return finish()
    check_composite(controller, 0, "special pixels")
    check_composite(controller, 100000, "100 000 pixels")

    # mismatched arrays: refused with an error, nothing changed, no communication
    exchange = pr.vtkParticleGBufferExchange()
    exchange.SetController(controller)
    messages = Messages(exchange)
    depth, payload = arrays(0, ranks)
    payload.SetNumberOfTuples(3)
    check(not exchange.CompositeNearest(depth, payload), "mismatched arrays are refused")
    check(len(messages.errors) == 1, "one error for mismatched arrays: %s" % messages.errors)
    check(depth.GetValue(1) == f32(0.9), "mismatched arrays are left alone")

    # one process: nothing changes
    single = pr.vtkParticleGBufferExchange()
    single.SetController(vtkDummyController())
    depth, payload = arrays(1, ranks)
    check(not single.IsDistributed(), "one process is not distributed")
    check(single.CompositeNearest(depth, payload) and math.isnan(depth.GetValue(2)) and
          payload.GetComponent(0, 0) == payloads_of(1, 1)[0, 0], "one process: unchanged")
    return finish()


# (pvbatch --symmetric: every rank runs this script; exiting with sys.exit(0) skips MPI's
# finalisation, which mpiexec takes for an abort)
if main() != 0:
    raise SystemExit("FAILED")
