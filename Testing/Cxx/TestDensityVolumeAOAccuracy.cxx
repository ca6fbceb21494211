// Strength of vtkDensityVolumeAOPass (Grottel et al. 2012, Eq. 4-5, default settings) against
// ground truth: the ray-traced ambient occlusion of vtkParticleReferenceRenderer (cosine-
// distributed rays against the real spheres up to four mean radii, Eq. 3 of Staib et al. 2015
// with binary visibility) on the LAMMPS liquid film, with the metric of Benchmarks/ao_study.py.
// Every particle is white and ambient-only (ambient 1, diffuse 0, specular 0) on a black
// background, so a pixel's red value is the method's occlusion factor A in [0, 1]. Compared
// pixels: where the reference hits a sphere, 1 pixel away from its silhouettes. Measured:
//   rmse       root mean square of A - A_ref
//   bias       mean of A - A_ref
//   slope      a of the least-squares fit A ~ a A_ref + b: the strength of the darkening
//              relative to ray-traced AO (0 when the pass does not darken at all)
//   structure  the RMSE left after that fit
// The bounds (Bounds below) are set around the measured values of the pass with room for
// platform noise, and must reject three wrong pictures made from the same scene: the image
// without the pass (AO silently off), the occlusion applied twice (A^2) and the darkening doubled
// (1 - 2 (1 - A)). The test fails when the real picture breaks a bound or a wrong picture does
// not.
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDensityVolumeAOPass.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParticleImageComparison.h"
#include "vtkParticleReferenceRenderer.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <vector>

namespace
{
const int Size = 256;

struct Stats
{
  double RMSE = 0.0;
  double Bias = 0.0;
  double Slope = 0.0;
  double Structure = 0.0;
  long long Pixels = 0;
};

Stats Measure(
  const std::vector<double>& a, const std::vector<double>& ref, const std::vector<bool>& use)
{
  Stats s;
  double sa = 0, sr = 0, srr = 0, sar = 0, sd = 0, sdd = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (!use[i])
    {
      continue;
    }
    const double d = a[i] - ref[i];
    sa += a[i];
    sr += ref[i];
    srr += ref[i] * ref[i];
    sar += a[i] * ref[i];
    sd += d;
    sdd += d * d;
    ++s.Pixels;
  }
  if (s.Pixels == 0)
  {
    return s;
  }
  const double n = static_cast<double>(s.Pixels);
  s.RMSE = std::sqrt(sdd / n);
  s.Bias = sd / n;
  const double varRef = srr / n - (sr / n) * (sr / n);
  const double cov = sar / n - (sa / n) * (sr / n);
  s.Slope = varRef > 0 ? cov / varRef : 0.0;
  const double intercept = sa / n - s.Slope * sr / n;
  double residual = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (use[i])
    {
      const double e = a[i] - (s.Slope * ref[i] + intercept);
      residual += e * e;
    }
  }
  s.Structure = std::sqrt(residual / n);
  return s;
}

// Bounds on the statistics of the pass. Measured at this view (256^2, 26692 compared pixels,
// 128 rays per pixel): the pass has rmse 0.189, structure 0.027, slope 0.32, bias +0.127 -- with
// the paper's density factor g = 1 its darkening is a third of ray-traced AO up to four radii and
// brighter on average, as Benchmarks/README.md documents (the study's wider view: bias +0.20).
// Wrong pictures: AO off has slope 0, bias +0.247, rmse 0.319; the occlusion applied twice has
// slope 0.555, bias +0.026, structure 0.048; the darkening doubled slope 0.643, bias +0.007,
// structure 0.055. The bounds hold slope and bias within about +-40 % of the pass's values.
struct Bounds
{
  double MaxRMSE = 0.25;
  double MaxStructure = 0.045;
  double MinSlope = 0.22;
  double MaxSlope = 0.45;
  double MinBias = 0.07;
  double MaxBias = 0.19;
};

bool Within(const Stats& s, const Bounds& b, std::string& why)
{
  why.clear();
  auto add = [&why](const std::string& text) { why += (why.empty() ? "" : "; ") + text; };
  if (s.Pixels == 0)
  {
    add("no pixel compared");
  }
  if (s.RMSE > b.MaxRMSE)
  {
    add("rmse " + std::to_string(s.RMSE) + " > " + std::to_string(b.MaxRMSE));
  }
  if (s.Structure > b.MaxStructure)
  {
    add("structure " + std::to_string(s.Structure) + " > " + std::to_string(b.MaxStructure));
  }
  if (s.Slope < b.MinSlope || s.Slope > b.MaxSlope)
  {
    add("slope " + std::to_string(s.Slope) + " outside [" + std::to_string(b.MinSlope) + ", " +
      std::to_string(b.MaxSlope) + "]");
  }
  if (s.Bias < b.MinBias || s.Bias > b.MaxBias)
  {
    add("bias " + std::to_string(s.Bias) + " outside [" + std::to_string(b.MinBias) + ", " +
      std::to_string(b.MaxBias) + "]");
  }
  return why.empty();
}

std::vector<double> Red(vtkRenderWindow* window)
{
  vtkSmartPointer<vtkImageData> image = prTest::GrabImage(window);
  vtkDataArray* rgb = image->GetPointData()->GetScalars();
  std::vector<double> a(rgb->GetNumberOfTuples());
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    a[i] = rgb->GetComponent(i, 0) / 255.0;
  }
  return a;
}

void Print(const char* what, const Stats& s)
{
  std::cout << std::left << std::setw(28) << what << std::right << std::fixed
            << std::setprecision(4) << " rmse " << s.RMSE << "  structure " << s.Structure
            << "  slope " << s.Slope << "  bias " << std::showpos << s.Bias << std::noshowpos
            << "  (" << s.Pixels << " pixels)\n";
  std::cout.unsetf(std::ios::fixed);
}
}

int TestDensityVolumeAOAccuracy(int argc, char* argv[])
{
  if (std::string(vtkSMPTools::GetBackend()) == "Sequential")
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  vtkSmartPointer<vtkPolyData> film =
    prTest::ReadPolyData(prTest::DataFile(argc, argv, "lj_film.vtp"));
  if (!film)
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkParticleSphereMapper> mapper;
  mapper->SetInputData(film);
  mapper->SetRadiusArrayName("radius");
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1, 1, 1);
  actor->GetProperty()->SetAmbient(1);
  actor->GetProperty()->SetDiffuse(0);
  actor->GetProperty()->SetSpecular(0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0, 0, 0);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Size, Size);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  // the study's oblique view of the film
  double b[6];
  film->GetBounds(b);
  const double centre[3] = { (b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2 };
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] + 0.9 * (b[1] - b[0]), centre[1] - 1.2 * (b[3] - b[2]),
    centre[2] + 0.8 * (b[5] - b[4]));
  camera->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  camera->Zoom(2.5);

  // without the pass: A = 1 on every sphere (the "AO silently off" picture)
  window->Render();
  const std::vector<double> off = Red(window);

  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkDensityVolumeAOPass> ao;
  ao->SetDelegatePass(steps);
  renderer->SetPass(ao);
  window->Render();
  const std::vector<double> gpu = Red(window);
  bool repeatable =
    vtkParticleImageComparison::TestRepeatable(window, "TestDensityVolumeAOAccuracy");

  vtkNew<vtkParticleReferenceRenderer> reference;
  reference->SetRenderer(renderer);
  reference->SetActor(actor);
  reference->SetAmbientOcclusionSamples(128);
  const double noRange[2] = { 0, 1 };
  const prTest::ParticleAttributes attributes =
    prTest::RawAttributes(film, "radius", 0.0, std::string(), nullptr, noRange);
  reference->SetParticleAttributes(attributes.Radii, nullptr, nullptr);
  if (!prTest::Check(reference->Render(), "reference renders"))
  {
    return EXIT_FAILURE;
  }
  vtkDataArray* refAO = reference->GetAmbientOcclusionImage()->GetPointData()->GetScalars();
  vtkNew<vtkUnsignedCharArray> silhouettes;
  vtkParticleImageComparison::MakeSilhouetteMask(
    reference->GetIdImage(), Size, Size, 1, silhouettes);
  std::vector<double> ref(gpu.size());
  std::vector<bool> use(gpu.size());
  for (size_t i = 0; i < gpu.size(); ++i)
  {
    ref[i] = refAO->GetComponent(static_cast<vtkIdType>(i), 0);
    use[i] = reference->GetIdImage()->GetValue(static_cast<vtkIdType>(i)) >= 0 &&
      silhouettes->GetValue(static_cast<vtkIdType>(i)) == 0;
  }
  std::cout << "reference: " << reference->GetAmbientOcclusionSamples() << " rays per pixel, "
            << reference->GetLastRenderSeconds() << " s\n";

  std::vector<double> squared(gpu.size());
  std::vector<double> doubled(gpu.size());
  for (size_t i = 0; i < gpu.size(); ++i)
  {
    squared[i] = gpu[i] * gpu[i];
    doubled[i] = std::max(0.0, 1.0 - 2.0 * (1.0 - gpu[i]));
  }
  const Bounds bounds;
  bool ok = true;
  std::string why;
  const Stats pass = Measure(gpu, ref, use);
  Print("density volume AO (pass)", pass);
  const bool within = Within(pass, bounds, why);
  ok &= prTest::Check(within, "the pass is outside the bounds: " + why);
  ok &= prTest::Check(pass.Pixels > Size * Size / 4, "enough sphere pixels compared");
  const std::pair<const char*, const std::vector<double>*> wrong[] = { { "AO off", &off },
    { "occlusion applied twice", &squared }, { "darkening doubled", &doubled } };
  for (const auto& w : wrong)
  {
    const Stats s = Measure(*w.second, ref, use);
    Print(w.first, s);
    const bool rejected = !Within(s, bounds, why);
    std::cout << "MUST-FAIL " << w.first << ": "
              << (rejected ? "rejected (" + why + ")" : "ACCEPTED") << "\n";
    ok &= prTest::Check(rejected, std::string("the bounds accept the picture with ") + w.first);
  }
  // Strength 2 (the ParaView default): the pass's darkening doubled in the shader, measured as
  // rendered. Post-processing the strength-1 image predicts rmse 0.091, slope 0.64, bias +0.007;
  // the bounds: rmse <= 0.12, slope 0.5-0.8, |bias| <= 0.05 (strength 1 fails the bias and
  // slope bounds, strength 3 the rmse and bias bounds)
  ao->SetStrength(2.0);
  window->Render();
  const std::vector<double> strong = Red(window);
  ao->SetStrength(1.0);
  const Stats two = Measure(strong, ref, use);
  Print("pass at strength 2", two);
  ok &= prTest::Check(
    two.RMSE <= 0.12 && two.Slope >= 0.5 && two.Slope <= 0.8 && std::abs(two.Bias) <= 0.05,
    "strength 2 is not as dark as ray-traced AO on average");
  ok &= prTest::Check(ao->GetNumberOfVolumeBuilds() == 1, "no volume rebuild for the strength");
  renderer->SetPass(nullptr);
  ao->ReleaseGraphicsResources(window);
  return ok && repeatable ? EXIT_SUCCESS : EXIT_FAILURE;
}
