// The transparent mode of vtkParticleReferenceRenderer (vtkTransparentSphereMapper's model), on
// the CPU only (no baseline image):
//   a) IntegrateDensity against closed forms derived here (solid integral minus the core's), both
//      density models, solid and hollow, impact parameters 0..r (incl. (1 - 1e-9) r), radii 1e-6,
//      1, 1e6, full and partial segments: 1e-12 relative;
//   b) NumericalMaximumPathIntegral against vtkTransparentSphereMapper::GetMaximumPathIntegral for
//      f in {0, 0.1, 0.5, 0.7, 0.7071, 0.72, 0.9, 0.99, 0.999}, both models: 1e-9 relative;
//   c) SegmentOpacity along the most opaque ray equals thetaMax (0, 1e-6, 0.5, 0.99, 1 - 1e-7) to
//      1e-12 relative;
//   d) Render() of 3 spheres in a row along the view axis (Opacity 0.5) against the composite
//      computed by hand at the centre pixel, for a solid constant-density and a hollow
//      squared-distance model; the eye inside the first sphere (no entry surface);
//   e) SetOpaqueLayer: a constant depth cutting the middle sphere, a depth in front of all
//      spheres, depth 1 everywhere, and clearing the layer;
//   f) Opacity 1: every particle opaque, the images equal the opaque mode's (plain
//      vtkParticleSphereMapper) exactly;
//   g) 22^3 (~1e4) translucent spheres at 512x512: timing, finite values in [0,1].
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkLightKit.h"
#include "vtkLookupTable.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkParticleReferenceRenderer.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTransparentSphereMapper.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
const double Inf = std::numeric_limits<double>::infinity();
const int Constant = vtkTransparentSphereMapper::CONSTANT_DENSITY;
const int Squared = vtkTransparentSphereMapper::SQUARED_DISTANCE_DENSITY;

std::string Describe(const std::string& what, double got, double expected)
{
  std::ostringstream s;
  s << std::setprecision(17) << what << ": got " << got << ", expected " << expected;
  return s.str();
}

bool Near(double got, double expected, double relTol, double absTol, const std::string& what)
{
  return prTest::Check(std::abs(got - expected) <= relTol * std::abs(expected) + absTol,
    Describe(what, got, expected));
}

// Antiderivative of the density along a ray of impact parameter b (tau from the closest
// approach): rho = 1 -> tau, rho = b^2 + tau^2 -> b^2 tau + tau^3 / 3.
double Antiderivative(int model, double b, double tau)
{
  return model == Constant ? tau : b * b * tau + tau * tau * tau / 3.0;
}

// Closed form: the solid sphere's integral over [tau0, tau1] clipped to the chord, minus the
// core ball's integral over the same range clipped to the core's chord.
double ClosedForm(int model, double f, double r, double b, double tau0, double tau1)
{
  if (!(b < r))
  {
    return 0.0;
  }
  const double h = std::sqrt((r - b) * (r + b));
  const double lo = std::max(tau0, -h);
  const double hi = std::min(tau1, h);
  if (!(lo < hi))
  {
    return 0.0;
  }
  double value = Antiderivative(model, b, hi) - Antiderivative(model, b, lo);
  const double rs = f * r;
  if (b < rs)
  {
    const double hs = std::sqrt((rs - b) * (rs + b));
    const double clo = std::max(lo, -hs);
    const double chi = std::min(hi, hs);
    if (clo < chi)
    {
      value -= Antiderivative(model, b, chi) - Antiderivative(model, b, clo);
    }
  }
  return value;
}

bool TestIntegrals()
{
  bool ok = true;
  const double fractions[] = { 0.0, 0.5, 0.9 };
  const double radii[] = { 1e-6, 1.0, 1e6 };
  const double impacts[] = { 0.0, 0.25, 0.5, 0.7071067811865476, 0.9, 1.0 - 1e-9, 1.0, 1.5 };
  int count = 0;
  for (int model : { Constant, Squared })
  {
    for (double f : fractions)
    {
      for (double r : radii)
      {
        std::vector<double> bs;
        for (double b : impacts)
        {
          bs.push_back(b * r);
        }
        bs.push_back(f * r); // tangent to the core
        for (double b : bs)
        {
          const double h = b < r ? std::sqrt((r - b) * (r + b)) : 0.0;
          const double hs = b < f * r ? std::sqrt((f * r - b) * (f * r + b)) : 0.0;
          // full chord, halves, partial segments, segments crossing and inside the core, a
          // segment beyond the sphere
          const double segments[][2] = { { -Inf, Inf }, { -2 * h, 2 * h }, { -Inf, 0 }, { 0, Inf },
            { -0.5 * h, 0.3 * h }, { -0.9 * h, -0.5 * (h + hs) }, { -0.5 * (h + hs), 0.5 * hs },
            { -0.5 * hs, 0.25 * hs }, { 0.5 * hs, Inf }, { 2 * h + r, 3 * h + 2 * r },
            { 0.7 * h, 0.2 * h } };
          for (const auto& seg : segments)
          {
            const double got =
              vtkParticleReferenceRenderer::IntegrateDensity(model, f, r, b, seg[0], seg[1]);
            const double expected = ClosedForm(model, f, r, b, seg[0], seg[1]);
            // absolute floor: rounding of the chord ends (h, hs) in the closed form
            const double scale = model == Constant ? r : r * r * r;
            std::ostringstream what;
            what << std::setprecision(17) << "IntegrateDensity(model " << model << ", f " << f
                 << ", r " << r << ", b " << b << ", [" << seg[0] << ", " << seg[1] << "])";
            ok &= Near(got, expected, 1e-12, 1e-15 * scale, what.str());
            ++count;
          }
        }
      }
    }
  }
  // the sign of the impact parameter does not matter, NaN gives 0
  ok &= Near(vtkParticleReferenceRenderer::IntegrateDensity(Squared, 0.3, 2.0, -0.5, -Inf, Inf),
    vtkParticleReferenceRenderer::IntegrateDensity(Squared, 0.3, 2.0, 0.5, -Inf, Inf), 1e-15, 0.0,
    "negative impact");
  ok &= prTest::Check(vtkParticleReferenceRenderer::IntegrateDensity(
                        Constant, 0.0, 1.0, 0.0, std::nan(""), 1.0) == 0.0,
    "NaN segment end gives 0");
  std::cout << "a) " << count << " integrals compared with the closed forms\n";
  return ok;
}

bool TestMaximum()
{
  bool ok = true;
  const double fractions[] = { 0, 0.1, 0.5, 0.7, 0.7071, 0.72, 0.9, 0.99, 0.999 };
  double worst = 0.0;
  for (int model : { Constant, Squared })
  {
    for (double f : fractions)
    {
      const double numerical = vtkParticleReferenceRenderer::NumericalMaximumPathIntegral(model, f);
      const double closed = vtkTransparentSphereMapper::GetMaximumPathIntegral(model, f);
      worst = std::max(worst, std::abs(numerical - closed) / closed);
      std::ostringstream what;
      what << "NumericalMaximumPathIntegral(model " << model << ", f " << f << ")";
      ok &= Near(numerical, closed, 1e-9, 0.0, what.str());
    }
  }
  std::cout << "b) largest relative difference of I_max: " << worst << "\n";
  return ok;
}

bool TestSegmentOpacity()
{
  bool ok = true;
  const double thetas[] = { 0.0, 1e-6, 0.5, 0.99, 1.0 - 1e-7 };
  double worst = 0.0;
  for (int model : { Constant, Squared })
  {
    for (double f : { 0.0, 0.5, 0.9 })
    {
      for (double r : { 1e-6, 1.0, 1e6 })
      {
        // the most opaque ray (class description of vtkTransparentSphereMapper)
        const double b = model == Constant ? f * r : std::max(f, std::sqrt(0.5)) * r;
        for (double theta : thetas)
        {
          const double got =
            vtkParticleReferenceRenderer::SegmentOpacity(model, f, r, b, -Inf, Inf, theta);
          std::ostringstream what;
          what << std::setprecision(17) << "SegmentOpacity(model " << model << ", f " << f << ", r "
               << r << ", most opaque ray, thetaMax " << theta << ")";
          if (theta == 0.0)
          {
            ok &= prTest::Check(got == 0.0, Describe(what.str(), got, 0.0));
            continue;
          }
          worst = std::max(worst, std::abs(got - theta) / theta);
          ok &= Near(got, theta, 1e-12, 0.0, what.str());
        }
      }
    }
  }
  ok &= prTest::Check(
    vtkParticleReferenceRenderer::SegmentOpacity(Constant, 0.0, 1.0, 0.5, -Inf, Inf, 1.0) == 1.0,
    "SegmentOpacity with thetaMax 1 is 1");
  ok &= prTest::Check(
    vtkParticleReferenceRenderer::SegmentOpacity(Constant, 0.0, 1.0, 1.5, -Inf, Inf, 1.0) == 0.0,
    "SegmentOpacity of a ray that misses is 0");
  // a half chord of the constant model: 1 - sqrt(1 - thetaMax)
  ok &= Near(vtkParticleReferenceRenderer::SegmentOpacity(Constant, 0.0, 3.0, 0.0, 0.0, Inf, 0.75),
    0.5, 1e-14, 0.0, "SegmentOpacity of half a diameter");
  std::cout << "c) largest relative error of Theta on the most opaque ray: " << worst << "\n";
  return ok;
}

//------------------------------------------------------------------------------
// Three unit spheres at z = 0, -3, -6 seen from (0, 0, 10) along -z, 65x65 pixels (the centre
// pixel's ray is the axis), headlight, scalar colours, Opacity 0.5.
const int Size = 65;
const size_t CentrePixel = static_cast<size_t>(Size / 2) * Size + Size / 2;
const double SphereColors[3][3] = { { 200, 60, 30 }, { 40, 180, 90 }, { 70, 100, 220 } };
const double Background[3] = { 0.1, 0.2, 0.3 };
const double BackgroundAlpha = 0.6;
const double AmbientK = 0.1;
const double DiffuseK = 0.8;
const double SpecularK = 0.3;
const double VolumeMix = 0.3;

struct RowScene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkTransparentSphereMapper> Mapper;
  vtkNew<vtkParticleReferenceRenderer> Reference;

  RowScene()
  {
    vtkNew<vtkPolyData> poly;
    vtkNew<vtkPoints> points;
    vtkNew<vtkUnsignedCharArray> colors;
    colors->SetNumberOfComponents(4);
    for (int i = 0; i < 3; ++i)
    {
      points->InsertNextPoint(0.0, 0.0, -3.0 * i);
      const unsigned char c[4] = { static_cast<unsigned char>(SphereColors[i][0]),
        static_cast<unsigned char>(SphereColors[i][1]),
        static_cast<unsigned char>(SphereColors[i][2]), 255 };
      colors->InsertNextTypedTuple(c);
    }
    poly->SetPoints(points);
    poly->GetPointData()->SetScalars(colors);
    this->Mapper->SetInputData(poly);
    this->Mapper->SetRadius(1.0);
    this->Mapper->SetColorModeToDirectScalars();
    this->Mapper->SetVolumeMix(VolumeMix);
    this->Actor->SetMapper(this->Mapper);
    vtkProperty* property = this->Actor->GetProperty();
    property->SetOpacity(0.5);
    property->SetAmbient(AmbientK);
    property->SetDiffuse(DiffuseK);
    property->SetSpecular(SpecularK);
    property->SetSpecularPower(10);
    this->Renderer->SetBackground(Background[0], Background[1], Background[2]);
    this->Renderer->SetBackgroundAlpha(BackgroundAlpha);
    this->Renderer->AddActor(this->Actor);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0, 0, 10);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    camera->SetViewAngle(30);
    camera->SetClippingRange(1, 100);
    this->Reference->SetRenderer(this->Renderer);
    this->Reference->SetActor(this->Actor);
    this->Reference->SetImageSize(Size, Size);
  }

  // L_R at the front pole seen along the axis with the headlight: n = v = (0,0,1), df = sf = 1
  static void SurfaceColor(int i, double out[3])
  {
    for (int k = 0; k < 3; ++k)
    {
      out[k] = (AmbientK + DiffuseK) * SphereColors[i][k] / 255.0 + SpecularK;
    }
  }
  static void VolumeColor(int i, double out[3])
  {
    for (int k = 0; k < 3; ++k)
    {
      out[k] = DiffuseK * SphereColors[i][k] / 255.0;
    }
  }
};

struct Composite
{
  double C[3] = { 0, 0, 0 };
  double T = 1.0;
  // a segment with (entry = true) or without an entry surface
  void Add(int sphere, double theta, bool entry)
  {
    double lr[3];
    double ci[3];
    RowScene::SurfaceColor(sphere, lr);
    RowScene::VolumeColor(sphere, ci);
    for (int k = 0; k < 3; ++k)
    {
      const double l =
        entry ? theta * ((1 - VolumeMix) * lr[k] + VolumeMix * ci[k]) : theta * ci[k];
      this->C[k] += this->T * l;
    }
    this->T *= 1.0 - theta;
  }
};

bool CheckCentre(vtkParticleReferenceRenderer* reference, const Composite& expected,
  const double back[4], double tolerance, const std::string& what)
{
  bool ok = true;
  const double* rgba =
    vtkDoubleArray::SafeDownCast(reference->GetColorImage()->GetPointData()->GetScalars())
      ->GetPointer(4 * CentrePixel);
  const double alpha = vtkDoubleArray::SafeDownCast(
    reference->GetTranslucentAlphaImage()->GetPointData()->GetScalars())
                         ->GetValue(static_cast<vtkIdType>(CentrePixel));
  const char* channel[4] = { "r", "g", "b", "a" };
  for (int k = 0; k < 3; ++k)
  {
    const double want = expected.C[k] + expected.T * back[k];
    ok &= Near(rgba[k], want, 0.0, tolerance, what + " centre " + channel[k]);
  }
  ok &= Near(rgba[3], 1.0 - expected.T * (1.0 - back[3]), 0.0, tolerance, what + " centre a");
  ok &= Near(alpha, 1.0 - expected.T, 0.0, tolerance, what + " translucent alpha");
  return ok;
}

bool TestRender()
{
  bool ok = true;
  const double back[4] = { Background[0], Background[1], Background[2], BackgroundAlpha };
  const double tolerance = 1e-12;

  // (d1) solid, constant density: every full chord through the centre is the most opaque ray
  {
    RowScene scene;
    ok &= prTest::Check(scene.Reference->Render(), "d1 render");
    Composite expected;
    for (int i = 0; i < 3; ++i)
    {
      expected.Add(i, 0.5, true);
    }
    ok &= CheckCentre(scene.Reference, expected, back, tolerance, "d1 constant");
    ok &= prTest::Check(scene.Reference->GetIdImage()->GetValue(CentrePixel) == 0, "d1 front id");
    const double viewDepth = vtkDoubleArray::SafeDownCast(
      scene.Reference->GetViewDepthImage()->GetPointData()->GetScalars())
                               ->GetValue(CentrePixel);
    ok &= Near(viewDepth, 9.0, 1e-14, 0.0, "d1 front view depth");
    // a corner pixel sees the background only
    const double* corner =
      vtkDoubleArray::SafeDownCast(scene.Reference->GetColorImage()->GetPointData()->GetScalars())
        ->GetPointer(0);
    ok &= prTest::Check(
      corner[0] == back[0] && corner[1] == back[1] && corner[2] == back[2] && corner[3] == back[3],
      "d1 corner pixel is the background");
    std::cout << "d1) centre " << std::setprecision(10) << expected.C[0] + expected.T * back[0]
              << " " << expected.C[1] + expected.T * back[1] << " "
              << expected.C[2] + expected.T * back[2] << "\n";

    // (e) the opaque layer, a plane at view distance 13 (the middle sphere's centre)
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    double P[16];
    vtkMatrix4x4::DeepCopy(P, camera->GetProjectionTransformMatrix(1.0, -1, 1));
    auto windowDepth = [&](double distance)
    {
      const double z = P[10] * -distance + P[11];
      const double w = P[14] * -distance + P[15];
      return 0.5 * z / w + 0.5;
    };
    const double layerColor[4] = { 0.7, 0.5, 0.2, 1.0 };
    vtkNew<vtkDoubleArray> layerRGBA;
    layerRGBA->SetNumberOfComponents(4);
    layerRGBA->SetNumberOfTuples(Size * Size);
    vtkNew<vtkDoubleArray> layerDepth;
    layerDepth->SetNumberOfTuples(Size * Size);
    for (vtkIdType i = 0; i < Size * Size; ++i)
    {
      layerRGBA->SetTypedTuple(i, layerColor);
    }
    layerDepth->Fill(windowDepth(13.0));
    scene.Reference->SetOpaqueLayer(layerRGBA, layerDepth);
    ok &= prTest::Check(scene.Reference->Render(), "e1 render");
    {
      Composite cut;
      cut.Add(0, 0.5, true);
      cut.Add(1, 1.0 - std::sqrt(0.5), true); // half the diameter: 1 - (1 - 0.5)^(1/2)
      ok &= CheckCentre(scene.Reference, cut, layerColor, 1e-9, "e1 layer cutting sphere 1");
      std::cout << "e1) centre " << cut.C[0] + cut.T * layerColor[0] << " "
                << cut.C[1] + cut.T * layerColor[1] << " " << cut.C[2] + cut.T * layerColor[2]
                << " (without the layer " << expected.C[0] + expected.T * back[0] << " ...)\n";
    }
    // in front of all spheres: the layer's colour only
    layerDepth->Fill(windowDepth(5.0));
    layerDepth->Modified();
    ok &= prTest::Check(scene.Reference->Render(), "e2 render");
    ok &= CheckCentre(scene.Reference, Composite(), layerColor, 0.0, "e2 layer in front");
    ok &= prTest::Check(scene.Reference->GetIdImage()->GetValue(CentrePixel) == -1, "e2 no id");
    // depth 1 everywhere: the background
    layerDepth->Fill(1.0);
    ok &= prTest::Check(scene.Reference->Render(), "e3 render");
    ok &= CheckCentre(scene.Reference, expected, back, tolerance, "e3 layer at depth 1");
    // cleared
    layerDepth->Fill(windowDepth(5.0));
    scene.Reference->SetOpaqueLayer(nullptr, nullptr);
    ok &= prTest::Check(scene.Reference->Render(), "e4 render");
    ok &= CheckCentre(scene.Reference, expected, back, tolerance, "e4 layer cleared");
    // wrong size: Render fails
    vtkNew<vtkDoubleArray> small;
    small->SetNumberOfTuples(3);
    scene.Reference->SetOpaqueLayer(layerRGBA, small);
    std::cout << "(an error about the opaque layer's size is expected)\n";
    ok &= prTest::Check(!scene.Reference->Render(), "a layer of the wrong size fails");
  }

  // (d2) hollow (f = 0.5), squared distance: I(b = 0) = 2 (1 - f^3) / 3 r^3 = 7/12,
  // I_max = 2 sqrt(2) / 3 (f <= 1/sqrt(2))
  {
    RowScene scene;
    scene.Mapper->SetDensityModelToSquaredDistance();
    scene.Mapper->SetHollowFraction(0.5);
    ok &= prTest::Check(scene.Reference->Render(), "d2 render");
    const double theta = 1.0 - std::pow(0.5, (7.0 / 12.0) / (2.0 * std::sqrt(2.0) / 3.0));
    Composite expected;
    for (int i = 0; i < 3; ++i)
    {
      expected.Add(i, theta, true);
    }
    ok &= CheckCentre(scene.Reference, expected, back, tolerance, "d2 hollow squared");
  }

  // (d3) the eye at the first sphere's centre looking along -z, near plane 0.01: the first
  // segment starts at the near plane (no entry surface), the others at their entry points
  {
    RowScene scene;
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->SetPosition(0, 0, 0);
    camera->SetFocalPoint(0, 0, -1);
    camera->SetClippingRange(0.01, 100);
    ok &= prTest::Check(scene.Reference->Render(), "d3 render");
    Composite expected;
    expected.Add(0, 1.0 - std::pow(0.5, 0.99 / 2.0), false);
    expected.Add(1, 0.5, true);
    expected.Add(2, 0.5, true);
    ok &= CheckCentre(scene.Reference, expected, back, 1e-12, "d3 eye inside");
    ok &= prTest::Check(scene.Reference->GetInsideImage()->GetValue(CentrePixel) == 1,
      "d3 the front segment starts inside");
    ok &= Near(vtkDoubleArray::SafeDownCast(
                 scene.Reference->GetViewDepthImage()->GetPointData()->GetScalars())
                 ->GetValue(CentrePixel),
      0.01, 1e-12, 0.0, "d3 front view depth (near plane)");
  }
  return ok;
}

// (f) Opacity 1: the transparent mode must reproduce the opaque mode exactly.
bool TestOpaqueEquivalence()
{
  bool ok = true;
  vtkSmartPointer<vtkPolyData> lattice = prTest::MakeLattice(5, 1.0, 7);
  vtkNew<vtkLookupTable> lut;
  lut->Build();
  vtkSmartPointer<vtkImageData> images[2][3];
  vtkNew<vtkIdTypeArray> idImages[2];
  for (int mode = 0; mode < 2; ++mode)
  {
    vtkSmartPointer<vtkParticleSphereMapper> mapper;
    if (mode == 0)
    {
      mapper = vtkSmartPointer<vtkParticleSphereMapper>::New();
    }
    else
    {
      mapper = vtkSmartPointer<vtkTransparentSphereMapper>::New();
    }
    mapper->SetInputData(lattice);
    mapper->SetRadiusArrayName("radius");
    mapper->SetLookupTable(lut);
    mapper->SetScalarRange(0, 12);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetSpecular(0.4);
    actor->GetProperty()->SetSpecularPower(20);
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkLightKit> kit;
    kit->AddLightsToRenderer(renderer);
    renderer->SetBackground(0.3, 0.3, 0.4);
    renderer->AddActor(actor);
    renderer->GetActiveCamera()->SetPosition(-3, 9, 12);
    renderer->GetActiveCamera()->SetFocalPoint(2, 2, 2);
    renderer->ResetCameraClippingRange();
    vtkNew<vtkParticleReferenceRenderer> reference;
    reference->SetRenderer(renderer);
    reference->SetActor(actor);
    reference->SetImageSize(160, 120);
    ok &= prTest::Check(reference->Render(), "f render");
    images[mode][0] = reference->GetColorImage();
    images[mode][1] = reference->GetDepthImage();
    images[mode][2] = reference->GetNormalImage();
    idImages[mode]->DeepCopy(reference->GetIdImage());
  }
  const char* names[3] = { "colour", "depth", "normal" };
  for (int i = 0; i < 3; ++i)
  {
    vtkDataArray* a = images[0][i]->GetPointData()->GetScalars();
    vtkDataArray* b = images[1][i]->GetPointData()->GetScalars();
    bool same = a->GetNumberOfValues() == b->GetNumberOfValues();
    for (vtkIdType k = 0; same && k < a->GetNumberOfValues(); ++k)
    {
      same = a->GetVariantValue(k) == b->GetVariantValue(k);
    }
    ok &= prTest::Check(same, std::string("f opaque particles: ") + names[i] + " images equal");
  }
  bool sameIds = idImages[0]->GetNumberOfValues() == idImages[1]->GetNumberOfValues();
  for (vtkIdType k = 0; sameIds && k < idImages[0]->GetNumberOfValues(); ++k)
  {
    sameIds = idImages[0]->GetValue(k) == idImages[1]->GetValue(k);
  }
  ok &= prTest::Check(sameIds, "f opaque particles: id images equal");
  return ok;
}

// (g) ~1e4 translucent spheres at 512x512
bool TestPerformance()
{
  bool ok = true;
  vtkSmartPointer<vtkPolyData> lattice = prTest::MakeLattice(22, 1.0, 5);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();
  for (int model : { Constant, Squared })
  {
    vtkNew<vtkTransparentSphereMapper> mapper;
    mapper->SetInputData(lattice);
    mapper->SetRadiusArrayName("radius");
    mapper->SetLookupTable(lut);
    mapper->SetScalarRange(0, 63);
    mapper->SetDensityModel(model);
    mapper->SetHollowFraction(model == Squared ? 0.3 : 0.0);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetOpacity(0.3);
    actor->GetProperty()->SetSpecular(0.3);
    actor->GetProperty()->SetSpecularPower(20);
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkLightKit> kit;
    kit->AddLightsToRenderer(renderer);
    renderer->AddActor(actor);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(-20, 30, 45);
    camera->SetFocalPoint(10.5, 10.5, 10.5);
    renderer->ResetCamera();
    camera->SetClippingRange(1, 1000); // every sphere entirely visible
    vtkNew<vtkParticleReferenceRenderer> reference;
    reference->SetRenderer(renderer);
    reference->SetActor(actor);
    reference->SetImageSize(512, 512);
    ok &= prTest::Check(reference->Render(), "g render");
    const double* rgba =
      vtkDoubleArray::SafeDownCast(reference->GetColorImage()->GetPointData()->GetScalars())
        ->GetPointer(0);
    const double* alpha = vtkDoubleArray::SafeDownCast(
      reference->GetTranslucentAlphaImage()->GetPointData()->GetScalars())
                            ->GetPointer(0);
    bool valid = true;
    double meanAlpha = 0.0;
    for (size_t i = 0; i < 512 * 512; ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        valid &= rgba[4 * i + k] >= 0.0 && rgba[4 * i + k] <= 1.0;
      }
      valid &= alpha[i] >= 0.0 && alpha[i] <= 1.0;
      meanAlpha += alpha[i];
    }
    ok &= prTest::Check(valid, "g colours and alphas finite and in [0,1]");

    // brute force on sampled pixels: the particles' transmittance is the product over ALL
    // spheres (order-independent), which checks that the grid traversal misses no sphere and
    // composites none twice
    double view[16];
    vtkMatrix4x4::DeepCopy(view, camera->GetModelViewTransformMatrix());
    vtkDataArray* radii = lattice->GetPointData()->GetArray("radius");
    const double scale = mapper->GetRadiusScaleVC(actor);
    const double maximum = vtkParticleReferenceRenderer::NumericalMaximumPathIntegral(
      model, mapper->GetHollowFraction());
    const vtkIdType n = lattice->GetNumberOfPoints();
    std::vector<double> centres(3 * n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      lattice->GetPoint(i, p);
      for (int k = 0; k < 3; ++k)
      {
        centres[3 * i + k] =
          view[4 * k] * p[0] + view[4 * k + 1] * p[1] + view[4 * k + 2] * p[2] + view[4 * k + 3];
      }
    }
    double worst = 0.0;
    int sampled = 0;
    for (int y = 3; y < 512; y += 23)
    {
      for (int x = 5; x < 512; x += 19)
      {
        double o[3];
        double d[3];
        reference->GetPixelRay(x + 0.5, y + 0.5, o, d);
        double opticalDepth = 0.0;
        for (vtkIdType i = 0; i < n; ++i)
        {
          const double r = radii->GetTuple1(i) * scale;
          double oc[3];
          for (int k = 0; k < 3; ++k)
          {
            oc[k] = centres[3 * i + k] - o[k];
          }
          const double tc = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
          double b2 = 0.0;
          for (int k = 0; k < 3; ++k)
          {
            b2 += (tc * d[k] - oc[k]) * (tc * d[k] - oc[k]);
          }
          if (!(b2 < r * r))
          {
            continue;
          }
          const double integral = vtkParticleReferenceRenderer::IntegrateDensity(
            model, mapper->GetHollowFraction(), r, std::sqrt(b2), -Inf, Inf);
          opticalDepth +=
            -std::log1p(-0.3) * integral / (maximum * (model == Squared ? r * r * r : r));
        }
        const double expected = -std::expm1(-opticalDepth);
        worst = std::max(worst, std::abs(alpha[y * 512 + x] - expected));
        ++sampled;
      }
    }
    std::ostringstream what;
    what << "g brute-force particle opacity on " << sampled << " pixels, largest error " << worst;
    ok &= prTest::Check(worst < 1e-12, what.str());
    std::cout << "g) " << reference->GetNumberOfSpheres() << " translucent spheres, model " << model
              << ", 512x512: " << reference->GetLastRenderSeconds() << " s on "
              << vtkSMPTools::GetEstimatedNumberOfThreads() << " threads, mean particle opacity "
              << meanAlpha / (512.0 * 512.0) << ", brute-force check on " << sampled
              << " pixels: largest error " << worst << "\n";
    // generous bound (shared machine); the target is a few seconds
    ok &= prTest::Check(reference->GetLastRenderSeconds() < 60.0, "g render time below 60 s");
  }
  return ok;
}
}

int TestReferenceTransparency(int, char*[])
{
  if (std::string(vtkSMPTools::GetBackend()) == "Sequential")
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  bool ok = true;
  ok &= TestIntegrals();
  ok &= TestMaximum();
  ok &= TestSegmentOpacity();
  ok &= TestRender();
  ok &= TestOpaqueEquivalence();
  ok &= TestPerformance();
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
