// Bad input to the sphere core: each case must give the expected warning (once, not every frame),
// skip exactly the bad particles and still render a sane picture (the valid particles).
// Cases, one viewport each:
//   0 no points            1 radius array missing     2 radius array with 2 components
//   3 zero/negative/NaN/Inf radii (half the particles)  4 NaN/Inf positions  5 string "radius"
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <limits>

namespace
{
struct Case
{
  vtkSmartPointer<vtkPolyData> Data;
  const char* RadiusArray;
  const char* ExpectedWarning; // nullptr: no warning expected
  vtkIdType ExpectedSkipped;
};
}

int TestParticleSphereMapperBadInput(int argc, char* argv[])
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Case cases[6];

  cases[0].Data = vtkSmartPointer<vtkPolyData>::New();
  cases[0].RadiusArray = "radius";
  cases[0].ExpectedWarning = "no points";
  cases[0].ExpectedSkipped = 0;

  cases[1].Data = prTest::MakeLattice(4, 1.0, 1);
  cases[1].RadiusArray = "no_such_array";
  cases[1].ExpectedWarning = "is not a point array";
  cases[1].ExpectedSkipped = 0;

  cases[2].Data = prTest::MakeLattice(4, 1.0, 2);
  {
    vtkNew<vtkDoubleArray> twoComponents;
    twoComponents->SetName("radius2");
    twoComponents->SetNumberOfComponents(2);
    twoComponents->SetNumberOfTuples(cases[2].Data->GetNumberOfPoints());
    twoComponents->Fill(0.3);
    cases[2].Data->GetPointData()->AddArray(twoComponents);
  }
  cases[2].RadiusArray = "radius2";
  cases[2].ExpectedWarning = "has 2 components";
  cases[2].ExpectedSkipped = 0;

  cases[3].Data = prTest::MakeLattice(4, 1.0, 3);
  {
    vtkFloatArray* radius =
      vtkFloatArray::SafeDownCast(cases[3].Data->GetPointData()->GetArray("radius"));
    const float bad[4] = { 0.0f, -0.4f, static_cast<float>(nan), static_cast<float>(inf) };
    for (vtkIdType i = 0; i < radius->GetNumberOfTuples(); i += 2)
    {
      radius->SetValue(i, bad[(i / 2) % 4]);
    }
  }
  cases[3].RadiusArray = "radius";
  cases[3].ExpectedWarning = "zero, negative, NaN or infinite radius";
  cases[3].ExpectedSkipped = 32;

  cases[4].Data = prTest::MakeLattice(4, 1.0, 4);
  {
    vtkPoints* points = cases[4].Data->GetPoints();
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); i += 4)
    {
      double p[3];
      points->GetPoint(i, p);
      p[i % 3] = (i % 8 == 0) ? nan : -inf;
      points->SetPoint(i, p);
    }
  }
  cases[4].RadiusArray = "radius";
  cases[4].ExpectedWarning = "NaN or infinite position";
  cases[4].ExpectedSkipped = 16;

  cases[5].Data = prTest::MakeLattice(4, 1.0, 5);
  {
    vtkNew<vtkStringArray> strings;
    strings->SetName("label");
    strings->SetNumberOfTuples(cases[5].Data->GetNumberOfPoints());
    cases[5].Data->GetPointData()->AddArray(strings);
  }
  cases[5].RadiusArray = "label";
  cases[5].ExpectedWarning = "is not numeric";
  cases[5].ExpectedSkipped = 0;

  vtkNew<vtkRenderWindow> window;
  window->SetSize(600, 400);
  window->SetMultiSamples(0);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();

  bool ok = true;
  vtkNew<vtkParticleSphereMapper> mappers[6];
  vtkNew<prTest::MessageCounter> observers[6];
  for (int c = 0; c < 6; ++c)
  {
    vtkParticleSphereMapper* mapper = mappers[c];
    observers[c]->Observe(mapper);
    mapper->SetInputData(cases[c].Data);
    mapper->SetRadiusArrayName(cases[c].RadiusArray);
    mapper->SetRadius(0.25);
    mapper->SetLookupTable(lut);
    mapper->SetScalarRange(0, 9);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    renderer->SetBackground(0.1 + 0.05 * c, 0.1, 0.15);
    renderer->SetViewport((c % 3) / 3.0, (c / 3) / 2.0, (c % 3 + 1) / 3.0, (c / 3 + 1) / 2.0);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(8, -5, 7);
    camera->SetFocalPoint(1.5, 1.5, 1.5);
    camera->SetViewUp(0, 0, 1);
    window->AddRenderer(renderer);
    renderer->ResetCameraClippingRange(-1, 4, -1, 4, -1, 4);
  }

  window->Render();
  window->Render(); // a second frame must not warn again

  for (int c = 0; c < 6; ++c)
  {
    prTest::MessageCounter* obs = observers[c];
    const std::string label = "case " + std::to_string(c) + ": ";
    ok &= prTest::Check(obs->Errors == 0, label + "unexpected error " + obs->LastError);
    if (cases[c].ExpectedWarning)
    {
      ok &= prTest::Check(obs->LastWarning.find(cases[c].ExpectedWarning) != std::string::npos,
        label + "expected a warning containing '" + cases[c].ExpectedWarning + "', got '" +
          obs->LastWarning + "'");
      ok &= prTest::Check(obs->Warnings == 1,
        label + "warned " + std::to_string(obs->Warnings) + " times, expected once");
    }
    else
    {
      ok &= prTest::Check(obs->Warnings == 0, label + "unexpected warning " + obs->LastWarning);
    }
    ok &= prTest::Check(mappers[c]->GetNumberOfSkippedParticles() == cases[c].ExpectedSkipped,
      label + "skipped " + std::to_string(mappers[c]->GetNumberOfSkippedParticles()) +
        " particles, expected " + std::to_string(cases[c].ExpectedSkipped));
    // the bounds must be finite whatever the input
    double* b = mappers[c]->GetBounds();
    for (int k = 0; k < 6 && c != 0; ++k)
    {
      ok &= prTest::Check(std::isfinite(b[k]), label + "non-finite bounds");
    }
  }

  // Criteria: the GPU's own image on the same platform; what matters is which particles are drawn
  // (a skipped or extra sphere changes hundreds of pixels by far more than 2/255), so at most a
  // tenth of a per cent of the pixels may differ by more than 2/255 and the mean by 0.5/255.
  prTest::ImageCriteria criteria;
  criteria.Tolerance = 2.0;
  criteria.MaxOverToleranceShare = 1e-3;
  criteria.MaxMean = 0.5;
  ok &= prTest::CompareWithBaseline(argc, argv, window, criteria);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
