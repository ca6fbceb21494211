"""The first minute with a LAMMPS run in ParaView: Debian's LAMMPS writes a dump series
(Testing/Data/Generators/in.dump_formats, files dump.0 ... dump.200, atoms evaporating), and the
test opens it as a user would -- OpenDataFile on the series, Show, play every step:
- OpenDataFile picks the LAMMPS Dump Reader, and Show gives the Particles representation;
- the time values are the LAMMPS timesteps 0, 50, ..., 200, and each step has the atom count
  LAMMPS logged;
- the radii come from the reader's "radius" array (Use Radius Array: Automatic), with the per-type
  radii set on the reader (type 2 smaller);
- no warning is logged;
- baseline image of the last step, coloured by type.
Criteria of the baseline comparison: the GPU's own image on the same platform (tolerance 2/255,
0.1 % of the pixels, mean 0.5/255); the LAMMPS run is serial with fixed seeds, so the dump is the
same every time on this platform.

usage: pvpython TestLAMMPSDumpParaView.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR --generator DIR
"""
import argparse
import glob
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.SAME_PLATFORM  # tolerance 2/255, 0.1 % of the pixels, mean 0.5/255

args = pr.parse_arguments()
extra = argparse.ArgumentParser()
extra.add_argument("--generator", required=True)
generator = os.path.abspath(extra.parse_known_args()[0].generator)
ok = True

# LAMMPS writes the dumps
work = os.path.join(args.temp_dir, "TestLAMMPSDumpParaView")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
lmp = shutil.which("lmp")
if not lmp:
    print("FAIL: LAMMPS (lmp) is not installed")
    pr.finish(False)
# (without the MPI environment of this pvpython process, which the serial lmp would join)
environment = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "PMI_"))}
subprocess.run([lmp, "-in", os.path.join(generator, "in.dump_formats"), "-log", "log.lammps",
                "-screen", "none"], cwd=work, check=True, env=environment)
logged = []
lines = open(os.path.join(work, "log.lammps")).read().splitlines()
start = lines.index(next(l for l in lines if l.split()[:2] == ["Step", "Atoms"])) + 1
for line in lines[start:]:
    if line.startswith("Loop time"):
        break
    logged.append((int(line.split()[0]), int(line.split()[1])))
series = sorted((f for f in glob.glob(os.path.join(work, "dump.*")) if f.split(".")[-1].isdigit()),
                key=lambda f: int(f.split(".")[-1]))
print("series:", [os.path.basename(f) for f in series], "logged:", logged)

# VTK's messages are captured while ParaView works (pvpython also routes Python's own output
# through the output window, so the test's report is printed after the window is restored)
report = []


def fail(text):
    global ok
    report.append("FAIL: " + text)
    ok = False


with pr.captured_messages() as messages:
    try:
        pr.load_plugin(args)
        reader = simple.OpenDataFile(series)
        if reader is None or reader.GetXMLName() != "LAMMPSDumpReader":
            raise RuntimeError("OpenDataFile picked %s" % (reader.GetXMLName() if reader else None))
        reader.TypeRadii = [2, 0.35]
        times = list(reader.TimestepValues)
        if times != [float(t) for t, _ in logged]:
            fail("time values %s, LAMMPS timesteps %s" % (times, [t for t, _ in logged]))

        view = pr.setup_view(simple.CreateView("RenderView"), size=(500, 400))
        display = simple.Show(reader, view)
        if display.Representation != "Particles":
            fail("the dump is shown as %r, not as Particles" % display.Representation)
        if display.UseRadiusArray != "Automatic":
            fail("Use Radius Array is %r" % display.UseRadiusArray)
        simple.ColorBy(display, ("POINTS", "type"))
        display.LookupTable = pr.type_lookup_table()
        box = simple.Show(simple.OutputPort(reader, 1), view)
        box.DiffuseColor = [0.9, 0.9, 0.9]
        box.AmbientColor = [0.9, 0.9, 0.9]

        scene = simple.GetAnimationScene()
        scene.UpdateAnimationUsingDataTimeSteps()
        pr.set_camera(view, position=(22.0, -14.0, 16.0), focal_point=(4.2, 4.2, 4.2))
        for t, n in logged:
            scene.AnimationTime = float(t)
            simple.Render(view)
            count = reader.GetDataInformation().GetNumberOfPoints()
            report.append("timestep %d: %d atoms (LAMMPS logged %d)" % (t, count, n))
            if count != n:
                fail("timestep %d: %d atoms, LAMMPS logged %d" % (t, count, n))
        image_path = os.path.join(args.temp_dir, "TestLAMMPSDumpParaView_capture.png")
        pr.capture(view, image_path)
    except Exception as error:  # reported below, after the output window is restored
        fail("%s: %s" % (type(error).__name__, error))
print("\n".join(report))
text = messages.GetOutput().strip()
if text:
    print("FAIL: messages were logged:\n" + text)
    ok = False
if ok:
    ok = pr.capture_and_compare(view, "TestLAMMPSDumpParaView", args, CRITERIA)[0]
pr.finish(ok)
