// Private header of ParticleRendering::Reference (vtkParticleReferenceRenderer): the
// emission-absorption model of vtkTransparentSphereMapper (Staib et al. 2015) by numerical
// integration -- adaptive Gauss-Kronrod quadrature of the density models, the segments of the
// spheres along a ray, and the transparent mode's per-pixel compositing.
#ifndef vtkParticleReferenceEmissionAbsorption_h
#define vtkParticleReferenceEmissionAbsorption_h

#include "vtkParticleReferenceRays.h"
#include "vtkTransparentSphereMapper.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace prReference
{
struct Frame;

//------------------------------------------------------------------------------
// Numerical integration (transparent mode). Gauss-Kronrod 7/15 nodes and weights (QUADPACK qk15).
const double GKNodes[8] = { 0.991455371120812639206854697526329,
  0.949107912342758524526189684047851, 0.864864423359769072789712788640926,
  0.741531185599394439863864773280788, 0.586087235467691130294144845693013,
  0.405845151377397166906606412076961, 0.207784955007898467600689403773245,
  0.000000000000000000000000000000000 };
const double KronrodWeights[8] = { 0.022935322010529224963732008058970,
  0.063092092629978553290700663189204, 0.104790010322250183839876322541518,
  0.140653259715525918745189590510238, 0.169004726639267902826583426598550,
  0.190350578064785409913256402421014, 0.204432940075298892414161999234649,
  0.209482141084727828012999174891714 };
// Gauss weights of the nodes 1, 3, 5 and 7 (the centre)
const double GaussWeights[4] = { 0.129484966168869693270611432679082,
  0.279705391489276667901467771423780, 0.381830050505118944950369775488975,
  0.417959183673469387755102040816327 };

const double IntegrationTolerance = 1e-12;

// 15-point Kronrod estimate of the integral of f over [a, b] and |Kronrod - Gauss|.
template <class F>
inline void GaussKronrod15(const F& f, double a, double b, double& value, double& error)
{
  const double centre = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  const double fc = f(centre);
  double kronrod = fc * KronrodWeights[7];
  double gauss = fc * GaussWeights[3];
  for (int j = 0; j < 7; ++j)
  {
    const double x = half * GKNodes[j];
    const double sum = f(centre - x) + f(centre + x);
    kronrod += KronrodWeights[j] * sum;
    if (j % 2 == 1)
    {
      gauss += GaussWeights[j / 2] * sum;
    }
  }
  value = kronrod * half;
  error = std::abs((kronrod - gauss) * half);
}

// Globally adaptive Gauss-Kronrod over the pieces [a_i, b_i] (breakpoints between them):
// bisect the interval of largest error estimate until the summed estimate is below
// relTol * |integral| (or the interval cannot be split further).
template <class F>
inline double AdaptiveIntegrate(const F& f, const double pieces[][2], int numPieces, double relTol)
{
  struct Interval
  {
    double A, B, Value, Error;
  };
  constexpr int MaxIntervals = 256;
  Interval intervals[MaxIntervals];
  int n = 0;
  for (int i = 0; i < numPieces; ++i)
  {
    if (pieces[i][1] > pieces[i][0])
    {
      Interval& iv = intervals[n++];
      iv.A = pieces[i][0];
      iv.B = pieces[i][1];
      GaussKronrod15(f, iv.A, iv.B, iv.Value, iv.Error);
    }
  }
  for (;;)
  {
    double total = 0.0;
    double error = 0.0;
    int worst = -1;
    for (int i = 0; i < n; ++i)
    {
      total += intervals[i].Value;
      error += intervals[i].Error;
      if (worst < 0 || intervals[i].Error > intervals[worst].Error)
      {
        worst = i;
      }
    }
    if (n == 0 || error <= relTol * std::abs(total) || n >= MaxIntervals)
    {
      return total;
    }
    Interval& w = intervals[worst];
    const double mid = 0.5 * (w.A + w.B);
    if (!(mid > w.A && mid < w.B))
    {
      return total;
    }
    Interval& right = intervals[n++];
    right.A = mid;
    right.B = w.B;
    GaussKronrod15(f, right.A, right.B, right.Value, right.Error);
    w.B = mid;
    GaussKronrod15(f, w.A, w.B, w.Value, w.Error);
  }
}

// See vtkParticleReferenceRenderer::IntegrateDensity.
inline double IntegrateDensityImpl(
  int model, double f, double r, double impact, double tau0, double tau1)
{
  const double b = std::abs(impact);
  if (!(r > 0.0) || !(b < r) || !std::isfinite(r))
  {
    return 0.0;
  }
  // half chord, without cancellation for grazing rays
  const double h = std::sqrt((r - b) * (r + b));
  const double lo = std::max(tau0, -h);
  const double hi = std::min(tau1, h);
  if (!(lo < hi))
  {
    return 0.0;
  }
  double pieces[2][2];
  int numPieces = 0;
  const double rs = std::min(std::max(f, 0.0), 1.0) * r;
  if (b < rs)
  {
    // breakpoints at the core's boundary: rho = 0 on [-hs, hs]
    const double hs = std::min(std::sqrt((rs - b) * (rs + b)), h);
    pieces[0][0] = lo;
    pieces[0][1] = std::min(hi, -hs);
    pieces[1][0] = std::max(lo, hs);
    pieces[1][1] = hi;
    numPieces = 2;
  }
  else
  {
    pieces[0][0] = lo;
    pieces[0][1] = hi;
    numPieces = 1;
  }
  if (model == vtkTransparentSphereMapper::SQUARED_DISTANCE_DENSITY)
  {
    const double b2 = b * b;
    return AdaptiveIntegrate(
      [b2](double tau) { return b2 + tau * tau; }, pieces, numPieces, IntegrationTolerance);
  }
  return AdaptiveIntegrate([](double) { return 1.0; }, pieces, numPieces, IntegrationTolerance);
}

// See vtkParticleReferenceRenderer::NumericalMaximumPathIntegral.
inline double NumericalMaximumPathIntegralImpl(int model, double f)
{
  const double inf = std::numeric_limits<double>::infinity();
  double best = -1.0;
  double bestB = 0.0;
  auto chord = [&](double b)
  {
    const double value = IntegrateDensityImpl(model, f, 1.0, b, -inf, inf);
    if (value > best)
    {
      best = value;
      bestB = b;
    }
    return value;
  };
  // scan, including the kink of the integral at the core's radius
  const int samples = 512;
  for (int k = 0; k <= samples; ++k)
  {
    chord(static_cast<double>(k) / samples);
  }
  if (f > 0.0 && f < 1.0)
  {
    chord(f);
  }
  // golden-section search in the bracket around the best sample
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = std::max(0.0, bestB - 1.0 / samples);
  double hi = std::min(1.0, bestB + 1.0 / samples);
  double x1 = hi - g * (hi - lo);
  double x2 = lo + g * (hi - lo);
  double f1 = chord(x1);
  double f2 = chord(x2);
  for (int it = 0; it < 200 && hi - lo > 1e-17; ++it)
  {
    if (f1 < f2)
    {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = chord(x2);
    }
    else
    {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = chord(x1);
    }
  }
  return std::max(best, 0.0);
}

// Theta = 1 - exp(-kappa I / I_max) with kappa = -ln(1 - Theta_i), in double.
inline double OpacityFromOpticalDepth(double opticalDepth)
{
  return opticalDepth > 0.0 ? -std::expm1(-opticalDepth) : 0.0;
}

// A translucent sphere's part of a pixel ray, relative to the closest approach of the ray to
// the centre (tau = t - Tc). An ellipsoid's part is that of the sphere that has the same chord
// and density profile along this ray (its unit-frame chord scaled by Radius = 1 / |A^-1 d|):
// impact Impact = |q_u| Radius, and an I_max scaled so that the ratio I / I_max is the
// ellipsoid's physical one (see MakeSegment).
struct Segment
{
  double Key;                // ray parameter of the segment's start (t_n after clipping)
  double Tc;                 // ray parameter of the closest approach
  double Q[3];               // closest approach point relative to the centre
  double H;                  // half chord
  double Radius = 0.0;       // the sphere's radius (the equivalent sphere's for an ellipsoid)
  double Impact = 0.0;       // distance of the ray from the (equivalent) centre
  double MaximumScale = 1.0; // I_max of the segment = the sphere's I_max times this
  double Tau0;               // start (-inf: the entry point)
  double Tau1;               // end (+inf: the exit point)
  std::uint32_t Index;
  bool Entry; // the segment starts at the visible entry point
};

// The chord of a sphere clipped to the visible part of the ray with the GPU's rule (see the
// class description). Returns false when no part of it is visible.
// densityPower: 1 for the constant density model, 3 for squared distance (I_max ~ r^p; see
// ChordOf for an ellipsoid's equivalent sphere along the ray).
inline bool MakeSegment(const RayCamera& cam, const double o[3], const double d[3],
  const SphereVC& s, double tNear, double tFar, std::uint32_t index, Segment& seg,
  int densityPower = 1)
{
  Chord chord;
  if (!ChordOf(o, d, s, densityPower, chord) || !(chord.H > 0.0))
  {
    return false; // missed, or tangent (no length)
  }
  const double tc = chord.Tc;
  const double* q = chord.Q;
  const double h = chord.H;
  seg.Radius = chord.Radius;
  seg.Impact = chord.Impact;
  seg.MaximumScale = chord.MaximumScale;
  double pIn[3];
  double pOut[3];
  for (int k = 0; k < 3; ++k)
  {
    pIn[k] = s.C[k] + (q[k] - h * d[k]);
    pOut[k] = s.C[k] + (q[k] + h * d[k]);
  }
  const int entry = cam.Classify(pIn);
  const int exit = cam.Classify(pOut);
  const double inf = std::numeric_limits<double>::infinity();
  seg.Entry = entry == 0;
  if (entry == 0)
  {
    seg.Tau0 = -inf;
  }
  else if (entry == -1)
  {
    seg.Tau0 = std::max(tNear - tc, -h); // starts at the near plane
  }
  else
  {
    return false; // entry beyond the far plane (or undefined): the whole chord is hidden
  }
  if (exit == 0)
  {
    seg.Tau1 = inf;
  }
  else if (exit == 1)
  {
    seg.Tau1 = std::min(tFar - tc, h); // ends at the far plane
  }
  else
  {
    return false; // exit in front of the near plane: the whole chord is
  }
  seg.Key = seg.Entry ? tc - h : tc + seg.Tau0;
  if (!(std::max(seg.Tau0, -h) < std::min(seg.Tau1, h)))
  {
    return false;
  }
  seg.Tc = tc;
  std::copy(q, q + 3, seg.Q);
  seg.H = h;
  seg.Index = index;
  return true;
}

/**
 * The transparent mode's per-pixel pass: every sphere segment along each pixel's ray,
 * composited front to back over the background, the opaque layer or the first opaque particle;
 * writes every output of the frame.
 */
void RenderTranslucent(const Frame& frame);
} // namespace prReference

#endif
