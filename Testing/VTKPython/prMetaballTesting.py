"""Helpers of the metaball tests and benchmarks: the depth and normal errors of a
vtkMetaballMapper picture against the exact surface of vtkParticleReferenceRenderer (metaball
mode), in units of a radius, over the pixels both cover."""
import numpy as np

import particlerendering as pr
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkLookupTable, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingOpenGL2 import vtkLightingMapPass


def metaball_view(xyz, size=(300, 300), radius=1.0, **arrays):
    """A vtkMetaballMapper of the particles xyz with constant `radius` and point arrays, in an
    offscreen window: (mapper, actor, renderer, window)."""
    from prVTKTesting import actor_view, particles_from
    mapper = pr.vtkMetaballMapper()
    mapper.SetInputData(particles_from(np.asarray(xyz, dtype=np.float64), **arrays))
    mapper.SetRadius(radius)
    actor, renderer, window = actor_view(mapper, size)
    return mapper, actor, renderer, window


def isolated_views(walking=False):
    """The isolated-particle scenes of the metaball tests: three particles far apart, seen near,
    with the camera 1e7 R away, and with the data 1e6 from the origin. Yields (name, far camera,
    mapper, actor, renderer, window), rendered once."""
    for name, offset, distance in (("near", 0.0, None), ("camera 1e7 R away", 0.0, 1e7),
                                   ("data 1e6 from the origin", 1e6, None)):
        xyz = np.array([[0.0, 0.0, 0.0], [5.0, 0.3, -0.2], [-4.0, 3.0, 1.0]]) + offset
        mapper, actor, renderer, window = metaball_view(xyz, (200, 200))
        if walking:
            mapper.SetMethodToWalkingDepthPlane()
            mapper.SetTimeBudget(1000.0)  # to convergence whatever the load
            mapper.SetMaximumPasses(1000)
        renderer.ResetCamera()
        if distance:
            camera = renderer.GetActiveCamera()
            camera.SetPosition(offset, offset, offset + distance)
            camera.SetFocalPoint(offset, offset, offset)
            camera.SetViewAngle(6e-6 * 30)  # the spheres fill the view from 1e7 R away
            renderer.ResetCameraClippingRange()
        window.Render()
        yield name, bool(distance), mapper, actor, renderer, window


def thin_neck(walking=False):
    """The paper's thin-neck situation (its Fig. 10/11): two particles 0.1 % short of the
    largest distance at which they connect (k = 2), seen across the neck. Returns the neck's
    radius (R), the reference's pixels in the columns within a pixel of the mid-plane, how many
    of them the GPU shows too, and the comparison."""
    k, c = 2.0, 16.0 / 9.0
    d = 2.0 * k * np.sqrt(1.0 - np.sqrt(1.0 / (2.0 * c))) * 0.999
    neck = np.sqrt(k * k * (1.0 - np.sqrt(1.0 / (2.0 * c))) - d * d / 4.0)
    mapper, actor, renderer, window = metaball_view([[-d / 2, 0, 0], [d / 2, 0, 0]], (400, 200))
    if walking:
        mapper.SetMethodToWalkingDepthPlane()
        mapper.SetTimeBudget(1000.0)  # to convergence whatever the load
        mapper.SetMaximumPasses(1000)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 0, 20)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewAngle(15)
    renderer.ResetCameraClippingRange()
    window.Render()
    r = compare(window, renderer, actor, 1.0)
    width, height = window.GetSize()
    reference_t = vtk_to_numpy(r["reference"].GetViewDepthImage().GetPointData().GetScalars())
    mid = np.abs(np.arange(width * height) % width - (width - 1) / 2.0) <= 1
    return neck, int(np.sum((reference_t >= 0) & mid)), int(np.sum(r["both"] & mid)), r


def droplet(seed=3):
    """The tests' droplet: 291 particles on a jittered lattice within 6 R, and 60 vapour atoms
    in a 28 R box; returns the positions and the type (0 droplet, 1 vapour)."""
    rng = np.random.default_rng(seed)
    g = np.mgrid[-3:4, -3:4, -3:4].reshape(3, -1).T * 1.9
    g = g[np.linalg.norm(g, axis=1) < 6.0]
    g = g + rng.normal(0, 0.25, g.shape)
    vapour = rng.uniform(-14, 14, (60, 3))
    return np.vstack([g, vapour]), np.r_[np.zeros(len(g)), np.ones(len(vapour))]


def type_lookup_table(first, last):
    """The two-colour table of the metaball tests and benchmarks: orange for the type `first`,
    blue for `last`."""
    lut = vtkLookupTable()
    lut.SetNumberOfTableValues(2)
    lut.SetTableValue(0, 0.85, 0.33, 0.10)
    lut.SetTableValue(1, 0.12, 0.47, 0.80)
    lut.SetTableRange(first, last)
    lut.Build()
    return lut


def gpu_view_depth(window, reference):
    """The window's depth buffer as distances along the reference's pixel rays (-1: none)."""
    width, height = window.GetSize()
    z = vtkFloatArray()
    window.GetZbufferData(0, 0, width - 1, height - 1, z)
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    image.GetPointData().SetScalars(z)
    out = vtkImageData()
    reference.WindowDepthToViewDepth(image, out)
    return vtk_to_numpy(out.GetPointData().GetScalars()).copy()


def gpu_normals(window, actor):
    """The view-coordinate normals the mapper lights with (vtkLightingMapPass's normal output,
    8 bits per component), one unit vector per pixel."""
    keys = actor.GetPropertyKeys()
    from vtkmodules.vtkCommonCore import vtkInformation
    info = vtkInformation()
    info.Set(vtkLightingMapPass.RENDER_NORMALS(), 1)
    actor.SetPropertyKeys(info)
    actor.GetMapper().Modified()  # the keys alone do not rebuild the shaders
    window.Render()
    width, height = window.GetSize()
    rgba = vtkUnsignedCharArray()
    window.GetRGBACharPixelData(0, 0, width - 1, height - 1, 0, rgba)
    actor.SetPropertyKeys(keys)
    actor.GetMapper().Modified()
    n = vtk_to_numpy(rgba)[:, :3].astype(np.float64) / 255.0 * 2.0 - 1.0
    length = np.linalg.norm(n, axis=1)
    return n / np.maximum(length, 1e-12)[:, None]


def compare(window, renderer, actor, radius, normals=False):
    """Render the reference of `actor` at the window's size and compare. Returns a dict:
    covered (pixels both show), only_gpu, only_ref (pixels one of them shows; the reference's
    pixels whose ray starts inside the surface are left out), depth errors in units of `radius`
    (mean, p99, max over the covered pixels), max_window (the largest window-depth difference
    outside silhouettes: the depth buffer's own resolution is 2^-24), silhouette (covered pixels whose reference depth
    jumps by more than one radius to a neighbour: ill-conditioned, counted apart), max_smooth
    (the largest error elsewhere), the masks both and smooth (covered, not silhouette), the GPU's
    view depth gpu_depth, and with normals=True the normal angle errors in degrees."""
    width, height = window.GetSize()
    reference = pr.vtkParticleReferenceRenderer()
    reference.SetRenderer(renderer)
    reference.SetActor(actor)
    reference.SetImageSize(width, height)
    reference.Render()
    gt = gpu_view_depth(window, reference)
    zbuffer = vtkFloatArray()
    window.GetZbufferData(0, 0, width - 1, height - 1, zbuffer)
    gz = vtk_to_numpy(zbuffer).astype(np.float64)
    rz = vtk_to_numpy(reference.GetDepthImage().GetPointData().GetScalars())
    rt = vtk_to_numpy(reference.GetViewDepthImage().GetPointData().GetScalars()).copy()
    inside = vtk_to_numpy(reference.GetInsideImage()) != 0
    both = (gt >= 0) & (rt >= 0)
    err = np.where(both, np.abs(gt - rt), 0.0) / radius
    grid = rt.reshape(height, width)
    padded = np.pad(grid, 1, mode="edge")
    jump = np.zeros_like(grid)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            shifted = padded[1 + dy:1 + dy + height, 1 + dx:1 + dx + width]
            jump = np.maximum(jump, np.where(shifted >= 0, np.abs(shifted - grid), np.inf))
    silhouette = both & (jump.ravel() > radius)
    e = err[both]
    result = {
        "covered": int(both.sum()),
        "only_gpu": int(((gt >= 0) & (rt < 0) & ~inside).sum()),
        "only_ref": int(((gt < 0) & (rt >= 0)).sum()),
        "mean": float(e.mean()) if e.size else 0.0,
        "p99": float(np.percentile(e, 99)) if e.size else 0.0,
        "max": float(e.max()) if e.size else 0.0,
        "silhouette": int(silhouette.sum()),
        "max_window": float(np.abs(gz - rz)[both & ~silhouette].max())
        if (both & ~silhouette).any() else 0.0,
        "max_smooth": float(err[both & ~silhouette].max()) if (both & ~silhouette).any() else 0.0,
        "reference_seconds": reference.GetLastRenderSeconds(),
        "reference": reference,
        "error": err,
        "both": both,
        "smooth": both & ~silhouette,
        "gpu_depth": gt,
    }
    if normals:
        nr = vtk_to_numpy(reference.GetNormalImage().GetPointData().GetScalars()).reshape(-1, 3)
        ng = gpu_normals(window, actor)
        cosine = np.clip(np.sum(nr * ng, axis=1), -1.0, 1.0)
        angle = np.degrees(np.arccos(cosine))[both & ~silhouette]
        result["normal_mean"] = float(angle.mean()) if angle.size else 0.0
        result["normal_p99"] = float(np.percentile(angle, 99)) if angle.size else 0.0
        window.Render()
    return result
