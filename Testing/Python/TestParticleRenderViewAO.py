"""Density-volume ambient occlusion (Grottel et al. 2012) in ParaView: the Particle Render View's
"Density Volume Ambient Occlusion" property puts vtkDensityVolumeAOPass into the view's pass
chain. The LAMMPS FCC block (32000 atoms, radii from 'radius', coloured by type) with AO on is
compared with a baseline; the image must be darker than without AO (never brighter), the chain
must hold one pass with AO on and none with it off, per-sphere retrieval must be close on average
(it differs per sphere by design) and GPU generation must give the same image to 2/255.

usage: pvpython TestParticleRenderViewAO.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

args = pr.parse_arguments()
pr.load_plugin(args)
ok = True

atoms, from_file = pr.open_particles(args, "fcc_block.vtp")
view = pr.setup_view(simple.CreateView("ParticleRenderView"))
display = pr.show_particles(atoms, view)
pr.set_camera(view, position=(84.0, -52.0, 62.0), focal_point=(15.1, 15.1, 13.5))


def passes():
    view.SMProxy.UpdatePropertyInformation()
    return view.GetPropertyValue("NumberOfParticlePasses")


plain = pr.capture(view, os.path.join(args.temp_dir, "TestParticleRenderViewAO_off.png"))
view.DensityVolumeAmbientOcclusion = 1
if passes() != 1:
    print("FAIL: AO on, but %s passes in the chain" % passes())
    ok = False
suffix = "" if from_file else "_synthetic"
image_ok, occluded = pr.capture_and_compare(view, "TestParticleRenderViewAO" + suffix, args)
ok = image_ok and ok

try:
    from vtkmodules.util.numpy_support import vtk_to_numpy
    a = vtk_to_numpy(plain.GetPointData().GetScalars()).astype(int)[:, :3].sum(axis=1)
    b = vtk_to_numpy(occluded.GetPointData().GetScalars()).astype(int)[:, :3].sum(axis=1)
    darker = int((b < a - 3).sum())
    brighter = int((b > a + 3).sum())
    print("AO: %d pixels darker, %d brighter" % (darker, brighter))
    if darker < 5000 or brighter > 0:
        print("FAIL: AO should darken the block and brighten nothing")
        ok = False
except ImportError:
    print("NOTE: numpy missing, darkening not checked")

def mean_abs_difference(image_a, image_b):
    try:
        from vtkmodules.util.numpy_support import vtk_to_numpy
        a = vtk_to_numpy(image_a.GetPointData().GetScalars()).astype(float)
        b = vtk_to_numpy(image_b.GetPointData().GetScalars()).astype(float)
        return float(abs(a - b).mean())
    except ImportError:
        return 0.0


# per sphere: six fetches per sphere instead of one per fragment -- locally different (each
# sphere gets one blend of its six values), on average close; GPU generation: the same volume;
# the paper's nearest-voxel splat: a different volume on this crystal (lattice aliasing), so the
# image must change, but on average little
for name, value, mean_limit, max_limit, min_max in (
        ("DensityVolumeRetrieval", "Per Sphere", 8.0, 255, 0),
        ("DensityVolumeGeneration", "GPU", 0.5, 2, 0),
        ("DensityVolumeSplat", "Nearest Voxel", 8.0, 255, 4)):
    setattr(view, name, value)
    other = pr.capture(view, os.path.join(args.temp_dir, "TestParticleRenderViewAO_%s.png" % name))
    difference = pr.max_abs_difference(occluded, other)
    mean = mean_abs_difference(occluded, other)
    print("%s = %s: difference to the default: max %s/255, mean %.2f/255"
          % (name, value, difference, mean))
    if difference is None or difference > max_limit or mean > mean_limit:
        print("FAIL: %s = %s changes the image too much" % (name, value))
        ok = False
    if difference is not None and difference < min_max:
        print("FAIL: %s = %s does not reach the pass" % (name, value))
        ok = False
    view.DensityVolumeRetrieval = "Per Fragment"
    view.DensityVolumeGeneration = "CPU"
    view.DensityVolumeSplat = "Trilinear"

view.DensityVolumeAmbientOcclusion = 0
if passes() != 0:
    print("FAIL: AO off, but %s passes in the chain" % passes())
    ok = False
off_again = pr.capture(view, os.path.join(args.temp_dir, "TestParticleRenderViewAO_off2.png"))
if pr.max_abs_difference(plain, off_again) != 0:
    print("FAIL: switching AO off does not restore the image")
    ok = False
pr.finish(ok)
