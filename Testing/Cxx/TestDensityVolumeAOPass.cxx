// vtkDensityVolumeAOPass (Grottel et al. 2012, Eq. 4-5, per-fragment retrieval) in plain VTK:
// the LAMMPS liquid film with ambient occlusion from the coarse density volume, baseline image.
// Checks that AO darkens the image (and never brightens a pixel), that the volume is built once
// and not again when only the camera moves, but again when the particles move, and that the
// translucent mapper gets the same AO at its first hit.
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDensityVolumeAOPass.h"
#include "vtkNew.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransparentSphereMapper.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

namespace
{
// Baseline criteria. The image is the GPU's own on the same platform, so the real picture
// matches to rounding; the test is about the darkening by AO, which changes the film by a mean
// of 11.4/255 with 45 % of the pixels over 4/255 (AO off, the must-fail case: score 45): a mean
// of 1/255 or 1 % of the pixels over 4/255 already rejects a pass whose occlusion is a tenth
// too weak or too strong.
prTest::ImageCriteria Criteria()
{
  prTest::ImageCriteria criteria;
  criteria.Tolerance = 4.0;
  criteria.MaxOverToleranceShare = 1e-2;
  criteria.MaxMean = 1.0;
  return criteria;
}
}

int TestDensityVolumeAOPass(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> film =
    prTest::ReadPolyData(prTest::DataFile(argc, argv, "lj_film.vtp"));
  if (!film)
  {
    return EXIT_FAILURE;
  }
  bool ok = true;
  vtkNew<vtkParticleSphereMapper> mapper;
  mapper->SetInputData(film);
  mapper->SetRadius(0.5);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.8, 0.7);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.15, 0.15, 0.2);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 300);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Elevation(35);
  renderer->GetActiveCamera()->Azimuth(20);
  renderer->GetActiveCamera()->Zoom(1.6);
  renderer->ResetCameraClippingRange();

  window->Render();
  if (prTest::MustFail(argc, argv, "ao-off"))
  {
    // the picture without AO, at the baseline's camera, must be rejected
    renderer->GetActiveCamera()->Azimuth(10);
    renderer->GetActiveCamera()->Azimuth(-10);
    window->Render();
    return prTest::CompareWithBaseline(argc, argv, window, Criteria()) ? EXIT_SUCCESS
                                                                       : EXIT_FAILURE;
  }
  vtkNew<vtkUnsignedCharArray> plain;
  window->GetRGBACharPixelData(0, 0, 399, 299, 1, plain);

  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkDensityVolumeAOPass> ao;
  ao->SetDelegatePass(steps);
  renderer->SetPass(ao);
  window->Render();
  vtkNew<vtkUnsignedCharArray> occluded;
  window->GetRGBACharPixelData(0, 0, 399, 299, 1, occluded);

  long long darker = 0;
  long long brighter = 0;
  for (vtkIdType i = 0; i < plain->GetNumberOfValues(); i += 4)
  {
    const int a = plain->GetValue(i) + plain->GetValue(i + 1) + plain->GetValue(i + 2);
    const int b = occluded->GetValue(i) + occluded->GetValue(i + 1) + occluded->GetValue(i + 2);
    darker += b < a - 3 ? 1 : 0;
    brighter += b > a + 3 ? 1 : 0;
  }
  std::cout << "ambient occlusion: " << darker << " pixels darker, " << brighter
            << " brighter; volume " << ao->GetNumberOfVolumeBuilds() << " build(s)\n";
  ok &= prTest::Check(darker > 5000, "AO darkens the film");
  ok &= prTest::Check(brighter == 0, "AO never brightens");
  ok &= prTest::Check(ao->GetNumberOfVolumeBuilds() == 1, "one volume build");

  renderer->GetActiveCamera()->Azimuth(10);
  window->Render();
  ok &= prTest::Check(ao->GetNumberOfVolumeBuilds() == 1, "no rebuild for a camera move");
  film->GetPoints()->SetPoint(0, 1.0, 1.0, 1.0);
  film->GetPoints()->Modified();
  window->Render();
  ok &= prTest::Check(ao->GetNumberOfVolumeBuilds() == 2, "a rebuild when the particles move");
  renderer->GetActiveCamera()->Azimuth(-10);
  window->Render();

  const bool baseline = prTest::CompareWithBaseline(argc, argv, window, Criteria());

  // per-sphere retrieval: six fetches per sphere, blended by the normal; no rebuild of the volume
  vtkNew<vtkUnsignedCharArray> perFragment;
  window->GetRGBACharPixelData(0, 0, 399, 299, 1, perFragment);
  ao->SetRetrievalMode(vtkDensityVolumeAOPass::PER_SPHERE);
  window->Render();
  vtkNew<vtkUnsignedCharArray> perSphere;
  window->GetRGBACharPixelData(0, 0, 399, 299, 1, perSphere);
  long long sphereDarker = 0;
  long long sphereBrighter = 0;
  double meanDifference = 0.0;
  for (vtkIdType i = 0; i < plain->GetNumberOfValues(); i += 4)
  {
    sphereDarker += perSphere->GetValue(i) + 3 < plain->GetValue(i) ? 1 : 0;
    sphereBrighter += perSphere->GetValue(i) > plain->GetValue(i) + 3 ? 1 : 0;
    meanDifference += std::abs(perSphere->GetValue(i) - perFragment->GetValue(i));
  }
  meanDifference /= plain->GetNumberOfValues() / 4;
  std::cout << "per sphere: " << sphereDarker << " pixels darker, " << sphereBrighter
            << " brighter, mean |per sphere - per fragment| " << meanDifference << "/255\n";
  ok &= prTest::Check(sphereDarker > 5000 && sphereBrighter == 0, "per-sphere AO darkens");
  ok &= prTest::Check(meanDifference < 10.0, "per-sphere close to per-fragment AO");
  ok &= prTest::Check(ao->GetNumberOfVolumeBuilds() == 2, "no rebuild for the retrieval mode");
  ao->SetRetrievalMode(vtkDensityVolumeAOPass::PER_FRAGMENT);

  // GPU generation (the mapper has drawn: its vertex buffers are splatted) gives the same image
  ao->SetGenerationMode(vtkDensityVolumeAOPass::GPU_GENERATION);
  window->Render();
  vtkNew<vtkUnsignedCharArray> gpuImage;
  window->GetRGBACharPixelData(0, 0, 399, 299, 1, gpuImage);
  int worstGPU = 0;
  for (vtkIdType i = 0; i < gpuImage->GetNumberOfValues(); ++i)
  {
    worstGPU = std::max(worstGPU, std::abs(gpuImage->GetValue(i) - perFragment->GetValue(i)));
  }
  std::cout << "GPU generation: max |GPU - CPU image| " << worstGPU << "/255, built on the "
            << (ao->GetLastGenerationMode() == vtkDensityVolumeAOPass::GPU_GENERATION ? "GPU"
                                                                                      : "CPU")
            << "\n";
  ok &= prTest::Check(ao->GetLastGenerationMode() == vtkDensityVolumeAOPass::GPU_GENERATION,
    "volume built on the GPU");
  ok &= prTest::Check(worstGPU <= 2, "GPU-generated AO equals CPU-generated AO");
  ok &= prTest::Check(ao->GetNumberOfVolumeBuilds() == 3, "one rebuild for the generation mode");
  ao->SetGenerationMode(vtkDensityVolumeAOPass::CPU_GENERATION);

  // translucent particles get the occlusion at their entry point too
  vtkNew<vtkTransparentSphereMapper> translucent;
  translucent->SetInputData(film);
  translucent->SetRadius(0.5);
  translucent->ScalarVisibilityOff();
  actor->SetMapper(translucent);
  actor->GetProperty()->SetOpacity(0.6);
  renderer->SetPass(nullptr);
  window->Render();
  window->GetRGBACharPixelData(0, 0, 399, 299, 1, plain);
  renderer->SetPass(ao);
  window->Render();
  window->GetRGBACharPixelData(0, 0, 399, 299, 1, occluded);
  long long darkerTranslucent = 0;
  for (vtkIdType i = 0; i < plain->GetNumberOfValues(); i += 4)
  {
    darkerTranslucent += occluded->GetValue(i) + 3 < plain->GetValue(i) ? 1 : 0;
  }
  std::cout << "translucent particles: " << darkerTranslucent << " pixels darker with AO\n";
  ok &= prTest::Check(darkerTranslucent > 5000, "AO darkens translucent particles");
  ok &= prTest::Check(
    ao->GetNumberOfVolumeBuilds() == 4, "a rebuild for the new mapper (and the mode)");
  renderer->SetPass(nullptr);
  ao->ReleaseGraphicsResources(window);
  return (ok && baseline) ? EXIT_SUCCESS : EXIT_FAILURE;
}
