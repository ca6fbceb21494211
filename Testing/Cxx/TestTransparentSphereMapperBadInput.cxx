// Bad input for vtkTransparentSphereMapper: every case gets a warning (once) and a sane image,
// never a crash or NaN: a missing, non-numeric or multi-component opacity array (maximum
// opacity 1), NaN opacities (those particles are not drawn), a reversed and an empty opacity
// range, everything fully transparent (nothing drawn), invalid radii and positions among
// translucent particles, an empty input, and time steps whose particle count changes.
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkParticleFrontToBackTarget.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkStringArray.h"
#include "vtkTransparentSphereMapper.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>

namespace
{
vtkSmartPointer<vtkPolyData> Particles(int n, vtkIdType& count)
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> opacity;
  opacity->SetName("opacity");
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      points->InsertNextPoint(1.2 * i, 1.2 * j, 0.3 * ((i + j) % 3));
      opacity->InsertNextValue(static_cast<float>((i * n + j) % 10) / 9.0f);
    }
  }
  data->SetPoints(points);
  data->GetPointData()->AddArray(opacity);
  count = points->GetNumberOfPoints();
  return data;
}

bool Sane(vtkRenderWindow* window, vtkTransparentSphereMapper* mapper, const std::string& what,
  bool expectParticles)
{
  window->Render();
  int* size = window->GetSize();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(0, 0, size[0] - 1, size[1] - 1, 1, pixels);
  long long lit = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    lit += pixels->GetValue(4 * i) > 60 ? 1 : 0; // background red is 25
  }
  std::vector<float> accumulation;
  bool finite = true;
  if (mapper->GetFrontToBackTarget()->GetAccumulation(accumulation))
  {
    for (float v : accumulation)
    {
      finite &= std::isfinite(v);
    }
  }
  bool ok = prTest::Check(finite, what + ": no NaN/Inf in the accumulation");
  ok &= prTest::Check(expectParticles ? lit > 100 : lit == 0,
    what + (expectParticles ? ": particles visible" : ": nothing drawn") + " (" +
      std::to_string(lit) + " bright pixels)");
  return ok;
}
}

int TestTransparentSphereMapperBadInput(int, char*[])
{
  bool ok = true;
  vtkIdType count = 0;
  vtkSmartPointer<vtkPolyData> data = Particles(12, count);

  vtkNew<vtkTransparentSphereMapper> mapper;
  mapper->SetInputData(data);
  mapper->SetRadius(0.5);
  mapper->ScalarVisibilityOff();
  mapper->GetFrontToBackTarget()->SetKeepAccumulation(true);
  vtkNew<prTest::MessageCounter> messages;
  messages->Observe(mapper, true, false);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.8, 0.3);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.1);
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 200);
  window->AddRenderer(renderer);
  renderer->ResetCamera();

  // a usable array first
  mapper->SetOpacityArrayName("opacity");
  ok &= Sane(window, mapper, "valid opacity array", true);
  ok &= prTest::Check(messages->Warnings == 0, "no warning for a valid array");

  // missing array: maximum opacity 1 for everyone, one warning even over several frames
  mapper->SetOpacityArrayName("nope");
  ok &= Sane(window, mapper, "missing opacity array", true);
  window->Render();
  ok &= prTest::Check(messages->Warnings == 1, "one warning for a missing array (" + std::to_string(messages->Warnings) + ")");
  ok &= prTest::Check(!mapper->HasTranslucentPolygonalGeometry(), "missing array: all opaque");

  // non-numeric array
  vtkNew<vtkStringArray> names;
  names->SetName("names");
  names->SetNumberOfValues(count);
  data->GetPointData()->AddArray(names);
  mapper->SetOpacityArrayName("names");
  ok &= Sane(window, mapper, "string opacity array", true);
  ok &= prTest::Check(messages->Warnings == 2, "a warning for a string array");

  // three components
  vtkNew<vtkDoubleArray> vectors;
  vectors->SetName("vectors");
  vectors->SetNumberOfComponents(3);
  vectors->SetNumberOfTuples(count);
  vectors->Fill(0.5);
  data->GetPointData()->AddArray(vectors);
  mapper->SetOpacityArrayName("vectors");
  ok &= Sane(window, mapper, "3-component opacity array", true);
  ok &= prTest::Check(messages->Warnings == 3, "a warning for a 3-component array");

  // NaN opacities: those particles are not drawn, the rest are
  vtkNew<vtkFloatArray> withNaN;
  withNaN->SetName("withNaN");
  withNaN->SetNumberOfTuples(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    withNaN->SetValue(i, i % 2 ? std::numeric_limits<float>::quiet_NaN() : 0.5f);
  }
  data->GetPointData()->AddArray(withNaN);
  mapper->SetOpacityArrayName("withNaN");
  ok &= Sane(window, mapper, "NaN opacities", true);
  ok &= prTest::Check(messages->Warnings == 4, "a warning for NaN opacities");
  ok &= prTest::Check(mapper->GetParticleOpacities()->GetValue(1) == 0.0, "NaN -> opacity 0");

  // reversed range (high values transparent) and an empty range (a threshold)
  mapper->SetOpacityArrayName("opacity");
  mapper->SetOpacityRange(1.0, 0.0);
  ok &= Sane(window, mapper, "reversed opacity range", true);
  ok &= prTest::Check(mapper->GetParticleOpacities()->GetValue(0) == 1.0, "reversed range maps 0 to 1");
  mapper->SetOpacityRange(0.5, 0.5);
  ok &= Sane(window, mapper, "empty opacity range", true);
  ok &= prTest::Check(mapper->GetParticleOpacities()->GetValue(0) == 0.0 &&
      mapper->GetParticleOpacities()->GetValue(9) == 1.0,
    "empty range is a threshold");

  // everything fully transparent: nothing at all
  mapper->SetOpacityRange(2.0, 3.0);
  ok &= Sane(window, mapper, "all transparent", false);
  ok &= prTest::Check(!mapper->HasTranslucentPolygonalGeometry() && !mapper->HasOpaqueGeometry(),
    "all transparent: neither opaque nor translucent");

  // invalid radii and positions among translucent particles
  mapper->SetOpacityRange(0.0, 1.0);
  data->GetPoints()->SetPoint(3, std::nan(""), 0, 0);
  data->GetPoints()->Modified();
  ok &= Sane(window, mapper, "NaN position", true);
  const int before = messages->Warnings;
  ok &= prTest::Check(before >= 5, "warning for the NaN position");

  // a time step with fewer, then more particles (re-sorted, no stale indices)
  vtkIdType fewer = 0;
  vtkSmartPointer<vtkPolyData> small = Particles(5, fewer);
  mapper->SetInputData(small);
  ok &= Sane(window, mapper, "fewer particles", true);
  vtkIdType more = 0;
  vtkSmartPointer<vtkPolyData> large = Particles(20, more);
  mapper->SetInputData(large);
  renderer->ResetCamera();
  ok &= Sane(window, mapper, "more particles", true);

  // empty input
  vtkNew<vtkPolyData> empty;
  mapper->SetInputData(empty);
  ok &= Sane(window, mapper, "empty input", false);

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
