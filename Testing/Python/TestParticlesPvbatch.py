"""The plugin in pvbatch: the LAMMPS droplets (Testing/Data/lj_droplets.vtp, 11033 atoms) as
Particles with radii from 'radius', coloured by type, in a 400x300 Render View; baseline-image
test. Also checks that a Particle Render View can be created and has its pass chain installed.
Runs unchanged under MPI (mpiexec -n 2 pvbatch ...), each rank drawing its piece.

usage: pvbatch TestParticlesPvbatch.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.SAME_PLATFORM  # tolerance 2/255, 0.1 % of the pixels, mean 0.5/255

args = pr.parse_arguments()
pr.load_plugin(args)
ok = True

atoms, from_file = pr.open_particles(args, "lj_droplets.vtp")
view = pr.setup_view(simple.CreateView("RenderView"), size=(400, 300))
pr.show_particles(atoms, view)
pr.set_camera(view, position=(125.0, 10.0, 85.0), focal_point=(40.0, 39.5, 39.0))
name = "TestParticlesPvbatch" + ("" if from_file else "_synthetic")
ok = pr.capture_and_compare(view, name, args, CRITERIA)[0] and ok

particle_view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=(200, 150))
pr.show_particles(atoms, particle_view)
simple.Render(particle_view)
particle_view.SMProxy.UpdatePropertyInformation()
if particle_view.GetPropertyValue("ParticlePassChainInstalled") != 1:
    print("FAIL: the Particle Render View's pass chain is not installed in pvbatch")
    ok = False

pr.finish(ok)
