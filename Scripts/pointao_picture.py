"""The README's side-by-side picture of ambient occlusion on opaque particles, from plain VTK
Python: the LAMMPS liquid film (Testing/Data/lj_film.vtp, coloured by type) with no AO,
vtkSSAOPass (ParaView's "Use Ambient Occlusion"), vtkPointAOPass (PointAO), the density volume
(vtkDensityVolumeAOPass) and voxel cones (vtkVoxelConeAOPass), each with its defaults (SSAO:
radius two mean radii, 32 samples, blur; the density volume at the view's strength 2).

usage: PYTHONPATH=build/lib/python3/dist-packages Scripts/with_xvfb.sh /usr/bin/python3 \
           Scripts/pointao_picture.py [--out Plugin/Documentation/pointao-film.png]
"""
import argparse

import particlerendering as pr
from prPictures import window_rgb, write_panels
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass, vtkSSAOPass
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)

METHODS = ("none", "ssao", "pointao", "density-volume", "voxel-cone")


def ambient_occlusion(method):
    """The pass of a method (None for no AO)."""
    if method == "ssao":
        ssao = vtkSSAOPass()
        ssao.SetRadius(2 * 0.475)  # two mean radii of the film's atoms
        ssao.SetKernelSize(32)
        ssao.BlurOn()
        return ssao
    if method == "pointao":
        # --- the example of the README: PointAO on opaque spheres ------------------------
        pointao = pr.vtkPointAOPass()
        pointao.SetNumberOfLevels(3)      # hemispheres of growing radius
        pointao.SetSamplesPerLevel(4)     # directions; level j takes j samples along each
        pointao.SetRadius(0.0)            # automatic: four mean particle radii
        pointao.SetStrength(1.4)
        # ----------------------------------------------------------------------------------
        return pointao
    if method == "density-volume":
        density = pr.vtkDensityVolumeAOPass()
        density.SetStrength(2.0)
        return density
    if method == "voxel-cone":
        return pr.vtkVoxelConeAOPass()
    return None


def render(path, method, size):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    mapper = pr.vtkParticleSphereMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    mapper.SetRadiusArrayName("radius")
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("type")
    lut = vtkLookupTable()
    lut.SetNumberOfTableValues(2)
    lut.SetTableValue(0, 0.85, 0.33, 0.10)
    lut.SetTableValue(1, 0.12, 0.47, 0.80)
    lut.SetTableRange(1, 2)
    mapper.SetLookupTable(lut)
    mapper.UseLookupTableScalarRangeOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.32, 0.34, 0.43)
    ao = ambient_occlusion(method)
    if ao is not None:
        ao.SetDelegatePass(vtkRenderStepsPass())
        renderer.SetPass(ao)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    b = reader.GetOutput().GetBounds()
    centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(centre[0] + 0.9 * (b[1] - b[0]), centre[1] - 1.2 * (b[3] - b[2]),
                       centre[2] + 0.8 * (b[5] - b[4]))
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    camera.Zoom(1.4)
    window.Render()
    return window_rgb(window, size)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", default="Testing/Data/lj_film.vtp")
    parser.add_argument("--out", default="Plugin/Documentation/pointao-film.png")
    parser.add_argument("--size", type=int, default=300)
    args = parser.parse_args()
    write_panels([render(args.data, m, args.size) for m in METHODS], args.out)
    print("wrote", args.out, "(left to right: %s)" % ", ".join(METHODS))


if __name__ == "__main__":
    main()
