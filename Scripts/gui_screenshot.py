"""Run inside the ParaView GUI (paraview --script=...): the README's first minute with a LAMMPS
dump series. Called by Scripts/gui_screenshot.sh, which sets PR_PLUGIN, PR_DUMPS and PR_DONE."""
import glob
import os
import traceback

from paraview.simple import *  # noqa: F401,F403



def main():
    LoadPlugin(os.environ["PR_PLUGIN"], remote=False, ns=globals())
    files = sorted(glob.glob(os.path.join(os.environ["PR_DUMPS"], "*.dump")),
                   key=lambda f: int(f.split(".")[-2]))
    run = OpenDataFile(files)
    RenameSource("lj_droplets.dump", run)

    # the layout's Render View becomes a Particle Render View (AO lives there)
    layout = GetLayout()
    Delete(GetActiveView())
    view = CreateView("ParticleRenderView")
    if GetLayout(view) is None:  # the GUI usually puts a new view into the empty frame itself
        AssignViewToLayout(view=view, layout=layout, hint=0)
    SetActiveView(view)

    display = Show(run, view)                 # Particles, radii from the reader's "radius"
    ColorBy(display, ("POINTS", "type"))
    types = GetColorTransferFunction("type")  # two atom types: two colours
    types.InterpretValuesAsCategories = 1
    types.Annotations = ["1", "type 1", "2", "type 2"]
    types.IndexedColors = [0.85, 0.35, 0.2, 0.2, 0.55, 0.9]
    display.SetScalarBarVisibility(view, True)
    display.Opacity = 0.7                     # translucency; "Opacity Of": Column Through The Data
    view.ParticleAmbientOcclusion = 'Density Volume'
    box = Show(OutputPort(run, 1), view)      # the simulation box
    box.DiffuseColor = [0.7, 0.7, 0.7]

    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = run.TimestepValues[-1]
    Render(view)  # the first render resets the camera: place it afterwards
    view.CameraPosition = [80.0, -66.0, 70.0]
    view.CameraFocalPoint = [40.0, 40.0, 33.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    SetActiveSource(run)
    Render(view)


try:
    main()
    status = "rendered\n"
except Exception:  # the GUI shows script errors only in its output window: keep them
    status = traceback.format_exc()
with open(os.environ["PR_DONE"], "w") as done:
    done.write(status)
