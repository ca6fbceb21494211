// Extreme geometry for the sphere core, one viewport each (the image must be sane, the
// checks below must hold):
//   0 parallel projection            1 eye inside a large sphere (its inner surface is seen)
//   2 camera 1e7 radii away          3 radii 1e-6 (scene scaled down)
//   4 radii 1e6 (scene scaled up)    5 all particles in one plane, plus 50 at a single point
// Cases 3 and 4 are the same lattice scaled by 1e-6/0.45 and 1e6/0.45 and seen through the
// same relative camera as each other: their panels must be the same picture (compared pixel by
// pixel). Case 2 is the lattice seen from 4.5e6 units (1e7 radii) with a view angle that frames
// a half-height of 3.2: a perspective so weak that it must be the parallel projection of case 0
// with a parallel scale of 3.2 (case 0 itself uses 3.5 in the baseline; the check re-renders it
// at 3.2 and compares the two panels).
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkParticleImageComparison.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <iostream>

namespace
{
// A copy of the lattice scaled by s about the origin (positions and radii).
vtkSmartPointer<vtkPolyData> Scaled(vtkPolyData* in, double s)
{
  vtkSmartPointer<vtkPolyData> out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(in);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < in->GetNumberOfPoints(); ++i)
  {
    double p[3];
    in->GetPoint(i, p);
    points->InsertNextPoint(p[0] * s, p[1] * s, p[2] * s);
  }
  out->SetPoints(points);
  vtkFloatArray* r = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("radius"));
  for (vtkIdType i = 0; i < r->GetNumberOfTuples(); ++i)
  {
    r->SetValue(i, static_cast<float>(r->GetValue(i) * s));
  }
  return out;
}

// Fraction of the viewport's pixels that differ from the background.
double Coverage(vtkRenderWindow* window, vtkRenderer* renderer)
{
  int* size = window->GetSize();
  double* vp = renderer->GetViewport();
  const int x0 = static_cast<int>(vp[0] * size[0]), x1 = static_cast<int>(vp[2] * size[0]) - 1;
  const int y0 = static_cast<int>(vp[1] * size[1]), y1 = static_cast<int>(vp[3] * size[1]) - 1;
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(x0, y0, x1, y1, 0, pixels);
  double* bg = renderer->GetBackground();
  vtkIdType covered = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    bool same = true;
    for (int k = 0; k < 3; ++k)
    {
      same &= std::abs(pixels->GetValue(3 * i + k) - bg[k] * 255.0) < 2.0;
    }
    covered += same ? 0 : 1;
  }
  return static_cast<double>(covered) / pixels->GetNumberOfTuples();
}
}

int TestParticleSphereMapperExtremes(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> lattice = prTest::MakeLattice(5, 1.0, 11);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(600, 400);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderers[6];
  vtkNew<vtkParticleSphereMapper> mappers[6];

  // the big sphere that holds the eye in case 1
  vtkSmartPointer<vtkPolyData> inside = vtkSmartPointer<vtkPolyData>::New();
  inside->DeepCopy(lattice);
  {
    vtkFloatArray* r = vtkFloatArray::SafeDownCast(inside->GetPointData()->GetArray("radius"));
    r->SetValue(62, 2.5); // the centre particle (2,2,2)-ish of the 5^3 lattice
  }
  // all particles in the plane z = 0, and 50 particles at one point
  vtkSmartPointer<vtkPolyData> flat = vtkSmartPointer<vtkPolyData>::New();
  flat->DeepCopy(lattice);
  for (vtkIdType i = 0; i < flat->GetNumberOfPoints(); ++i)
  {
    double p[3];
    flat->GetPoint(i, p);
    if (i < 50)
    {
      p[0] = p[1] = 2.0;
    }
    p[2] = 0.0;
    flat->GetPoints()->SetPoint(i, p);
  }

  vtkPolyData* inputs[6] = { lattice, inside, lattice, nullptr, nullptr, flat };
  vtkSmartPointer<vtkPolyData> tiny = Scaled(lattice, 1e-6 / 0.45);
  vtkSmartPointer<vtkPolyData> huge = Scaled(lattice, 1e6 / 0.45);
  inputs[3] = tiny;
  inputs[4] = huge;
  const double scales[6] = { 1, 1, 1, 1e-6 / 0.45, 1e6 / 0.45, 1 };

  for (int c = 0; c < 6; ++c)
  {
    mappers[c]->SetInputData(inputs[c]);
    mappers[c]->SetRadiusArrayName("radius");
    mappers[c]->SetLookupTable(lut);
    mappers[c]->SetScalarRange(0, 12);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mappers[c]);
    renderers[c]->AddActor(actor);
    renderers[c]->SetBackground(0.1, 0.1, 0.15);
    renderers[c]->SetViewport(
      (c % 3) / 3.0, 0.5 - (c / 3) / 2.0, (c % 3 + 1) / 3.0, 1.0 - (c / 3) / 2.0);
    window->AddRenderer(renderers[c]);
    vtkCamera* camera = renderers[c]->GetActiveCamera();
    const double s = scales[c];
    camera->SetFocalPoint(2 * s, 2 * s, 2 * s);
    camera->SetPosition(9 * s, -4 * s, 8 * s);
    camera->SetViewUp(0, 0, 1);
    renderers[c]->ResetCameraClippingRange();
  }
  // 0: parallel projection
  renderers[0]->GetActiveCamera()->ParallelProjectionOn();
  renderers[0]->GetActiveCamera()->SetParallelScale(3.5);
  // 1: the eye at the centre of the big sphere, looking at its inner surface past its neighbours
  {
    double c[3];
    inside->GetPoint(62, c);
    vtkCamera* camera = renderers[1]->GetActiveCamera();
    camera->SetPosition(c[0] + 0.3, c[1] - 0.2, c[2] + 0.1);
    camera->SetFocalPoint(c[0] + 3, c[1] + 1, c[2] + 0.5);
    camera->SetViewAngle(80);
    camera->SetClippingRange(0.01, 20);
  }
  // 2: 1e7 mean radii away, with a view angle that frames the lattice
  {
    vtkCamera* camera = renderers[2]->GetActiveCamera();
    const double d = 0.45e7;
    double dir[3] = { 7, -6, 6 };
    const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    camera->SetPosition(2 + d * dir[0] / n, 2 + d * dir[1] / n, 2 + d * dir[2] / n);
    camera->SetViewAngle(2.0 * std::atan(3.2 / d) * 180.0 / 3.14159265358979);
    renderers[2]->ResetCameraClippingRange();
  }
  window->Render();

  bool ok = vtkParticleImageComparison::TestRepeatable(window, "TestParticleSphereMapperExtremes");
  for (int c = 0; c < 6; ++c)
  {
    const double coverage = Coverage(window, renderers[c]);
    std::cout << "case " << c << ": coverage " << coverage << "\n";
    ok &= prTest::Check(coverage > 0.05, "case " + std::to_string(c) + ": almost nothing drawn");
  }
  // the eye is inside a sphere: its inner surface covers the whole viewport
  ok &= prTest::Check(Coverage(window, renderers[1]) > 0.999, "case 1: inner surface not full");
  // cases 3 and 4 are the scaled copies of one scene: same picture (coverage) within 1%
  ok &=
    prTest::Check(std::abs(Coverage(window, renderers[3]) - Coverage(window, renderers[4])) < 0.01,
      "cases 3/4: scaled scenes differ");
  // Criteria: the GPU's own image on the same platform (rounding only); silhouettes compared.
  prTest::ImageCriteria criteria;
  criteria.Tolerance = 2.0;
  criteria.MaxOverToleranceShare = 1e-3;
  criteria.MaxMean = 0.5;
  ok &= prTest::CompareWithBaseline(argc, argv, window, criteria);

  // panels 3 and 4: the same picture; panel 2: the parallel projection of panel 0 at scale 3.2
  auto panel = [&](int c)
  {
    vtkNew<vtkImageData> image;
    vtkParticleImageComparison::GrabColorBuffer(window, image, renderers[c]);
    return vtkParticleImageComparison::ExtractRGB(image);
  };
  vtkNew<vtkParticleImageComparison> same;
  same->SetTolerance(2.0 / 255.0);
  same->SetMaximumOverToleranceFraction(2e-3);
  same->SetMaximumMeanError(0.5 / 255.0);
  ok &= prTest::Check(
    same->TestImages(panel(4), panel(3), nullptr, prTest::TempDirectory(argc, argv).c_str(),
      "TestParticleSphereMapperExtremes_panel4_vs_3"),
    "cases 3/4: the scaled scenes differ");
  renderers[0]->GetActiveCamera()->SetParallelScale(3.2);
  window->Render();
  ok &= prTest::Check(
    same->TestImages(panel(2), panel(0), nullptr, prTest::TempDirectory(argc, argv).c_str(),
      "TestParticleSphereMapperExtremes_panel2_vs_parallel"),
    "case 2: the far camera is not the parallel projection");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
