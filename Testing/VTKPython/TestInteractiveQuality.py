"""Interactive and still quality (vtkParticleFrameBudget) of every technique with a cheaper
interactive level, in plain VTK through the render window's DesiredUpdateRate:

- translucency (vtkTransparentSphereMapper, AUTOMATIC overlap on gas that penetrates): the
  sorted spheres at half resolution, then at full resolution with early termination, while
  moving, the exact overlap lists still (three levels);
- PointAO: half resolution while moving, full still;
- density-volume AO: per-sphere retrieval while moving, per fragment still; voxel-cone AO: one
  cone per sphere, the cones per sphere, per fragment still (three levels);
- metaballs (vicinity): the particles' iso-spheres while moving, the exact surface still.

Scene: prVTKTesting.gas_and_slab (10^5 particles: an FCC slab between layers of random gas whose
spheres penetrate each other), 480 x 360. For each technique:
- a still frame (VTK's still rate, 0.0001/s) is exact: the exact level is drawn and timed;
- an interactive frame whose budget nothing fits (10^6 frames/s) draws the cheap level the first
  time (to measure it), then the faster of the two measured levels;
- the cheap level's picture (Quality INTERACTIVE) differs from the still one, within the error
  stated for it here (measured at 1024 x 768 on the bundled scenes: Benchmarks/results/quality.csv);
- the budget is honoured in direction: an interactive frame long enough for the measured exact
  time (StillFrameTime raised, 10^-6 frames/s) draws the exact level, the same picture as still;
- the still frame after the interactive ones equals the first still frame, bit for bit;
- Quality EXACT draws exact in a short frame.
"""
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import check, finish, gas_and_slab, grab_image, offscreen_window, particles_from
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
from vtkmodules.vtkRenderingOpenGL2 import vtkCameraPass, vtkRenderStepsPass
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)

STILL_RATE = 0.0001  # VTK's StillUpdateRate
SHORT_RATE = 1.0e6  # a 1 us frame: no level but the cheapest fits
B = pr.vtkParticleFrameBudget

# stated interactive errors in 1/255 (Documentation/Performance.md): the mean difference over
# the pixels and the 99th percentile of the pixels' largest channel difference. The AO levels
# change fine detail everywhere (a pixel-count criterion does not fit them); measured here
# (mean, 99th percentile): translucent (half resolution: the gas's spheres are 2-6 pixels here)
# 5.3, 56; PointAO 3.1, 62; density 1.9, 35; voxel cones
# (one cone per sphere) 7.6, 85; metaballs 10.5, 207 (the iso-spheres show the slab's merged surface as its spheres:
# a preview, whose mean is what is bounded).
STATED = {
    "translucent": (7.0, 80),
    "pointao": (5.0, 80),
    "density": (3.0, 50),
    "voxelcone": (9.0, 110),
    "metaballs": (14.0, 255),
}


def build_scene(technique):
    xyz, radius, kinds = gas_and_slab()
    data = particles_from(xyz, radius=radius, type=kinds.astype(np.float32))
    if technique == "translucent":
        mapper = pr.vtkTransparentSphereMapper()
    elif technique == "metaballs":
        mapper = pr.vtkMetaballMapper()
    else:
        mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(data)
    mapper.SetRadiusArrayName("radius")
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("type")
    mapper.SetScalarRange(1, 2)
    actor = vtkActor()
    actor.SetMapper(mapper)
    if technique == "translucent":
        actor.GetProperty().SetOpacity(0.6)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.1, 0.1, 0.12)
    window = offscreen_window(renderer, (480, 360))
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(32, 32, 8)
    camera.SetPosition(95, -40, 70)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    camera_pass = vtkCameraPass()
    owner = mapper
    if technique in ("translucent", "metaballs"):
        camera_pass.SetDelegatePass(vtkRenderStepsPass())
    else:
        aopass = {"pointao": pr.vtkPointAOPass, "density": pr.vtkDensityVolumeAOPass,
                  "voxelcone": pr.vtkVoxelConeAOPass}[technique]()
        aopass.SetDelegatePass(vtkRenderStepsPass())
        camera_pass.SetDelegatePass(aopass)
        owner = aopass
    renderer.SetPass(camera_pass)
    return window, mapper, owner


def frame(window, rate):
    window.SetDesiredUpdateRate(rate)
    return grab_image(window)[:, :3]


for technique in ("translucent", "pointao", "density", "voxelcone", "metaballs"):
    window, mapper, owner = build_scene(technique)
    budget = owner.GetFrameBudget()
    still = frame(window, STILL_RATE)
    levels = budget.GetLastNumberOfLevels()
    expected_levels = 3 if technique in ("voxelcone", "translucent") else 2
    check(levels == expected_levels, "%s: %d levels (%d)" % (technique, expected_levels, levels))
    check(budget.GetLastLevel() == levels - 1, "%s: a still frame is exact" % technique)
    if technique == "translucent":
        check(mapper.GetExactOverlapInUse(), "translucent: the still frame uses the exact lists")

    # ADAPTIVE in a frame nothing fits: the cheap level, not measured yet, is tried ...
    window.SetDesiredUpdateRate(SHORT_RATE)
    window.Render()
    check(budget.GetLastLevel() == 0 and budget.GetLastFrameInteractive(),
          "%s: the first 1 us interactive frame draws the cheap level" % technique)
    if technique == "translucent":
        check(not mapper.GetExactOverlapInUse(), "translucent: moving, the sorted spheres")
    # ... then the fastest measured level (times set here, so that the check does not depend on
    # this machine's)
    budget.ForgetTimes()
    budget.ReportTime(0, 1.0e4)  # (a real time read at the frame's start can only lower it)
    budget.ReportTime(levels - 1, 1.0e-9)
    window.Render()
    check(budget.GetLastLevel() == levels - 1,
          "%s: nothing fits and the exact level is the faster one: exact" % technique)
    budget.ForgetTimes()
    budget.ReportTime(0, 1.0e-9)
    for level in range(1, levels):
        budget.ReportTime(level, 1.0e4)
    window.Render()
    check(budget.GetLastLevel() == 0, "%s: nothing fits, the cheap level is faster: cheap"
          % technique)

    budget.SetQuality(B.INTERACTIVE)
    moving = frame(window, STILL_RATE)
    check(budget.GetLastLevel() == 0, "%s: INTERACTIVE draws the cheap level in a still frame"
          % technique)
    budget.SetQuality(B.ADAPTIVE)
    d = np.abs(moving - still).max(axis=1)
    mean = float(np.abs(moving - still).mean())
    p99 = float(np.percentile(d, 99))
    stated = STATED[technique]
    print("%s: interactive vs still: mean %.2f/255, 99th percentile %.0f/255, max %d/255; %s"
          % (technique, mean, p99, d.max(),
             budget.GetLastChoiceText(owner.GetQualityLevelNames())))
    check(d.max() > 0, "%s: the interactive picture is the cheaper one (it differs)" % technique)
    check(mean <= stated[0] and p99 <= stated[1],
          "%s: interactive error within the stated mean %.1f/255, 99th percentile %d/255"
          % (technique, stated[0], stated[1]))

    budget.ForgetTimes()
    frame(window, STILL_RATE)  # measures the exact level
    exact_time = budget.GetMeasuredTime(levels - 1)
    budget.SetStillFrameTime(1.0e9)
    long_frame = frame(window, 1.0e-6)  # 10^6 s: interactive, and the exact time fits
    check(exact_time > 0.0 and budget.GetLastFrameInteractive() and
          budget.GetLastLevel() == levels - 1,
          "%s: an interactive frame that fits the measured exact time (%g s) draws exact"
          % (technique, exact_time))
    check(np.array_equal(long_frame, still), "%s: ... the still picture" % technique)
    budget.SetStillFrameTime(1.0)

    window.SetDesiredUpdateRate(SHORT_RATE)
    window.Render()
    again = frame(window, STILL_RATE)
    check(np.array_equal(again, still),
          "%s: the still frame after interactive ones equals the first, bit for bit" % technique)
    budget.SetQuality(B.EXACT)
    check(np.array_equal(frame(window, SHORT_RATE), still),
          "%s: EXACT draws the still picture in a short frame" % technique)

sys.exit(finish())
