// Transparency-aware ray-traced ambient occlusion and ambient illumination of
// vtkParticleReferenceRenderer (Staib et al. 2015, Eq. 5-7; the reference of vtkVoxelConeAOPass),
// against closed forms, in the transparent mode (vtkTransparentSphereMapper, constant density):
//
// 1. One translucent occluder (radius R, most opaque ray Theta, kappa = ln(1 - Theta)) seen from
//    a point on a large opaque receiver at distance D from its centre, at angle beta from the
//    normal, the occluder entirely above the tangent plane: the transmittance of a ray at angle
//    psi from the axis is exp(kappa sqrt(1 - (D sin psi / R)^2)), and the cosine-weighted
//    integral over the occluder's cone is exact:
//      A_O = 1 - cos(beta) (R / D)^2 F(kappa),  F(kappa) = 1 - 2 (e^kappa (kappa - 1) + 1) /
//      kappa^2
//    (F -> 1 for an opaque occluder: its form factor), and L_A = e_A c (1 - A_O).
// 2. A slab of translucent spheres at random (Poisson) positions above the receiver: the number
//    of spheres a ray meets is Poisson, so the expected transmittance along a direction at theta
//    from the normal is exp(-n pi r^2 <Theta> t / cos theta) (t the thickness of the slab of
//    centres, <Theta> the opacity averaged over a sphere's disc) and
//      E[A_O] = 2 E_3(n pi r^2 <Theta> t),  E[L_A] = e_A c (1 - E[A_O]).
// A transparency-unaware (binary) occlusion misses both by far more than the tolerances.
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkParticleReferenceRenderer.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTransparentSphereMapper.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{
const double ReceiverRadius = 1000.0;

// 1 - 2 (e^k (k - 1) + 1) / k^2 for k = ln(1 - theta) < 0; 1 for an opaque occluder
double F(double theta)
{
  if (theta >= 1.0)
  {
    return 1.0;
  }
  const double k = std::log1p(-theta);
  return 1.0 - 2.0 * (std::exp(k) * (k - 1.0) + 1.0) / (k * k);
}

// 2 E_3(tau) = 2 int_0^1 mu exp(-tau / mu) dmu, composite Simpson (smooth, 0 at mu = 0)
double TwoE3(double tau)
{
  const int n = 20000;
  auto f = [tau](double mu) { return mu > 0.0 ? mu * std::exp(-tau / mu) : 0.0; };
  double sum = f(0.0) + f(1.0);
  for (int i = 1; i < n; ++i)
  {
    sum += (i % 2 ? 4.0 : 2.0) * f(static_cast<double>(i) / n);
  }
  return 2.0 * sum / (3.0 * n);
}

struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkTransparentSphereMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkParticleReferenceRenderer> Reference;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkFloatArray> Radii;
  vtkNew<vtkUnsignedCharArray> Colors;
  vtkNew<vtkFloatArray> Opacities;

  Scene()
  {
    this->Window->SetSize(24, 24);
    this->Window->AddRenderer(this->Renderer);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Mapper->SetDensityModel(vtkTransparentSphereMapper::CONSTANT_DENSITY);
    this->Reference->SetRenderer(this->Renderer);
    this->Reference->SetActor(this->Actor);
    this->Colors->SetNumberOfComponents(4);
    // the receiver: a large opaque sphere whose top is the plane z = 0 near the origin
    this->Add(0.0, 0.0, -ReceiverRadius, ReceiverRadius, 1.0, 255, 255, 255);
  }

  void Add(double x, double y, double z, double r, double theta, unsigned char cr, unsigned char cg,
    unsigned char cb)
  {
    this->Points->InsertNextPoint(x, y, z);
    this->Radii->InsertNextValue(static_cast<float>(r));
    const unsigned char rgba[4] = { cr, cg, cb, 255 };
    this->Colors->InsertNextTypedTuple(rgba);
    this->Opacities->InsertNextValue(static_cast<float>(theta));
  }

  // render with the camera at eye looking at the origin; false on failure
  bool Render(const double eye[3], double viewAngle, int samples)
  {
    vtkNew<vtkPolyData> input;
    input->SetPoints(this->Points);
    this->Mapper->SetInputData(input);
    this->Reference->SetParticleAttributes(this->Radii, this->Colors, this->Opacities);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(0, 0, 0);
    camera->SetPosition(eye[0], eye[1], eye[2]);
    camera->SetViewUp(0, 0, 1);
    camera->SetViewAngle(viewAngle);
    const double distance = std::sqrt(vtkMath::Dot(eye, eye));
    camera->SetClippingRange(0.05 * distance, 4.0 * ReceiverRadius);
    this->Reference->SetAmbientOcclusionSamples(samples);
    this->Reference->SetAmbientOcclusionDistance(1e4);
    return this->Reference->Render();
  }

  // the receiver's visible points: world point and normal per pixel that shows it
  void ReceiverPoints(std::vector<std::array<double, 6>>& out, std::vector<vtkIdType>& pixels)
  {
    out.clear();
    pixels.clear();
    vtkIdTypeArray* ids = this->Reference->GetIdImage();
    vtkDataArray* t = this->Reference->GetViewDepthImage()->GetPointData()->GetScalars();
    vtkNew<vtkMatrix4x4> viewInverse;
    vtkMatrix4x4::Invert(
      this->Renderer->GetActiveCamera()->GetModelViewTransformMatrix(), viewInverse);
    int dims[3];
    this->Reference->GetViewDepthImage()->GetDimensions(dims);
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x)
      {
        const vtkIdType pixel = static_cast<vtkIdType>(y) * dims[0] + x;
        if (ids->GetValue(pixel) != 0)
        {
          continue;
        }
        double o[3];
        double d[3];
        this->Reference->GetPixelRay(x + 0.5, y + 0.5, o, d);
        const double tt = t->GetComponent(pixel, 0);
        double pv[4] = { o[0] + tt * d[0], o[1] + tt * d[1], o[2] + tt * d[2], 1.0 };
        double pw[4];
        viewInverse->MultiplyPoint(pv, pw);
        std::array<double, 6> pn = { pw[0], pw[1], pw[2], pw[0], pw[1], pw[2] + ReceiverRadius };
        const double len = std::sqrt(pn[3] * pn[3] + pn[4] * pn[4] + pn[5] * pn[5]);
        for (int k = 3; k < 6; ++k)
        {
          pn[k] /= len;
        }
        out.push_back(pn);
        pixels.push_back(pixel);
      }
    }
  }
};

// one occluder: every receiver pixel against the closed form
bool OneOccluder(double theta, int samples)
{
  bool ok = true;
  const double radius = 1.0;
  const double center[3] = { 0.0, 0.0, 3.0 };
  const double color[3] = { 1.0, 128.0 / 255.0, 0.0 };
  Scene scene;
  scene.Add(center[0], center[1], center[2], radius, theta, 255, 128, 0);
  scene.Reference->SetAmbientEmission(0.75);
  const double eye[3] = { 8.0, 0.0, 8.0 };
  ok &= prTest::Check(scene.Render(eye, 8.0, samples), "render one occluder");
  std::vector<std::array<double, 6>> points;
  std::vector<vtkIdType> pixels;
  scene.ReceiverPoints(points, pixels);
  vtkDataArray* ao = scene.Reference->GetAmbientOcclusionImage()->GetPointData()->GetScalars();
  vtkDataArray* light = scene.Reference->GetAmbientLightImage()->GetPointData()->GetScalars();
  double maxError = 0.0;
  double sumError = 0.0;
  double maxLightError = 0.0;
  double sumExpected = 0.0;
  int used = 0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    const double* p = points[i].data();
    const double* n = p + 3;
    const double v[3] = { center[0] - p[0], center[1] - p[1], center[2] - p[2] };
    const double dist = std::sqrt(vtkMath::Dot(v, v));
    const double cosBeta = vtkMath::Dot(v, n) / dist;
    // the occluder entirely above the tangent plane: beta + alpha <= 90 degrees
    if (std::acos(std::min(1.0, cosBeta)) + std::asin(radius / dist) > 0.5 * vtkMath::Pi())
    {
      continue;
    }
    const double expected = 1.0 - cosBeta * (radius / dist) * (radius / dist) * F(theta);
    const double got = ao->GetComponent(pixels[i], 0);
    maxError = std::max(maxError, std::abs(got - expected));
    sumError += got - expected;
    sumExpected += expected;
    for (int k = 0; k < 3; ++k)
    {
      const double expectedLight = 0.75 * color[k] * (1.0 - expected);
      maxLightError =
        std::max(maxLightError, std::abs(light->GetComponent(pixels[i], k) - expectedLight));
    }
    ++used;
  }
  const double meanError = used ? sumError / used : 1.0;
  std::cout << "one occluder, Theta " << theta << ": " << used << " pixels, mean A_O "
            << (used ? sumExpected / used : 0.0) << ", max |error| " << maxError << ", mean error "
            << meanError << ", max L_A error " << maxLightError << "\n";
  ok &= prTest::Check(used > 300, "the receiver is seen around the occluder's foot");
  // Hammersley sets of `samples` cosine-distributed rays: the error of the quadrature
  // (largest for the opaque occluder, whose silhouette is a discontinuity: 5.6e-3 at 1024 rays)
  ok &= prTest::Check(maxError < 8e-3, "A_O matches the closed form per pixel");
  ok &= prTest::Check(std::abs(meanError) < 5e-4, "A_O matches the closed form on average");
  ok &= prTest::Check(maxLightError < 8e-3, "L_A = e_A c (1 - A_O) per pixel");

  // Eq. 7 applied: the colour becomes A_O L + alpha_A L_A
  vtkNew<vtkDoubleArray> plain;
  plain->DeepCopy(scene.Reference->GetColorImage()->GetPointData()->GetScalars());
  vtkNew<vtkDoubleArray> occlusion;
  occlusion->DeepCopy(ao);
  vtkNew<vtkDoubleArray> ambientLight;
  ambientLight->DeepCopy(light);
  scene.Reference->SetApplyAmbientOcclusion(true);
  scene.Reference->SetAmbientIllumination(0.5);
  ok &= prTest::Check(scene.Render(eye, 8.0, samples), "render with Eq. 7 applied");
  vtkDataArray* applied = scene.Reference->GetColorImage()->GetPointData()->GetScalars();
  double maxApplyError = 0.0;
  for (vtkIdType pixel : pixels)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double expected = std::min(1.0,
        occlusion->GetValue(pixel) * plain->GetComponent(pixel, k) +
          0.5 * ambientLight->GetComponent(pixel, k));
      maxApplyError = std::max(maxApplyError, std::abs(applied->GetComponent(pixel, k) - expected));
    }
  }
  ok &= prTest::Check(maxApplyError < 1e-12, "ApplyAmbientOcclusion gives A_O L + alpha_A L_A");
  return ok;
}

// a Poisson slab: the mean over the receiver pixels of several realisations against 2 E_3
bool Slab(double theta, int realisations, int samples)
{
  bool ok = true;
  const double r = 1.0;
  const double halfWidth = 150.0;
  const double thickness = 16.0;
  const double bottom = 1.5; // lowest centre: the spheres stay 0.5 above the receiver
  const double fraction = 0.1;
  const double density = fraction / (4.0 / 3.0 * vtkMath::Pi() * r * r * r);
  const int count = static_cast<int>(density * 4.0 * halfWidth * halfWidth * thickness);
  const double meanTheta = F(theta); // <Theta> over the disc equals F (same integral)
  const double tau = density * vtkMath::Pi() * r * r * meanTheta * thickness;
  const double expected = TwoE3(tau);
  const double expectedOpaque = TwoE3(density * vtkMath::Pi() * r * r * thickness);
  double sumAO = 0.0;
  double sumLight = 0.0;
  int used = 0;
  vtkNew<vtkMinimalStandardRandomSequence> random;
  for (int s = 0; s < realisations; ++s)
  {
    random->SetSeed(17 + 31 * s);
    Scene scene;
    for (int i = 0; i < count; ++i)
    {
      const double x = random->GetNextRangeValue(-halfWidth, halfWidth);
      const double y = random->GetNextRangeValue(-halfWidth, halfWidth);
      const double z = random->GetNextRangeValue(bottom, bottom + thickness);
      scene.Add(x, y, z, r, theta, 0, 255, 0);
    }
    // the eye between the receiver and the slab, looking down at the origin at a grazing
    // angle: the pixels see the receiver from 1 to 14 units away (independent neighbourhoods)
    const double eye[3] = { -2.0, 0.0, 0.25 };
    ok &= prTest::Check(scene.Render(eye, 12.0, samples), "render the slab");
    std::vector<std::array<double, 6>> points;
    std::vector<vtkIdType> pixels;
    scene.ReceiverPoints(points, pixels);
    vtkDataArray* ao = scene.Reference->GetAmbientOcclusionImage()->GetPointData()->GetScalars();
    vtkDataArray* light = scene.Reference->GetAmbientLightImage()->GetPointData()->GetScalars();
    double realisation = 0.0;
    for (vtkIdType pixel : pixels)
    {
      realisation += ao->GetComponent(pixel, 0);
      sumLight += light->GetComponent(pixel, 1);
      ++used;
    }
    sumAO += realisation;
    std::cout << "  realisation " << s << ": mean A_O "
              << (pixels.empty() ? 0.0 : realisation / pixels.size()) << "\n";
  }
  const double meanAO = used ? sumAO / used : 0.0;
  const double meanLight = used ? sumLight / used : 0.0;
  std::cout << "slab of " << count << " spheres, Theta " << theta << ", <Theta> " << meanTheta
            << ", optical depth " << tau << ": mean A_O " << meanAO << " (2 E_3: " << expected
            << ", opaque spheres: " << expectedOpaque << "), mean L_A " << meanLight
            << " (expected " << 1.0 - expected << ") over " << used << " pixels\n";
  ok &= prTest::Check(used > 0, "the receiver is visible");
  // the realisations' spread sets the tolerance: their means scatter by 0.027 (10 of them:
  // 0.0085), so 0.025 is 3 sigma of the mean; opaque spheres would be 0.32 off
  ok &= prTest::Check(std::abs(meanAO - expected) < 0.025, "A_O matches 2 E_3 on average");
  ok &= prTest::Check(std::abs(meanLight - (1.0 - expected)) < 0.025, "L_A = 1 - A_O");
  return ok;
}
}

int TestReferenceTranslucentAO(int, char*[])
{
  if (std::string(vtkSMPTools::GetBackend()) == "Sequential")
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  bool ok = true;
  ok &= OneOccluder(0.5, 1024);
  ok &= OneOccluder(0.9, 1024);
  ok &= OneOccluder(1.0 - 1e-7, 1024);
  ok &= OneOccluder(1.0, 1024);
  ok &= Slab(0.5, 10, 64);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
