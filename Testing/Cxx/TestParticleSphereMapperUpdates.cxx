// What triggers a particle upload, and time series with changing particle counts.
// - camera moves, actor moves, material changes and RadiusScaleFactor changes do NOT re-upload
//   (but RadiusScaleFactor does change the picture);
// - a new time step, a new radius array, a lookup-table change DO re-upload;
// - a time series whose particle count changes (5000 -> 11033 -> 0 -> 11033) and then only its
//   radii draws at every step exactly what a fresh mapper draws for that step's data.
#include "prTestUtilities.h"
#include "vtkParticleImageComparison.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <string>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> FirstParticles(vtkPolyData* in, vtkIdType n)
{
  vtkSmartPointer<vtkPolyData> out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(in->GetPoints()->GetDataType());
  points->SetNumberOfPoints(n);
  out->GetPointData()->CopyAllocate(in->GetPointData(), n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, in->GetPoint(i));
    out->GetPointData()->CopyData(in->GetPointData(), i, i);
  }
  out->SetPoints(points);
  return out;
}

// number of pixels that are not background
vtkIdType Covered(vtkRenderWindow* window)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  int* size = window->GetSize();
  window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels);
  vtkIdType n = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    n += (pixels->GetValue(3 * i) + pixels->GetValue(3 * i + 1) + pixels->GetValue(3 * i + 2)) > 0;
  }
  return n;
}
}

int TestParticleSphereMapperUpdates(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> steps[5];
  for (int t = 0; t < 5; ++t)
  {
    steps[t] = prTest::ReadPolyData(
      prTest::DataFile(argc, argv, "lj_droplets_t" + std::to_string(t) + ".vtp"));
    if (!steps[t])
    {
      return EXIT_FAILURE;
    }
  }
  vtkNew<vtkLookupTable> lut;
  lut->SetTableRange(1, 2);
  lut->Build();
  vtkNew<vtkParticleSphereMapper> mapper;
  mapper->SetInputData(steps[0]);
  mapper->SetRadiusArrayName("radius");
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("type");
  mapper->SetLookupTable(lut);
  mapper->UseLookupTableScalarRangeOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  window->Render();

  bool ok = vtkParticleImageComparison::TestRepeatable(window, "TestParticleSphereMapperUpdates");
  vtkIdType uploads = mapper->GetNumberOfUploads();
  ok &= prTest::Check(uploads == 1, "first frame: expected 1 upload");
  auto expectUploads = [&](vtkIdType expected, const std::string& what)
  {
    window->Render();
    const vtkIdType now = mapper->GetNumberOfUploads() - uploads;
    uploads = mapper->GetNumberOfUploads();
    ok &= prTest::Check(now == expected,
      what + ": " + std::to_string(now) + " uploads, expected " + std::to_string(expected));
  };

  renderer->GetActiveCamera()->Azimuth(30);
  expectUploads(0, "camera orbit");
  actor->SetPosition(0.5, 0, 0);
  expectUploads(0, "actor move");
  actor->GetProperty()->SetSpecular(0.5);
  actor->GetProperty()->SetDiffuseColor(0.2, 0.3, 0.4);
  expectUploads(0, "material change");
  const vtkIdType before = Covered(window);
  mapper->SetRadiusScaleFactor(1.5);
  expectUploads(0, "radius scale factor");
  ok &= prTest::Check(Covered(window) > before, "radius scale factor did not grow the spheres");
  mapper->SetRadiusScaleFactor(1.0);
  mapper->SetInputData(steps[1]);
  expectUploads(1, "new time step");
  lut->SetTableValue(0, 1, 1, 1, 1);
  expectUploads(1, "lookup table change");
  mapper->SetRadiusArrayName(nullptr);
  expectUploads(1, "radius source change");
  mapper->SetRadiusArrayName("radius");
  expectUploads(1, "radius source change back");

  // Changing particle counts and values. Every step must draw exactly what a fresh mapper draws
  // for the same data (a buffer kept from an earlier step would draw stale or too few particles):
  // grow from 5000 to 11033, shrink to nothing, grow again, and change only the radii.
  vtkSmartPointer<vtkPolyData> fewer = FirstParticles(steps[2], 5000);
  vtkNew<vtkPolyData> empty;
  vtkSmartPointer<vtkPolyData> halfRadii = vtkSmartPointer<vtkPolyData>::New();
  halfRadii->DeepCopy(steps[3]);
  {
    vtkDataArray* r = halfRadii->GetPointData()->GetArray("radius");
    for (vtkIdType i = 0; i < r->GetNumberOfTuples(); ++i)
    {
      r->SetComponent(i, 0, 0.5 * r->GetComponent(i, 0));
    }
  }
  vtkPolyData* series[6] = { fewer, steps[2], empty, steps[3], halfRadii, steps[4] };
  const vtkIdType counts[6] = { 5000, 11033, 0, 11033, 11033, 11033 };
  auto snapshot = [&]()
  {
    vtkNew<vtkUnsignedCharArray> pixels;
    int* size = window->GetSize();
    window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels);
    return std::vector<unsigned char>(
      pixels->GetPointer(0), pixels->GetPointer(0) + pixels->GetNumberOfValues());
  };
  for (int t = 0; t < 6; ++t)
  {
    mapper->SetInputData(series[t]);
    window->Render();
    const vtkIdType drawn = series[t]->GetNumberOfPoints() - mapper->GetNumberOfSkippedParticles();
    ok &= prTest::Check(drawn == counts[t],
      "step " + std::to_string(t) + ": drew " + std::to_string(drawn) + " particles, expected " +
        std::to_string(counts[t]));
    const std::vector<unsigned char> image = snapshot();
    // the same data through a fresh mapper, in the same window and camera
    vtkNew<vtkParticleSphereMapper> fresh;
    fresh->SetInputData(series[t]);
    fresh->SetRadiusArrayName("radius");
    fresh->SetScalarModeToUsePointFieldData();
    fresh->SelectColorArray("type");
    fresh->SetLookupTable(lut);
    fresh->UseLookupTableScalarRangeOn();
    actor->SetMapper(fresh);
    window->Render();
    ok &= prTest::Check(
      snapshot() == image, "step " + std::to_string(t) + ": image differs from a fresh mapper's");
    actor->SetMapper(mapper);
    fresh->ReleaseGraphicsResources(window);
    if (t == 4)
    {
      ok &= prTest::Check(Covered(window) > 0, "half radii: nothing drawn");
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
