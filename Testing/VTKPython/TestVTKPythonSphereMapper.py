"""vtkParticleSphereMapper from plain VTK Python (no ParaView): the LAMMPS droplets coloured by
atom type, radii from the 'radius' array, a light kit. Baseline-image test; a missing baseline
fails. The comparison is vtkParticleImageComparison (the suite's one image test) with the
criteria of the same-platform baseline tests: at most 0.1 % of the pixels over 2/255, mean error
at most 0.5/255.

usage: python3 TestVTKPythonSphereMapper.py --data DIR --baseline PNG --temp DIR
"""
import argparse
import os
import sys

import particlerendering  # ParticleRendering's Python-wrapped VTK module
from vtkmodules.vtkCommonColor import vtkNamedColors  # noqa: F401 (module load check)
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import vtkActor, vtkLightKit, vtkRenderer, vtkRenderWindow
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL factory overrides)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", required=True)
    parser.add_argument("--baseline", required=True)
    parser.add_argument("--temp", required=True)
    args = parser.parse_args()

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(args.data, "lj_droplets.vtp"))

    lut = vtkLookupTable()
    lut.SetNumberOfTableValues(2)
    lut.SetTableValue(0, 0.85, 0.35, 0.2, 1.0)
    lut.SetTableValue(1, 0.2, 0.55, 0.9, 1.0)
    lut.SetTableRange(1, 2)

    mapper = particlerendering.vtkParticleSphereMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    mapper.SetRadiusArrayName("radius")
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("type")
    mapper.SetLookupTable(lut)
    mapper.UseLookupTableScalarRangeOn()

    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetSpecular(0.4)
    actor.GetProperty().SetSpecularPower(25)

    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.12, 0.12, 0.16)
    kit = vtkLightKit()
    kit.AddLightsToRenderer(renderer)
    window = vtkRenderWindow()
    window.SetSize(500, 400)
    window.SetMultiSamples(0)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Elevation(25)
    camera.Azimuth(30)
    camera.Zoom(2.2)
    renderer.ResetCameraClippingRange()
    window.Render()

    if mapper.GetNumberOfSkippedParticles() != 0:
        print("FAIL: particles skipped in valid data")
        return 1
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    comparison = particlerendering.vtkParticleImageComparison()
    comparison.SetTolerance(2.0 / 255.0)
    comparison.SetMaximumOverToleranceFraction(1e-3)
    comparison.SetMaximumMeanError(0.5 / 255.0)
    name = os.path.splitext(os.path.basename(args.baseline))[0]
    if not comparison.TestImage(grab.GetOutput(), args.baseline, args.temp, name):
        print("FAIL: image differs from the baseline (see %s)" % args.temp)
        return 1
    if not particlerendering.vtkParticleImageComparison.TestRepeatable(window, name):
        print("FAIL: the same frame drawn twice differs")
        return 1

    # The transparent mapper from plain VTK Python: the same droplets with the maximum opacity
    # from the speed, composited by the mapper (one sort, or -- the droplets' spheres overlap --
    # the exact-overlap lists, which need none), visibly different from the opaque image but not
    # the background.
    from vtkmodules.vtkCommonCore import vtkUnsignedCharArray

    opaque = vtkUnsignedCharArray()
    window.GetRGBACharPixelData(0, 0, 499, 399, 1, opaque)
    translucent_mapper = particlerendering.vtkTransparentSphereMapper()
    translucent_mapper.SetInputConnection(reader.GetOutputPort())
    translucent_mapper.SetRadiusArrayName("radius")
    translucent_mapper.SetScalarModeToUsePointFieldData()
    translucent_mapper.SelectColorArray("type")
    translucent_mapper.SetLookupTable(lut)
    translucent_mapper.UseLookupTableScalarRangeOn()
    translucent_mapper.SetOpacityArrayName("speed")
    translucent_mapper.SetOpacityRange(0.0, 3.0)
    translucent_mapper.SetDensityModelToSquaredDistance()
    translucent_mapper.SetHollowFraction(0.4)
    actor.SetMapper(translucent_mapper)
    window.Render()
    translucent = vtkUnsignedCharArray()
    window.GetRGBACharPixelData(0, 0, 499, 399, 1, translucent)
    if not particlerendering.vtkParticleImageComparison.TestRepeatable(window, name + " translucent"):
        print("FAIL: the same translucent frame drawn twice differs")
        return 1
    changed = sum(1 for i in range(0, translucent.GetNumberOfValues(), 4 * 7)
                  if translucent.GetValue(i) != opaque.GetValue(i))
    print("transparent mapper: %d sort(s), %d of %d sampled pixels differ from the opaque image"
          % (translucent_mapper.GetNumberOfSorts(), changed,
             translucent.GetNumberOfValues() // (4 * 7)))
    exact = translucent_mapper.GetExactOverlapInUse()
    print("overlapping spheres: %s, exact-overlap lists: %s"
          % (translucent_mapper.HasOverlappingSpheres(), exact))
    expected_sorts = 0 if translucent_mapper.HasOverlappingSpheres() else 1
    if (translucent_mapper.GetNumberOfSorts() != expected_sorts or changed < 1000
            or exact != (expected_sorts == 0)):
        print("FAIL: the transparent mapper did not composite translucent particles")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
