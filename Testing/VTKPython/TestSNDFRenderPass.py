"""vtkSNDFRenderPass (Ibrahim et al. 2017), scale-consistent shading of sub-pixel particles,
from plain VTK Python. Checked:
- the lighting table (Eqs. 12-14) for 4x4, 8x8 and 16x16 bins against a double-precision
  integral over each bin ∩ unit disk, and the closed forms over the whole disk: a headlight's
  diffuse mean n_z = 2/3, its specular mean n_z^p = 2/(p+2);
- convergence: an fcc crystal of two species with about two pixels per atom, 256 jittered
  samples per pixel, against the 16x16 super-sampled core (rendered at 16x the size and box
  filtered): the plain one-sample image is far off, the S-NDF image close; the frame of a change
  is the plain image; the converged picture drawn again, and the picture a fresh pass converges
  to on the same view, are identical to it, bit for bit;
- shading per sample: the shaded bin sums kept up to date sample by sample equal those formed
  again from the bins;
- re-lighting: another light re-shades the converged S-NDFs without a sample pass and matches
  the super-sampled image under the new light; a camera move restarts;
- material and colour map: a new material re-shades (one particle actor); a new colour map
  whose colours are a linear function of the old ones (three types, two types with a new range)
  recolours the samples without a sample pass, equal to sampling under it, and refinement goes
  on with the new colours; four types, five categorical types (an indexed table) and continuous
  maps re-shade from the bins' moments of the scalar, near sampling under the new map, also after
  a zoom out by 2 (averaged moments) and with two particle actors (one of them solid); without
  the moments, or with an ambient term, they sample again;
- other geometry: an opaque box through part of the crystal and the crystal's outline (lines)
  converge to the super-sampled core like the crystal alone, the box's colour where it hides
  particles; translucent geometry: one warning and the plain image;
- pan (parallel projection, whole pixels): no restart, the kept pixels converged at once (the
  picture before, shifted), the uncovered ones refine; converged, the picture of a pass that
  started at the new view;
- the S-MIP (Sec. 6): a pan back finds the tiles in the cache (the picture before, no sample); a
  half-pixel pan uses tiles of another grid phase, a 0.3-pixel pan restarts; a zoom out by 2
  averages level 1 from level 0 (against level 1 rendered directly) and a zoom back in shows the
  cached level 0; tiles out of view during a light change are rebaked when they come back; a
  cache of one view's tiles evicts the least recently used and samples them again;
- ConvergeOnRender: one render (also the render of a change) takes all 256 samples and gives
  the progressive picture, reporting its progress (vtkCommand::ProgressEvent, 0 to 1);
- bad input: an empty input, a memory limit below 4x4 bins (a warning, the plain image), a limit
  that forces fewer bins, a wrong bin count, a resize while refining, NaN/Inf positions, a
  translucent particle actor (a warning, the plain image); --gl33: a context without compute
  shaders (an error, the plain image).

usage: python3 TestSNDFRenderPass.py [--gl33]
"""
import itertools
import sys

import numpy as np

import particlerendering as pr
import prVTKTesting
from prVTKTesting import (Messages, check, crystal_view, fcc_crystal, finish, image_error,
                          window_pixels)
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkOutlineSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

W, H = 120, 90
S = 16  # reference super-sampling per axis


def add_actor(renderer, source, colour):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*colour)
    renderer.AddActor(actor)
    return actor


def scene(xyz, rgb, size, sndf=None, box=False, box_opacity=1.0, line_width=1.0):
    """The crystal (prVTKTesting.crystal_view: camera pass -> [sndf ->] render steps), with box:
    an opaque (or box_opacity) box through part of it and its outline."""
    renderer, window, actor = crystal_view(xyz, rgb, size, sndf)
    if box:
        cube = vtkCubeSource()
        cube.SetBounds(9, 20, -1, 5, 15, 19)
        add_actor(renderer, cube, (0.9, 0.85, 0.3)).GetProperty().SetOpacity(box_opacity)
        # the simulation box's outline, as ParaView shows a LAMMPS box: lines
        outline = vtkOutlineSource()
        outline.SetBounds(-0.5, 16.5, -0.5, 16.5, -0.5, 16.5)
        add_actor(renderer, outline, (0.2, 0.9, 0.3)).GetProperty().SetLineWidth(line_width)
        renderer.ResetCameraClippingRange()
    return renderer, window, actor


def image(window, width=W, height=H):
    """Render once and read the picture (without the second render of grab_image)."""
    window.Render()
    return window_pixels(window, width, height)


def reference(xyz, rgb, light=None, box=False, specular=0.0, zoom=1.0):
    """The 16x16 super-sampled core: rendered at 16x the size, box filtered."""
    # (lines S pixels wide at S times the size: one pixel wide in the filtered picture)
    renderer, window, actor = scene(xyz, rgb, (W * S, H * S), box=box, line_width=S)
    renderer.GetActiveCamera().Zoom(zoom)
    actor.GetProperty().SetSpecular(specular)
    actor.GetProperty().SetSpecularPower(20)
    if light is not None:
        renderer.AddLight(light)
    big = image(window, W * S, H * S)
    return big.reshape(H, S, W, S, 3).mean(axis=(1, 3))


def converge(sndf, window, limit=200):
    renders = 0
    while not sndf.GetConverged() and renders < limit:
        window.Render()
        renders += 1
    return renders


error = image_error


gl33 = "--gl33" in sys.argv
xyz, rgb = fcc_crystal(16)

if gl33:
    # --- a context without compute shaders: one error, the plain image --------------------------
    sndf = pr.vtkSNDFRenderPass()
    messages = Messages(sndf)
    renderer, window, _ = scene(xyz, rgb, (W, H), sndf)
    out = image(window)
    image(window)
    _, plain_window, _ = scene(xyz, rgb, (W, H))
    plain = image(plain_window)
    check(np.array_equal(out, plain), "OpenGL 3.3: the plain image")
    check(len(messages.errors) == 1 and "compute" in str(messages.text),
          "OpenGL 3.3: one error naming compute shaders (%s)" % messages.text)
    sys.exit(finish())

# --- the lighting table ----------------------------------------------------------------------
fine = 2048
u = (np.arange(fine) + 0.5) / fine * 2.0 - 1.0
X, Y = np.meshgrid(u, u, indexing="xy")
inside = X * X + Y * Y <= 1.0
Z = np.sqrt(np.clip(1.0 - X * X - Y * Y, 0.0, 1.0))
power = 20.0
for bins in (4, 8, 16):
    sndf = pr.vtkSNDFRenderPass()
    sndf.SetBinsPerAxis(bins)
    renderer, window, actor = scene(xyz[:64], rgb[:64], (32, 32), sndf)
    actor.GetProperty().SetSpecularPower(power)
    window.Render()  # the frame of the change: the plain image
    window.Render()  # the first sample pass builds the table
    window.MakeCurrent()
    table = vtkFloatArray()
    check(sndf.GetLightingTable(table), "%d bins: a table" % bins)
    n = bins * bins
    check(table.GetNumberOfTuples() == 7 * n, "%d bins: seven rows per bin" % bins)
    rows = np.array([table.GetTuple3(t) for t in range(table.GetNumberOfTuples())]).reshape(7, n, 3)
    diffuse, specular = rows[0, :, 0], rows[1, :, 0]
    fx, fy = (X + 1) * 0.5 * bins, (Y + 1) * 0.5 * bins
    cell = fx.astype(int).clip(0, bins - 1) + bins * fy.astype(int).clip(0, bins - 1)
    area = np.bincount(cell[inside], minlength=n).astype(float)
    used = area > 0

    def bin_mean(values):
        return np.bincount(cell[inside], weights=values[inside], minlength=n)[used] / area[used]

    lit_d, lit_s = np.maximum(1e-6, Z), np.maximum(1e-6, Z) ** power
    err_d = np.abs(diffuse[used] - bin_mean(lit_d)).max()
    err_s = np.abs(specular[used] - bin_mean(lit_s)).max()
    check(err_d < 3e-3 and err_s < 3e-3,
          "%d bins: per-bin means against the double-precision integral (diffuse %.2e, specular "
          "%.2e)" % (bins, err_d, err_s))
    # the slopes: least-squares planes over the bin coordinates u (covariance + 1e-4, as the
    # shader), and the centroid, in double precision
    ux, uy = fx - np.floor(fx).clip(0, bins - 1), fy - np.floor(fy).clip(0, bins - 1)
    mx, my = bin_mean(ux), bin_mean(uy)
    cxx = bin_mean(ux * ux) - mx * mx + 1e-4
    cxy = bin_mean(ux * uy) - mx * my
    cyy = bin_mean(uy * uy) - my * my + 1e-4
    err_c = np.abs(rows[6, used, :2] - np.stack([mx, my], 1)).max()
    slope_errors = []
    for row, lit in ((2, lit_d), (4, lit_s)):
        mf = bin_mean(lit)
        cxf, cyf = bin_mean(ux * lit) - mx * mf, bin_mean(uy * lit) - my * mf
        det = cxx * cyy - cxy * cxy
        gx, gy = (cyy * cxf - cxy * cyf) / det, (cxx * cyf - cxy * cxf) / det
        # relative to the variation over the bin (slopes are per bin width)
        scale = np.maximum(1e-3, np.abs(gx) + np.abs(gy))
        slope_errors.append((np.abs(rows[row, used, 0] - gx) / scale).max())
        slope_errors.append((np.abs(rows[row + 1, used, 0] - gy) / scale).max())
    check(err_c < 6e-3 and max(slope_errors) < 0.03,
          "%d bins: centroids (%.1e) and slopes (largest relative error %.1e) against the "
          "double-precision least-squares planes" % (bins, err_c, max(slope_errors)))
    disk_d = (area * diffuse).sum() / area.sum()
    disk_s = (area * specular).sum() / area.sum()
    check(abs(disk_d - 2.0 / 3.0) < 1e-3 and abs(disk_s - 2.0 / (power + 2.0)) < 1e-3,
          "%d bins: disk means %.5f (2/3) and %.5f (2/(p+2) = %.5f)"
          % (bins, disk_d, disk_s, 2.0 / (power + 2.0)))

# --- convergence against the super-sampled core ----------------------------------------------
ref = reference(xyz, rgb)
_, plain_window, _ = scene(xyz, rgb, (W, H))
plain = image(plain_window)
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(32)
renderer, window, actor = scene(xyz, rgb, (W, H), sndf)
first = image(window)
check(sndf.GetNumberOfSamples() == 0 and np.array_equal(first, plain),
      "the frame of a change is the plain image, no sample taken")
renders = converge(sndf, window)
out = image(window)
plain_error = error(plain, ref)
sndf_error = error(out, ref)
print("plain vs reference: mean %.2f p99 %.1f max %.1f /255" % plain_error)
print("S-NDF (%d samples, %d renders) vs reference: mean %.2f p99 %.1f max %.1f /255"
      % ((sndf.GetNumberOfSamples(), renders) + sndf_error))
check(sndf.GetConverged() and sndf.GetNumberOfSamples() == 256, "256 samples")
check(plain_error[0] > 4.0, "the one-sample image aliases (mean %.2f)" % plain_error[0])
check(sndf_error[0] < 0.5 and sndf_error[1] < 4.5 and sndf_error[2] < 8.0,
      "S-NDF within mean 0.5, p99 4.5, max 8 /255 of the super-sampled core")
passes = sndf.GetNumberOfSamplePasses()
again = image(window)
check(sndf.GetNumberOfSamplePasses() == passes, "converged: no more sample passes")
# the same frame drawn twice (a progressive pass: the converged picture, and the whole
# refinement run again by a pass that starts afresh) gives the same picture, bit for bit
print("converged picture drawn again: max %d/255" % np.abs(again - out).max())
check(np.array_equal(again, out), "converged: the same frame drawn twice differs")
fresh = pr.vtkSNDFRenderPass()
fresh.SetSamplesPerFrame(32)
_, fresh_window, _ = scene(xyz, rgb, (W, H), fresh)
image(fresh_window)
converge(fresh, fresh_window)
rerun = image(fresh_window)
print("a fresh pass converged on the same view: max %d/255" % np.abs(rerun - out).max())
check(np.array_equal(rerun, out), "a fresh pass converges to another picture")

# --- particles several pixels wide: shaded without facets --------------------------------------
# (each pixel sees a small patch of one sphere, so its samples crowd into part of one bin; the
# bin's mean position and the table's slopes (SNDFBins.glsl) keep the shading from being
# quantised into 8 x 8 facets: with the bins' mean light only, this view was off by mean 5.0,
# p99 30, max 48 /255 and the spheres showed bands; now 0.8, 5.3, 9.2)
zoomed_ref = reference(xyz, rgb, zoom=6.0)
zoomed_sndf = pr.vtkSNDFRenderPass()
zoomed_sndf.SetSamplesPerFrame(64)
zoomed_renderer, zoomed_window, _ = scene(xyz, rgb, (W, H), zoomed_sndf)
zoomed_renderer.GetActiveCamera().Zoom(6.0)
converge(zoomed_sndf, zoomed_window)
zoomed_error = error(image(zoomed_window), zoomed_ref)
print("about 12 px per atom, S-NDF vs reference: mean %.2f p99 %.1f max %.1f /255" % zoomed_error)
check(zoomed_error[0] < 1.2 and zoomed_error[1] < 8.0,
      "particles 12 px wide: within mean 1.2, p99 8 /255 of the super-sampled core")

# the shaded bin sums kept per sample equal the sums formed again from the bins (a table build
# forced by a light intensity changed in the sixth digit)
lights = renderer.GetLights()
lights.InitTraversal()
builds = sndf.GetNumberOfTableBuilds()
headlight = lights.GetNextItem()
headlight.SetIntensity(headlight.GetIntensity() * (1.0 + 1e-6))
rebaked = image(window)
print("per-sample shading vs shading from the bins: max %.1f /255" % np.abs(rebaked - out).max())
check(sndf.GetNumberOfTableBuilds() == builds + 1 and sndf.GetNumberOfSamplePasses() == passes
      and np.abs(rebaked - out).max() <= 1.0,
      "per-sample shading equals shading from the bins (max %.1f /255)" % np.abs(rebaked - out).max())

# --- re-lighting -----------------------------------------------------------------------------
light = vtkLight()
light.SetLightTypeToCameraLight()
light.SetPosition(1, 0.6, 0.3)
light.SetFocalPoint(0, 0, 0)
light.SetColor(1.0, 0.9, 0.8)
renderer.RemoveAllLights()
renderer.AddLight(light)
builds = sndf.GetNumberOfTableBuilds()
relit = image(window)
check(sndf.GetNumberOfSamplePasses() == passes and sndf.GetNumberOfTableBuilds() == builds + 1,
      "a new light re-shades without a sample pass")
light_ref = vtkLight()
light_ref.DeepCopy(light)
ref_relit = reference(xyz, rgb, light_ref)
relit_error = error(relit, ref_relit)
print("re-lit S-NDF vs re-rendered reference: mean %.2f p99 %.1f max %.1f /255" % relit_error)
check(np.abs(relit - out).mean() > 5.0, "the light changed the picture")
check(relit_error[0] < 0.5 and relit_error[1] < 4.5 and relit_error[2] < 8.0,
      "re-lit within mean 0.5, p99 4.5, max 8 /255 of the re-rendered reference")
restarts = sndf.GetNumberOfRestarts()
renderer.GetActiveCamera().Azimuth(5)
image(window)
check(sndf.GetNumberOfRestarts() == restarts + 1 and sndf.GetNumberOfSamples() == 0,
      "a camera move restarts (the plain image, no sample)")

# --- material changes re-shade (one particle actor) ---------------------------------------------
def converged_material(solid, ambient, diffuse, ambient_colour, diffuse_colour, second=False):
    """A pass converged to 64 samples on the crystal coloured by its rgb scalars (or solid:
    scalars off), the material set before the first render; second: a second particle actor."""
    material_sndf = pr.vtkSNDFRenderPass()
    material_sndf.SetSamplesPerFrame(64)
    material_sndf.SetTargetSamples(64)
    material_renderer, material_window, material_actor = scene(xyz, rgb, (W, H), material_sndf)
    if second:
        _, _, other = crystal_view(xyz[:4] + 40.0, rgb[:4], (8, 8))
        material_renderer.AddActor(other)
    material_actor.GetMapper().SetScalarVisibility(not solid)
    set_material(material_actor, ambient, diffuse, ambient_colour, diffuse_colour)
    image(material_window)
    converge(material_sndf, material_window)
    return material_sndf, material_window, material_actor


def set_material(actor, ambient, diffuse, ambient_colour, diffuse_colour):
    p = actor.GetProperty()
    p.SetAmbient(ambient)
    p.SetDiffuse(diffuse)
    p.SetAmbientColor(*ambient_colour)
    p.SetDiffuseColor(*diffuse_colour)


before_material = ((0.0, 1.0, (1, 1, 1), (1, 1, 1)), (0.1, 0.8, (0.9, 0.6, 0.3), (0.9, 0.6, 0.3)))
after_material = ((0.0, 0.6, (1, 1, 1), (1, 1, 1)), (0.3, 0.5, (0.3, 0.7, 0.9), (0.5, 0.8, 0.4)))
for solid in (False, True):
    what = "solid colour" if solid else "colour by scalars"
    old, new = before_material[solid], after_material[solid]
    msndf, mwindow, mactor = converged_material(solid, *old)
    start = image(mwindow)
    passes, restarts = msndf.GetNumberOfSamplePasses(), msndf.GetNumberOfRestarts()
    set_material(mactor, *new)
    changed = image(mwindow)
    fresh_sndf, fresh_window, _ = converged_material(solid, *new)
    fresh = image(fresh_window)
    d = np.abs(changed - fresh)
    print("%s: material changed after convergence vs converged under it: mean %.3f max %.1f "
          "/255 (the change moved the picture by %.1f)" % (what, d.mean(), d.max(),
                                                           np.abs(changed - start).mean()))
    check(msndf.GetNumberOfSamplePasses() == passes and msndf.GetNumberOfRestarts() == restarts
          and msndf.GetNumberOfSamples() == 64 and d.max() <= 1.0
          and np.abs(changed - start).mean() > 3.0,
          "%s: a new material re-shades without a sample pass, equal to sampling under it "
          "(max %.1f /255)" % (what, d.max()))
# colour by scalars: the ambient term is drawn with the scalar colours into the samples, so the
# ambient coefficient samples again
msndf, mwindow, mactor = converged_material(False, *before_material[0])
restarts = msndf.GetNumberOfRestarts()
mactor.GetProperty().SetAmbient(0.2)
image(mwindow)
check(msndf.GetNumberOfRestarts() == restarts + 1,
      "colour by scalars: a new ambient coefficient samples again")
# two particle actors (a solid colour and two scalar colours): the samples hold the diffuse
# colours as drawn; a new diffuse coefficient or colour of one of them maps the three stored
# colours linearly (vtkSNDFRenderPass "Colour"): recoloured, equal to sampling under it; a new
# ambient coefficient samples again
for what, change in (("diffuse coefficient", lambda p: p.SetDiffuse(0.4)),
                     ("diffuse colour", lambda p: p.SetDiffuseColor(0.2, 0.8, 0.5))):
    msndf, mwindow, mactor = converged_material(True, *before_material[1], second=True)
    start = image(mwindow)
    passes, restarts = msndf.GetNumberOfSamplePasses(), msndf.GetNumberOfRestarts()
    change(mactor.GetProperty())
    changed = image(mwindow)
    fresh_sndf, fresh_window, fresh_actor = converged_material(True, *before_material[1],
                                                               second=True)
    change(fresh_actor.GetProperty())
    fresh_sndf.Restart()
    image(fresh_window)
    converge(fresh_sndf, fresh_window)
    fresh = image(fresh_window)
    d = np.abs(changed - fresh)
    print("two particle actors, new %s vs sampled under it: mean %.3f max %.1f /255 (moved by %.1f)"
          % (what, d.mean(), d.max(), np.abs(changed - start).mean()))
    check(msndf.GetNumberOfSamplePasses() == passes and msndf.GetNumberOfRestarts() == restarts
          and msndf.GetNumberOfRecolours() == 1 and d.max() <= 1.0
          and np.abs(changed - start).mean() > 1.0,
          "two particle actors: a new %s re-shades without a sample pass, equal to sampling "
          "under it (max %.1f /255, moved by %.1f)" % (what, d.max(), np.abs(changed - start).mean()))
restarts = msndf.GetNumberOfRestarts()
mactor.GetProperty().SetAmbient(0.3)
image(mwindow)
check(msndf.GetNumberOfRestarts() == restarts + 1,
      "two particle actors: a new ambient coefficient samples again")

# --- colour-map changes re-shade where the new colours are linear in the old ones -----------
def converged_types(types, points, ambient=0.0, keep=True, parallel=False):
    """A pass converged to 64 samples on the crystal coloured by the scalar "type" (`types`, one
    value per atom) through a colour transfer function with the given (value, r, g, b) points."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkRenderingCore import vtkColorTransferFunction
    type_sndf = pr.vtkSNDFRenderPass()
    type_sndf.SetSamplesPerFrame(64)
    type_sndf.SetTargetSamples(64)
    type_sndf.SetKeepColourCoordinates(keep)
    type_renderer, type_window, type_actor = scene(xyz, rgb, (W, H), type_sndf)
    data = type_actor.GetMapper().GetInput()
    array = numpy_to_vtk(np.asarray(types, dtype=np.float32), deep=True)
    array.SetName("type")
    data.GetPointData().AddArray(array)
    if isinstance(points, list):
        ctf = vtkColorTransferFunction()
        set_points(ctf, points)
    else:
        ctf = points  # a lookup table made by the caller
    mapper = type_actor.GetMapper()
    mapper.SetLookupTable(ctf)
    mapper.SetColorModeToMapScalars()
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("type")
    mapper.SetScalarRange(0.0, 1.0)
    type_actor.GetProperty().SetAmbient(ambient)
    if parallel:
        type_renderer.GetActiveCamera().ParallelProjectionOn()
        type_renderer.GetActiveCamera().SetParallelScale(16.0)
        type_renderer.ResetCameraClippingRange()
    image(type_window)
    converge(type_sndf, type_window)
    return type_sndf, type_window, ctf


def set_points(ctf, points):
    ctf.RemoveAllPoints()
    for point in points:
        ctf.AddRGBPoint(*point)


def remapped(make, before, after, apply):
    """A pass converged under the colour map `before` (make(map) -> (sndf, window, table)), then
    apply(table, after): returns |that picture - a pass converged under `after`|, how far the
    change moved the picture (mean) and whether the samples were kept (recoloured once from the
    moments: no sample pass, no restart)."""
    msndf, mwindow, table = make(before)
    start = image(mwindow)
    passes, restarts = msndf.GetNumberOfSamplePasses(), msndf.GetNumberOfRestarts()
    apply(table, after)
    changed = image(mwindow)
    _, fresh_window, _ = make(after)
    kept = (msndf.GetTileCache().GetMoments() and msndf.GetNumberOfSamplePasses() == passes
            and msndf.GetNumberOfRestarts() == restarts and msndf.GetNumberOfRecolours() == 1)
    return np.abs(changed - image(fresh_window)), np.abs(changed - start).mean(), kept


index = np.arange(len(xyz))
three_types = (index % 3) * 0.5  # 0, 0.5, 1
old_map = [(0.0, 0.23, 0.30, 0.75), (0.5, 0.87, 0.87, 0.87), (1.0, 0.71, 0.02, 0.15)]
new_map = [(0.0, 0.95, 0.80, 0.20), (0.5, 0.20, 0.60, 0.35), (1.0, 0.45, 0.25, 0.85)]
for what, types, before, after in (
        ("three types", three_types, old_map, new_map),
        ("two types, range narrowed", (index % 2).astype(float), old_map,
         [(-0.5, 0.23, 0.30, 0.75), (0.25, 0.87, 0.87, 0.87), (0.75, 0.71, 0.02, 0.15)])):
    tsndf, twindow, tctf = converged_types(types, before)
    start = image(twindow)
    passes, restarts = tsndf.GetNumberOfSamplePasses(), tsndf.GetNumberOfRestarts()
    recoloured = tsndf.GetTileCache().GetNumberOfRecolouredTiles()
    set_points(tctf, after)
    changed = image(twindow)
    fresh_sndf, fresh_window, _ = converged_types(types, after)
    fresh = image(fresh_window)
    d = np.abs(changed - fresh)
    print("%s: colour map changed after convergence vs converged under it: mean %.3f max %.1f "
          "/255 (the change moved the picture by %.1f; %d tiles recoloured)"
          % (what, d.mean(), d.max(), np.abs(changed - start).mean(),
             tsndf.GetTileCache().GetNumberOfRecolouredTiles() - recoloured))
    check(tsndf.GetNumberOfSamplePasses() == passes and tsndf.GetNumberOfRestarts() == restarts
          and tsndf.GetNumberOfRecolours() == 1 and tsndf.GetNumberOfSamples() == 64
          and d.max() <= 1.0 and np.abs(changed - start).mean() > 3.0,
          "%s: a new colour map re-shades without a sample pass, equal to sampling under it "
          "(max %.1f /255)" % (what, d.max()))
    # and refinement after it goes on with the new colours (a larger target)
    tsndf.SetTargetSamples(128)
    fresh_sndf.SetTargetSamples(128)
    converge(tsndf, twindow)
    converge(fresh_sndf, fresh_window)
    d = np.abs(image(twindow) - image(fresh_window))
    check(d.max() <= 1.0, "%s: refined on to 128 samples after the recolouring, equal to a pass "
          "sampled under the new map throughout (max %.1f /255)" % (what, d.max()))
# colour maps that are not linear in the old colours re-shade from the bins' moments of the
# colour coordinate (the scalar; vtkSNDFRenderPass "Colour", KeepColourCoordinates, on by
# default): four types of unrelated colours, a continuous map (colour by speed) to another
# diverging map and to a five-point rainbow; without the moments they sample again, and so does
# a new map where the ambient term carries the colours
rng = np.random.default_rng(5)
speeds = rng.random(len(xyz))
rainbow = [(0.0, 0.0, 0.0, 1.0), (0.25, 0.0, 1.0, 1.0), (0.5, 0.0, 1.0, 0.0), (0.75, 1.0, 1.0, 0.0),
           (1.0, 1.0, 0.0, 0.0)]
for what, types, before, after, limits in (
        ("four types", (index % 4) / 3.0, old_map + [(1.0 / 3.0, 0.2, 0.8, 0.2)],
         new_map + [(1.0 / 3.0, 0.9, 0.1, 0.6)], (0.1, 1.0, 2.0)),
        ("a continuous map", speeds, old_map, new_map, (0.1, 1.0, 2.0)),
        ("a continuous map to a rainbow", speeds, old_map, rainbow, (0.1, 2.0, 16.0))):
    d, moved, kept = remapped(lambda m: converged_types(types, m), before, after, set_points)
    print("%s: colour map changed after convergence vs converged under it: mean %.3f p99 %.1f "
          "max %.1f /255 (the change moved the picture by %.1f)"
          % (what, d.mean(), np.percentile(d, 99), d.max(), moved))
    check(kept and d.mean() <= limits[0] and np.percentile(d, 99) <= limits[1]
          and d.max() <= limits[2] and moved > 3.0,
          "%s: a new colour map re-shades from the moments without a sample pass, near sampling "
          "under it (mean %.3f <= %.1f, p99 %.1f <= %.1f, max %.1f <= %.1f /255)"
          % (what, d.mean(), limits[0], np.percentile(d, 99), limits[1], d.max(), limits[2]))
# the moments are averaged with the bins when the S-MIP zooms out: zoomed out by 2 (level 1
# averaged from level 0), then a new map, against the same zoom of a pass sampled under it
tsndf, twindow, tctf = converged_types(speeds, old_map, parallel=True)
tcamera = twindow.GetRenderers().GetFirstRenderer().GetActiveCamera()
tcamera.SetParallelScale(32.0)
image(twindow)
downsampled = tsndf.GetTileCache().GetNumberOfDownsampledTiles()
set_points(tctf, rainbow)
changed = image(twindow)
fresh_sndf, fresh_window, _ = converged_types(speeds, rainbow, parallel=True)
fresh_window.GetRenderers().GetFirstRenderer().GetActiveCamera().SetParallelScale(32.0)
d = np.abs(changed - image(fresh_window))
print("zoomed out by 2, then a continuous map to a rainbow, vs the same zoom sampled under it: "
      "mean %.3f p99 %.1f max %.1f /255 (%d tiles averaged)"
      % (d.mean(), np.percentile(d, 99), d.max(), downsampled))
check(downsampled > 0 and tsndf.GetNumberOfRecolours() == 1 and tsndf.GetNumberOfRestarts() == 1
      and d.mean() <= 0.2 and np.percentile(d, 99) <= 4.0,
      "zoomed out, a new map re-shades the averaged bins from their averaged moments (mean "
      "%.3f <= 0.2, p99 %.1f <= 4 /255)" % (d.mean(), np.percentile(d, 99)))
# categorical colours (an indexed lookup table, ParaView's "Interpret Values As Categories"):
# new colours for five atom types re-shade from the moments (the quadrature's nodes take the
# colour of the nearest type)
def categories(colours):
    from vtkmodules.vtkCommonCore import vtkLookupTable, vtkVariant
    table = vtkLookupTable()
    table.IndexedLookupOn()
    table.SetNumberOfTableValues(len(colours))
    for k, colour in enumerate(colours):
        table.SetTableValue(k, *colour, 1.0)
        table.SetAnnotation(vtkVariant(float(k)), "type %d" % k)
    return table


five_old = [(0.23, 0.30, 0.75), (0.87, 0.87, 0.87), (0.71, 0.02, 0.15), (0.2, 0.8, 0.2),
            (0.9, 0.6, 0.1)]
five_new = [(0.95, 0.80, 0.20), (0.20, 0.60, 0.35), (0.45, 0.25, 0.85), (0.9, 0.1, 0.6),
            (0.1, 0.9, 0.9)]
five_types = (index % 5).astype(float)


def set_categories(table, colours):
    for k, colour in enumerate(colours):
        table.SetTableValue(k, *colour, 1.0)


d, moved, kept = remapped(lambda c: converged_types(five_types, categories(c)), five_old, five_new,
                          set_categories)
print("five categorical types: new colours after convergence vs converged under them: mean %.3f "
      "p99 %.1f max %.1f /255 (the change moved the picture by %.1f)"
      % (d.mean(), np.percentile(d, 99), d.max(), moved))
check(kept and d.mean() <= 0.1 and np.percentile(d, 99) <= 2.0 and moved > 3.0,
      "five categorical types: new colours re-shade without a sample pass, near sampling under "
      "them (mean %.3f <= 0.1, p99 %.1f <= 2 /255)" % (d.mean(), np.percentile(d, 99)))


# two particle actors (the crystal's halves), the first coloured by the speed through its own
# map, the second through another map or by its property's colour: a rainbow for the first
# re-shades from the moments (each actor's coordinate in its own part of [0, 1])
half_windows = []


def converged_halves(map_a, map_b):
    """A pass converged to 64 samples on the crystal's halves x < 8 and x >= 8 as two particle
    actors coloured by `speeds` through the maps (map_b None: a solid colour)."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkRenderingCore import vtkColorTransferFunction
    half_sndf = pr.vtkSNDFRenderPass()
    half_sndf.SetSamplesPerFrame(64)
    half_sndf.SetTargetSamples(64)
    half = xyz[:, 0] < 8.0
    half_renderer, half_window, actor_a = scene(xyz[half], rgb[half], (W, H), half_sndf)
    _, other_window, actor_b = crystal_view(xyz[~half], rgb[~half], (8, 8))
    # (kept: its end releases the shared mapper's resources, which modifies it: a restart)
    half_windows.append(other_window)
    half_renderer.AddActor(actor_b)
    half_renderer.ResetCameraClippingRange()
    tables = []
    for actor, points, values in ((actor_a, map_a, speeds[half]), (actor_b, map_b, speeds[~half])):
        mapper = actor.GetMapper()
        if points is None:
            mapper.ScalarVisibilityOff()
            actor.GetProperty().SetColor(0.3, 0.8, 0.4)
            continue
        array = numpy_to_vtk(np.asarray(values, dtype=np.float32), deep=True)
        array.SetName("speed")
        mapper.GetInput().GetPointData().AddArray(array)
        table = vtkColorTransferFunction()
        set_points(table, points)
        mapper.SetLookupTable(table)
        mapper.SetColorModeToMapScalars()
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray("speed")
        tables.append(table)
    image(half_window)
    converge(half_sndf, half_window)
    return half_sndf, half_window, tables


for what, other in (("two table-coloured actors", new_map), ("a table-coloured and a solid actor", None)):
    d, moved, kept = remapped(lambda m: converged_halves(m, other), old_map, rainbow,
                              lambda tables, m: set_points(tables[0], m))
    print("%s: a rainbow for the first after convergence vs converged under it: mean %.3f p99 %.1f "
          "max %.1f /255 (the change moved the picture by %.1f)"
          % (what, d.mean(), np.percentile(d, 99), d.max(), moved))
    check(kept and d.mean() <= 0.1 and np.percentile(d, 99) <= 2.0 and moved > 3.0,
          "%s: a new map re-shades from the moments without a sample pass, near sampling under it "
          "(mean %.3f <= 0.1, p99 %.1f <= 2 /255)" % (what, d.mean(), np.percentile(d, 99)))
for what, types, before, after, ambient, keep in (
        ("a continuous map without the moments", speeds, old_map, new_map, 0.0, False),
        ("three types with ambient 0.2", three_types, old_map, new_map, 0.2, True)):
    tsndf, twindow, tctf = converged_types(types, before, ambient, keep)
    restarts = tsndf.GetNumberOfRestarts()
    set_points(tctf, after)
    image(twindow)
    check(tsndf.GetNumberOfRestarts() == restarts + 1 and tsndf.GetNumberOfRecolours() == 0
          and tsndf.GetTileCache().GetMoments() == keep,
          "%s: a new colour map samples again" % what)

# --- other geometry: an opaque box through part of the crystal and the outline (lines) -------
ref_box = reference(xyz, rgb, box=True)
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(32)
messages = Messages(sndf)
renderer, window, _ = scene(xyz, rgb, (W, H), sndf, box=True)
image(window)
converge(sndf, window)
with_box = image(window)
_, plain_box_window, _ = scene(xyz, rgb, (W, H), box=True)
plain_box_error = error(image(plain_box_window), ref_box)
# the reference's S-pixel-wide lines have no joins: leave out 5x5 pixels around the outline's
# corners
away = np.ones((H, W), bool)
for corner in itertools.product((-0.5, 16.5), repeat=3):
    renderer.SetWorldPoint(*corner, 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    away[max(0, int(round(y)) - 2):int(round(y)) + 3, max(0, int(round(x)) - 2):int(round(x)) + 3] = False
box_error = error(with_box[away], ref_box[away])
print("box and outline: plain vs reference mean %.2f p99 %.1f max %.1f /255" % plain_box_error)
print("box and outline: S-NDF vs reference mean %.2f p99 %.1f max %.1f /255" % box_error)
check(sndf.GetConverged() and not messages.warnings and box_error[0] < 0.5
      and box_error[1] < 4.5 and box_error[2] < 8.0,
      "opaque box and outline in the view: within mean 0.5, p99 4.5, max 8 /255 (%s)" % messages.text)
# the box alone where it covers particles: its colour, no particle shading added
box_pixels = (np.abs(ref_box - ref).max(axis=2) > 40)
check(np.abs(with_box - ref_box)[box_pixels].mean() < 1.0,
      "where the box hides particles: the box's colour (mean %.2f /255 over %d pixels)"
      % (np.abs(with_box - ref_box)[box_pixels].mean(), box_pixels.sum()))

# translucent geometry: a warning and the plain image
sndf = pr.vtkSNDFRenderPass()
messages = Messages(sndf)
renderer, window, _ = scene(xyz, rgb, (W, H), sndf, box=True, box_opacity=0.5)
with_glass = image(window)
image(window)
plain_renderer, plain_glass_window, _ = scene(xyz, rgb, (W, H), box=True, box_opacity=0.5)
check(np.array_equal(with_glass, image(plain_glass_window)) and len(messages.warnings) == 1
      and "translucent geometry" in str(messages.text) and sndf.GetNumberOfSamplePasses() == 0,
      "translucent geometry in the view: one warning, the plain image (%s)" % messages.text)

# --- pan: the S-NDFs move with the picture (parallel projection, whole pixels) --------------
def parallel_view(sndf):
    renderer, window, _ = scene(xyz, rgb, (W, H), sndf)
    renderer.GetActiveCamera().ParallelProjectionOn()
    renderer.GetActiveCamera().SetParallelScale(16.0)
    renderer.ResetCameraClippingRange()
    return renderer, window


def pan_camera(camera, pixels_right, pixels_up):
    prVTKTesting.pan_camera(camera, pixels_right, pixels_up, H)


def converged_parallel_view(samples_per_frame=64):
    """A new S-NDF pass in parallel_view(), converged; returns (sndf, renderer, window)."""
    sndf = pr.vtkSNDFRenderPass()
    sndf.SetSamplesPerFrame(samples_per_frame)
    renderer, window = parallel_view(sndf)
    image(window)
    converge(sndf, window)
    return sndf, renderer, window


sndf, renderer, window = converged_parallel_view()
before = image(window)
restarts = sndf.GetNumberOfRestarts()
pan_camera(renderer.GetActiveCamera(), 7, -5)
after = image(window)
# the new pixel (x, y) is the old (x + 7, y - 5) (rows count from the bottom)
kept = np.abs(after[5:, :W - 7] - before[:H - 5, 7:])
print("pan by (7, -5) px: the kept pixels vs the picture before: mean %.3f max %.1f /255"
      % (kept.mean(), kept.max()))
check(sndf.GetNumberOfPans() == 1 and sndf.GetNumberOfRestarts() == restarts
      and sndf.GetNumberOfSamples() == 64 and kept.max() <= 2.0,
      "a whole-pixel pan keeps the S-NDFs: no restart, the kept pixels converged at once (max %.1f)"
      % kept.max())
converge(sndf, window)
panned = image(window)
fresh = pr.vtkSNDFRenderPass()
fresh.SetSamplesPerFrame(64)
fresh_renderer, fresh_window = parallel_view(fresh)
pan_camera(fresh_renderer.GetActiveCamera(), 7, -5)
image(fresh_window)
converge(fresh, fresh_window)
difference = np.abs(panned - image(fresh_window))
check(difference.max() <= 1.0,
      "after the pan, converged: the picture of a pass that started there (max %.1f)"
      % difference.max())
# --- the S-MIP: tiles in an LRU cache, pan back, zoom out by levels, re-light while away -----
cache = sndf.GetTileCache()
cleared = cache.GetNumberOfClearedTiles()
pan_camera(renderer.GetActiveCamera(), -7, 5)
back = image(window)
check(sndf.GetNumberOfPans() == 2 and sndf.GetNumberOfRestarts() == restarts
      and cache.GetNumberOfClearedTiles() == cleared and sndf.GetConverged()
      and np.array_equal(back, before),
      "a pan back finds the tiles in the cache: converged at once, the picture before (max %.1f)"
      % np.abs(back - before).max())
# a pan by 0.3 pixel lies on another grid of the level: no tile in the cache, so the frame of
# the change is the plain image, then new tiles refine; the pan back finds the first grid's
passes = sndf.GetNumberOfSamplePasses()
pan_camera(renderer.GetActiveCamera(), 0.3, 0)
shifted_plain = image(window)
shifted_renderer, shifted_window = parallel_view(None)
pan_camera(shifted_renderer.GetActiveCamera(), 0.3, 0)
check(sndf.GetNumberOfRestarts() == restarts and sndf.GetNumberOfSamples() == 0
      and np.array_equal(shifted_plain, image(shifted_window)),
      "a pan by 0.3 pixel: no restart, the plain image on the frame of the change")
image(window)
check(sndf.GetNumberOfSamples() == 64 and cache.GetNumberOfClearedTiles() > cleared,
      "then tiles of another grid phase, sampled from the first sample on")
pan_camera(renderer.GetActiveCamera(), -0.3, 0)
check(np.array_equal(image(window), before) and sndf.GetNumberOfSamplePasses() == passes + 64,
      "and back: the tiles of the first grid, converged")
# pans neither rebuild the lighting table nor rebake a tile, although the camera distance
# changes by rounding errors as position and focal point move together (the table once
# depended on the exact distance, and a pan of a 10^6-atom view could rebake ~900 tiles)
pan_sndf, pan_renderer, pan_window = converged_parallel_view()
pan_cam = pan_renderer.GetActiveCamera()
builds = pan_sndf.GetNumberOfTableBuilds()
rebaked = pan_sndf.GetTileCache().GetNumberOfRebakedTiles()
distances = set()
for k in range(12):
    pan_camera(pan_cam, (-1) ** k * (3 + k), 2 - k % 5)
    distances.add(pan_cam.GetDistance())
    image(pan_window)
check(len(distances) > 1 and pan_sndf.GetNumberOfTableBuilds() == builds
      and pan_sndf.GetTileCache().GetNumberOfRebakedTiles() == rebaked,
      "12 pans (%d distinct camera distances): no table built, no tile rebaked"
      % len(distances))
# a rotation restarts
renderer.GetActiveCamera().Azimuth(1)
image(window)
check(sndf.GetNumberOfRestarts() == restarts + 1, "a rotation restarts")
renderer.GetActiveCamera().Azimuth(-1)

# zoom out by one level: the level-1 tiles are averaged from level 0 (2x2), no sample is taken
# where level 0 was sampled; compared with rendering level 1 directly
sndf, renderer, window = converged_parallel_view()
level0 = image(window)
cache = sndf.GetTileCache()
restarts = sndf.GetNumberOfRestarts()
renderer.GetActiveCamera().SetParallelScale(32.0)
zoomed = image(window)
direct = pr.vtkSNDFRenderPass()
direct.SetSamplesPerFrame(64)
direct_renderer, direct_window = parallel_view(direct)
direct_renderer.GetActiveCamera().SetParallelScale(32.0)
image(direct_window)
converge(direct, direct_window)
level1 = image(direct_window)
# the middle half of the view: texels whose 2x2 finer texels were all in the level-0 view
middle = (slice(H // 4 + 1, 3 * H // 4 - 1), slice(W // 4 + 1, 3 * W // 4 - 1))
zoom_error = error(zoomed[middle], level1[middle])
print("zoom out by one level, averaged from level 0 vs level 1 rendered directly: mean %.2f "
      "p99 %.1f max %.1f /255 (%d tiles averaged)" % (zoom_error + (cache.GetNumberOfDownsampledTiles(),)))
check(sndf.GetNumberOfZooms() == 1 and sndf.GetNumberOfRestarts() == restarts
      and cache.GetNumberOfDownsampledTiles() > 0,
      "a zoom out by a factor 2 keeps the samples (averaged tiles, no restart)")
check(zoom_error[0] < 0.5 and zoom_error[1] < 4.0 and zoom_error[2] < 8.0,
      "zoomed out at once: within mean 0.5, p99 4, max 8 /255 of level 1 rendered directly")
converge(sndf, window)
whole = error(image(window), level1)
print("zoomed out and converged vs level 1 rendered directly: mean %.2f p99 %.1f max %.1f /255" % whole)
check(whole[0] < 0.5 and whole[2] < 8.0, "zoomed out and converged: level 1 within mean 0.5, max 8")
renderer.GetActiveCamera().SetParallelScale(16.0)
passes = sndf.GetNumberOfSamplePasses()
check(np.array_equal(image(window), level0) and sndf.GetNumberOfSamplePasses() == passes
      and sndf.GetNumberOfZooms() == 2,
      "zoom back in: the level-0 tiles from the cache, no sample")

# zoom between levels: off by default, a zoom by 1.25 samples anew; with ZoomBetweenLevels the
# view is the box filter of the nearest level's texels (the converged level-0 picture's pixels)
def box_filter_of(texels, factor):
    """What a parallel zoom by `factor` (parallel scale times it, about the view's centre) shows
    with ZoomBetweenLevels: each pixel the area-weighted mean of the level-0 texels under its
    footprint. Returns the picture and where the footprint lies within the level-0 view."""
    def weights(n):
        m = np.zeros((n, n))
        inside = np.ones(n, bool)
        for i in range(n):
            lo = n / 2 + (i - n / 2) * factor
            hi = lo + factor
            if lo < 0 or hi > n:
                inside[i] = False
                continue
            for j in range(int(np.floor(lo)), int(np.ceil(hi))):
                m[i, j] = min(hi, j + 1) - max(lo, j)
        return m / np.maximum(m.sum(axis=1, keepdims=True), 1e-30), inside
    wy, iy = weights(H)
    wx, ix = weights(W)
    return np.einsum("ij,jkc,lk->ilc", wy, texels, wx), np.outer(iy, ix)


def parallel_reference(scale):
    """The 16x16 super-sampled core of parallel_view() at another parallel scale."""
    ref_renderer, ref_window, _ = scene(xyz, rgb, (W * S, H * S))
    ref_renderer.GetActiveCamera().ParallelProjectionOn()
    ref_renderer.GetActiveCamera().SetParallelScale(scale)
    ref_renderer.ResetCameraClippingRange()
    return image(ref_window, W * S, H * S).reshape(H, S, W, S, 3).mean(axis=(1, 3))


sndf, renderer, window = converged_parallel_view()
restarts = sndf.GetNumberOfRestarts()
renderer.GetActiveCamera().SetParallelScale(20.0)
image(window)
check(sndf.GetNumberOfRestarts() == restarts + 1 and sndf.GetNumberOfSamples() == 0,
      "ZoomBetweenLevels off: a zoom by 1.25 samples anew (the plain image first)")
for factor in (1.25, 1.9, 0.84):
    sndf = pr.vtkSNDFRenderPass()
    sndf.SetSamplesPerFrame(64)
    sndf.ZoomBetweenLevelsOn()
    renderer, window = parallel_view(sndf)
    image(window)
    converge(sndf, window)
    level0 = image(window)
    restarts, zooms = sndf.GetNumberOfRestarts(), sndf.GetNumberOfZooms()
    renderer.GetActiveCamera().SetParallelScale(16.0 * factor)
    shown = image(window)
    if factor > 1.0:
        expected, inside = box_filter_of(level0, factor)
        d = np.abs(shown - expected)[inside]
        print("zoom out by %.2f between levels: the first frame vs the box filter of the level-0 "
              "picture: mean %.3f max %.1f /255 over %d pixels" % (factor, d.mean(), d.max(),
                                                                   inside.sum()))
        check(sndf.GetNumberOfRestarts() == restarts and d.max() <= 1.5,
              "zoom out by %.2f with ZoomBetweenLevels: no restart, where level 0 was sampled the "
              "box filter of its texels at once (max %.1f /255)" % (factor, d.max()))
    else:
        # (zoom in: the finer level -1 has no tile yet, the frame of the change is plain)
        check(sndf.GetNumberOfRestarts() == restarts and sndf.GetNumberOfSamples() == 0,
              "zoom in by %.2f with ZoomBetweenLevels: no restart, level -1 sampled from the "
              "next frame on" % (1.0 / factor))
    converge(sndf, window)
    zoomed = image(window)
    plain_renderer, plain_window = parallel_view(None)
    plain_renderer.GetActiveCamera().SetParallelScale(16.0 * factor)
    zoom_ref = parallel_reference(16.0 * factor)
    between = error(zoomed, zoom_ref)
    plain_error = error(image(plain_window), zoom_ref)
    print("  converged, against the 16x16 super-sampled view: mean %.2f p99 %.1f max %.1f /255 "
          "(the plain image: mean %.2f p99 %.1f)" % (between + plain_error[:2]))
    check(sndf.GetNumberOfRestarts() == restarts and sndf.GetConverged()
          and between[0] < 0.5 * plain_error[0] and between[1] < 0.5 * plain_error[1],
          "zoom by %.2f between levels, converged: no restart, nearer the super-sampled view "
          "than the plain image" % factor)
    renderer.GetActiveCamera().SetParallelScale(16.0)
    check(np.array_equal(image(window), level0) and sndf.GetNumberOfRestarts() == restarts,
          "and back at level 0: the picture before, no restart")

# re-light while tiles are out of view: they are rebaked when they come back, never stale
sndf, renderer, window = converged_parallel_view()
# (a pan by 150 pixels leaves the crystal out of the view: no tile of the first view is seen)
pan_camera(renderer.GetActiveCamera(), 150, 0)
image(window)
converge(sndf, window)
light = vtkLight()
light.SetLightTypeToSceneLight()
light.SetPosition(-30, 40, 20)
light.SetFocalPoint(8, 8, 8)
light.SetColor(0.9, 0.6, 0.5)
renderer.AddLight(light)
image(window)
rebaked = sndf.GetTileCache().GetNumberOfRebakedTiles()
passes = sndf.GetNumberOfSamplePasses()
restarts = sndf.GetNumberOfRestarts()
pan_camera(renderer.GetActiveCamera(), -150, 0)
relit_back = image(window)
fresh = pr.vtkSNDFRenderPass()
fresh.SetSamplesPerFrame(64)
fresh_renderer, fresh_window = parallel_view(fresh)
image(fresh_window)  # (the first render adds the headlight)
fresh_light = vtkLight()
fresh_light.DeepCopy(light)
fresh_renderer.AddLight(fresh_light)
image(fresh_window)
converge(fresh, fresh_window)
stale = np.abs(relit_back - image(fresh_window))
check(sndf.GetTileCache().GetNumberOfRebakedTiles() > rebaked and sndf.GetNumberOfRestarts() == restarts
      and sndf.GetNumberOfSamplePasses() == passes and stale.max() <= 1.0,
      "re-lit while out of view: the tiles rebaked on the pan back, no sample, the new light "
      "(max %.1f /255 from a pass that sampled under it)" % stale.max())

# a cache that holds one view's tiles only: the least recently used tiles make room (evicted),
# a pan back samples them again, never shows a wrong one
tiles = pr.vtkSNDFTileCache.GetTilesForView(W, H)
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(64)
sndf.SetMaximumMemory(tiles * pr.vtkSNDFTileCache.GetTileBytes(8) / 1048576.0 + 0.01)
messages = Messages(sndf)
renderer, window = parallel_view(sndf)
image(window)
converge(sndf, window)
cache = sndf.GetTileCache()
# four tiles at the start, 8 after a pan by (-30, -30), 10 wanted after (+60, +60): one evicted
pan_camera(renderer.GetActiveCamera(), -30, -30)
image(window)
converge(sndf, window)
first = image(window)
pan_camera(renderer.GetActiveCamera(), 60, 60)
image(window)
converge(sndf, window)
cleared = cache.GetNumberOfClearedTiles()
pan_camera(renderer.GetActiveCamera(), -60, -60)
image(window)
evicted = cache.GetNumberOfEvictedTiles()
check(cache.GetNumberOfSlots() == tiles and evicted > 0 and sndf.GetNumberOfSamples() < 256
      and cache.GetNumberOfClearedTiles() > cleared and not messages.warnings,
      "a cache of %d tiles: %d evicted by the pan, sampled again on the pan back" % (tiles, evicted))
converge(sndf, window)
lru = error(image(window), first)
check(lru[0] < 0.2 and lru[2] <= 4.0,
      "and converged again: the first picture (mean %.2f max %.1f /255, other jitter)" % (lru[0], lru[2]))

# a view whose tiles span several shader-storage buffers (llvmpipe: 128 MB blocks, 63 tiles of
# 8x8 bins each): every tile against the 4x4 super-sampled core
BW, BH = 640, 480
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(16)
sndf.SetTargetSamples(16)
renderer, window, _ = scene(xyz, rgb, (BW, BH), sndf)
image(window, BW, BH)
converge(sndf, window)
big = image(window, BW, BH)
cache = sndf.GetTileCache()
per_buffer = int(cache.GetBlockBytes() // (4096 * 4 * pr.vtkSNDFTileCache.GetWordsPerTexel(8)))
_, big_window, _ = scene(xyz, rgb, (4 * BW, 4 * BH))
big_ref = image(big_window, 4 * BW, 4 * BH).reshape(BH, 4, BW, 4, 3).mean(axis=(1, 3))
tile_errors = [np.abs(big[y:y + 64, x:x + 64] - big_ref[y:y + 64, x:x + 64]).mean()
               for y in range(0, BH, 64) for x in range(0, BW, 64)]
_, plain_big_window, _ = scene(xyz, rgb, (BW, BH))
plain_big = image(plain_big_window, BW, BH)
plain_tile_errors = [np.abs(plain_big[y:y + 64, x:x + 64] - big_ref[y:y + 64, x:x + 64]).mean()
                     for y in range(0, BH, 64) for x in range(0, BW, 64)]
excess = max(e - p for e, p in zip(tile_errors, plain_tile_errors))
print("640x480 (about 3 px per atom), %d tiles in a pool of %d slots, %d per storage buffer: "
      "tile mean errors against the 4x4 core up to %.2f /255 (plain image: %.2f)"
      % (cache.GetNumberOfTiles(), cache.GetNumberOfSlots(), per_buffer, max(tile_errors),
         max(plain_tile_errors)))
check(cache.GetNumberOfTiles() > per_buffer and excess < 0.5,
      "tiles over several storage buffers: no tile further from the 4x4 core than the plain "
      "image's (by %.2f /255 at most)" % excess)

# a zoom out whose finer tiles lie in two storage buffers (the averaging gathers them part by
# part): against level 1 rendered directly
def big_parallel(sndf, scale):
    renderer, window, _ = scene(xyz, rgb, (BW, BH), sndf)
    renderer.GetActiveCamera().ParallelProjectionOn()
    renderer.GetActiveCamera().SetParallelScale(scale)
    renderer.ResetCameraClippingRange()
    return renderer, window


def converged_big_parallel(scale):
    """A big_parallel view with a pass of 64 samples per frame, converged to 64 samples."""
    sndf = pr.vtkSNDFRenderPass()
    sndf.SetSamplesPerFrame(64)
    sndf.SetTargetSamples(64)
    renderer, window = big_parallel(sndf, scale)
    image(window, BW, BH)
    converge(sndf, window)
    return sndf, renderer, window


sndf, renderer, window = converged_big_parallel(6.0)
renderer.GetActiveCamera().SetParallelScale(12.0)
zoomed_big = image(window, BW, BH)
direct, _, direct_window = converged_big_parallel(12.0)
middle = (slice(BH // 4 + 1, 3 * BH // 4 - 1), slice(BW // 4 + 1, 3 * BW // 4 - 1))
big_zoom = error(zoomed_big[middle], image(direct_window, BW, BH)[middle])
cache = sndf.GetTileCache()
print("640x480 zoom out, %d tiles in the cache (%d per buffer), %d of them averaged: mean %.2f "
      "p99 %.1f max %.1f /255 from level 1 rendered directly (64 samples each)"
      % ((cache.GetNumberOfTiles(), per_buffer, cache.GetNumberOfDownsampledTiles()) + big_zoom))
check(cache.GetNumberOfTiles() - cache.GetNumberOfDownsampledTiles() > per_buffer
      and cache.GetNumberOfDownsampledTiles() > 0 and big_zoom[0] < 1.0 and big_zoom[1] < 8.0,
      "zoom out across storage buffers: within mean 1, p99 8 /255 of level 1 rendered directly")

# --- an error target stops refinement early: the estimate against the true distance to the
# 256-sample picture
for target in (2.0, 0.5):
    sndf = pr.vtkSNDFRenderPass()
    sndf.SetSamplesPerFrame(4)
    sndf.SetErrorTarget(target)
    renderer, window, _ = scene(xyz, rgb, (W, H), sndf)
    image(window)
    converge(sndf, window)
    early = image(window)
    true_error = np.abs(early - out).mean()
    print("error target %.1f /255: stopped at %d samples, estimate %.2f, distance to the "
          "256-sample picture %.2f /255" % (target, sndf.GetNumberOfSamples(),
                                             sndf.GetEstimatedError(), true_error))
    check(sndf.GetConverged() and sndf.GetNumberOfSamples() < 256
          and 0.0 < sndf.GetEstimatedError() <= target and true_error <= target,
          "error target %.1f: refinement stops early, the picture within the target of the "
          "converged one" % target)
    passes = sndf.GetNumberOfSamplePasses()
    image(window)
    check(sndf.GetNumberOfSamplePasses() == passes, "and takes no more samples")

# --- ConvergeOnRender: one Render() converges (also the render of a change), with progress ---
from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.util.vtkConstants import VTK_DOUBLE  # noqa: E402
from vtkmodules.vtkCommonCore import vtkCommand  # noqa: E402
sndf = pr.vtkSNDFRenderPass()
sndf.ConvergeOnRenderOn()
sndf.SetTargetSamples(256)
progress = []


@calldata_type(VTK_DOUBLE)
def on_progress(caller, event, fraction):
    progress.append((fraction, caller.GetProgressText()))


sndf.AddObserver(vtkCommand.ProgressEvent, on_progress)
renderer, window, _ = scene(xyz, rgb, (W, H), sndf)
at_once = image(window)
check(sndf.GetNumberOfSamples() == 256 and np.abs(at_once - out).max() <= 1.0,
      "ConvergeOnRender: the first render takes 256 samples, the progressive picture (max %.1f)"
      % np.abs(at_once - out).max())
check(len(progress) == 257 and progress[0][0] == 0.0 and progress[-1][0] == 1.0
      and all(b[0] > a[0] for a, b in zip(progress, progress[1:]))
      and "S-NDF" in progress[-1][1],
      "ConvergeOnRender: progress from 0 to 1 in 257 events, named S-NDF (%d, %s)"
      % (len(progress), progress[-1] if progress else None))

# --- bad input -------------------------------------------------------------------------------
# empty input: the plain image, no message
sndf = pr.vtkSNDFRenderPass()
messages = Messages(sndf)
renderer, window, _ = scene(np.zeros((0, 3)), np.zeros((0, 3), np.uint8), (W, H), sndf)
empty = image(window)
_, plain_empty_window, _ = scene(np.zeros((0, 3)), np.zeros((0, 3), np.uint8), (W, H))
check(np.array_equal(empty, image(plain_empty_window)) and not messages.errors,
      "empty input: the background, no error")

# memory below 4x4 bins: a warning, the plain image
sndf = pr.vtkSNDFRenderPass()
sndf.SetMaximumMemory(0.01)
messages = Messages(sndf)
renderer, window, _ = scene(xyz, rgb, (W, H), sndf)
small = image(window)
image(window)
check(np.array_equal(small, plain) and len(messages.warnings) == 1 and "MaximumMemory" in str(messages.text)
      and sndf.GetActiveBinsPerAxis() == 0, "no memory: one warning, the plain image")

# a limit between 4x4 and 8x8: 4x4 bins with a warning, still converging
sndf = pr.vtkSNDFRenderPass()
sndf.SetMaximumMemory(pr.vtkSNDFTileCache.GetTilesForView(W, H) * pr.vtkSNDFTileCache.GetTileBytes(4)
                      * 1.5 / 1048576.0)
sndf.SetSamplesPerFrame(64)
messages = Messages(sndf)
renderer, window, _ = scene(xyz, rgb, (W, H), sndf)
converge(sndf, window)
four_error = error(image(window), ref)
check(sndf.GetActiveBinsPerAxis() == 4 and len(messages.warnings) == 1 and four_error[0] < 1.5,
      "memory for 4x4 bins: a warning, 4x4 bins, mean %.2f /255" % four_error[0])

# a wrong bin count
sndf = pr.vtkSNDFRenderPass()
messages = Messages(sndf)
sndf.SetBinsPerAxis(5)
check(sndf.GetBinsPerAxis() == 8 and len(messages.errors) == 1, "5 bins refused with an error")

# resize while refining
sndf = pr.vtkSNDFRenderPass()
renderer, window, _ = scene(xyz, rgb, (W, H), sndf)
image(window)
image(window)
window.SetSize(W + 30, H + 20)
window.Render()
check(sndf.GetNumberOfSamples() == 0, "a resize restarts")
# (the picture is not read: vtkWindowToImageFilter crashes after this resize without the pass too)
window.Render()
check(sndf.GetNumberOfSamples() == sndf.GetSamplesPerFrame(), "and samples at the new size")
converge(sndf, window)
check(sndf.GetConverged(), "and converges at the new size")

# NaN / Inf positions: the finite particles' picture, no NaN
bad = xyz.copy()
bad[::7] = np.nan
bad[3::11] = np.inf
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(64)
renderer, window, _ = scene(bad, rgb, (W, H), sndf)
converge(sndf, window)
finite = image(window)
check(np.isfinite(finite).all() and np.abs(finite - ref).mean() < 20.0,
      "NaN/Inf positions: a finite picture")

# a translucent particle actor: a warning, the plain image
sndf = pr.vtkSNDFRenderPass()
messages = Messages(sndf)
renderer, window, actor = scene(xyz, rgb, (W, H), sndf)
actor.GetProperty().SetOpacity(0.5)
translucent = image(window)
# (the same pass chain without the S-NDF pass)
plain_renderer, plain_translucent_window, plain_actor = scene(xyz, rgb, (W, H))
plain_actor.GetProperty().SetOpacity(0.5)
plain_translucent = image(plain_translucent_window)
check(np.array_equal(translucent, plain_translucent) and len(messages.warnings) == 1,
      "a translucent particle actor: one warning, the plain image (%s)" % messages.text)

# a renderer that does not fill its window (the left half): a warning, the plain image
sndf = pr.vtkSNDFRenderPass()
sndf.SetSamplesPerFrame(4)
messages = Messages(sndf)
renderer, window, _ = scene(xyz, rgb, (2 * W, H), sndf)
renderer.SetViewport(0.0, 0.0, 0.5, 1.0)
half_view = image(window, 2 * W, H)
image(window, 2 * W, H)
plain_renderer, plain_window, _ = scene(xyz, rgb, (2 * W, H))
plain_renderer.SetViewport(0.0, 0.0, 0.5, 1.0)
plain_half = image(plain_window, 2 * W, H)
check(np.array_equal(half_view, plain_half) and len(messages.warnings) == 1 and
      sndf.GetNumberOfSamples() == 0,
      "a renderer not filling its window: one warning, the plain image (%s)" % messages.text)

sys.exit(finish())
