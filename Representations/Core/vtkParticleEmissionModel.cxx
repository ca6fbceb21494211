#include "vtkParticleEmissionModel.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkParticleEmissionModel);

namespace
{
// 16-point Gauss-Legendre nodes and weights on [-1, 1] (positive half; symmetric)
const double GaussNodes[8] = { 0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
  0.6178762444026438, 0.7554044083550030, 0.8656312023878318, 0.9445750230732326,
  0.9894009349916499 };
const double GaussWeights[8] = { 0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
  0.1495959888165767, 0.1246289712555339, 0.0951585116824928, 0.0622535239386479,
  0.0271524594117541 };

// integral of f over [a, b] with the 16-point rule
template <typename F>
double Integrate(F f, double a, double b)
{
  const double mid = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  double sum = 0.0;
  for (int i = 0; i < 8; ++i)
  {
    sum += GaussWeights[i] * (f(mid - half * GaussNodes[i]) + f(mid + half * GaussNodes[i]));
  }
  return sum * half;
}
}

//------------------------------------------------------------------------------
double vtkParticleEmissionModel::GetMaximumPathIntegral(int model, double f)
{
  f = std::min(std::max(f, 0.0), 0.999);
  // the chord through the core's tangent point, 2 sqrt(1 - f^2), as (1 - f)(1 + f) for f near 1
  const double g = std::sqrt((1.0 - f) * (1.0 + f));
  if (model == CONSTANT_DENSITY)
  {
    return 2.0 * g;
  }
  if (f <= std::sqrt(0.5))
  {
    return 2.0 * std::sqrt(2.0) / 3.0;
  }
  return 2.0 * g * (1.0 + 2.0 * f * f) / 3.0;
}

//------------------------------------------------------------------------------
double vtkParticleEmissionModel::MeanDiscOpacity(
  double theta, int densityModel, double hollowFraction)
{
  if (!(theta > 0.0))
  {
    return 0.0; // also NaN
  }
  if (theta >= 1.0)
  {
    return 1.0;
  }
  const double depth = -std::log1p(-theta); // optical depth of the most opaque ray
  const double f = std::min(std::max(hollowFraction, 0.0), 0.999);
  if (densityModel == vtkParticleEmissionModel::CONSTANT_DENSITY && f == 0.0)
  {
    // <Theta> = 2 int_0^1 (1 - e^{-T s}) s ds = 1 - 2 (1 - e^{-T} (1 + T)) / T^2
    if (depth < 1e-4)
    {
      return depth * (2.0 / 3.0) - depth * depth * 0.25;
    }
    return 1.0 - 2.0 * (-std::expm1(-depth) - depth * std::exp(-depth)) / (depth * depth);
  }
  // Over the disc, with s = sqrt(1 - u^2) the chord's half-length (u the impact parameter):
  // 2 u du = 2 s ds, and the path integrals are polynomials in s. Outside the hollow core's
  // shadow (s < s0 = sqrt(1 - f^2)) the integrand is smooth; inside it q = sqrt(s^2 - s0^2), the
  // core's half-chord, makes it smooth again (2 s ds = 2 q dq, q in [0, f]).
  const double maximum = vtkParticleEmissionModel::GetMaximumPathIntegral(densityModel, f);
  auto opacity = [&](double half, double coreHalf)
  {
    const double u2 = std::max(0.0, 1.0 - half * half);
    double path = 0.0;
    if (densityModel == vtkParticleEmissionModel::CONSTANT_DENSITY)
    {
      path = 2.0 * (half - coreHalf);
    }
    else
    {
      // rho = |x - p|^2 = u^2 + t^2 along the chord
      path = 2.0 * (u2 * half + half * half * half / 3.0) -
        2.0 * (u2 * coreHalf + coreHalf * coreHalf * coreHalf / 3.0);
    }
    return -std::expm1(-depth * path / maximum);
  };
  const double s0 = std::sqrt(1.0 - f * f);
  double result = Integrate([&](double s) { return opacity(s, 0.0) * 2.0 * s; }, 0.0, s0);
  if (f > 0.0)
  {
    result +=
      Integrate([&](double q) { return opacity(std::sqrt(s0 * s0 + q * q), q) * 2.0 * q; }, 0.0, f);
  }
  return result;
}

//------------------------------------------------------------------------------
void vtkParticleEmissionModel::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
