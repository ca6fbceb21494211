"""Translucent particles with ambient occlusion, in two views at once (the missing test of the
restructuring issue): the LAMMPS droplets with Opacity 0.4 in a Particle Render View and in a
plain Render View, with ParaView's own screen-space AO ("Use Ambient Occlusion", vtkSSAOPass) and
with our density-volume AO.
- ParaView's SSAO occludes opaque geometry only (VTK's vtkSSAOPass draws translucent geometry
  after its AO): with translucent particles its picture equals the one without it (max 0), in
  both views; with opaque particles it darkens them (mean on the particles > 2/255), so it runs.
- Density-volume AO darkens the translucent particles (mean on the particles > 2/255, never
  brighter by more than 1/255) and leaves the background exactly as it is.
- No message at all, and none at teardown: a second pvpython shows translucent particles in two
  views and exits; releasing one view's GPU objects while the other view's OpenGL context is
  current must raise no OpenGL error, neither in VTK's checks nor under MESA_DEBUG (it did: the
  depth sort's compute programs and buffers were deleted in the wrong context).

usage: pvpython TestTranslucentParticlesWithAO.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR
"""
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

args = pr.parse_arguments()
ok = True
report = []


def fail(message):
    global ok
    ok = False
    report.append("FAIL: " + message)


def grab(view, name):
    image = pr.capture(view, os.path.join(args.temp_dir, "TestTranslucentParticlesWithAO_%s.png"
                                          % name))
    width, height, _ = image.GetDimensions()
    values = vtk_to_numpy(image.GetPointData().GetScalars())
    return values.reshape(height, width, -1)[:, :, :3].astype(float)


with pr.captured_messages() as messages:  # (reported after the block)
    pr.load_plugin(args)
    atoms, _ = pr.open_particles(args, "lj_droplets.vtp")
    views = {}
    for kind in ("ParticleRenderView", "RenderView"):
        view = pr.setup_view(simple.CreateView(kind), size=(400, 300))
        display = pr.show_particles(atoms, view)
        display.Opacity = 0.4
        pr.set_camera(view, position=(40.0, -60.0, 40.0), focal_point=(40.0, 40.0, 40.0))
        views[kind] = (view, display)

    for kind, (view, display) in views.items():
        plain = grab(view, kind + "_translucent")
        background = (abs(plain - plain[0, 0]).max(axis=-1) == 0)
        particles = ~background
        if particles.mean() < 0.05:
            fail("%s: the particles cover only %.3f of the view" % (kind, particles.mean()))
            continue
        view.UseAmbientOcclusion = 1
        ssao = grab(view, kind + "_translucent_ssao")
        view.UseAmbientOcclusion = 0
        change = abs(ssao - plain).max()
        report.append("%s: SSAO on translucent particles changes at most %d/255" % (kind, change))
        if change != 0:
            fail("%s: ParaView's SSAO changed the translucent particles (max %d/255)"
                 % (kind, change))
        display.Opacity = 1.0
        opaque = grab(view, kind + "_opaque")
        view.UseAmbientOcclusion = 1
        opaque_ssao = grab(view, kind + "_opaque_ssao")
        view.UseAmbientOcclusion = 0
        display.Opacity = 0.4
        darkening = (opaque - opaque_ssao)[particles].mean()
        report.append("%s: SSAO darkens opaque particles by %.2f/255 on average" % (kind, darkening))
        if not darkening > 2.0:
            fail("%s: ParaView's SSAO does not run (opaque particles darkened by %.2f/255)"
                 % (kind, darkening))
        if kind == "ParticleRenderView":
            view.ParticleAmbientOcclusion = 'Density Volume'
            dao = grab(view, kind + "_translucent_density_ao")
            view.ParticleAmbientOcclusion = 'None'
            darker = (plain - dao)[particles].mean()
            brighter = (dao - plain).max()
            background_change = abs(dao - plain)[background].max()
            report.append("%s: density AO darkens translucent particles by %.2f/255 on average "
                          "(brightens at most %d/255, background changes %d/255)"
                          % (kind, darker, brighter, background_change))
            if not darker > 2.0 or brighter > 1.0 or background_change != 0:
                fail("%s: density AO on translucent particles: darker %.2f, brighter %d, "
                     "background %d" % (kind, darker, brighter, background_change))


# Teardown: a separate pvpython shows translucent particles in two views and exits, as a user's
# script does; ParaView then releases one view's props while the other view's context is
# current. Nothing may be reported, neither by VTK's OpenGL error checks nor by Mesa
# (MESA_DEBUG=1 reports every OpenGL usage error, e.g. deleting a name of another context).
TEARDOWN = r"""
import sys
from paraview import simple
simple.LoadPlugin(sys.argv[1], remote=False)
source = simple.Sphere(ThetaResolution=40, PhiResolution=40)
for i in range(2):
    view = simple.CreateView("RenderView")
    view.ViewSize = [200, 150]
    display = simple.Show(source, view)
    display.Representation = "Particles"
    display.Opacity = 0.4
    simple.Render(view)
print("rendered")
"""
script = os.path.join(args.temp_dir, "TestTranslucentParticlesWithAO_teardown.py")
with open(script, "w") as out:
    out.write(TEARDOWN)
environment = dict(os.environ, MESA_DEBUG="1")
for key in list(environment):
    if key.startswith(("OMPI_", "PMIX_")):
        del environment[key]  # (a pvpython started from a pvpython must not join its MPI world)
pvpython = shutil.which("pvpython") or "/usr/bin/pvpython"
run = subprocess.run([pvpython, "--force-offscreen-rendering", script, args.plugin],
                     stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=environment,
                     timeout=240)
output = run.stdout.decode(errors="replace")
problems = [line for line in output.splitlines()
            if "ERR|" in line or re.search(r"Mesa: (User )?error", line) or "OpenGL errors" in line]
report.append("teardown of two views with translucent particles: exit status %d, %d problem "
              "line(s)" % (run.returncode, len(problems)))
if run.returncode != 0 or "rendered" not in output or problems:
    fail("teardown of two views with translucent particles:\n" + "\n".join(problems or
                                                                           [output[-2000:]]))

text = messages.GetOutput().strip()
print("\n".join(report))
if text:
    print("FAIL: messages were logged:\n" + text)
    ok = False
pr.finish(ok)
