#!/usr/bin/env python3
"""One driver for every benchmark and study in Benchmarks/ (stdlib only).

usage: python3 Benchmarks/run.py --list
       python3 Benchmarks/run.py SUITE [--quick] [--out DIR] [--build DIR] [--dry-run]
                                 [-- extra arguments for the suite]

SUITE is a name from --list. The driver finds the build (--build, else $BUILD_DIR, else
<repo>/build) and checks that it has what the suite needs, sets PYTHONPATH (the build's
lib/python3/dist-packages for `import particlerendering`, plus Testing/VTKPython and Benchmarks),
runs every command that needs a display under Scripts/with_xvfb.sh when $DISPLAY is unset, and
writes <out>/<suite>.command.txt: the exact command lines, the date, `git rev-parse HEAD`, the
build and the ParaView/VTK versions -- the command that made the results.

--out    where the CSV/PNG go. Default Benchmarks/results (the committed results); with --quick
         and no --out, <build>/Testing/Temporary/bench-<suite>, so a quick run never overwrites
         the committed results.
--quick  the smallest settings that still exercise the suite (as the CTest smoke tests do).
-- ...   extra arguments: appended to the suite's measuring command (argparse scripts: a repeated
         option overrides, e.g. `-- --frames 3`); for the scripts with positional arguments
         (sndf*, smip*, large-counts) they replace the positional arguments; for the run_*.sh
         suites NAME=VALUE words set environment variables (FRAMES=5, LARGE=1, ...).

The run_*.sh scripts and every Python script keep working on their own with their old arguments.
"""
import argparse
import datetime
import os
import re
import shlex
import subprocess
import sys
import time

BENCH = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(BENCH)
DATA = os.path.join(TOP, "Testing", "Data")
PY = "/usr/bin/python3"  # Debian's python: VTK (python3-paraview) and matplotlib
XVFB = os.path.join(TOP, "Scripts", "with_xvfb.sh")
PLUGIN = os.path.join("lib", "paraview-plugins", "ParticleRendering", "ParticleRendering.so")
PYPKG = os.path.join("lib", "python3", "dist-packages")
# what a suite needs from the build, by interpreter
NEEDS = {"python": [os.path.join(PYPKG, "particlerendering")],
         "pvpython": [PLUGIN], "pvbatch": [PLUGIN],
         "cxx": [os.path.join("bin", "prBenchmark"), os.path.join("bin", "prTransparentBenchmark")],
         "bash": []}


class Cmd:
    """One command: argv, extra environment, whether it renders (needs a display), where its
    standard output also goes (a suite whose result is its printout)."""

    def __init__(self, argv, env=None, display=True, tee=None, main=False):
        self.argv, self.env, self.display, self.tee, self.main = argv, env or {}, display, tee, main


class Suite:
    def __init__(self, name, interpreter, script, measures, peer, outputs, plot, full, quick,
                 quick_text, positional=False, needs=(), time_text="", inputs=()):
        # needs: what the build must have; inputs: what an earlier run must have left there
        # (checked when the suite runs, not by --dry-run or --check)
        self.inputs = inputs
        self.name, self.interpreter, self.script = name, interpreter, script
        self.measures, self.peer, self.outputs, self.plot = measures, peer, outputs, plot
        self.full, self.quick, self.quick_text = full, quick, quick_text
        self.positional, self.needs, self.time_text = positional, needs, time_text


def py(script, *args, display=True, main=True, tee=None):
    return Cmd([PY, os.path.join(BENCH, script)] + [str(a) for a in args], display=display,
               main=main, tee=tee)


OUT, BUILD = "{out}", "{build}"  # placeholders in a suite's arguments, filled in per run


def pyargs(script, *args):
    """A suite whose one command is a Python script: its arguments, OUT and BUILD filled in."""

    def commands(c):
        fill = {OUT: c.out, BUILD: c.build}
        return [py(script, *(fill.get(a, a) for a in args))]

    return commands


def plot(script, *args):
    return Cmd([PY, os.path.join(BENCH, script)] + [str(a) for a in args], display=False)


def bash(script, c, env=None):
    # the run_*.sh scripts start their own Xvfb (Scripts/with_xvfb.sh) where they render
    return Cmd(["bash", os.path.join(BENCH, script), c.build], env=dict(env or {},
               RESULTS_DIR=c.out), display=False, main=True)


# ---- the suites -------------------------------------------------------------------------------
def margins_commands(c):
    return [Cmd([PY, os.path.join(TOP, "Scripts", "image_test_margins.py"),
                 os.path.join(c.build, "Testing", "Temporary", "LastTest.log"), "--csv",
                 os.path.join(c.out, "image_test_margins.csv")], display=False, main=True)]


def sphere_full(c):
    return [bash("run_sphere_core.sh", c)]


def sphere_quick(c):
    csv = os.path.join(c.out, "sphere_core.csv")
    return [Cmd(["rm", "-f", csv], display=False),
            Cmd([os.path.join(c.build, "bin", "prBenchmark"), "--data",
                 os.path.join(DATA, "lj_droplets.vtp"), "--mapper", "pointgaussian", "--mapper",
                 "vtksphere", "--mapper", "particle-nocull", "--mapper", "particle", "--frames",
                 "2", "--size", "200x150", "--color-array", "type", "--label", "lj_droplets",
                 "--csv", csv], main=True),
            plot("plot_results.py", csv, os.path.join(c.out, "sphere_core.png"), "--title",
                 "Sphere core vs Point Gaussian and vtkOpenGLSphereMapper (quick, 200x150)")]


def transparent_full(c):
    return [bash("run_transparent.sh", c)]


def transparent_quick(c):
    exe = os.path.join(c.build, "bin", "prTransparentBenchmark")
    data = ["--data", os.path.join(DATA, "lj_droplets.vtp"), "--max-particles", "1000",
            "--size", "200x150", "--color-array", "type"]
    timing, errors, early = (os.path.join(c.out, "transparent_%s.csv" % n)
                             for n in ("timing", "errors", "early_termination"))
    return [Cmd(["rm", "-f", timing, errors, early], display=False),
            Cmd([exe] + data + ["--frames", "1", "--static-frames", "1", "--opacity", "0.5",
                                "--label", "gas", "--csv", timing], main=True),
            Cmd([exe] + data + ["--opacity", "0.5", "--label", "gas", "--errors", errors]),
            Cmd([exe] + data + ["--mapper", "transparent", "--mapper", "transparent-et",
                                "--frames", "1", "--static-frames", "1", "--opacity", "0.9",
                                "--label", "clustered", "--csv", early]),
            plot("plot_transparent.py", "--results", c.out)]


SUITES = [
    Suite("sphere-core", "cxx (bash run_sphere_core.sh)", "run_sphere_core.sh -> build/bin/prBenchmark",
          "frame time of vtkParticleSphereMapper (culling on/off) on gas, lattice, LAMMPS film, 1e4-1e6 (LARGE=1: 1e7)",
          "vtkPointGaussianMapper (ParaView's Point Gaussian, Sphere splat) and vtkOpenGLSphereMapper",
          ["sphere_core.csv", "sphere_core.png"], "plot_results.py", sphere_full, sphere_quick,
          "prBenchmark on Testing/Data/lj_droplets.vtp, 4 mappers, 2 frames, 200x150 (as BenchmarkSmoke.cmake)",
          needs=[os.path.join("bin", "prBenchmark")], time_text="~1.5 min"),
    Suite("transparent", "cxx (bash run_transparent.sh)", "run_transparent.sh -> build/bin/prTransparentBenchmark",
          "translucent spheres: frame and stage times, error against the reference, early termination",
          "vtkOpenGLSphereMapper and Point Gaussian composited by dual depth peeling (4 peels)",
          ["transparent_timing.csv", "transparent_errors.csv", "transparent_early_termination.csv",
           "transparent_fits.csv", "transparent_time.png", "transparent_stages.png",
           "transparent_early_termination.png"], "plot_transparent.py", transparent_full,
          transparent_quick,
          "prTransparentBenchmark on the first 1000 atoms of lj_droplets.vtp, 1 frame, 200x150: timing, errors, early termination (as BenchmarkSmoke.cmake)",
          needs=[os.path.join("bin", "prTransparentBenchmark")], time_text="~10 min"),
    Suite("overlap", "python", "overlap_benchmark.py",
          "exact overlap compositing (per-pixel lists) vs sorted spheres: error and frame time",
          "vtkTransparentSphereMapper's Sorted Spheres (the paper's depth-sorted glyphs)",
          ["overlap_compositing.csv", "overlap_compositing.png"], "(built in)",
          pyargs("overlap_benchmark.py", "--build", BUILD, "--out", OUT),
          pyargs("overlap_benchmark.py", "--build", BUILD, "--out", OUT, "--quick",
                 "--frames", "1"),
          "--quick --frames 1: the LJ film at opacity 0.5 and the 2k molecule only",
          time_text="~8 min"),
    Suite("ellipsoids", "python", "ellipsoid_benchmark.py",
          "frame time of oriented ellipsoids (rods 1:1:3, needles 1:1:10; 1e4-1e6) against the sphere core on the same particles",
          "ParaView's Tensor Glyph (vtkTensorGlyph of a sphere, resolution 8 and 16) and the sphere core at the volume radius",
          ["ellipsoids.csv", "ellipsoids.png"], "(built in)",
          pyargs("ellipsoid_benchmark.py", "--build", BUILD, "--out", OUT),
          pyargs("ellipsoid_benchmark.py", "--build", BUILD, "--out", OUT, "--quick"),
          "--quick: 1e3 particles, 3 frames, 320x240", time_text="~5 min"),
    Suite("ao", "python", "ao_benchmark.py",
          "cost of vtkDensityVolumeAOPass (paper Table 1): static and time series, CPU vs GPU build, 1e4-1e6",
          "plain spheres (vtkParticleSphereMapper without the pass)",
          ["ao_timing.csv", "ao_overhead.png"], "(built in)",
          pyargs("ao_benchmark.py", "--out", OUT, "--counts", "1e4,1e5,1e6",
                 "--frames", "9"),
          pyargs("ao_benchmark.py", "--out", OUT, "--counts", "1e3", "--frames", "1",
                 "--size", "160x90"),
          "--counts 1e3 --frames 1 --size 160x90 (the CTest AOBenchmarkSmoke)", time_text="~5 min"),
    Suite("ao-study", "python", "ao_study.py",
          "error of vtkDensityVolumeAOPass against ray-traced AO vs frame time; FCC Fig. 6 artefact",
          "vtkSSAOPass (ParaView's Use Ambient Occlusion)",
          ["ao_accuracy.csv", "ao_accuracy.png", "ao_fcc_volume.csv", "ao_fcc_artefact.png"],
          "(built in; summarise_ao.py prints the README tables)",
          lambda c: [py("ao_study.py", "--data", DATA, "--out", c.out, "--samples", "256",
                        "--frames", "9"),
                     plot("summarise_ao.py", "--results", c.out)],
          pyargs("ao_study.py", "--data", DATA, "--out", OUT, "--quick", "--samples",
                 "16", "--size", "96", "--frames", "1"),
          "--quick --samples 16 --size 96 --frames 1: FCC scene, 2 resolutions (the CTest AOStudySmoke)",
          time_text="~6 min"),
    Suite("pointao", "python", "pointao_benchmark.py",
          "cost of vtkPointAOPass: frame time over the plain core, per-stage GPU times, 1e4-1e6, two windows",
          "vtkSSAOPass and vtkDensityVolumeAOPass in the same run",
          ["pointao_timing.csv (appended)", "pointao_timing.png"], "(built in)",
          pyargs("pointao_benchmark.py", "--out", OUT, "--counts", "1e4,1e5,1e6",
                 "--sizes", "640x360,1280x720", "--frames", "9"),
          pyargs("pointao_benchmark.py", "--out", OUT, "--counts", "1e3", "--frames",
                 "1", "--sizes", "160x90"),
          "--counts 1e3 --frames 1 --sizes 160x90 (the CTest PointAOBenchmarkSmoke)",
          time_text="~5 min"),
    Suite("pointao-study", "python", "pointao_study.py",
          "error of vtkPointAOPass against ray-traced AO vs frame time over levels and directions",
          "vtkSSAOPass; vtkDensityVolumeAOPass and vtkVoxelConeAOPass on the same chart",
          ["pointao_accuracy.csv", "pointao_accuracy.png"],
          "(built in; compare_accuracy.py BEFORE AFTER OUT compares two runs -> pointao_fix_accuracy.csv)",
          pyargs("pointao_study.py", "--data", DATA, "--out", OUT, "--samples", "256",
                 "--frames", "9"),
          pyargs("pointao_study.py", "--data", DATA, "--out", OUT, "--quick",
                 "--samples", "16", "--size", "96", "--frames", "1"),
          "--quick --samples 16 --size 96 --frames 1 (the CTest PointAOStudySmoke)",
          time_text="~9 min"),
    Suite("voxel-cone", "python", "voxel_cone_benchmark.py",
          "transparency + voxel-cone AO (Staib et al. Tables 2/3): frame and stage times, droplets 1x/2^3x/4^3x",
          "the opaque core (vtkParticleSphereMapper) in the same window",
          ["voxel_cone_benchmark.csv", "voxel_cone_benchmark.png"], "(built in)",
          pyargs("voxel_cone_benchmark.py", "--data", DATA, "--out", OUT),
          pyargs("voxel_cone_benchmark.py", "--data", DATA, "--out", OUT, "--tiles",
                 "1", "--frames", "1", "--size", "160x120"),
          "--tiles 1 --frames 1 --size 160x120", time_text="~6 min"),
    Suite("voxel-cone-study", "python", "voxel_cone_study.py",
          "error of vtkVoxelConeAOPass (opaque) against ray-traced AO (near and far) vs frame time",
          "vtkDensityVolumeAOPass and vtkSSAOPass",
          ["voxel_cone_accuracy.csv", "voxel_cone_accuracy.png"], "(built in)",
          pyargs("voxel_cone_study.py", "--data", DATA, "--out", OUT),
          pyargs("voxel_cone_study.py", "--data", DATA, "--out", OUT, "--quick",
                 "--samples", "16", "--size", "96", "--frames", "1"),
          "--quick --samples 16 --size 96 --frames 1", time_text="~6 min"),
    Suite("voxel-cone-translucent", "python", "voxel_cone_translucent_study.py",
          "error of vtkVoxelConeAOPass on translucent particles against transparency-aware ray-traced AO",
          "vtkDensityVolumeAOPass and vtkSSAOPass",
          ["voxel_cone_translucent.csv", "voxel_cone_translucent.png"], "(built in)",
          pyargs("voxel_cone_translucent_study.py", "--data", DATA, "--out", OUT,
                 "--cache", "/tmp/vct_cache"),
          pyargs("voxel_cone_translucent_study.py", "--data", DATA, "--out", OUT,
                 "--quick", "--samples", "16", "--size", "96", "--frames", "1"),
          "--quick --samples 16 --size 96 --frames 1", time_text="~9 min"),
    Suite("metaball", "python", "metaball_benchmark.py",
          "vtkMetaballMapper: frame time vs the core, error against the exact surface, the grid peer",
          "vtkGaussianSplatter (Gaussian Resampling) + vtkFlyingEdges3D contour",
          ["metaball_frames.csv", "metaball_accuracy.csv", "metaball_peer.csv",
           "metaball_benchmark.png"], "(built in; --plot-only redraws from Benchmarks/results)",
          pyargs("metaball_benchmark.py", "--out", OUT),
          pyargs("metaball_benchmark.py", "--out", OUT, "--quick"),
          "--quick: 2 frames per mapper, the two coarsest grids of the peer", time_text="~10 min"),
    Suite("sndf", "python", "sndf_benchmark.py",
          "vtkSNDFRenderPass: refinement frame vs plain, re-light vs re-sampling, memory, pan",
          "the plain core (no pass) and re-sampling to the same quality",
          ["sndf_timings.csv (appended)", "sndf_pan.csv (appended)"], "-",
          pyargs("sndf_benchmark.py", "63", "1280", "720", "64"),
          pyargs("sndf_benchmark.py", "4", "160", "120", "4"),
          "CELLS 4, 160x120, 4 samples", positional=True, time_text="~2 min"),
    Suite("sndf-accuracy", "python", "sndf_accuracy_study.py",
          "S-NDF error against time and the bins knob (fcc crystal, 16 384 atoms)",
          "plain super-sampling at equal time",
          ["sndf_accuracy.csv", "sndf_accuracy.png"], "(built in)",
          pyargs("sndf_accuracy_study.py", "160", "120"),
          pyargs("sndf_accuracy_study.py", "40", "30"),
          "40x30 (the reference 32x: 1280x960)", positional=True),
    Suite("sndf-recolour", "python", "sndf_recolour.py",
          "S-NDF colour-map change re-shaded from the samples (types / speed, moments on / off)",
          "sampling again to the same sample count",
          ["sndf_recolour.csv (appended)", "sndf_recolour.png"], "(built in, from all rows)",
          lambda c: [py("sndf_recolour.py", "63", "1280", "720", "64", mode, keep)
                     for mode, keep in (("types", 1), ("speed", 1), ("speed", 0), ("types", 0))],
          pyargs("sndf_recolour.py", "4", "160", "120", "4", "types", "1"),
          "CELLS 4, 160x120, 4 samples, types, moments on", positional=True),
    Suite("smip", "python", "smip_benchmark.py",
          "S-MIP: zoom out by 2 from cached level 0, pan back, re-light (crystal 1e6, liquid 1.2e6)",
          "re-sampling level 1 to the same samples; a restart's frame",
          ["smip_timings.csv (appended)", "smip_timings.png"], "(built in, from all rows)",
          pyargs("smip_benchmark.py", "63", "8", "1280", "720", "64"),
          pyargs("smip_benchmark.py", "4", "1", "160", "120", "4"),
          "CELLS 4, REPEAT 1, 160x120, 4 samples", positional=True),
    Suite("smip-quality", "python", "smip_quality.py",
          "S-MIP zoom out against re-sampling at equal quality (equal-quality sample count N*)",
          "level 1 rendered directly at 16 ... 4xSAMPLES samples",
          ["smip_quality.csv"], "-",
          pyargs("smip_quality.py", "63", "8", "640", "360", "64", "16"),
          pyargs("smip_quality.py", "4", "1", "160", "90", "8", "2"),
          "CELLS 4, REPEAT 1, 160x90, 8 samples, 2x2 super-sampled reference", positional=True),
    Suite("smip-between-levels", "python", "smip_between_levels.py",
          "S-MIP ZoomBetweenLevels: zoom by 1.25 keeping the samples vs sampling anew",
          "sampling anew at the zoomed view (the default)",
          ["smip_between_levels.csv (appended)"], "-",
          pyargs("smip_between_levels.py", "63", "1280", "720", "64", "1.25"),
          pyargs("smip_between_levels.py", "4", "160", "120", "4", "1.25"),
          "CELLS 4, 160x120, 4 samples, factor 1.25", positional=True),
    Suite("reader", "python", "reader_benchmark.py",
          "speed and memory of vtkLAMMPSDumpReader on a 1e7-atom LAMMPS dump (written by lmp)",
          "numpy.loadtxt and ParaView's CSV reader (vtkDelimitedTextReader)",
          ["reader_speed.csv", "reader_speed.png"], "(built in)",
          lambda c: [py("reader_benchmark.py", "--out", c.out, "--atoms", "1e7", "--work",
                        "/tmp/reader_benchmark", display=False)],
          lambda c: [py("reader_benchmark.py", "--out", c.out, "--atoms", "1e4", "--repeat", "1",
                        "--work", os.path.join(c.out, "reader_work"), display=False)],
          "--atoms 1e4 --repeat 1, the dump in <out>/reader_work", time_text="~4 min"),
    Suite("mpi-scaling", "pvbatch (mpiexec; bash run_mpi_scaling.sh)",
          "run_mpi_scaling.sh -> mpi_scaling.py",
          "strong scaling of distributed rendering, 1/2/4 ranks, LAMMPS film 2x2 and 7x7",
          "one rank (the same pipeline without distribution)",
          ["mpi_scaling.csv (appended)", "mpi_scaling.png"], "plot_mpi_scaling.py",
          lambda c: [bash("run_mpi_scaling.sh", c)],
          lambda c: [Cmd(["mpiexec", "-np", "2", "--oversubscribe", "-x", "DISPLAY", "-x",
                          "PYTHONPATH", "pvbatch", os.path.join(BENCH, "mpi_scaling.py"),
                          "--plugin", os.path.join(c.build, PLUGIN), "--data", DATA, "--repeat",
                          "1", "--size", "200", "150", "--frames", "1", "--csv",
                          os.path.join(c.out, "mpi_scaling.csv")],
                         env={"OMPI_ALLOW_RUN_AS_ROOT": "1",
                              "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}, main=True),
                     plot("plot_mpi_scaling.py", os.path.join(c.out, "mpi_scaling.csv"),
                          os.path.join(c.out, "mpi_scaling.png"))],
          "2 ranks, the film once (19 360 atoms), 200x150, 1 frame", needs=[PLUGIN]),
    Suite("mpi-partition-accuracy", "pvbatch (mpiexec; bash run_mpi_partition_accuracy.sh)",
          "run_mpi_partition_accuracy.sh -> mpi_partition_accuracy.py",
          "np 2 and 3 against np 1 per technique on a gas-plus-slab and a deeply penetrating "
          "scene: pixels over 2/255 and 3/255",
          "one rank (the same pipeline without distribution)",
          ["mpi_partition_accuracy.csv", "mpi_partition_accuracy.png"],
          "mpi_partition_accuracy_compare.py",
          lambda c: [bash("run_mpi_partition_accuracy.sh", c)],
          lambda c: [bash("run_mpi_partition_accuracy.sh", c, env={
              "CASES": "gas:speed-squared:Exact Overlap,gas:metaballs:Automatic"})],
          "two gas cases (exact translucency, metaballs)", needs=[PLUGIN], time_text="~6 min"),
    Suite("mpi-reproducer", "pvbatch (mpiexec; bash run_mpi_partition_accuracy.sh)",
          "run_mpi_partition_accuracy.sh -> mpi_partition_accuracy.py (REPRODUCER_CASES)",
          "issue 61's reproducer (100 000 atoms, opacity from an array, 480x360), np 2 and 3 "
          "against np 1, with and without FXAA: pixels over 2/255 and 3/255",
          "one rank (the same pipeline without distribution)",
          ["mpi_partition_accuracy_reproducer.csv", "mpi_partition_accuracy_reproducer.png"],
          "mpi_partition_accuracy_compare.py",
          lambda c: [bash("run_mpi_partition_accuracy.sh", c, env={
              "CASES": "reproducer", "SIZE": "480 360",
              "RESULTS_NAME": "mpi_partition_accuracy_reproducer",
              "IMAGE_DIR": os.path.join(c.build, "mpi_partition_accuracy_reproducer")})],
          lambda c: [bash("run_mpi_partition_accuracy.sh", c, env={
              "CASES": "reproducer:speed-custom-squared-fxaa:Automatic", "SIZE": "480 360",
              "RESULTS_NAME": "mpi_partition_accuracy_reproducer",
              "IMAGE_DIR": os.path.join(c.build, "mpi_partition_accuracy_reproducer")})],
          "one case (squared density with FXAA)", needs=[PLUGIN], time_text="~4 min"),
    Suite("view-overhead", "pvpython", "view_overhead.py",
          "Particles representation in the Render View and the Particle Render View (AO off), alone and alternating",
          "Point Gaussian (Sphere) in a view of the same data",
          ["view_overhead.csv"], "-",
          lambda c: [Cmd(["pvpython", "--force-offscreen-rendering",
                          os.path.join(BENCH, "view_overhead.py"), "--plugin",
                          os.path.join(c.build, PLUGIN), "--count", "1000000", "--frames", "10",
                          "--csv", os.path.join(c.out, "view_overhead.csv")], main=True)],
          lambda c: [Cmd(["pvpython", "--force-offscreen-rendering",
                          os.path.join(BENCH, "view_overhead.py"), "--plugin",
                          os.path.join(c.build, PLUGIN), "--count", "1000", "--frames", "1",
                          "--size", "200x150", "--csv",
                          os.path.join(c.out, "view_overhead.csv")], main=True)],
          "--count 1000 --frames 1 --size 200x150", needs=[PLUGIN]),
    Suite("quality", "pvpython", "quality_benchmark.py",
          "interactive and still frames per technique (dense, mixed, sparse bundled scenes), ratios to the opaque core, the interactive picture's error against the still one",
          "the opaque core's still frame (Particles, no AO) of each scene in the same process",
          ["quality.csv", "quality.png"], "(built in)",
          lambda c: [Cmd(["pvpython", "--force-offscreen-rendering",
                          os.path.join(BENCH, "quality_benchmark.py"), "--plugin",
                          os.path.join(c.build, PLUGIN), "--data", DATA, "--frames", "9",
                          "--csv", os.path.join(c.out, "quality.csv"),
                          "--png", os.path.join(c.out, "quality.png")], main=True)],
          lambda c: [Cmd(["pvpython", "--force-offscreen-rendering",
                          os.path.join(BENCH, "quality_benchmark.py"), "--plugin",
                          os.path.join(c.build, PLUGIN), "--data", DATA, "--frames", "1",
                          "--size", "200x150", "--scenes", "sparse",
                          "--csv", os.path.join(c.out, "quality.csv")], main=True)],
          "the sparse scene, 200x150, 1 frame", needs=[PLUGIN], time_text="~6 min"),
    Suite("samples", "pvpython", "../Scripts/render_samples.py",
          "README command 1: every technique on the bundled LAMMPS data in the Particle Render View, frame time over the opaque core, error against the reference renderer; contact sheet",
          "the opaque core's still frame of the same scene in the same process",
          ["samples.csv", "samples.md", "samples.png"], "(built in)",
          lambda c: [Cmd(["pvpython", "--force-offscreen-rendering",
                          os.path.join(TOP, "Scripts", "render_samples.py"), "--plugin",
                          os.path.join(c.build, PLUGIN), "--data", DATA, "--out",
                          os.path.join(c.build, "Testing", "Temporary", "samples-results"),
                          "--results", c.out], main=True)],
          lambda c: [Cmd(["pvpython", "--force-offscreen-rendering",
                          os.path.join(TOP, "Scripts", "render_samples.py"), "--plugin",
                          os.path.join(c.build, PLUGIN), "--data", DATA, "--quick", "--out",
                          os.path.join(c.build, "Testing", "Temporary", "samples-quick"),
                          "--results", c.out], main=True)],
          "--quick: 240x180, 1 frame, 32 AO reference rays", needs=[PLUGIN],
          time_text="~40 s"),
    Suite("large-counts", "python", "large_counts.py",
          "first frame, frame time and peak memory of vtkParticleSphereMapper at 1e8 (and beyond)",
          "- (its own rows of the sphere-core table)",
          ["large_counts.txt (the printout and /usr/bin/time -v)"], "-",
          lambda c: [Cmd(["/usr/bin/time", "-v", PY, os.path.join(BENCH, "large_counts.py"),
                          "1e8"], main=True, tee=os.path.join(c.out, "large_counts.txt"))],
          lambda c: [Cmd(["/usr/bin/time", "-v", PY, os.path.join(BENCH, "large_counts.py"),
                          "1e4"], main=True, tee=os.path.join(c.out, "large_counts.txt"))],
          "N = 1e4", positional=True, time_text="1e8: ~1 min, 5.7 GB"),
    Suite("image-test-margins", "python (no rendering)", "../Scripts/image_test_margins.py",
          "margins of the image tests: each test's score against its must-fail pictures (from the CTest log)",
          "- (the must-fail pictures)",
          ["image_test_margins.csv (the _debian13/_unstable variants come from those platforms' CI)"],
          "-",
          margins_commands, margins_commands,
          "the same (it only reads <build>/Testing/Temporary/LastTest.log; run ctest first)",
          inputs=[os.path.join("Testing", "Temporary", "LastTest.log")]),
]
BY_NAME = {s.name: s for s in SUITES}
TOOLS = [("make_particles.py", "synthetic lattice / gas / clustered data sets (used by the suites)"),
         ("compare_accuracy.py", "two runs of an accuracy study side by side"),
         ("summarise_ao.py", "the Markdown tables of the AO study"),
         ("plot_results.py / plot_transparent.py / plot_mpi_scaling.py", "CSV -> PNG")]


def needs(suite):
    if suite.needs:
        return list(suite.needs)
    return NEEDS.get(suite.interpreter.split()[0], [])


def list_suites():
    width = max(len(s.name) for s in SUITES)
    print("Suites (python3 Benchmarks/run.py SUITE [--quick] [--out DIR] [--build DIR] [-- ARGS]):")
    for s in SUITES:
        print("  %-*s  %s; peer: %s -> %s" % (width, s.name, s.measures, s.peer,
                                               ", ".join(o.split(" (")[0] for o in s.outputs)))
    print("Tools (run directly): " + "; ".join("%s: %s" % t for t in TOOLS))
    print("Details and the latest tables: Benchmarks/README.md")


def find_build(arg):
    build = arg or os.environ.get("BUILD_DIR") or os.path.join(TOP, "build")
    return os.path.abspath(build)


def git_head():
    try:  # read-only
        return subprocess.run(["git", "-C", TOP, "rev-parse", "HEAD"], capture_output=True,
                              text=True, timeout=20).stdout.strip() or "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def versions(build):
    out = []
    cache = os.path.join(build, "CMakeCache.txt")
    if os.path.exists(cache):
        with open(cache, errors="replace") as f:
            for line in f:
                m = re.match(r"(ParaView_DIR|VTK_DIR|CMAKE_BUILD_TYPE):\w+=(.*)", line)
                if m:
                    out.append("%s=%s" % m.groups())
    try:
        r = subprocess.run(["dpkg-query", "-W", "-f", "${Package} ${Version}\\n", "paraview",
                            "python3-paraview"], capture_output=True, text=True, timeout=20)
        out += [line for line in r.stdout.splitlines() if line.strip()]
    except (OSError, subprocess.SubprocessError):
        pass
    try:
        r = subprocess.run([PY, "-c", "from vtkmodules.vtkCommonCore import vtkVersion; "
                            "print(vtkVersion.GetVTKVersion())"], capture_output=True, text=True,
                           timeout=60)
        if r.returncode == 0 and r.stdout.strip():
            out.append("VTK (%s) %s" % (PY, r.stdout.strip()))
    except (OSError, subprocess.SubprocessError):
        pass
    return out or ["unknown"]


def apply_extra(suite, commands, extra):
    """Extra arguments after `--`: NAME=VALUE words are environment variables for the run_*.sh
    suites; the rest are appended to the measuring command (or replace its positional
    arguments)."""
    env_words = [a for a in extra if re.match(r"^[A-Z_][A-Z0-9_]*=", a)]
    args = [a for a in extra if a not in env_words]
    for cmd in commands:
        if not cmd.main:
            continue
        for word in env_words:
            name, value = word.split("=", 1)
            cmd.env[name] = value
        if args:
            if suite.positional:
                script = next(i for i, a in enumerate(cmd.argv) if a.endswith(".py"))
                cmd.argv = cmd.argv[:script + 1] + args
            else:
                cmd.argv = cmd.argv + args
    return commands


def check_all(build_arg):
    """Every suite's commands (quick and full) made against the build, nothing run; 1 if any
    suite cannot make them."""
    failures = 0
    for suite in SUITES:
        for quick in (True, False):
            argv = [sys.executable, os.path.abspath(__file__), suite.name, "--dry-run"]
            argv += ["--quick"] if quick else []
            argv += ["--build", build_arg] if build_arg else []
            done = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  universal_newlines=True)
            ok = done.returncode == 0 and "# commands:" in done.stdout
            print("%-24s %-6s %s" % (suite.name, "quick" if quick else "full",
                                     "ok" if ok else "FAILED\n" + done.stdout))
            failures += not ok
    print("run.py --check: %d suites, %d failures" % (len(SUITES), failures))
    return 1 if failures else 0


def main():
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     usage="run.py SUITE [--quick] [--out DIR] [--build DIR] "
                                           "[--list] [--dry-run] [-- extra args]")
    parser.add_argument("suite", nargs="?")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out")
    parser.add_argument("--build")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--dry-run", action="store_true", help="print the commands, run nothing")
    parser.add_argument("--check", action="store_true",
                        help="make every suite's commands, quick and full, against the build "
                             "and run nothing (CTest's ParticleRendering.Benchmark.Driver)")
    args = parser.parse_args(argv)
    if args.check:
        return check_all(args.build)
    if args.list or not args.suite:
        list_suites()
        return 0 if args.list else 2
    if args.suite not in BY_NAME:
        sys.exit("run.py: unknown suite %r; python3 Benchmarks/run.py --list shows them"
                 % args.suite)
    suite = BY_NAME[args.suite]

    build = find_build(args.build)
    if not os.path.isdir(build):
        sys.exit("run.py: no build at %s: build the project first (bash Scripts/build.sh), or "
                 "pass --build DIR / set BUILD_DIR" % build)
    missing = [p for p in needs(suite) if not os.path.exists(os.path.join(build, p))]
    if missing:
        sys.exit("run.py: the build %s lacks %s (needed by %s): build it with Scripts/build.sh "
                 "(PARTICLERENDERING_WRAP_PYTHON on for the Python suites)"
                 % (build, ", ".join(missing), suite.name))
    absent = [p for p in suite.inputs if not os.path.exists(os.path.join(build, p))]
    if absent and not args.dry_run:
        sys.exit("run.py: %s reads %s from an earlier run, and the build %s has none: run ctest "
                 "there first (bash Scripts/run_tests.sh)" % (suite.name, ", ".join(absent), build))
    if args.out:
        out = os.path.abspath(args.out)
    elif args.quick:
        out = os.path.join(build, "Testing", "Temporary", "bench-" + suite.name)
    else:
        out = os.path.join(BENCH, "results")

    class Context:
        pass
    c = Context()
    c.build, c.out = build, out
    commands = apply_extra(suite, (suite.quick if args.quick else suite.full)(c), extra)

    env = dict(os.environ)
    pythonpath = [os.path.join(build, PYPKG)]
    if suite.interpreter.split()[0] == "python":  # plain VTK scripts: helpers of the tests too
        pythonpath += [os.path.join(TOP, "Testing", "VTKPython"), BENCH]
    env["PYTHONPATH"] = os.pathsep.join(pythonpath + ([env["PYTHONPATH"]]
                                                      if env.get("PYTHONPATH") else []))
    env["BUILD_DIR"] = build
    env["PR_BENCHMARK_RESULTS"] = out  # the scripts without --out write there
    xvfb = not os.environ.get("DISPLAY")
    lines = []
    for cmd in commands:
        argv_ = ([XVFB] if (xvfb and cmd.display) else []) + cmd.argv
        cmd.full = argv_
        assigned = ["PYTHONPATH=" + env["PYTHONPATH"], "BUILD_DIR=" + build,
                    "PR_BENCHMARK_RESULTS=" + out]
        assigned += ["%s=%s" % kv for kv in sorted(cmd.env.items())]
        text = "env " + " ".join(shlex.quote(a) for a in assigned) + " " + shlex.join(argv_)
        if cmd.tee:
            text += " 2>&1 | tee " + shlex.quote(cmd.tee)
        cmd.text = text
        lines.append(text)

    header = ["# Benchmarks/run.py %s%s" % (suite.name, " --quick" if args.quick else ""),
              "# invoked: " + shlex.join([sys.executable] + sys.argv),
              "# date: " + datetime.datetime.now().astimezone().isoformat(timespec="seconds"),
              "# git HEAD: " + git_head(),
              "# build: " + build,
              "# output: " + out,
              "# display: " + ("Scripts/with_xvfb.sh (DISPLAY unset)" if xvfb
                               else os.environ["DISPLAY"]),
              "# cwd: " + TOP]
    if args.dry_run:
        print("\n".join(header + ["# commands:"] + lines))
        return 0
    os.makedirs(out, exist_ok=True)
    header += ["# versions: " + "; ".join(versions(build))]
    record = os.path.join(out, suite.name + ".command.txt")

    def write(status):
        with open(record, "w") as f:
            f.write("\n".join(header + ["# commands (cd to the cwd above):"]) + "\n")
            for text, st in zip(lines, status + [None] * (len(lines) - len(status))):
                f.write(text + "\n")
                if st is not None:
                    f.write("#   -> exit %d, %.1f s\n" % st)
    write([])
    status = []
    for cmd in commands:
        print("run.py: " + cmd.text, flush=True)
        start = time.time()
        run_env = dict(env, **cmd.env)
        if cmd.tee:
            with open(cmd.tee, "w") as log:
                p = subprocess.Popen(cmd.full, cwd=TOP, env=run_env, stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, text=True)
                for line in p.stdout:
                    sys.stdout.write(line)
                    log.write(line)
                rc = p.wait()
        else:
            rc = subprocess.run(cmd.full, cwd=TOP, env=run_env).returncode
        status.append((rc, time.time() - start))
        write(status)
        if rc != 0:
            print("run.py: %s failed (exit %d); the commands are in %s"
                  % (suite.name, rc, record), file=sys.stderr)
            return rc
    produced = [o.split(" (")[0] for o in suite.outputs]
    present = [o for o in produced if os.path.exists(os.path.join(out, o))]
    print("run.py: %s done in %s: %s; commands in %s" % (
        suite.name, out, ", ".join(present) or "(no files listed for it)", record))
    return 0


if __name__ == "__main__":
    sys.exit(main())
