"""Run inside the ParaView GUI (paraview --script=...) by TestEllipsoidsGUI.sh: the bundled LAMMPS
ellipsoid dump (PR_DATA/gb_ellipsoids.lammpstrj.gz) opened with OpenDataFile and shown in a
Particle Render View, as a user of the GUI does; the Particles representation's Shape Automatic
must draw oriented ellipsoids opaque, with voxel-cone ambient occlusion and translucent. Each
picture is saved (PR_WORK/<name>.png) and a line "<name> <draws ellipsoids> <mean brightness>"
goes to PR_RESULT, then "done"; errors go there as "error" and a traceback."""
import os
import traceback

from paraview.simple import *  # noqa: F401,F403

import particlerendering  # noqa: F401,E402 (the plugin's classes in Python: the mapper's methods)


def mean_brightness(path):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return float(vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].mean())


def draws_ellipsoids(view):
    actors = view.GetRenderer().GetActors()
    actors.InitTraversal()
    for _ in range(actors.GetNumberOfItems()):
        actor = actors.GetNextActor()
        mapper = actor.GetMapper()
        if actor.GetVisibility() and mapper is not None and mapper.IsA("vtkParticleSphereMapper"):
            return int(mapper.GetDrawsEllipsoids())
    return -1


def main():
    LoadPlugin(os.environ["PR_PLUGIN"], remote=False, ns=globals())
    rods = OpenDataFile(os.path.join(os.environ["PR_DATA"], "gb_ellipsoids.lammpstrj.gz"))
    layout = GetLayout()
    Delete(GetActiveView())
    view = CreateView("ParticleRenderView")
    if GetLayout(view) is None:
        AssignViewToLayout(view=view, layout=layout, hint=0)
    SetActiveView(view)
    display = Show(rods, view)
    ColorBy(display, ("POINTS", "velocity", "Magnitude"))
    view.CameraPosition = [-40.0, -55.0, 50.0]
    view.CameraFocalPoint = [7.5, 7.5, 16.5]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    # (enumeration properties print quoted)
    lines = ["representation %s shape %s" % (str(display.Representation).strip("'"),
                                               str(display.Shape).strip("'"))]
    for name, settings in (("opaque", {}),
                           ("ao", {"view.ParticleAmbientOcclusion": "Voxel Cone Tracing"}),
                           ("translucent", {"display.Opacity": 0.8})):
        for key, value in settings.items():
            owner, prop = key.split(".")
            setattr(display if owner == "display" else view, prop, value)
        Render(view)
        path = os.path.join(os.environ["PR_WORK"], name + ".png")
        SaveScreenshot(path, view, ImageResolution=[500, 400])
        lines.append("%s %d %.2f" % (name, draws_ellipsoids(view.GetClientSideObject()),
                                     mean_brightness(path)))
    with open(os.environ["PR_RESULT"], "w") as result:
        result.write("\n".join(lines) + "\ndone\n")


try:
    main()
except Exception:  # the GUI shows script errors only in its output window: keep them
    with open(os.environ["PR_RESULT"], "w") as result:
        result.write("error\n" + traceback.format_exc())
