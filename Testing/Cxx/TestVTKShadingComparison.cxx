// Our lighting port checked against VTK's own shading, not only against our reference: the same
// spheres drawn by vtkParticleSphereMapper and by VTK's vtkOpenGLSphereMapper (VTK's polydata
// fragment lighting -- vtkOpenGLPolyDataMapper's light and material code -- on exact ray-cast
// sphere normals), in the same window, and compared pixel by pixel. Scenes: the renderer's
// headlight with perspective; a light kit (five lights, lighting complexity 2) with specular
// highlights in parallel projection; a spot light and an attenuated point light (complexity 3)
// with specular highlights in perspective. This test found that our port used the view vector
// (0,0,1) in parallel projection where VTK 9.2 uses normalize(-vertexVC) in both projections
// (up to 69/255 apart on highlights), and a specular base clamped at 0 where VTK clamps at 1e-5
// (also true of VTK's shading of a finely tessellated vtkSphereSource).
// Compared pixels: outside a one-pixel band around every change of visible sphere (silhouettes
// and sphere/sphere occlusion edges, from vtkParticleReferenceRenderer's id image, with the
// particles given from the raw arrays), where sub-pixel differences between two rasterisations
// legitimately change the colour. Criteria (stated in Criteria()): every compared pixel within
// 3/255 per channel -- two float implementations of the same Phong model -- and the mean
// within 0.5/255. Must-fail checks: the same comparison rejects our picture with the spheres'
// diffuse term 10 % darker, and one with specular highlights where VTK has none.
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkParticleImageComparison.h"
#include "vtkParticleReferenceRenderer.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>
#include <functional>
#include <iostream>

namespace
{
const int Size = 400;

void Criteria(vtkParticleImageComparison* comparison)
{
  comparison->SetTolerance(3.0 / 255.0);
  comparison->SetMaximumError(3.0 / 255.0);
  comparison->SetMaximumOverToleranceFraction(1e-3); // (the maximum error already bounds all)
  comparison->SetMaximumMeanError(0.5 / 255.0);
  comparison->SetMaskRadius(0); // the id mask below
}

vtkSmartPointer<vtkImageData> Render(vtkRenderWindow* window, vtkActor* actor, vtkMapper* mapper)
{
  actor->SetMapper(mapper);
  window->Render();
  return prTest::GrabImage(window);
}
}

int TestVTKShadingComparison(int argc, char* argv[])
{
  const std::string temp = prTest::TempDirectory(argc, argv);
  vtkSmartPointer<vtkPolyData> lattice = prTest::MakeLattice(5, 1.0, 13);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();

  vtkNew<vtkParticleSphereMapper> ours;
  ours->SetInputData(lattice);
  ours->SetRadiusArrayName("radius");
  ours->SetLookupTable(lut);
  ours->SetScalarRange(0, 12);
  vtkNew<vtkOpenGLSphereMapper> vtks;
  vtks->SetInputData(lattice);
  vtks->SetScaleArray("radius");
  vtks->SetLookupTable(lut);
  vtks->SetScalarRange(0, 12);

  bool ok = true;
  struct Scene
  {
    const char* Name;
    std::function<void(vtkRenderer*, vtkActor*)> Setup;
  };
  const Scene scenes[] = {
    { "headlight_perspective",
      [](vtkRenderer* renderer, vtkActor*)
      {
        vtkCamera* camera = renderer->GetActiveCamera();
        camera->SetFocalPoint(2, 2, 2);
        camera->SetPosition(2.5, 1.5, 16);
        camera->SetViewUp(0, 1, 0);
        camera->SetViewAngle(30);
      } },
    { "lightkit_specular_parallel",
      [](vtkRenderer* renderer, vtkActor* actor)
      {
        vtkNew<vtkLightKit> kit;
        kit->AddLightsToRenderer(renderer);
        actor->GetProperty()->SetSpecular(0.5);
        actor->GetProperty()->SetSpecularPower(20);
        vtkCamera* camera = renderer->GetActiveCamera();
        camera->ParallelProjectionOn();
        camera->SetFocalPoint(2, 2, 2);
        camera->SetPosition(10, -5, 9);
        camera->SetViewUp(0, 0, 1);
        camera->SetParallelScale(3.3);
      } },
    { "spot_and_point_lights",
      [](vtkRenderer* renderer, vtkActor* actor)
      {
        actor->GetProperty()->SetSpecular(0.4);
        actor->GetProperty()->SetSpecularPower(15);
        vtkCamera* camera = renderer->GetActiveCamera();
        camera->SetFocalPoint(2, 2, 2);
        camera->SetPosition(3, 0.5, 15);
        camera->SetViewUp(0, 1, 0);
        camera->SetViewAngle(30);
        vtkNew<vtkLight> spot;
        spot->SetLightTypeToSceneLight();
        spot->SetPositional(true);
        spot->SetPosition(4, 5, 12);
        spot->SetFocalPoint(2, 2, 2);
        spot->SetConeAngle(12);
        spot->SetExponent(2);
        spot->SetColor(1.0, 0.95, 0.9);
        renderer->AddLight(spot);
        vtkNew<vtkLight> point;
        point->SetLightTypeToSceneLight();
        point->SetPositional(true);
        point->SetConeAngle(180);
        point->SetPosition(-6, 1, 8);
        point->SetFocalPoint(2, 2, 2);
        point->SetAttenuationValues(0.6, 0.03, 0.001);
        point->SetColor(0.5, 0.7, 1.0);
        renderer->AddLight(point);
      } },
  };
  for (const Scene& scene : scenes)
  {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(Size, Size);
    window->SetMultiSamples(0);
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0.1, 0.1, 0.15);
    window->AddRenderer(renderer);
    vtkNew<vtkActor> actor;
    renderer->AddActor(actor);
    scene.Setup(renderer, actor);
    actor->SetMapper(ours);
    renderer->ResetCameraClippingRange();

    vtkSmartPointer<vtkImageData> vtkImage = Render(window, actor, vtks);
    vtkSmartPointer<vtkImageData> ourImage = Render(window, actor, ours);
    ok &= vtkParticleImageComparison::TestRepeatable(
      window, (std::string("TestVTKShadingComparison_") + scene.Name).c_str());

    // the visible-surface ids of the spheres (radii and colours from the raw arrays)
    vtkNew<vtkParticleReferenceRenderer> reference;
    reference->SetRenderer(renderer);
    reference->SetActor(actor);
    const double range[2] = { 0, 12 };
    const prTest::ParticleAttributes attributes =
      prTest::RawAttributes(lattice, "radius", 0.0, "value", lut, range);
    reference->SetParticleAttributes(attributes.Radii, attributes.Colors, nullptr);
    ok &= prTest::Check(reference->Render(), std::string(scene.Name) + ": reference renders");
    vtkNew<vtkIdTypeArray> surfaces;
    reference->GetSurfaceIdImage(surfaces);
    vtkNew<vtkUnsignedCharArray> mask;
    vtkParticleImageComparison::MakeSilhouetteMask(surfaces, Size, Size, 1, mask);

    vtkNew<vtkParticleImageComparison> comparison;
    Criteria(comparison);
    const std::string name = std::string("TestVTKShadingComparison_") + scene.Name;
    vtkParticleImageComparison::WritePNG(vtkImage, (temp + "/" + name + "_vtk.png").c_str());
    ok &=
      prTest::Check(comparison->TestImages(ourImage, vtkImage, mask, temp.c_str(), name.c_str()),
        std::string(scene.Name) + ": our shading differs from VTK's");
    ok &= prTest::Check(comparison->GetNumberOfComparedPixels() > Size * Size / 2,
      std::string(scene.Name) + ": at least half of the pixels compared");

    // wrong pictures the same comparison must reject
    actor->GetProperty()->SetDiffuse(0.9);
    vtkSmartPointer<vtkImageData> darker = Render(window, actor, ours);
    actor->GetProperty()->SetDiffuse(1.0);
    ok &= prTest::Check(
      comparison->TestRejects(darker, vtkImage, mask, (name + " diffuse 10 % darker").c_str()),
      std::string(scene.Name) + ": a 10 % darker diffuse term passes");
    const double specular = actor->GetProperty()->GetSpecular();
    actor->GetProperty()->SetSpecular(specular > 0 ? 0.0 : 0.5);
    vtkSmartPointer<vtkImageData> highlights = Render(window, actor, ours);
    actor->GetProperty()->SetSpecular(specular);
    ok &= prTest::Check(
      comparison->TestRejects(highlights, vtkImage, mask, (name + " specular changed").c_str()),
      std::string(scene.Name) + ": a changed specular term passes");
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
