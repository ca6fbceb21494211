"""The README's picture of voxel-cone ambient occlusion on translucent particles, from plain VTK
Python: the LAMMPS droplets (Testing/Data/lj_droplets.vtp) as emission-absorption spheres
(vtkTransparentSphereMapper, coloured by type, Theta 0.4), side by side without ambient
occlusion, with vtkVoxelConeAOPass (occlusion only, the defaults) and with ambient illumination
(alpha_A = 0.5).

usage: PYTHONPATH=build/lib/python3/dist-packages Scripts/with_xvfb.sh /usr/bin/python3 \
           Scripts/voxel_cone_picture.py [--out Plugin/Documentation/voxel-cone-droplets.png]
"""
import argparse

import particlerendering as pr
from prPictures import window_rgb, write_panels
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderWindow
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)


def render(path, mode, size):
    # --- the example of the README: translucent spheres with voxel-cone AO -----------------
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    mapper = pr.vtkTransparentSphereMapper()
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
    actor.GetProperty().SetOpacity(0.4)         # Theta_i of every atom
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.32, 0.34, 0.43)
    if mode != "none":
        cones = pr.vtkVoxelConeAOPass()
        cones.SetDelegatePass(vtkRenderStepsPass())
        cones.SetConeCount(3)                   # the paper's three cones
        cones.SetConeAperture(60.0)             # degrees
        cones.SetAmbientIllumination(0.5 if mode == "illumination" else 0.0)  # alpha_A
        renderer.SetPass(cones)
    # ----------------------------------------------------------------------------------------
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(40.0, 40.0, 40.0)
    camera.SetPosition(40.0, -60.0, 40.0)
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.SetViewAngle(30.0)
    renderer.ResetCameraClippingRange()
    window.Render()
    return window_rgb(window, size)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", default="Testing/Data/lj_droplets.vtp")
    parser.add_argument("--out", default="Plugin/Documentation/voxel-cone-droplets.png")
    parser.add_argument("--size", type=int, default=360)
    args = parser.parse_args()
    panels = [render(args.data, mode, args.size) for mode in ("none", "occlusion", "illumination")]
    write_panels(panels, args.out)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
