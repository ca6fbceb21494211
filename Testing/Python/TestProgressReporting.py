"""Long rendering work reaches ParaView's progress bar. ParaView listens to the progress of the
algorithms registered with the session's progress handler, and only while a render or an update
runs; our long work happens inside a render, in a mapper (particle upload, depth sort) and in a
render pass (the AO density volume), neither of which ParaView listens to. The Particles
representation passes its mapper's progress on, the Particle Render View its pass's (through an
algorithm it registers).

Checked, with 1.1 million translucent particles (above the default threshold of 2^20) and
density-volume AO in the Particle Render View:
- the session's progress handler (what the GUI's progress bar shows) receives, during the first
  render, progress with the texts "Uploading N particles", "Sorting N translucent particles" and
  "Ambient occlusion: density volume of N particles";
- the representation passes on every report of its mapper, from 0 to 1 without going back: the
  upload's stages (0, 0.15, 0.3, 1) and the sort's radix passes (0, 1/p, ..., 1 for its p
  passes) (the volume build's own sequence is checked in plain VTK, TestProgressEvents);
- a second render after a camera move sorts again (and reports it) but neither uploads nor
  rebuilds the volume (and reports neither);
- 10 000 particles (below the threshold) report nothing.

usage: pvpython TestProgressReporting.py --plugin ParticleRendering.so --data DIR
           --baseline-dir DIR --temp-dir DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import prParaViewTesting as pr  # noqa: E402
from paraview import servermanager, simple  # noqa: E402

args = pr.parse_arguments()
pr.load_plugin(args)
ok = True


def fail(message):
    global ok
    ok = False
    print("FAIL: " + message)


LARGE = 1100000
SMALL = 10000

handler = servermanager.ActiveConnection.Session.GetProgressHandler()
handler.SetProgressInterval(0.01)  # the smallest: keep (almost) every report
received = []


def on_handler_progress(obj, event):
    received.append((obj.GetLastProgressText() or "", obj.GetLastProgress()))


handler.AddObserver("ProgressEvent", on_handler_progress)

view = pr.setup_view(simple.CreateView("ParticleRenderView"), size=(400, 300))
view.ParticleAmbientOcclusion = 'Density Volume'
# a ball of random points; vtkPointSource makes single-precision points and a vertex cell
source = simple.PointSource(NumberOfPoints=LARGE, Radius=60.0)
display = pr.show_particles(source, view, color_by_type=False, use_radius_array=False)
display.Radius = 0.5
display.Opacity = 0.5
# the random points overlap: keep the sorted path, whose sort's progress this test is about
display.OverlapCompositing = "Sorted Spheres"

# what the representation passes on from its mapper (unthrottled: every report)
representation = display.GetClientSideObject().GetActiveRepresentation()
reports = {}  # text -> list of fractions


def on_representation_progress(obj, event):
    text = obj.GetProgressText() or ""
    if "particles" in text:
        reports.setdefault(text, []).append(round(obj.GetProgress(), 6))


representation.AddObserver("ProgressEvent", on_representation_progress)

texts = {
    "upload": "Uploading %d particles" % LARGE,
    "sort": "Sorting %d translucent particles" % LARGE,
    "volume": "Ambient occlusion: density volume of %d particles" % LARGE,
}

simple.Render(view)

# 1. what ParaView's progress bar receives
handler_texts = set(text for text, _ in received)
for key, text in texts.items():
    values = [value for t, value in received if t == text]
    print("handler: %-55s %d reports, %s" % (text, len(values), values))
    if not values:
        fail("the session's progress handler received no progress for %r" % text)
    elif any(v < 0 or v > 100 for v in values):
        fail("progress for %r outside 0..100: %s" % (text, values))

# 2. from the representation: complete, ordered reports of the upload and the sort (the
# volume build's sequence is checked in plain VTK, TestProgressEvents)
# (the first render may sort more than once: ParaView resets the camera in it)


def runs(fractions):
    """The reports split into runs, each starting at 0."""
    result = []
    for value in fractions:
        if value == 0.0 or not result:
            result.append([])
        result[-1].append(value)
    return result


for key in ("upload", "sort"):
    text = texts[key]
    print("representation: %-45s %s" % (text, reports.get(text, [])))
    for run in runs(reports.get(text, [])) or [[]]:
        if not run or run[0] != 0.0 or run[-1] != 1.0:
            fail("%r does not run from 0 to 1: %s" % (text, run))
        if any(b < a for a, b in zip(run, run[1:])):
            fail("%r goes back: %s" % (text, run))
upload = reports.get(texts["upload"], [])
if upload != [0.0, 0.15, 0.3, 1.0]:
    fail("the upload's stages are %s, not [0, 0.15, 0.3, 1] once" % upload)
for sort in runs(reports.get(texts["sort"], [])):
    passes = len(sort) - 1
    if not 1 <= passes <= 8 or sort != [round(i / passes, 6) for i in range(passes + 1)]:
        fail("the sort's reports %s are not 0, 1/p, ..., 1 for p radix passes" % sort)

# 3. a camera move: one more sort, no upload, no volume build
reports.clear()
del received[:]
camera = view.GetActiveCamera()
camera.Azimuth(30.0)
simple.Render(view)
moved = sorted(set(text for text, _ in received) | set(reports))
print("after a camera move, reported: %s" % moved)
if moved != [texts["sort"]]:
    fail("after a camera move the reports are %s, expected the sort alone" % moved)

# 4. below the threshold nothing is reported
reports.clear()
del received[:]
source.NumberOfPoints = SMALL
simple.Render(view)
ours = sorted(set(text for text, _ in received if "particles" in text) | set(reports))
print("with %d particles, reported: %s" % (SMALL, ours))
if ours:
    fail("%d particles (below the threshold) reported progress: %s" % (SMALL, ours))

pr.finish(ok)
