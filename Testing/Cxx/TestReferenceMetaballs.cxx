// The exact metaball surface of vtkParticleReferenceMetaballs (Mueller et al. 2007, Eq. 2;
// the ground truth for vtkMetaballMapper) against closed forms:
//
// 1. The quartic root isolation (FirstNonNegative): simple roots to 1e-15, two roots 1e-4 apart
//    (the first one, to eps / slope), a touching root (to sqrt(eps): the expanded polynomial
//    rounds to 0 within 1e-8 of it), no root.
// 2. One particle: the surface is its sphere, D(R) = 1 (hit distance to 1e-12 R, normal to
//    1e-12), for a camera 5 R away, 1e7 R away and with the data 1e6 from the origin (goal:
//    1e-5 R); rays that pass within (R, 2R) of the centre see nothing.
// 3. Two equal particles at distance d: on the mid-plane the field is 2 c q^2, q = 1 - r^2/(kR)^2,
//    so the neck radius is rho^2 = (kR)^2 (1 - sqrt(iso / (2c))) - d^2/4 (k = 2: c = 16/9;
//    k = 3: c = 81/64), with the normal along the mid-plane; beyond d_max = 2 k R sqrt(1 -
//    sqrt(iso/(2c))) there is no neck. A neck 0.04 R thin is hit by a ray through it.
// 4. Two coincident particles: a sphere of radius k R sqrt(1 - sqrt(iso / (2c))).
// 5. A random cluster of 300 particles (radii 0.5...1.5): every hit lies on the surface (field =
//    iso to 1e-9) with the field below iso at 20000 samples before it, and a dense march with
//    bisection (step 1e-3) finds no earlier crossing; the misses are confirmed by the march.
// 6. A ray that starts inside: t = tMin, inside, normal against the ray.
// 7. Bad input: NaN positions and radii <= 0 are skipped.
#include "prTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkParticleReferenceMetaballs.h"
#include "vtkPoints.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace
{
int failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    ++failures;
    std::printf("FAIL: %s\n", what.c_str());
  }
}

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0)
{
  char text[512];
  std::snprintf(text, sizeof(text), format, a, b, c);
  return text;
}

// analytic first hit of a ray on a sphere (sphere-relative form), -1 when it misses
double SphereHit(const double o[3], const double d[3], const double c[3], double r)
{
  const double rel[3] = { c[0] - o[0], c[1] - o[1], c[2] - o[2] };
  const double closest = rel[0] * d[0] + rel[1] * d[1] + rel[2] * d[2];
  double perp2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double p = rel[k] - closest * d[k];
    perp2 += p * p;
  }
  if (perp2 > r * r)
  {
    return -1.0;
  }
  return closest - std::sqrt(r * r - perp2);
}

void Normalize(double v[3])
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  v[0] /= n;
  v[1] /= n;
  v[2] /= n;
}

// one particle of radius R at centre, rays from `distance` away towards random points of its disc
void SingleParticle(const double centre[3], double radius, double distance, const char* label)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(centre);
  vtkNew<vtkDoubleArray> radii;
  radii->InsertNextValue(radius);
  vtkNew<vtkParticleReferenceMetaballs> metaballs;
  metaballs->SetParticles(points, radii);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(3);
  double worstT = 0.0;
  double worstN = 0.0;
  int misses = 0;
  for (int ray = 0; ray < 400; ++ray)
  {
    // a random direction from the centre to the eye, a random aim within 2 R of the centre
    double toEye[3];
    for (int k = 0; k < 3; ++k)
    {
      toEye[k] = random->GetNextRangeValue(-1.0, 1.0);
      random->Next();
    }
    Normalize(toEye);
    double aim[3];
    for (int k = 0; k < 3; ++k)
    {
      aim[k] = centre[k] + random->GetNextRangeValue(-2.0, 2.0) * radius;
      random->Next();
    }
    double o[3];
    for (int k = 0; k < 3; ++k)
    {
      o[k] = centre[k] + distance * toEye[k];
    }
    double d[3] = { aim[0] - o[0], aim[1] - o[1], aim[2] - o[2] };
    Normalize(d);
    double t = 0.0;
    double n[3];
    bool inside = false;
    const bool hit =
      metaballs->IntersectRay(o, d, 0.0, std::numeric_limits<double>::infinity(), t, n, inside);
    const double expected = SphereHit(o, d, centre, radius);
    if (expected < 0.0)
    {
      misses += hit ? 1 : 0;
      continue;
    }
    if (!hit)
    {
      ++misses;
      continue;
    }
    worstT = std::max(worstT, std::abs(t - expected) / radius);
    double exact[3];
    for (int k = 0; k < 3; ++k)
    {
      // the hit point relative to the centre, formed without the large coordinates
      exact[k] = (o[k] - centre[k]) + expected * d[k];
    }
    Normalize(exact);
    worstN = std::max(worstN,
      std::sqrt(std::pow(n[0] - exact[0], 2) + std::pow(n[1] - exact[1], 2) +
        std::pow(n[2] - exact[2], 2)));
  }
  std::printf("%s: worst hit error %.3g R, normal %.3g, wrong hit/miss %d of 400\n", label, worstT,
    worstN, misses);
  const double tolerance = distance > 1e3 ? 1e-5 : 1e-12;
  Check(worstT <= tolerance,
    std::string(label) + Format(": hit distance within %g R (%.3g)", tolerance, worstT));
  Check(worstN <= (distance > 1e3 ? 1e-4 : 1e-12),
    std::string(label) + Format(": normal (%.3g)", worstN));
  Check(misses == 0, std::string(label) + ": every ray that meets the sphere hits, no other");
}

// two particles of radius 1 at (+-d/2, 0, 0); the neck radius from the mid-plane ray along +y
void TwoParticles(double d, double k)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(-0.5 * d, 0.0, 0.0);
  points->InsertNextPoint(0.5 * d, 0.0, 0.0);
  vtkNew<vtkParticleReferenceMetaballs> metaballs;
  metaballs->SetParticles(points, nullptr);
  metaballs->SetInfluenceFactor(k);
  const double c = vtkParticleReferenceMetaballs::KernelScale(k);
  const double rho2 = k * k * (1.0 - std::sqrt(1.0 / (2.0 * c))) - 0.25 * d * d;
  const double o[3] = { 0.0, -10.0, 0.0 };
  const double dir[3] = { 0.0, 1.0, 0.0 };
  double t = 0.0;
  double n[3];
  bool inside = false;
  const bool hit = metaballs->IntersectRay(o, dir, 0.0, 20.0, t, n, inside);
  if (rho2 <= 0.0)
  {
    Check(!hit, Format("d = %g, k = %g: no neck beyond d_max", d, k));
    return;
  }
  const double expected = 10.0 - std::sqrt(rho2);
  std::printf(
    "d = %g, k = %g: neck radius %.15f (closed form %.15f)\n", d, k, 10.0 - t, std::sqrt(rho2));
  Check(hit && std::abs(t - expected) <= 1e-12,
    Format("d = %g, k = %g: neck radius to 1e-12 (error %.3g)", d, k, hit ? t - expected : 1.0));
  Check(hit && std::abs(n[1] + 1.0) <= 1e-12 && std::abs(n[0]) <= 1e-12,
    Format("d = %g, k = %g: the neck's normal lies in the mid-plane (%.3g)", d, k,
      hit ? std::abs(n[0]) : 1.0));
}
}

int TestReferenceMetaballs(int, char*[])
{
  // 1. root isolation
  Check(std::abs(vtkParticleReferenceMetaballs::KernelScale(2.0) - 16.0 / 9.0) < 1e-15,
    "kernel scale 16/9 for k = 2 (Eq. 2)");
  {
    // -(u - 0.3)(u - 0.7)(u^2 + 1) = -(u^2 - u + 0.21)(u^2 + 1)
    const double p[5] = { -0.21, 1.0, -1.21, 1.0, -1.0 };
    const double r = vtkParticleReferenceMetaballs::FirstNonNegative(p, 2.0);
    Check(std::abs(r - 0.3) <= 1e-15, Format("simple root 0.3 (%.17g)", r));
    const double touch[5] = { -0.25, 1.0, -1.0, 0.0, 0.0 }; // -(u - 0.5)^2
    const double t = vtkParticleReferenceMetaballs::FirstNonNegative(touch, 2.0);
    // a touching root is determined to sqrt(eps) only: within 1e-8 of it the expanded
    // polynomial rounds to 0 (a ray grazing the surface: 1e-8 R in depth at a silhouette)
    Check(std::abs(t - 0.5) <= 2e-8, Format("touching root 0.5 (%.17g)", t));
    const double never[5] = { -1.0, 0.0, 0.0, 0.0, -1.0 };
    Check(vtkParticleReferenceMetaballs::FirstNonNegative(never, 10.0) == -1.0, "no root");
    // two roots close together (a thin neck along the ray): 1e-4 apart
    const double a = 0.6;
    const double b = 0.6001;
    const double thin[5] = { -a * b, a + b, -1.0, 0.0, 0.0 }; // -(u - a)(u - b)
    const double s = vtkParticleReferenceMetaballs::FirstNonNegative(thin, 1.0);
    // conditioning eps / slope (slope 1e-4)
    Check(std::abs(s - a) <= 1e-12, Format("close roots: the first (%.17g)", s));
  }

  // 2. one particle
  const double origin[3] = { 0.0, 0.0, 0.0 };
  SingleParticle(origin, 1.0, 5.0, "one particle, camera 5 R away");
  SingleParticle(origin, 1.0, 1e7, "one particle, camera 1e7 R away");
  const double far[3] = { 1e6, -1e6, 1e6 };
  SingleParticle(far, 1.0, 5.0, "one particle 1e6 from the origin");
  SingleParticle(far, 1e-3, 5e-3, "radius 1e-3, 1e6 from the origin");

  // 3. two particles: neck radius
  for (double d : { 0.5, 1.0, 2.0, 2.7, 2.74, 2.75 })
  {
    TwoParticles(d, 2.0);
  }
  for (double d : { 1.0, 3.0, 4.2, 4.5 })
  {
    TwoParticles(d, 3.0);
  }
  {
    // a neck 0.042 R thin (d = 2.74): a ray along z through it at y = 0.03 must find it
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->InsertNextPoint(-1.37, 0.0, 0.0);
    points->InsertNextPoint(1.37, 0.0, 0.0);
    vtkNew<vtkParticleReferenceMetaballs> metaballs;
    metaballs->SetParticles(points, nullptr);
    const double o[3] = { 0.0, 0.03, -10.0 };
    const double dir[3] = { 0.0, 0.0, 1.0 };
    double t = 0.0;
    double n[3];
    bool inside = false;
    const bool hit = metaballs->IntersectRay(o, dir, 0.0, 20.0, t, n, inside);
    double p[3] = { 0.0, 0.03, -10.0 + t };
    Check(hit && std::abs(metaballs->EvaluateField(p) - 1.0) <= 1e-12,
      Format("a thin neck (0.042 R) is hit, on the surface (field %.15f)",
        hit ? metaballs->EvaluateField(p) : 0.0));
  }

  // 4. coincident particles
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->InsertNextPoint(0.3, 0.2, 0.1);
    points->InsertNextPoint(0.3, 0.2, 0.1);
    vtkNew<vtkParticleReferenceMetaballs> metaballs;
    metaballs->SetParticles(points, nullptr);
    const double radius = 2.0 * std::sqrt(1.0 - std::sqrt(9.0 / 32.0));
    const double o[3] = { 0.3, 0.2, -10.0 };
    const double dir[3] = { 0.0, 0.0, 1.0 };
    double t = 0.0;
    double n[3];
    bool inside = false;
    const bool hit = metaballs->IntersectRay(o, dir, 0.0, 20.0, t, n, inside);
    Check(hit && std::abs((10.1 - t) - radius) <= 1e-12,
      Format("coincident particles: a sphere of radius %.15f (%.15f)", radius, 10.1 - t));
  }

  // 5. a random cluster against a dense march
  {
    vtkNew<vtkMinimalStandardRandomSequence> random;
    random->SetSeed(11);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkDoubleArray> radii;
    for (int i = 0; i < 300; ++i)
    {
      double p[3];
      for (int k = 0; k < 3; ++k)
      {
        p[k] = random->GetNextRangeValue(0.0, 12.0);
        random->Next();
      }
      points->InsertNextPoint(p);
      radii->InsertNextValue(random->GetNextRangeValue(0.5, 1.5));
      random->Next();
    }
    vtkNew<vtkParticleReferenceMetaballs> metaballs;
    metaballs->SetParticles(points, radii);
    int hits = 0;
    int earlier = 0;
    int missedByMarch = 0;
    double worstField = 0.0;
    for (int ray = 0; ray < 300; ++ray)
    {
      double o[3] = { -8.0, 0.0, 0.0 };
      double target[3];
      for (int k = 0; k < 3; ++k)
      {
        if (k > 0)
        {
          o[k] = random->GetNextRangeValue(-2.0, 14.0);
          random->Next();
        }
        target[k] = k == 0 ? 20.0 : random->GetNextRangeValue(-2.0, 14.0);
        random->Next();
      }
      double d[3] = { target[0] - o[0], target[1] - o[1], target[2] - o[2] };
      Normalize(d);
      double t = 0.0;
      double n[3];
      bool inside = false;
      const bool hit = metaballs->IntersectRay(o, d, 0.0, 40.0, t, n, inside);
      // the march: the first sample at or above the iso-value, then bisection
      const double step = 1e-3;
      double marched = -1.0;
      for (double s = 0.0; s <= 40.0; s += step)
      {
        const double p[3] = { o[0] + s * d[0], o[1] + s * d[1], o[2] + s * d[2] };
        if (metaballs->EvaluateField(p) >= 1.0)
        {
          double lo = s - step;
          double hi = s;
          for (int it = 0; it < 60; ++it)
          {
            const double mid = 0.5 * (lo + hi);
            const double q[3] = { o[0] + mid * d[0], o[1] + mid * d[1], o[2] + mid * d[2] };
            (metaballs->EvaluateField(q) >= 1.0 ? hi : lo) = mid;
          }
          marched = hi;
          break;
        }
      }
      if (hit)
      {
        ++hits;
        const double p[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
        worstField = std::max(worstField, std::abs(metaballs->EvaluateField(p) - 1.0));
        if (marched >= 0.0 && marched < t - 1e-9)
        {
          ++earlier;
        }
        if (marched < 0.0 || marched > t + step)
        {
          ++missedByMarch; // a crossing thinner than the march's step
        }
      }
      else if (marched >= 0.0)
      {
        ++earlier;
      }
    }
    std::printf("cluster: %d of 300 rays hit, |field - 1| <= %.3g at the hits, %d with an "
                "earlier marched crossing, %d hits the march missed\n",
      hits, worstField, earlier, missedByMarch);
    Check(hits > 50, "the cluster is hit by many rays");
    Check(worstField <= 1e-9, Format("every hit lies on the surface (%.3g)", worstField));
    Check(earlier == 0, "no crossing before the exact one (and no missed surface)");
  }

  // 6. a ray that starts inside
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->InsertNextPoint(0.0, 0.0, 0.0);
    vtkNew<vtkParticleReferenceMetaballs> metaballs;
    metaballs->SetParticles(points, nullptr);
    const double o[3] = { 0.1, 0.0, 0.0 };
    const double dir[3] = { 0.0, 0.0, 2.0 };
    double t = -1.0;
    double n[3];
    bool inside = false;
    const bool hit = metaballs->IntersectRay(o, dir, 0.25, 10.0, t, n, inside);
    Check(hit && inside && t == 0.25 && n[2] == -1.0,
      "a ray starting inside: t = tMin, inside, normal against the ray");
  }

  // 7. bad input
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->InsertNextPoint(0.0, 0.0, 0.0);
    points->InsertNextPoint(std::nan(""), 0.0, 0.0);
    points->InsertNextPoint(3.0, 0.0, 0.0);
    points->InsertNextPoint(6.0, 0.0, 0.0);
    vtkNew<vtkDoubleArray> radii;
    radii->InsertNextValue(1.0);
    radii->InsertNextValue(1.0);
    radii->InsertNextValue(0.0);
    radii->InsertNextValue(-1.0);
    vtkNew<vtkParticleReferenceMetaballs> metaballs;
    metaballs->SetParticles(points, radii);
    Check(metaballs->GetNumberOfParticles() == 1, "NaN positions and radii <= 0 are skipped");
  }

  std::printf("%d failure(s)\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
