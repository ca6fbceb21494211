"""Run inside the ParaView GUI (paraview --script=...) by TestSNDFRefinementGUI.sh: a Particle
Render View with S-NDF shading on (16 samples per render, target 160: ten refinement renders,
more than the GUI's own renders after a script's) receives one still render from this script; the plugin's refinement behaviour must then render it again by itself until
the S-NDFs converge, and stop. Every render of the view writes "renders samples" to PR_RESULT
(an observer of the view proxy's EndEvent; the builtin session's pass reports its samples)."""
import os
import traceback

from paraview.simple import *  # noqa: F401,F403

CRYSTAL = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
g = np.arange(12)
base = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1).reshape(-1, 3).astype(float)
offsets = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
xyz = (base[:, None, :] + offsets[None]).reshape(-1, 3)
out = self.GetPolyDataOutput()
points = vtkPoints()
points.SetData(numpy_to_vtk(xyz, deep=True))
out.SetPoints(points)
"""
state = {"renders": 0}


def main():
    LoadPlugin(os.environ["PR_PLUGIN"], remote=False, ns=globals())
    crystal = ProgrammableSource()
    crystal.OutputDataSetType = "vtkPolyData"
    crystal.Script = CRYSTAL
    layout = GetLayout()
    Delete(GetActiveView())
    view = CreateView("ParticleRenderView")
    if GetLayout(view) is None:
        AssignViewToLayout(view=view, layout=layout, hint=0)
    SetActiveView(view)
    display = Show(crystal, view)
    display.Representation = "Particles"
    display.Radius = 0.36
    view.ScaleConsistentShading = 1
    view.SNDFSamplesPerFrame = 16
    view.SNDFTargetSamples = 160
    Render(view)
    view.CameraPosition = [30.0, 22.0, 40.0]
    view.CameraFocalPoint = [6.0, 6.0, 6.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]

    def ended(proxy, event):
        state["renders"] += 1
        proxy.UpdatePropertyInformation()
        samples = proxy.GetProperty("SNDFNumberOfSamples").GetElement(0)
        with open(os.environ["PR_RESULT"], "w") as result:
            result.write("%d %d\n" % (state["renders"], samples))

    view.SMProxy.AddObserver("EndEvent", ended)
    Render(view)  # the one still render asked for by the script: the render of a change


try:
    main()
except Exception:  # the GUI shows script errors only in its output window: keep them
    with open(os.environ["PR_RESULT"], "w") as result:
        result.write("error\n" + traceback.format_exc())
