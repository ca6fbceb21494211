"""Time series through the Particles representation: the LAMMPS droplet series
lj_droplets_t0.vtp ... lj_droplets_t4.vtp (t = 0, 2.5, ..., 10 tau; t4 is byte-identical to
lj_droplets.vtp) read as one time-dependent source. At every animation time the view must show
exactly what the single file of that time step shows (compared to 1/255), and t0 and t4 must
differ: the representation re-executes on time changes and the mapper re-uploads. Then the
last frame is compared with a baseline.

usage: pvpython TestParticlesTimeSeries.py --plugin ParticleRendering.so --data DIR
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

files = [os.path.join(args.data, "lj_droplets_t%d.vtp" % i) for i in range(5)]
missing = [f for f in files if not os.path.exists(f)]
if missing:
    print("FAIL: missing data files %s" % missing)
    pr.finish(False)

CAMERA = dict(position=(125.0, 10.0, 85.0), focal_point=(40.0, 39.5, 39.0))
series = simple.XMLPolyDataReader(FileName=files)
view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=(400, 300))
pr.show_particles(series, view)
pr.set_camera(view, **CAMERA)
scene = simple.GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
times = list(series.TimestepValues)
if len(times) != 5:
    print("FAIL: expected 5 time steps, got %r" % times)
    pr.finish(False)

frames = []
for i, t in enumerate(times):
    scene.AnimationTime = t
    frames.append(pr.capture(view, os.path.join(args.temp_dir,
                                                 "TestParticlesTimeSeries-t%d.png" % i)))

# each frame against its single file, rendered in a second view with the same settings
reference_view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=(400, 300))
for i in (0, 2, 4):
    single = simple.XMLPolyDataReader(FileName=[files[i]])
    shown = pr.show_particles(single, reference_view)
    pr.set_camera(reference_view, **CAMERA)
    reference = pr.capture(reference_view, os.path.join(args.temp_dir,
                                                        "TestParticlesTimeSeries-file%d.png" % i))
    diff = pr.max_abs_difference(frames[i], reference)
    print("t = %g: series frame vs single file: max abs difference %s/255" % (times[i], diff))
    if diff is None or diff > 1:
        print("FAIL: the frame at t = %g does not show time step %d" % (times[i], i))
        ok = False
    simple.Hide(single, reference_view)
    simple.Delete(single)

motion = pr.max_abs_difference(frames[0], frames[4])
print("t0 vs t4: max abs difference %s/255" % motion)
if not motion or motion < 20:
    print("FAIL: the view does not change with time")
    ok = False

scene.AnimationTime = times[-1]
ok = pr.capture_and_compare(view, "TestParticlesTimeSeries", args, CRITERIA)[0] and ok
pr.finish(ok)
