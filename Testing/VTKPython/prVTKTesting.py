"""Shared helpers of the plain-VTK-Python tests of ParticleRendering: a check that records
failures, the closing line, the capture of an object's VTK errors and warnings, scenes, and the
depth, coverage and normal errors of a picture against vtkParticleReferenceRenderer (compare)."""
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline

FAILURES = []


def check(condition, what):
    """Record a failed check (and print it). Returns the condition."""
    if not condition:
        FAILURES.append(what)
        print("FAIL: " + what)
    return condition


def finish():
    """The closing line and the exit status of a test."""
    print("%d failure(s)" % len(FAILURES))
    return 1 if FAILURES else 0


class Messages:
    """The error and warning texts a VTK object gives (they are then not printed)."""

    def __init__(self, obj):
        self.errors = []
        self.warnings = []
        obj.AddObserver("ErrorEvent", self.on_error)
        obj.AddObserver("WarningEvent", self.on_warning)

    @property
    def text(self):
        return self.errors + self.warnings

    @calldata_type(VTK_STRING)
    def on_error(self, obj, event, text):
        self.errors.append(text)

    @calldata_type(VTK_STRING)
    def on_warning(self, obj, event, text):
        self.warnings.append(text)


def time_steps(algorithm):
    """The TIME_STEPS of an algorithm's first output after UpdateInformation ([] when none)."""
    algorithm.UpdateInformation()
    info = algorithm.GetOutputInformation(0)
    key = vtkStreamingDemandDrivenPipeline.TIME_STEPS()
    return list(info.Get(key)) if info.Has(key) else []


def open_reader(reader, path):
    """Point a reader at a file, capture its messages and read its information: returns
    (reader, messages, time values)."""
    messages = Messages(reader)
    reader.SetFileName(path)
    return reader, messages, time_steps(reader)


def grab_image(window, repeat=True):
    """The window's RGB(A) pixels as an (N, components) int numpy array (the filter renders the
    window first). With repeat (the default: every image test of the suite), the same frame
    grabbed once more must be identical, bit for bit (vtkParticleImageComparison.TestIdentical),
    with no OpenGL error from the context's debug output (vtkParticleGLDebugLog), a failed check
    otherwise; repeat=False only for a progressive pass, whose next frame
    refines the picture. (vtkWindowToImageFilter renders with the view angle recomputed through
    atan(tan()): its frame may differ from a plain Render()'s in the last bit of the camera, so
    the repeat is grabbed the same way.)"""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    first = _filter_grab(window)
    if repeat:
        _REPEATS[0] += 1
        name = _repeat_name()
        import particlerendering as pr
        # the second frame under the context's debug output (as TestRepeatable)
        log = pr.vtkParticleGLDebugLog.GetInstance()
        log.StartFrame(window)
        again = _filter_grab(window)
        check(log.EndFrame(name), "%s: OpenGL error(s) while the frame was drawn" % name)
        check(pr.vtkParticleImageComparison.TestIdentical(first, again, name),
              "%s: the same frame drawn twice differs" % name)
    return vtk_to_numpy(first.GetPointData().GetScalars()).astype(int)


def _filter_grab(window):
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    image = vtkImageData()
    image.DeepCopy(grab.GetOutput())
    return image


_REPEATS = [0]


def _repeat_name():
    import os
    import sys
    return "%s frame %d" % (os.path.basename(sys.argv[0]), _REPEATS[0])


def check_repeatable(window, name=None):
    """The repeatability check: the window's frame drawn twice must be identical, bit for bit
    (vtkParticleImageComparison.TestRepeatable; a failed check otherwise). Returns whether it
    is."""
    import particlerendering as pr
    _REPEATS[0] += 1
    name = name or _repeat_name()
    return check(pr.vtkParticleImageComparison.TestRepeatable(window, name),
                 "%s: the same frame drawn twice differs" % name)


def picked_ids(renderer, area):
    """The ids the hardware selector reports in the pixel rectangle area (x0, y0, x1, y1)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkRenderingCore import vtkHardwareSelector
    selector = vtkHardwareSelector()
    selector.SetRenderer(renderer)
    selector.SetArea(*area)
    selection = selector.Select()
    ids = set()
    for i in range(selection.GetNumberOfNodes()):
        ids.update(vtk_to_numpy(selection.GetNode(i).GetSelectionList()).tolist())
    return ids


def particles_from(xyz, **arrays):
    """A vtkPolyData with the points xyz (an (N, 3) array, its precision kept) and one point
    array per keyword (name=values)."""
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz), deep=True))
    data = vtkPolyData()
    data.SetPoints(points)
    for name, values in arrays.items():
        array = numpy_to_vtk(np.ascontiguousarray(values), deep=True)
        array.SetName(name)
        data.GetPointData().AddArray(array)
    return data


def offscreen_window(renderer, size=(200, 200), samples=0):
    """An off-screen render window of `size` showing `renderer`, multisampling `samples`."""
    from vtkmodules.vtkRenderingCore import vtkRenderWindow
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(samples)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    return window


def crystal_view(xyz, rgb, size, sndf=None, radius=0.36, position=(40, 30, 55),
                 focal_point=(8, 8, 8), background=(0.1, 0.1, 0.12), specular=0.0):
    """Particles at xyz coloured by rgb ((N, 3) uint8, direct scalars) with a constant radius, in
    an off-screen window of `size` whose renderer runs vtkCameraPass -> [sndf ->]
    vtkRenderStepsPass (with sndf, a vtkSNDFRenderPass, in between when given); camera at
    `position` looking at `focal_point`, y up, headlight. Returns (renderer, window, actor)."""
    import particlerendering as pr
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
    from vtkmodules.vtkRenderingOpenGL2 import vtkCameraPass, vtkRenderStepsPass
    data = particles_from(xyz)
    colours = numpy_to_vtk(rgb, deep=True)
    colours.SetName("rgb")
    data.GetPointData().SetScalars(colours)
    mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputData(data)
    mapper.SetRadius(radius)
    mapper.SetColorModeToDirectScalars()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetSpecular(specular)
    actor.GetProperty().SetSpecularPower(20)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(*background)
    window = offscreen_window(renderer, size)
    camera_pass = vtkCameraPass()
    if sndf is None:
        camera_pass.SetDelegatePass(vtkRenderStepsPass())
    else:
        camera_pass.SetDelegatePass(sndf)
        sndf.SetDelegatePass(vtkRenderStepsPass())
    renderer.SetPass(camera_pass)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*position)
    camera.SetFocalPoint(*focal_point)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCameraClippingRange()
    return renderer, window, actor


def window_pixels(window, width, height):
    """The RGB picture in the window's back buffer as a (height, width, 3) float array, read
    without rendering again (a progressive pass would take another step)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ShouldRerenderOff()
    grab.ReadFrontBufferOff()
    grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    return pixels[:, :3].reshape(height, width, 3).astype(float)


def image_error(a, b):
    """(mean, 99th percentile of the per-pixel largest channel, max) of |a - b| in 1/255."""
    import numpy as np
    d = np.abs(np.asarray(a, float) - np.asarray(b, float))
    return d.mean(), np.percentile(d.max(axis=-1), 99), d.max()


def actor_view(mapper, size=(200, 200)):
    """An actor with `mapper` alone in a renderer of an off-screen window of `size` (no
    multisampling): returns (actor, renderer, window)."""
    from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    return actor, renderer, offscreen_window(renderer, size)


def transparent_view(mapper, size):
    """actor_view with a transparent black background and alpha bit planes, for images that are
    composited "over" one another (composite_over): returns (actor, renderer, window)."""
    actor, renderer, window = actor_view(mapper, size)
    renderer.SetBackground(0.0, 0.0, 0.0)
    renderer.SetBackgroundAlpha(0.0)
    window.SetAlphaBitPlanes(1)
    return actor, renderer, window


def composite_over(front, back):
    """Premultiplied 8-bit RGBA rows (numpy, N x 4) composited front "over" back, as IceT does."""
    return front + (1.0 - front[:, 3:4] / 255.0) * back


def fcc_lattice(cells, constant=1.0):
    """The atoms of an fcc lattice of cells = (nx, ny, nz) unit cells (4 atoms each, the cell
    at the origin first, z fastest) with the given lattice constant, as an (N, 3) float array."""
    import numpy as np
    axes = [np.arange(n) for n in cells]
    base = np.stack(np.meshgrid(*axes, indexing="ij"), -1).reshape(-1, 3).astype(float)
    offsets = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
    return ((base[:, None, :] + offsets[None]) * constant).reshape(-1, 3)


def fcc_crystal(cells, fraction=0.3, seed=1):
    """An fcc crystal of cells^3 unit cells (lattice constant 1, 4 atoms each) of two species:
    returns (xyz, rgb), a random `fraction` of the atoms red (220, 60, 40), the others blue
    (90, 140, 230), as uint8."""
    import numpy as np
    xyz = fcc_lattice((cells, cells, cells))
    species = np.random.default_rng(seed).random(len(xyz)) < fraction
    rgb = np.where(species[:, None], [220, 60, 40], [90, 140, 230]).astype(np.uint8)
    return xyz, rgb


def append_csv(path, header, row):
    """Append `row` (floats as %.6g) to the CSV at `path`, writing `header` (its column names,
    one line) first when the file is new; prints the header and the row."""
    import os
    header = header.rstrip("\n") + "\n"
    new = not os.path.exists(path)
    with open(path, "a") as f:
        if new:
            f.write(header)
        f.write(",".join("%.6g" % v if isinstance(v, float) else str(v) for v in row) + "\n")
    print(header + ",".join(str(v) for v in row))


def pan_camera(camera, pixels_right, pixels_up, height):
    """Move position and focal point of a parallel-projection camera together in the view
    plane by whole (or fractional) pixels of a view `height` pixels high."""
    import numpy as np
    pixel = 2.0 * camera.GetParallelScale() / height
    m = camera.GetViewTransformMatrix()
    right = np.array([m.GetElement(0, a) for a in range(3)])
    up = np.array([m.GetElement(1, a) for a in range(3)])
    move = pixel * (pixels_right * right + pixels_up * up)
    camera.SetPosition(*(np.array(camera.GetPosition()) + move))
    camera.SetFocalPoint(*(np.array(camera.GetFocalPoint()) + move))


def gas_and_slab(count=100000, seed=7):
    """A LAMMPS-like scene of `count` particles (radius 0.5, lattice units): a dense FCC slab of
    40 x 40 x 11 cells (70 400 atoms, lattice constant 1.5874, type 1) between two layers of gas
    (the rest, uniform random, 40 units thick above and below the slab, type 2). Returns
    (xyz, radius, type) as float64, float32 and int32 arrays."""
    import numpy as np
    a = 1.5874
    slab = fcc_lattice((40, 40, 11), a)[:count]
    rng = np.random.default_rng(seed)
    n_gas = count - len(slab)
    gas = rng.random((n_gas, 3)) * [40 * a, 40 * a, 80.0]
    gas[:, 2] = np.where(gas[:, 2] < 40.0, gas[:, 2] - 40.0, gas[:, 2] - 40.0 + 11 * a)
    xyz = np.vstack([slab, gas])
    kinds = np.r_[np.ones(len(slab), np.int32), np.full(n_gas, 2, np.int32)]
    return xyz, np.full(len(xyz), 0.5, np.float32), kinds


def gpu_view_depth(window, reference):
    """The window's depth buffer as distances along the reference's pixel rays (-1: none)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkFloatArray
    from vtkmodules.vtkCommonDataModel import vtkImageData
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
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
    from vtkmodules.vtkRenderingOpenGL2 import vtkLightingMapPass
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
    import numpy as np
    import particlerendering as pr
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkFloatArray
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


def random_quaternions(count, rng):
    """`count` unit quaternions (w, x, y, z) uniformly distributed over the rotations (numpy)."""
    import numpy as np
    q = rng.normal(size=(count, 4))
    return q / np.linalg.norm(q, axis=1)[:, None]


def quaternion_rotations(q):
    """The rotation matrices (N, 3, 3) of unit quaternions q (N, 4) = (w, x, y, z): a body
    vector b is R b in the model frame (LAMMPS's and vtkParticleSphereMapper's convention)."""
    import numpy as np
    w, x, y, z = np.asarray(q, dtype=np.float64).T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1)], 1)
