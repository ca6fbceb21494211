"""vtkVoxelConeAOPass (Staib et al. 2015, Sec. 3.2 and 5) and its voxel volume
vtkParticleAmbientVolume, from plain VTK Python. Checked:
- MeanDiscOpacity: the closed form for constant density against the quadrature (a hollow core of
  1e-7 radii), 0 and 1 at the ends, finite below 1 at 1 - 1e-7, NaN -> 0, monotonic, and the
  squared-distance model (most opaque ray off-centre) against a fine numerical disc average;
- the GPU voxelisation (compute shaders, the default) gives the CPU's pyramid to float rounding
  on 403 spheres of 1e-3 to 19 voxel edges, every level; the picture with either path differs
  by at most 1/255;
- voxelisation conserves the extinction: the sum over the voxels equals
  sum_i (4/3 pi rho_i^3) (3 / (4 rho_i)) <Theta_i> (rho in voxel edges) for radii from 1e-3 to 4
  voxel edges (spheres smaller than the sub-grid included), and every mip level keeps the total;
- rendering, per fragment and per sphere: a probe sphere above a slab of spheres is darker on its side facing the slab than
  on its far side; a translucent slab (Theta 0.3) occludes less than an opaque one; an isolated
  sphere is barely changed; with AmbientIllumination a red slab tints the probe's underside red;
  AO alone never brightens a pixel;
- builds: a camera move re-traces only (no new volume), a colour change and a volume setting
  rebuild;
- bad input: NaN/Inf positions give the finite particles' picture and no NaN; no particle props
  and no delegate give a warning and no crash.

usage: python3 TestVoxelConeAOPass.py
"""
import math
import sys

import numpy as np

import particlerendering as pr
from prVTKTesting import Messages, check, finish, grab_image, offscreen_window, particles_from
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass, vtkTextureObject
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

# --- mean disc opacity ----------------------------------------------------------------------
mean = pr.vtkParticleAmbientVolume.MeanDiscOpacity
for theta in (1e-6, 0.01, 0.3, 0.5, 0.9, 0.999):
    closed = mean(theta, 0, 0.0)
    quadrature = mean(theta, 0, 1e-7)
    check(abs(closed - quadrature) < 1e-9,
          "constant density, theta %g: closed form %.9f vs quadrature %.9f"
          % (theta, closed, quadrature))
check(mean(0.0, 0, 0.0) == 0.0 and mean(1.0, 0, 0.0) == 1.0, "theta 0 -> 0, 1 -> 1")
edge = mean(1.0 - 1e-7, 0, 0.0)
check(math.isfinite(edge) and 0.99 < edge < 1.0, "theta 1 - 1e-7: finite, below 1 (%r)" % edge)
check(mean(float("nan"), 0, 0.0) == 0.0, "NaN theta -> 0")
values = [mean(t, 1, 0.0) for t in np.linspace(0.0, 0.99, 34)]
check(all(b >= a for a, b in zip(values, values[1:])), "squared distance: monotonic in theta")
# squared distance: rho = d^2, path integral at impact u: 2 (u^2 h + h^3 / 3), maximum 2 sqrt(2)/3
theta = 0.6
u = (np.arange(200000) + 0.5) / 200000
h = np.sqrt(1.0 - u * u)
path = 2.0 * (u * u * h + h ** 3 / 3.0) / (2.0 * math.sqrt(2.0) / 3.0)
numeric = float(np.sum((1.0 - np.exp(math.log1p(-theta) * path)) * 2.0 * u) / len(u))
check(abs(mean(theta, 1, 0.0) - numeric) < 2e-4,
      "squared distance, theta 0.6: %.6f vs numeric %.6f" % (mean(theta, 1, 0.0), numeric))

# hollow constant density (f = 0.5): path 2 (h - h_core), maximum 2 sqrt(1 - f^2)
f = 0.5
theta = 0.9
core = np.sqrt(np.maximum(0.0, f * f - u * u))
path = 2.0 * (h - core) / (2.0 * math.sqrt(1.0 - f * f))
numeric = float(np.sum((1.0 - np.exp(math.log1p(-theta) * path)) * 2.0 * u) / len(u))
check(abs(mean(theta, 0, f) - numeric) < 2e-6,
      "hollow constant density, theta 0.9: %.7f vs numeric %.7f" % (mean(theta, 0, f), numeric))

# --- the texture's half floats: the same bits as numpy's float16 (round to nearest even) -------
half = pr.vtkParticleAmbientVolume.FloatToHalf
rng16 = np.random.default_rng(11)
samples = np.concatenate([
    np.exp(rng16.uniform(np.log(1e-9), np.log(65000.0), 20000)).astype(np.float32),
    np.array([0.0, 2.0 ** -24, 2.0 ** -25, 1.5 * 2.0 ** -25, 2.0 ** -14, 65504.0, 1.0, 0.5,
              1.0 + 2.0 ** -11, 1.0 + 3 * 2.0 ** -11], dtype=np.float32),
    # exact ties between neighbouring halves
    (np.arange(1, 2000, dtype=np.float32) * np.float32(2.0 ** -24) + np.float32(2.0 ** -25)),
    np.float32(1.0) + np.arange(0, 2000, dtype=np.float32) * np.float32(2.0 ** -11)])
ours = np.array([half(float(v)) for v in samples], dtype=np.uint16)
numpy_bits = samples.astype(np.float16).view(np.uint16)
mismatch = int((ours != numpy_bits).sum())
check(mismatch == 0, "FloatToHalf agrees with numpy's float16 on %d values (%d differ, e.g. %s)"
      % (len(samples), mismatch, samples[ours != numpy_bits][:3]))
check(half(float("nan")) == 0 and half(1e30) == 0x7bff and half(float("inf")) == 0x7bff,
      "FloatToHalf: NaN -> 0, beyond 65504 and Inf -> 65504")

# --- voxelisation conserves the extinction -------------------------------------------------
rng = np.random.default_rng(7)
n = 400
volume = pr.vtkParticleAmbientVolume()
volume.SetResolution(32)
centers = rng.random((n, 3)) * 10.0
radii = np.exp(rng.uniform(math.log(3e-4), math.log(1.3), n))  # voxel edge ~ 10/32
colors = rng.random((n, 3))
opacities = rng.uniform(0.0, 1.0, n)
check(volume.Voxelise(centers.ravel().tolist(), radii.tolist(), colors.ravel().tolist(),
                      opacities.tolist()), "Voxelise() succeeds")
edge = volume.GetVoxelSize()
rho = radii / edge
expected = float(np.sum(4.0 / 3.0 * math.pi * rho ** 3 * 0.75 / rho * opacities))
level0 = np.array(volume.GetLevel(0), dtype=np.float64).reshape(-1, 4)
total = float(level0[:, 3].sum())
check(abs(total - expected) <= 1e-5 * expected,
      "extinction sum %.7g vs expected %.7g (radii %.1e..%.1f voxel edges)"
      % (total, expected, rho.min(), rho.max()))
colour_expected = float(np.sum(4.0 / 3.0 * math.pi * rho ** 3 * 0.75 / rho * opacities
                               * colors[:, 0]))
check(abs(float(level0[:, 0].sum()) - colour_expected) <= 1e-5 * colour_expected,
      "emission sum (red) conserved")
for level in range(1, volume.GetNumberOfLevels()):
    data = np.array(volume.GetLevel(level), dtype=np.float64).reshape(-1, 4)
    scaled = float(data[:, 3].sum()) * 8 ** level
    check(abs(scaled - total) <= 1e-5 * total,
          "mip level %d keeps the total (%.7g vs %.7g)" % (level, scaled, total))
    if level > 6:
        break

# --- the GPU voxelisation (compute shaders) equals the CPU's to float rounding ---------------
# the same 400 spheres plus three larger than several voxels (one spans 40 % of the grid)
radii_big = radii.copy()
radii_big[:3] = [4.0, 6.0, 0.9]
arguments = (centers.ravel().tolist(), radii_big.tolist(), colors.ravel().tolist(),
             opacities.tolist())
cpu = pr.vtkParticleAmbientVolume()
cpu.SetResolution(32)
check(cpu.Voxelise(*arguments), "CPU Voxelise() of the mixed sizes succeeds")
gl_window = offscreen_window(vtkRenderer(), (16, 16))
gl_window.Render()
gl_window.MakeCurrent()
gpu_texture = vtkTextureObject()
gpu = pr.vtkParticleAmbientVolume()
gpu.SetResolution(32)
check(gpu.BuildTexture(gl_window, gpu_texture, *arguments) and gpu.GetLastBuildOnGPU(),
      "BuildTexture() voxelises on the GPU (GPUVoxelisation on by default)")
check(gpu.ReadLevels(gl_window), "the GPU's float pyramid reads back")
check(tuple(gpu.GetDimensions()) == tuple(cpu.GetDimensions()), "the same grid")
for level in range(cpu.GetNumberOfLevels()):
    a = np.array(cpu.GetLevel(level), dtype=np.float64)
    b = np.array(gpu.GetLevel(level), dtype=np.float64)
    worst = float(np.abs(a - b).max() / np.abs(a).max()) if a.size == b.size else float("inf")
    check(worst <= 2e-6, "level %d: GPU and CPU agree to %.2g of the largest value (float "
          "rounding; the order of the GPU's additions varies)" % (level, worst))
gpu.GPUVoxelisationOff()
check(gpu.BuildTexture(gl_window, gpu_texture, *arguments) and not gpu.GetLastBuildOnGPU(),
      "GPUVoxelisation off: the CPU path fills the texture")
gpu.ReleaseGraphicsResources(gl_window)


# --- rendering ------------------------------------------------------------------------------
def slab(count=14, spacing=1.0, radius=0.5):
    g = (np.arange(count) - (count - 1) / 2.0) * spacing
    x, y = np.meshgrid(g, g)
    return np.stack([x.ravel(), y.ravel(), np.zeros(x.size)], axis=1), radius


def scene(slab_opacity=1.0, probe=True, slab_present=True, slab_color=(0.8, 0.8, 0.8),
          ambient=0.0, pass_on=True, extra=None, gpu=True):
    renderer = vtkRenderer()
    renderer.SetBackground(0.0, 0.0, 0.0)
    actors = []
    if slab_present:
        xyz, r = slab()
        data = particles_from(xyz, radius=np.full(len(xyz), r))
        mapper = pr.vtkTransparentSphereMapper() if slab_opacity < 1.0 else \
            pr.vtkParticleSphereMapper()
        mapper.SetInputData(data)
        mapper.SetRadiusArrayName("radius")
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*slab_color)
        actor.GetProperty().SetOpacity(slab_opacity)
        renderer.AddActor(actor)
        actors.append(actor)
    if probe:
        xyz = np.array([[0.0, 0.0, 1.6]])
        if extra is not None:
            xyz = np.vstack([xyz, extra])
        data = particles_from(xyz, radius=np.full(len(xyz), 1.0))
        mapper = pr.vtkParticleSphereMapper()
        mapper.SetInputData(data)
        mapper.SetRadiusArrayName("radius")
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(0.9, 0.9, 0.9)
        renderer.AddActor(actor)
        actors.append(actor)
    aopass = None
    if pass_on:
        aopass = pr.vtkVoxelConeAOPass()
        aopass.SetDelegatePass(vtkRenderStepsPass())
        aopass.SetAmbientIllumination(ambient)
        aopass.SetRetrievalMode(MODE)
        aopass.GetAmbientVolume().SetGPUVoxelisation(gpu)
        renderer.SetPass(aopass)
    window = offscreen_window(renderer, (300, 300))
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0.0, 0.0, 1.6)
    camera.SetPosition(0.0, -12.0, 2.2)  # from the side, slightly above: the probe's underside
    camera.SetViewUp(0.0, 0.0, 1.0)      # faces the slab, its top the open space
    renderer.ResetCameraClippingRange()
    window.Render()
    return window, renderer, aopass, actors


def probe_rows(image):
    """Mean brightness of the probe's lower and upper part (rows around the probe's centre)."""
    img = image.reshape(300, 300, -1)[:, :, :3].astype(float)
    # the probe is the sphere at the centre of the view: 70 px radius or so
    lower = img[150 - 60:150 - 30, 135:165].mean()   # window rows start at the bottom
    upper = img[150 + 30:150 + 60, 135:165].mean()
    return lower, upper


for MODE in (0, 1):  # PER_FRAGMENT, PER_SPHERE
    print("retrieval mode", MODE)
    window, renderer, aopass, actors = scene(pass_on=False)
    plain = grab_image(window)
    window, renderer, aopass, actors = scene()
    occluded = grab_image(window)
    check(aopass.GetNumberOfVolumeBuilds() == 1, "one volume build for the first frame")
    check(aopass.GetAmbientVolume().GetLastBuildOnGPU(), "voxelised on the GPU")
    cpu_built = grab_image(scene(gpu=False)[0])
    check(int(np.abs(cpu_built[:, :3] - occluded[:, :3]).max()) <= 1,
          "the CPU-voxelised volume gives the same picture (max difference %d/255)"
          % int(np.abs(cpu_built[:, :3] - occluded[:, :3]).max()))
    lower0, upper0 = probe_rows(plain)
    lower1, upper1 = probe_rows(occluded)
    print("probe without AO: lower %.1f upper %.1f; with: lower %.1f upper %.1f"
          % (lower0, upper0, lower1, upper1))
    check(lower1 < 0.85 * lower0, "the side facing the slab is darker (%.1f -> %.1f)"
          % (lower0, lower1))
    if MODE == 0:
        check(upper1 > 0.9 * upper0, "the open side keeps its light (%.1f -> %.1f)"
              % (upper0, upper1))
    else:
        # per sphere the side results blend into the top as well: only the order is kept
        check(lower1 / lower0 < upper1 / upper0 - 0.1,
              "per sphere: the side facing the slab keeps less light (%.2f) than the open side "
              "(%.2f)" % (lower1 / lower0, upper1 / upper0))
    check(int((occluded[:, :3] - plain[:, :3]).max()) <= 1, "AO alone never brightens (max +%d)"
          % int((occluded[:, :3] - plain[:, :3]).max()))
    check(np.isfinite(occluded).all(), "no NaN")

    # camera move: no new volume; colour change and a volume setting: rebuild
    renderer.GetActiveCamera().Azimuth(30)
    window.Render()
    check(aopass.GetNumberOfVolumeBuilds() == 1, "a camera move re-traces only (builds %d)"
          % aopass.GetNumberOfVolumeBuilds())
    actors[0].GetProperty().SetColor(0.2, 0.9, 0.3)
    window.Render()
    check(aopass.GetNumberOfVolumeBuilds() == 2, "a colour change rebuilds (builds %d)"
          % aopass.GetNumberOfVolumeBuilds())
    aopass.GetAmbientVolume().SetSubGridSamples(4)
    window.Render()
    check(aopass.GetNumberOfVolumeBuilds() == 3, "a volume setting rebuilds (builds %d)"
          % aopass.GetNumberOfVolumeBuilds())

    # translucent slab occludes less
    window, renderer, aopass, actors = scene(slab_opacity=0.3)
    translucent = grab_image(window)
    window, renderer, aopass, actors = scene(slab_opacity=0.3, pass_on=False)
    translucent_plain = grab_image(window)
    lower_t, _ = probe_rows(translucent)
    lower_tp, _ = probe_rows(translucent_plain)
    print("translucent slab: lower %.1f without AO, %.1f with" % (lower_tp, lower_t))
    check(lower_t / lower_tp > lower1 / lower0 + 0.05,
          "a translucent slab occludes less (%.2f of the light kept vs %.2f)"
          % (lower_t / lower_tp, lower1 / lower0))

    # isolated sphere: barely changed
    window, renderer, aopass, actors = scene(slab_present=False, pass_on=False)
    alone_plain = grab_image(window)
    window, renderer, aopass, actors = scene(slab_present=False)
    alone = grab_image(window)
    diff = np.abs(alone[:, :3] - alone_plain[:, :3])
    check(diff.mean() < 0.5 and diff.max() <= 8,
          "an isolated sphere is barely changed (mean %.2f, max %d)" % (diff.mean(), diff.max()))

    # ambient illumination: a red slab tints the underside red
    window, renderer, aopass, actors = scene(slab_color=(1.0, 0.0, 0.0), ambient=0.0)
    red0 = grab_image(window).reshape(300, 300, -1)[150 - 60:150 - 30, 135:165, :3].mean(axis=(0, 1))
    window, renderer, aopass, actors = scene(slab_color=(1.0, 0.0, 0.0), ambient=1.0)
    red1 = grab_image(window).reshape(300, 300, -1)[150 - 60:150 - 30, 135:165, :3].mean(axis=(0, 1))
    print("underside RGB with alpha_A 0:", red0, "with 1:", red1)
    check(red1[0] - red0[0] > 5 * max(red1[1] - red0[1], red1[2] - red0[2], 1.0),
          "ambient illumination tints the underside red (gain R %.1f, G %.1f, B %.1f)"
          % tuple(red1 - red0))

# NaN / Inf positions: the finite particles' picture
bad = np.array([[np.nan, 0.0, 0.0], [np.inf, 1.0, 1.0]])
window, renderer, aopass, actors = scene(extra=bad)
with_bad = grab_image(window)
check(int(np.abs(with_bad - occluded).max()) == 0 or
      int(np.abs(with_bad[:, :3] - grab_image(scene()[0])[:, :3]).max()) == 0,
      "NaN/Inf particles leave the picture of the finite ones")
check(np.isfinite(with_bad).all(), "no NaN with bad input")

# no particle props; no delegate
renderer = vtkRenderer()
aopass = pr.vtkVoxelConeAOPass()
aopass.SetDelegatePass(vtkRenderStepsPass())
messages = Messages(aopass)
renderer.SetPass(aopass)
window = offscreen_window(renderer, (64, 64))
window.Render()
check(any("No visible props" in t for t in messages.warnings),
      "no particle props: a warning (%s)" % messages.text)
renderer = vtkRenderer()
aopass = pr.vtkVoxelConeAOPass()
messages = Messages(aopass)
renderer.SetPass(aopass)
window = offscreen_window(renderer, (64, 64))
window.Render()
check(any("No delegate" in t for t in messages.warnings), "no delegate: a warning")

sys.exit(finish())
