"""Ambient occlusion in ParaView: the Particle Render View's one "Particle Ambient Occlusion"
choice puts vtkDensityVolumeAOPass (Grottel et al. 2012) or vtkVoxelConeAOPass (Staib et al.
2015) into the view's pass chain, never both. The LAMMPS FCC block (32000 atoms, radii from 'radius', coloured by type) with AO on is
compared with a baseline; the image must be darker than without AO (never brighter), the chain
must hold one pass with AO on and none with it off. Each setting must reach the pass: per-sphere
retrieval changes the picture locally (it differs per sphere by design) but little on average,
GPU generation builds the volume on the GPU (information property) and gives the same image to
2/255, the paper's nearest-voxel splat changes the picture. Voxel cone tracing: one pass in the
chain, the block darker and nowhere brighter, another picture than the density volume's, one
volume build; the cone count re-traces (picture changes, no build), the resolution rebuilds;
back to the density volume gives its picture again.

Criteria of the baseline comparison: the GPU's own image on the same platform matches to
rounding; AO darkens the block by a mean of ~10/255, so a mean of 1/255 or 1 % of the pixels
over 4/255 rejects a picture whose occlusion is off, a tenth too weak or too strong.
Must-fail case: ao-off (the picture without AO against the AO baseline).

usage: pvpython TestParticleRenderViewAO.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR [--must-fail ao-off]
"""
import os
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

CRITERIA = pr.Criteria(tolerance=4.0, max_share=1e-2, max_mean=1.0)

args = pr.parse_arguments()
pr.load_plugin(args)
ok = True

atoms, from_file = pr.open_particles(args, "fcc_block.vtp")
view = pr.setup_view(simple.CreateView("ParticleRenderView"))
display = pr.show_particles(atoms, view)
pr.set_camera(view, position=(84.0, -52.0, 62.0), focal_point=(15.1, 15.1, 13.5))
suffix = "" if from_file else "_synthetic"
name = "TestParticleRenderViewAO" + suffix
if view.AmbientOcclusionStrength != 2.0:
    print("FAIL: the default Ambient Occlusion Strength is %s, not 2" % view.AmbientOcclusionStrength)
    ok = False
# the baseline is of the paper's strength (1); the default strength 2 is checked against it below
view.AmbientOcclusionStrength = 1.0



def info(property_name):
    view.SMProxy.UpdatePropertyInformation()
    return view.GetPropertyValue(property_name)


def rgb(image):
    return vtk_to_numpy(image.GetPointData().GetScalars()).astype(int)[:, :3]


def full_test():
    ok = True
    plain = pr.capture(view, os.path.join(args.temp_dir, "TestParticleRenderViewAO_off.png"))
    view.ParticleAmbientOcclusion = 'Density Volume'
    if info("NumberOfParticlePasses") != 1:
        print("FAIL: AO on, but %s passes in the chain" % info("NumberOfParticlePasses"))
        ok = False
    image_ok, occluded = pr.capture_and_compare(view, name, args, CRITERIA)
    ok = image_ok and ok

    a = rgb(plain).sum(axis=1)
    b = rgb(occluded).sum(axis=1)
    # strength 2 (the default): twice the darkening (less where 1 - 2 D would go below 0)
    view.AmbientOcclusionStrength = 2.0
    doubled = rgb(pr.capture(view, os.path.join(args.temp_dir,
                                                "TestParticleRenderViewAO_strength2.png"))).sum(axis=1)
    view.AmbientOcclusionStrength = 1.0
    shaded = a > 0
    ratio = float((a - doubled)[shaded].sum()) / max(1.0, float((a - b)[shaded].sum()))
    print("strength 2 darkens %.2f times as much as strength 1" % ratio)
    if not 1.7 <= ratio <= 2.05:
        print("FAIL: strength 2 should about double the darkening")
        ok = False
    darker = int((b < a - 3).sum())
    brighter = int((b > a + 3).sum())
    print("AO: %d pixels darker, %d brighter" % (darker, brighter))
    if darker < 5000 or brighter > 0:
        print("FAIL: AO should darken the block and brighten nothing")
        ok = False

    # each setting must reach the pass: per sphere (six fetches per sphere instead of one per
    # fragment) differs locally, on average a little; the nearest-voxel splat is a different volume
    # on this crystal (lattice aliasing); GPU generation is the same volume built elsewhere
    for prop, value, mean_range, max_range in (
            ("DensityVolumeRetrieval", "Per Sphere", (0.5, 8.0), (16, 255)),
            ("DensityVolumeGeneration", "GPU", (0.0, 0.5), (0, 2)),
            ("DensityVolumeSplat", "Nearest Voxel", (0.2, 8.0), (4, 255))):
        builds = info("NumberOfDensityVolumeBuilds")
        setattr(view, prop, value)
        other = pr.capture(view, os.path.join(args.temp_dir, "TestParticleRenderViewAO_%s.png" % prop))
        worst, mean = pr.difference(occluded, other)
        print("%s = %s: difference to the default: max %s/255, mean %s/255"
              % (prop, value, None if worst is None else round(worst),
                 None if mean is None else round(mean, 2)))
        if worst is None or not (max_range[0] <= worst <= max_range[1]) \
                or not (mean_range[0] <= mean <= mean_range[1]):
            print("FAIL: %s = %s: max %s outside %s or mean %s outside %s"
                  % (prop, value, worst, max_range, mean, mean_range))
            ok = False
        if prop == "DensityVolumeGeneration":
            if info("DensityVolumeLastGeneration") != 1 or info("NumberOfDensityVolumeBuilds") <= builds:
                print("FAIL: GPU generation did not reach the pass (last generation %s, builds %s -> %s)"
                      % (info("DensityVolumeLastGeneration"), builds,
                         info("NumberOfDensityVolumeBuilds")))
                ok = False
        view.DensityVolumeRetrieval = "Per Fragment"
        view.DensityVolumeGeneration = "CPU"
        view.DensityVolumeSplat = "Trilinear"

    # voxel cone tracing (Staib et al. 2015): the one AO choice replaces the density volume
    view.ParticleAmbientOcclusion = 'Voxel Cone Tracing'
    if info("NumberOfParticlePasses") != 1:
        print("FAIL: voxel cones on, but %s passes in the chain" % info("NumberOfParticlePasses"))
        ok = False
    cones = rgb(pr.capture(view, os.path.join(args.temp_dir, "TestParticleRenderViewAO_cones.png")))
    c = cones.sum(axis=1)
    darker = int((c < a - 3).sum())
    brighter = int((c > a + 3).sum())
    print("voxel cones: %d pixels darker, %d brighter, %d builds"
          % (darker, brighter, info("NumberOfVoxelConeBuilds")))
    if darker < 5000 or brighter > 0 or info("NumberOfVoxelConeBuilds") != 1:
        print("FAIL: voxel cones should darken the block, brighten nothing, build once")
        ok = False
    if pr.max_abs_difference(occluded, pr.capture(view, os.path.join(
            args.temp_dir, "TestParticleRenderViewAO_cones2.png"))) == 0:
        print("FAIL: voxel cones give the density volume's picture")
        ok = False
    # settings reach the pass: cone count re-traces only, resolution rebuilds
    for prop, value, rebuild in (("VoxelConeCount", 6, False), ("VoxelConeResolution", 32, True)):
        builds = info("NumberOfVoxelConeBuilds")
        setattr(view, prop, value)
        other = rgb(pr.capture(view, os.path.join(args.temp_dir,
                                                  "TestParticleRenderViewAO_%s.png" % prop)))
        changed = int((abs(other - cones).max(axis=1) > 2).sum())
        print("%s = %s: %d pixels changed, builds %d -> %d"
              % (prop, value, changed, builds, info("NumberOfVoxelConeBuilds")))
        if changed < 1000 or (info("NumberOfVoxelConeBuilds") > builds) != rebuild:
            print("FAIL: %s did not reach the pass as expected" % prop)
            ok = False
    view.VoxelConeCount = 3
    view.VoxelConeResolution = 0
    view.ParticleAmbientOcclusion = 'Density Volume'
    if info("NumberOfParticlePasses") != 1 or pr.max_abs_difference(
            occluded, pr.capture(view, os.path.join(args.temp_dir,
                                                    "TestParticleRenderViewAO_back.png"))) != 0:
        print("FAIL: back to the density volume: one pass and its picture expected")
        ok = False

    view.ParticleAmbientOcclusion = 'None'
    if info("NumberOfParticlePasses") != 0:
        print("FAIL: AO off, but %s passes in the chain" % info("NumberOfParticlePasses"))
        ok = False
    off_again = pr.capture(view, os.path.join(args.temp_dir, "TestParticleRenderViewAO_off2.png"))
    if pr.max_abs_difference(plain, off_again) != 0:
        print("FAIL: switching AO off does not restore the image")
        ok = False
    return ok


if pr.must_fail(args, "ao-off"):
    # the picture without AO, at the same camera, against the AO baseline: must be rejected
    pr.finish(pr.capture_and_compare(view, name, args, CRITERIA)[0])
else:
    pr.finish(full_test() and ok)
