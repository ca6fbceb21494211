"""Distributed rendering in client-server mode: pvpython connects to a pvserver with 2 MPI ranks
and gets the picture of the built-in (single-process) connection.

The test first renders the LAMMPS film (Testing/Data/lj_film.vtp, split into interleaved pieces,
see prMPITesting) as translucent Particles (opacity 0.7) with density-volume AO in a Particle
Render View over the built-in connection (also opaque with PointAO, with S-NDF, and translucent
with FXAA on; CASES). It then starts `mpiexec -np 2 pvserver` on a free
port, connects, loads the plugin on both sides, forces rendering on the server (remote render
threshold 0, so both ranks render and IceT composites) and renders the same scene: the image
must equal the built-in one within 2/255 (then again with the client rendering: the server
gathers the particles to it, ghost copies included, which it must leave out) (one step more on at most 0.01 % of the pixels, the
ranks' 8-bit images; without the partition on the server translucent particles split over two
ranks differ by up to ~90/255, without the summed volume the AO by up to ~95/255, see
TestParticlesMPI). The server must have 2 ranks. (The representation's ParticleDistribution
information comes from the client's object in client-server mode, so the per-rank counts are
checked by TestParticlesMPI under pvbatch.)

usage: pvpython TestParticlesPvserver.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR --mpiexec PATH --pvserver PATH [--np N]
"""
import argparse
import os
import socket
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from prMPITesting import (apply_case, compare_with_single_process,  # noqa: E402
                          make_film_pieces, show_film)
from paraview import simple  # noqa: E402

# translucent with the summed AO volume, opaque with PointAO and converged S-NDF shading (the
# ranks' G-buffers are composited inside IceT's draw: every rank must draw), and translucent
# with ParaView's FXAA on (+fxaa: FXAA filters the composited picture, so the ranks' translucent
# particles must be composited as one process composites them, issue 61)
CASES = ("ao-translucent", "pointao", "sndf", "translucent-squared+fxaa")


def parse_extra():
    parser = argparse.ArgumentParser()
    parser.add_argument("--mpiexec", required=True)
    parser.add_argument("--pvserver", required=True)
    parser.add_argument("--np", type=int, default=2)
    extra, _ = parser.parse_known_args()
    return extra


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


def start_server(extra, port):
    """mpiexec -np N pvserver on `port`; returns the process once it accepts connections."""
    import select  # here: the ProgrammableSource replaced the global `select` (numpy's)
    # this pvpython is an MPI singleton: its Open MPI / PMIx variables would make mpiexec fail
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PRTE_"))}
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    command = [extra.mpiexec, "-np", str(extra.np), "--oversubscribe", "-x", "DISPLAY",
               "-x", "PYTHONPATH", extra.pvserver, "--server-port=%d" % port,
               "--force-offscreen-rendering"]
    print("starting: %s" % " ".join(command))
    server = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env)
    deadline = time.time() + 120.0
    output = b""
    while time.time() < deadline:
        ready, _, _ = select.select([server.stdout], [], [], 1.0)
        if ready:
            chunk = os.read(server.stdout.fileno(), 4096)
            if not chunk:
                break
            output += chunk
            if b"Accepting connection" in output:
                return server
        if server.poll() is not None:
            break
    print("FAIL: the server did not start:\n%s" % output.decode(errors="replace"))
    server.kill()
    return None


def render_case(args, case, name):
    source = make_film_pieces(args)
    view, display = show_film(source, pr)
    base, _, fxaa = case.partition("+")
    apply_case(view, display, base)
    if fxaa:
        # (UseFXAA is linked to the settings: both)
        simple.GetSettingsProxy("RenderViewSettings").UseFXAA = 1
        view.UseFXAA = 1
    path = os.path.join(args.temp_dir, "TestParticlesPvserver_%s_%s.png" % (case, name))
    image = pr.capture(view, path)
    simple.GetSettingsProxy("RenderViewSettings").UseFXAA = 0
    simple.Delete(display)
    simple.Delete(source)
    simple.Delete(view)
    return image


def main():
    args = pr.parse_arguments()
    extra = parse_extra()
    ok = True

    # the built-in connection's picture
    pr.load_plugin(args)
    reference = {}
    for case in CASES:
        render_case(args, case, "builtin")
        reference[case] = os.path.join(args.temp_dir, "TestParticlesPvserver_%s_builtin.png" % case)
    simple.Disconnect()

    port = free_port()
    server = start_server(extra, port)
    if server is None:
        return False
    try:
        simple.Connect("localhost", port)
        simple.LoadPlugin(args.plugin, remote=True)
        simple.LoadPlugin(args.plugin, remote=False)
        # every server rank renders its part, IceT composites (no gathering to the client)
        simple.GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 0.0
        partitions = simple.servermanager.ActiveConnection.GetNumberOfDataPartitions()
        if partitions != extra.np:
            print("FAIL: the server has %d ranks, not %d" % (partitions, extra.np))
            ok = False
        for case in CASES:
            ok = compare_with_single_process(
                pr, render_case(args, case, "pvserver"), reference[case], args.temp_dir,
                "TestParticlesPvserver_%s_server" % case)[0] and ok
        # the client renders: the server gathers the partitioned particles to it, ghost copies
        # included, which the client must leave out
        simple.GetSettingsProxy("RenderViewSettings").RemoteRenderThreshold = 1e6
        for case in CASES:
            ok = compare_with_single_process(
                pr, render_case(args, case, "client"), reference[case], args.temp_dir,
                "TestParticlesPvserver_%s_client" % case)[0] and ok
        simple.Disconnect()
    finally:
        server.terminate()
        try:
            server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            server.kill()
    return ok


pr.finish(main())
