"""Two views sharing one lookup table, rendered alternately, redo nothing per render.

A user's report: with a Point Gaussian view open in the same pvpython process and the two views
rendered alternately, the Particles view became slower. Whatever is redone per render when views
or contexts alternate (colour mapping of the shared lookup table, buffer upload, shader rebuild)
shows in the mapper's counters. Set-up: the LAMMPS film coloured by type through ParaView's one
"type" lookup table, shown with Particles in a Particle Render View (AO off), with Particles in a
plain Render View and with Point Gaussian (Sphere) in a third view. Checked:
- after the first round, 6 rounds of alternating renders with camera moves upload nothing and
  build no shader in either Particles mapper;
- a change of the shared lookup table (a colour) uploads each Particles mapper exactly once, and
  both show it (so the counters do count);
- the images of the two Particles views are equal (same data, camera and colours);
- the occlusion culler runs in both (ParaView's windows have no multisampling).

usage: pvpython TestTwoViewsSharedLookupTable.py --plugin ParticleRendering.so --data DIR ...
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import simple  # noqa: E402

import particlerendering  # noqa: E402,F401 (wraps the mapper objects reached below)

args = pr.parse_arguments()
pr.load_plugin(args)
failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message)


film, _ = pr.open_particles(args, "lj_film.vtp")
particle_view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=(300, 240))
particle_view.ParticleAmbientOcclusion = 'None'
render_view = pr.setup_view(simple.CreateView("RenderView"), size=(300, 240))
gaussian_view = pr.setup_view(simple.CreateView("RenderView"), size=(300, 240))
views = [particle_view, render_view, gaussian_view]

particles_a = pr.show_particles(film, particle_view)
particles_b = pr.show_particles(film, render_view)
gaussian = simple.Show(film, gaussian_view)
gaussian.Representation = "Point Gaussian"
gaussian.ShaderPreset = "Sphere"
gaussian.GaussianRadius = 0.5
simple.ColorBy(gaussian, ("POINTS", "type"))
gaussian.LookupTable = pr.type_lookup_table()
lut = pr.type_lookup_table()
if not (particles_a.LookupTable == lut and particles_b.LookupTable == lut):
    fail("the displays do not share the 'type' lookup table")


def particle_mapper(view):
    actors = view.GetClientSideObject().GetRenderer().GetActors()
    actors.InitTraversal()
    for _ in range(actors.GetNumberOfItems()):
        actor = actors.GetNextActor()
        mapper = actor.GetMapper()
        if mapper is not None and mapper.IsA("vtkParticleSphereMapper"):
            return mapper
    return None


for view in views:
    pr.set_camera(view, (20.0, -80.0, 60.0), (20.0, 20.0, 9.0))
    simple.Render(view)
mappers = [particle_mapper(particle_view), particle_mapper(render_view)]
if None in mappers:
    pr.finish(False)


def counters():
    return [(m.GetNumberOfUploads(), m.GetNumberOfShaderBuilds()) for m in mappers]


# ParaView's views have no multisampling: the occlusion culler works there (19 360 particles,
# above its threshold of 8192)
for view, mapper in zip((particle_view, render_view), mappers):
    reads = mapper.GetOcclusionCuller().GetLastNumberOfDepthReads()
    print("%s: %d depth read-backs of the occlusion culler" % (view.GetXMLName(), reads))
    if reads <= 0:
        fail("the occlusion culler does not run in the %s" % view.GetXMLName())

start = counters()
print("after the first renders (uploads, shader builds): %s" % start)
for round_ in range(6):
    for view in views:
        view.GetActiveCamera().Azimuth(5.0)
        simple.Render(view)
after = counters()
print("after 6 alternating rounds: %s" % after)
if after != start:
    fail("alternating renders redo work: (uploads, shader builds) %s -> %s" % (start, after))



def pass_chain(view):
    """The class names of the renderer's pass and its delegates."""
    chain = []
    render_pass = view.GetClientSideObject().GetRenderer().GetPass()
    while render_pass is not None and len(chain) < 16:
        chain.append(render_pass.GetClassName())
        render_pass = render_pass.GetDelegatePass() if hasattr(render_pass, "GetDelegatePass") \
            else None
    return chain


particle_chain = pass_chain(particle_view)
plain_chain = pass_chain(render_view)
print("passes: Particle Render View (AO off) %s, Render View %s" % (particle_chain, plain_chain))
# (the chain with no pass on renders its inner vtkPVDefaultPass directly; its cost against the
# Render View is measured in Benchmarks/view_overhead.py, not asserted here)
if particle_chain != ["vtkCameraPass", "vtkParticlePassChain"]:
    fail("unexpected passes in the Particle Render View: %s" % particle_chain)

# a change of the shared lookup table: one upload per Particles mapper
lut.IndexedColors = [0.30, 0.80, 0.30, 0.20, 0.55, 0.90]
for view in views:
    simple.Render(view)
changed = counters()
print("after a lookup-table change: %s" % changed)
for (uploads, builds), (uploads0, _) in zip(changed, after):
    if uploads != uploads0 + 1:
        fail("a lookup-table change uploaded %d times, not once" % (uploads - uploads0))
for view in views:
    simple.Render(view)
if counters() != changed:
    fail("a render after the lookup-table change redoes work: %s -> %s" % (changed, counters()))

image_a = pr.capture(particle_view, os.path.join(args.temp_dir, "TestTwoViewsA.png"))
image_b = pr.capture(render_view, os.path.join(args.temp_dir, "TestTwoViewsB.png"))
difference = pr.max_abs_difference(image_a, image_b)
print("largest difference between the two Particles views: %s" % difference)
if difference != 0:
    fail("the two Particles views differ by up to %s" % difference)

pr.finish(not failures)
