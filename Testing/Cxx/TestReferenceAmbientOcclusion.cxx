// Ray-traced ambient occlusion of vtkParticleReferenceRenderer (the ground truth for
// vtkDensityVolumeAOPass): an isolated sphere is unoccluded everywhere (exactly 1); in a lattice
// the visible points are occluded, more with a longer ray distance (monotone, pixel by pixel);
// the result is deterministic; ApplyAmbientOcclusion multiplies the lit colour by the factor.
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParticleReferenceRenderer.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace
{
std::vector<double> Values(vtkImageData* image)
{
  vtkDataArray* a = image->GetPointData()->GetScalars();
  std::vector<double> v(a->GetNumberOfValues());
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    v[i] = a->GetComponent(i / a->GetNumberOfComponents(), i % a->GetNumberOfComponents());
  }
  return v;
}
}

int TestReferenceAmbientOcclusion(int, char*[])
{
  if (std::string(vtkSMPTools::GetBackend()) == "Sequential")
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  bool ok = true;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(96, 96);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkParticleSphereMapper> mapper;
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  vtkNew<vtkParticleReferenceRenderer> reference;
  reference->SetRenderer(renderer);
  reference->SetActor(actor);
  reference->SetAmbientOcclusionSamples(64);

  // one sphere: nothing occludes it
  vtkNew<vtkPolyData> one;
  vtkNew<vtkPoints> onePoint;
  onePoint->InsertNextPoint(0, 0, 0);
  one->SetPoints(onePoint);
  mapper->SetInputData(one);
  renderer->ResetCamera();
  ok &= prTest::Check(reference->Render(), "render one sphere");
  double minimum = 1.0;
  for (double v : Values(reference->GetAmbientOcclusionImage()))
  {
    minimum = std::min(minimum, v);
  }
  ok &= prTest::Check(minimum == 1.0, "an isolated sphere is unoccluded");

  // a 6x6x6 lattice of touching spheres (spacing 1, radius 0.5)
  vtkSmartPointer<vtkPolyData> lattice = prTest::MakeLattice(6, 1.0, 5);
  mapper->SetInputData(lattice);
  mapper->SetRadius(0.5);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->GetActiveCamera()->Elevation(20);
  renderer->ResetCameraClippingRange();
  reference->SetAmbientOcclusionDistance(1.0);
  reference->Render();
  const std::vector<double> shortRays = Values(reference->GetAmbientOcclusionImage());
  reference->Render();
  const std::vector<double> again = Values(reference->GetAmbientOcclusionImage());
  reference->SetAmbientOcclusionDistance(3.0);
  reference->Render();
  const std::vector<double> longRays = Values(reference->GetAmbientOcclusionImage());
  double meanShort = 0.0;
  double meanLong = 0.0;
  long long hits = 0;
  bool monotone = true;
  for (size_t i = 0; i < shortRays.size(); ++i)
  {
    monotone &= longRays[i] <= shortRays[i] + 1e-12;
    if (shortRays[i] < 1.0 || longRays[i] < 1.0)
    {
      meanShort += shortRays[i];
      meanLong += longRays[i];
      ++hits;
    }
  }
  meanShort /= std::max<long long>(1, hits);
  meanLong /= std::max<long long>(1, hits);
  std::cout << "lattice: " << hits << " occluded pixels, mean AO " << meanShort << " (distance 1), "
            << meanLong << " (distance 3); reference " << reference->GetLastRenderSeconds()
            << " s with 64 rays per pixel\n";
  ok &= prTest::Check(shortRays == again, "deterministic");
  ok &= prTest::Check(monotone, "longer rays never see more sky");
  ok &= prTest::Check(
    hits > 1000 && meanShort < 0.9 && meanLong < meanShort, "the lattice occludes itself");

  // the colour is the lit colour times the factor
  const std::vector<double> plainColor = Values(reference->GetColorImage());
  reference->SetApplyAmbientOcclusion(true);
  reference->Render();
  const std::vector<double> occludedColor = Values(reference->GetColorImage());
  double worst = 0.0;
  for (size_t i = 0; i < longRays.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      worst =
        std::max(worst, std::abs(occludedColor[4 * i + k] - longRays[i] * plainColor[4 * i + k]));
    }
  }
  ok &= prTest::Check(worst < 1e-12, "ApplyAmbientOcclusion multiplies the colour");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
