// Bad input for vtkTransparentSphereMapper: a sane image for every case, never a crash or NaN.
// Bad input gets exactly one warning that says what is wrong: a missing, non-numeric or
// multi-component opacity array (maximum opacity 1), NaN opacities (those particles are not
// drawn), a NaN position among translucent particles, an empty input. Deliberate settings get
// none: a reversed opacity range (high values transparent), an empty range (a threshold),
// everything fully transparent (nothing drawn). Time steps whose particle count changes must
// give exactly the image of a fresh mapper on the same step (no stale sort indices or buffers).
// Each frame's float accumulation is read back from that frame (the retained copy is cleared
// before it) and must be free of NaN/Inf.
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
  mapper->GetFrontToBackTarget()->ClearRetainedAccumulation();
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
  const bool composited = mapper->GetFrontToBackTarget()->GetAccumulation(accumulation);
  for (float v : accumulation)
  {
    finite &= std::isfinite(v);
  }
  bool ok = prTest::Check(finite, what + ": no NaN/Inf in the accumulation");
  ok &= prTest::Check(composited == mapper->HasTranslucentPolygonalGeometry(),
    what + ": this frame's accumulation read back exactly when it has translucent particles");
  ok &= prTest::Check(expectParticles ? lit > 100 : lit == 0,
    what + (expectParticles ? ": particles visible" : ": nothing drawn") + " (" +
      std::to_string(lit) + " bright pixels)");
  return ok;
}

// The window's image with a fresh mapper (same settings) on the same data, for comparison.
vtkSmartPointer<vtkUnsignedCharArray> FreshImage(
  vtkRenderWindow* window, vtkActor* actor, vtkTransparentSphereMapper* like)
{
  vtkNew<vtkTransparentSphereMapper> fresh;
  fresh->SetInputData(like->GetInput());
  fresh->SetRadius(like->GetRadius());
  fresh->ScalarVisibilityOff();
  fresh->SetOpacityArrayName(like->GetOpacityArrayName());
  fresh->SetOpacityRange(like->GetOpacityRange());
  vtkMapper* previous = actor->GetMapper();
  previous->Register(nullptr);
  actor->SetMapper(fresh);
  window->Render();
  auto pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
  int* size = window->GetSize();
  window->GetRGBACharPixelData(0, 0, size[0] - 1, size[1] - 1, 1, pixels);
  actor->SetMapper(previous);
  previous->UnRegister(nullptr);
  fresh->ReleaseGraphicsResources(window);
  return pixels;
}

bool SameAsFresh(vtkRenderWindow* window, vtkActor* actor, vtkTransparentSphereMapper* mapper,
  const std::string& what)
{
  window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  int* size = window->GetSize();
  window->GetRGBACharPixelData(0, 0, size[0] - 1, size[1] - 1, 1, pixels);
  vtkSmartPointer<vtkUnsignedCharArray> expected = FreshImage(window, actor, mapper);
  int worst = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfValues(); ++i)
  {
    worst = std::max(worst, std::abs(int(pixels->GetValue(i)) - int(expected->GetValue(i))));
  }
  std::cout << what << ": max |image - fresh mapper's image| " << worst << "/255\n";
  return prTest::Check(worst == 0, what + ": differs from a fresh mapper's image (stale state)");
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
  ok &= prTest::Check(messages->Warnings == 1,
    "one warning for a missing array (" + std::to_string(messages->Warnings) + ")");
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

  // reversed range (high values transparent) and an empty range (a threshold): deliberate
  // settings, no warning
  mapper->SetOpacityArrayName("opacity");
  const int settingsWarnings = messages->Warnings;
  mapper->SetOpacityRange(1.0, 0.0);
  ok &= Sane(window, mapper, "reversed opacity range", true);
  ok &=
    prTest::Check(mapper->GetParticleOpacities()->GetValue(0) == 1.0, "reversed range maps 0 to 1");
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
  ok &= prTest::Check(messages->Warnings == settingsWarnings,
    "no warning for a reversed or empty range or all transparent (" + messages->LastWarning + ")");

  // invalid radii and positions among translucent particles
  mapper->SetOpacityRange(0.0, 1.0);
  data->GetPoints()->SetPoint(3, std::nan(""), 0, 0);
  data->GetPoints()->Modified();
  const int before = messages->Warnings;
  ok &= Sane(window, mapper, "NaN position", true);
  window->Render();
  ok &= prTest::Check(messages->Warnings == before + 1 &&
      messages->LastWarning.find("1 of 144 particles have a NaN or infinite position") !=
        std::string::npos,
    "one warning naming the NaN position (got " + std::to_string(messages->Warnings - before) +
      ": " + messages->LastWarning + ")");
  ok &= SameAsFresh(window, actor, mapper, "NaN position");

  // a time step with fewer, then more particles (re-sorted, no stale indices)
  vtkIdType fewer = 0;
  vtkSmartPointer<vtkPolyData> small = Particles(5, fewer);
  mapper->SetInputData(small);
  ok &= Sane(window, mapper, "fewer particles", true);
  ok &= SameAsFresh(window, actor, mapper, "fewer particles");
  vtkIdType more = 0;
  vtkSmartPointer<vtkPolyData> large = Particles(20, more);
  mapper->SetInputData(large);
  renderer->ResetCamera();
  ok &= Sane(window, mapper, "more particles", true);
  ok &= SameAsFresh(window, actor, mapper, "more particles");

  // empty input: one warning that says so
  vtkNew<vtkPolyData> empty;
  mapper->SetInputData(empty);
  const int beforeEmpty = messages->Warnings;
  ok &= Sane(window, mapper, "empty input", false);
  window->Render();
  ok &= prTest::Check(messages->Warnings == beforeEmpty + 1 &&
      messages->LastWarning.find("no points") != std::string::npos,
    "one warning for the empty input (" + messages->LastWarning + ")");

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
