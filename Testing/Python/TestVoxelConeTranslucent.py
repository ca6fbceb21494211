"""Voxel-cone ambient occlusion on translucent particles in ParaView (Staib et al. 2015, the
paper's own case): the LAMMPS droplets (Testing/Data/lj_droplets.vtp, coloured by type, Opacity
0.4) in a Particle Render View with Particle Ambient Occlusion = Voxel Cone Tracing, compared with
a baseline.
- The occlusion darkens the translucent droplets (mean over the particles > 3/255), brightens no
  pixel by more than 1/255 and leaves the background exactly as it is.
- It is transparency-aware: the same droplets at Opacity 0.9 are darkened more (relative to their
  own picture without AO) than at 0.4, since the voxels' extinction follows the glyphs' opacity.
- Ambient illumination (alpha_A = 0.5, Eq. 7) brightens the picture against alpha_A = 0 without
  a new voxelisation; changing the opacity does voxelise again (the voxels hold it).

Criteria of the baseline comparison: the GPU's own image on the same platform matches to
rounding; the occlusion darkens the particles by several /255 on average, so a mean of 1/255 or
1 % of the pixels over 4/255 rejects the picture without it (must-fail case ao-off).

usage: pvpython TestVoxelConeTranslucent.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR [--must-fail ao-off]
"""
import os
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.Criteria(tolerance=4.0, max_share=1e-2, max_mean=1.0)

args = pr.parse_arguments()
pr.load_plugin(args)
atoms, from_file = pr.open_particles(args, "lj_droplets.vtp")
view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=(400, 300))
display = pr.show_particles(atoms, view)
display.Opacity = 0.4
pr.set_camera(view, position=(40.0, -60.0, 40.0), focal_point=(40.0, 40.0, 40.0))
name = "TestVoxelConeTranslucent" + ("" if from_file else "_synthetic")


def info(property_name):
    view.SMProxy.UpdatePropertyInformation()
    return view.GetPropertyValue(property_name)


def grab(label):
    image = pr.capture(view, os.path.join(args.temp_dir, "%s_%s.png" % (name, label)))
    width, height, _ = image.GetDimensions()
    values = vtk_to_numpy(image.GetPointData().GetScalars())
    return values.reshape(height, width, -1)[:, :, :3].astype(float)


def full_test():
    ok = True
    plain = grab("off")
    background = abs(plain - plain[0, 0]).max(axis=-1) == 0
    particles = ~background
    view.ParticleAmbientOcclusion = "Voxel Cone Tracing"
    image_ok, _ = pr.capture_and_compare(view, name, args, CRITERIA)
    ok = image_ok and ok
    occluded = grab("cones")
    darker = (plain - occluded)[particles].mean()
    brighter = (occluded - plain).max()
    background_change = abs(occluded - plain)[background].max()
    print("voxel cones on translucent droplets: darker by %.2f/255 on average, brighter by at "
          "most %d/255, background changed by %d/255, %d builds"
          % (darker, brighter, background_change, info("NumberOfVoxelConeBuilds")))
    if not darker > 3.0 or brighter > 1.0 or background_change != 0:
        print("FAIL: the occlusion should darken the droplets, brighten nothing and leave the "
              "background")
        ok = False

    # ambient illumination: traced, not voxelised again
    builds = info("NumberOfVoxelConeBuilds")
    view.VoxelConeAmbientIllumination = 0.5
    lit = grab("illumination")
    view.VoxelConeAmbientIllumination = 0.0
    gain = (lit - occluded)[particles].mean()
    print("alpha_A 0.5: brighter by %.2f/255 on average, builds %d -> %d"
          % (gain, builds, info("NumberOfVoxelConeBuilds")))
    if not gain > 1.0 or info("NumberOfVoxelConeBuilds") != builds:
        print("FAIL: ambient illumination should brighten the droplets without a new volume")
        ok = False

    # transparency-aware: more opaque particles occlude (and are occluded) more
    display.Opacity = 0.9
    builds = info("NumberOfVoxelConeBuilds")
    dense = grab("opacity09_cones")
    rebuilt = info("NumberOfVoxelConeBuilds") > builds
    view.ParticleAmbientOcclusion = "None"
    dense_plain = grab("opacity09_off")
    view.ParticleAmbientOcclusion = "Voxel Cone Tracing"
    display.Opacity = 0.4
    lit_plain = plain[particles].sum(axis=-1)
    relative_thin = 1.0 - occluded[particles].sum(axis=-1).sum() / max(1.0, lit_plain.sum())
    relative_dense = 1.0 - dense[particles].sum(axis=-1).sum() / max(
        1.0, dense_plain[particles].sum(axis=-1).sum())
    print("relative darkening: %.3f at opacity 0.4, %.3f at 0.9; the opacity change rebuilt the "
          "volume: %s" % (relative_thin, relative_dense, rebuilt))
    if not relative_dense > 1.2 * relative_thin or not rebuilt:
        print("FAIL: the occlusion should follow the particles' opacity (and rebuild for it)")
        ok = False
    return ok


if pr.must_fail(args, "ao-off"):
    # the translucent picture without AO against the AO baseline: must be rejected
    pr.finish(pr.capture_and_compare(view, name, args, CRITERIA)[0])
else:
    pr.finish(full_test())
