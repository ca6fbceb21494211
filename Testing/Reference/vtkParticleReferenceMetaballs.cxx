#include "vtkParticleReferenceMetaballs.h"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkParticleReferenceRays.h"
#include "vtkPoints.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkParticleReferenceMetaballs);

namespace
{
// p(u) for coefficients c[0..degree] (Horner)
double Evaluate(const double* c, int degree, double u)
{
  double value = c[degree];
  for (int j = degree - 1; j >= 0; --j)
  {
    value = value * u + c[j];
  }
  return value;
}

// the point of [lo, hi] where p changes sign (p(lo) and p(hi) of opposite signs, p monotone in
// between), by bisection to adjacent doubles
double Bisect(const double* c, int degree, double lo, double hi, bool lowNegative)
{
  for (;;)
  {
    const double mid = lo + 0.5 * (hi - lo);
    if (!(mid > lo && mid < hi))
    {
      return hi;
    }
    const bool negative = Evaluate(c, degree, mid) < 0.0;
    (negative == lowNegative ? lo : hi) = mid;
  }
}

// every root of p in [0, width], increasing: the critical points (the roots of p', recursively)
// split it into monotone pieces, each holding at most one
void Roots(const double* c, int degree, double width, std::vector<double>& roots)
{
  roots.clear();
  if (degree <= 0)
  {
    return;
  }
  if (degree == 1)
  {
    if (c[1] != 0.0)
    {
      const double r = -c[0] / c[1];
      if (r >= 0.0 && r <= width)
      {
        roots.push_back(r);
      }
    }
    return;
  }
  double derivative[4];
  for (int j = 0; j < degree; ++j)
  {
    derivative[j] = (j + 1) * c[j + 1];
  }
  std::vector<double> points;
  Roots(derivative, degree - 1, width, points);
  points.insert(points.begin(), 0.0);
  points.push_back(width);
  for (size_t k = 0; k + 1 < points.size(); ++k)
  {
    const double f0 = Evaluate(c, degree, points[k]);
    const double f1 = Evaluate(c, degree, points[k + 1]);
    if (f0 == 0.0)
    {
      if (roots.empty() || roots.back() != points[k])
      {
        roots.push_back(points[k]);
      }
    }
    else if ((f0 < 0.0) != (f1 < 0.0) && f1 != 0.0)
    {
      roots.push_back(Bisect(c, degree, points[k], points[k + 1], f0 < 0.0));
    }
  }
  if (Evaluate(c, degree, width) == 0.0 && (roots.empty() || roots.back() != width))
  {
    roots.push_back(width);
  }
}

// one particle's influence along a ray (unit direction)
struct Interval
{
  std::uint32_t Index;
  double Closest;    // ray parameter of the closest approach to the centre
  double Impact2;    // squared distance of the ray from the centre
  double Influence2; // squared influence radius
  double Enter;
  double Leave;
};
}

//------------------------------------------------------------------------------
class vtkParticleReferenceMetaballs::vtkInternals
{
public:
  std::vector<prReference::SphereVC> Influence; // centre and influence radius k R
  std::vector<double> Radii;
  std::vector<vtkIdType> Input; // index of each kept particle in SetParticles()' centres
  prReference::SphereGrid Grid;
  bool GridValid = false;
  double GridFactor = 0.0;
};

//------------------------------------------------------------------------------
vtkParticleReferenceMetaballs::vtkParticleReferenceMetaballs()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkParticleReferenceMetaballs::~vtkParticleReferenceMetaballs()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
double vtkParticleReferenceMetaballs::KernelScale(double k)
{
  const double s = 1.0 - 1.0 / (k * k);
  return 1.0 / (s * s);
}

//------------------------------------------------------------------------------
void vtkParticleReferenceMetaballs::SetParticles(vtkPoints* centers, vtkDataArray* radii)
{
  vtkInternals& internals = *this->Internals;
  internals.Influence.clear();
  internals.Radii.clear();
  internals.Input.clear();
  internals.GridValid = false;
  const vtkIdType n = centers ? centers->GetNumberOfPoints() : 0;
  if (radii && radii->GetNumberOfTuples() < n)
  {
    vtkErrorMacro(<< "SetParticles(): " << n << " centres but " << radii->GetNumberOfTuples()
                  << " radii.");
    return;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    prReference::SphereVC s;
    centers->GetPoint(i, s.C);
    const double r = radii ? radii->GetComponent(i, 0) : this->DefaultRadius;
    if (!(r > 0.0) || !std::isfinite(r) || !std::isfinite(s.C[0] + s.C[1] + s.C[2]))
    {
      continue;
    }
    s.R = r; // scaled by the influence factor when the grid is built
    internals.Influence.push_back(s);
    internals.Radii.push_back(r);
    internals.Input.push_back(i);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkIdType vtkParticleReferenceMetaballs::GetNumberOfParticles()
{
  return static_cast<vtkIdType>(this->Internals->Radii.size());
}

//------------------------------------------------------------------------------
double vtkParticleReferenceMetaballs::EvaluateField(const double point[3])
{
  const vtkInternals& internals = *this->Internals;
  const double k = this->InfluenceFactor;
  const double c = KernelScale(k);
  double sum = 0.0;
  for (size_t i = 0; i < internals.Radii.size(); ++i)
  {
    const double* center = internals.Influence[i].C;
    const double dx = point[0] - center[0];
    const double dy = point[1] - center[1];
    const double dz = point[2] - center[2];
    const double rho = k * internals.Radii[i];
    const double q = 1.0 - (dx * dx + dy * dy + dz * dz) / (rho * rho);
    if (q > 0.0)
    {
      sum += c * q * q;
    }
  }
  return sum;
}

//------------------------------------------------------------------------------
void vtkParticleReferenceMetaballs::EvaluateGradient(const double point[3], double gradient[3])
{
  const vtkInternals& internals = *this->Internals;
  const double k = this->InfluenceFactor;
  const double c = KernelScale(k);
  gradient[0] = gradient[1] = gradient[2] = 0.0;
  for (size_t i = 0; i < internals.Radii.size(); ++i)
  {
    const double* center = internals.Influence[i].C;
    const double x[3] = { point[0] - center[0], point[1] - center[1], point[2] - center[2] };
    const double rho2 = k * k * internals.Radii[i] * internals.Radii[i];
    const double q = 1.0 - (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) / rho2;
    if (q > 0.0)
    {
      for (int j = 0; j < 3; ++j)
      {
        gradient[j] += -4.0 * c * q * x[j] / rho2;
      }
    }
  }
}

//------------------------------------------------------------------------------
double vtkParticleReferenceMetaballs::FirstNonNegative(const double c[5], double width)
{
  if (Evaluate(c, 4, 0.0) >= 0.0)
  {
    return 0.0;
  }
  if (!(width > 0.0))
  {
    return -1.0;
  }
  double derivative[4];
  for (int j = 0; j < 4; ++j)
  {
    derivative[j] = (j + 1) * c[j + 1];
  }
  std::vector<double> points;
  Roots(derivative, 3, width, points);
  points.insert(points.begin(), 0.0);
  points.push_back(width);
  for (size_t k = 0; k + 1 < points.size(); ++k)
  {
    if (Evaluate(c, 4, points[k + 1]) >= 0.0)
    {
      // p(points[k]) < 0 <= p(points[k + 1]), p monotone in between
      return Bisect(c, 4, points[k], points[k + 1], true);
    }
  }
  return -1.0;
}

//------------------------------------------------------------------------------
void vtkParticleReferenceMetaballs::Prepare()
{
  vtkInternals& internals = *this->Internals;
  const double k = this->InfluenceFactor;
  if (!internals.GridValid || internals.GridFactor != k)
  {
    std::vector<prReference::SphereVC> spheres = internals.Influence;
    for (size_t i = 0; i < spheres.size(); ++i)
    {
      spheres[i].R = k * internals.Radii[i];
    }
    internals.Grid.Build(spheres);
    internals.GridValid = true;
    internals.GridFactor = k;
  }
}

//------------------------------------------------------------------------------
bool vtkParticleReferenceMetaballs::IntersectRay(const double origin[3], const double direction[3],
  double tMin, double tMax, double& t, double normal[3], bool& inside)
{
  this->Prepare();
  vtkIdType candidates = 0;
  const bool hit =
    this->IntersectRay(origin, direction, tMin, tMax, t, normal, inside, nullptr, candidates);
  this->LastCandidates = candidates;
  return hit;
}

//------------------------------------------------------------------------------
bool vtkParticleReferenceMetaballs::IntersectRay(const double origin[3], const double direction[3],
  double tMin, double tMax, double& t, double normal[3], bool& inside,
  std::vector<Contribution>* contributions, vtkIdType& candidateCount) const
{
  const vtkInternals& internals = *this->Internals;
  inside = false;
  candidateCount = 0;
  if (contributions)
  {
    contributions->clear();
  }
  const double length = std::sqrt(prReference::Dot(direction, direction));
  if (!(length > 0.0) || !std::isfinite(length) || internals.Radii.empty() || !(tMax >= tMin) ||
    !internals.GridValid || internals.GridFactor != this->InfluenceFactor)
  {
    return false;
  }
  const double k = this->InfluenceFactor;
  const double d[3] = { direction[0] / length, direction[1] / length, direction[2] / length };
  const double t0 = tMin * length;
  const double t1 = tMax * length;

  // the influence intervals along the ray
  std::vector<std::uint32_t> candidates;
  internals.Grid.Collect(origin, d, t0, t1, candidates);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  std::vector<Interval> intervals;
  std::vector<double> ends = { t0, t1 };
  for (std::uint32_t i : candidates)
  {
    const double* center = internals.Influence[i].C;
    const double rel[3] = { center[0] - origin[0], center[1] - origin[1], center[2] - origin[2] };
    const double closest = prReference::Dot(rel, d);
    const double perp[3] = { rel[0] - closest * d[0], rel[1] - closest * d[1],
      rel[2] - closest * d[2] };
    const double impact2 = prReference::Dot(perp, perp);
    const double rho = k * internals.Radii[i];
    const double influence2 = rho * rho;
    if (!(impact2 < influence2))
    {
      continue;
    }
    const double half = std::sqrt(influence2 - impact2);
    const Interval interval = { i, closest, impact2, influence2, closest - half, closest + half };
    if (interval.Leave < t0 || interval.Enter > t1)
    {
      continue;
    }
    intervals.push_back(interval);
    for (double end : { interval.Enter, interval.Leave })
    {
      if (end > t0 && end < t1)
      {
        ends.push_back(end);
      }
    }
  }
  candidateCount = static_cast<vtkIdType>(intervals.size());
  if (intervals.empty())
  {
    return false;
  }
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());

  const double c = KernelScale(k);
  const double iso = this->IsoValue;
  double hit = -1.0;
  for (size_t e = 0; e + 1 < ends.size() && hit < 0.0; ++e)
  {
    const double lo = ends[e];
    const double hi = ends[e + 1];
    // sum of the active kernels minus the iso-value, as a quartic in u = t - lo:
    // D = c (alpha + beta u + gamma u^2)^2 with alpha = 1 - (h^2 + e^2) / rho^2,
    // beta = -2 e / rho^2, gamma = -1 / rho^2, e = lo - t_closest
    double p[5] = { -iso, 0.0, 0.0, 0.0, 0.0 };
    bool any = false;
    for (const Interval& in : intervals)
    {
      if (!(in.Enter < hi && in.Leave > lo))
      {
        continue;
      }
      any = true;
      const double offset = lo - in.Closest;
      const double alpha = 1.0 - (in.Impact2 + offset * offset) / in.Influence2;
      const double beta = -2.0 * offset / in.Influence2;
      const double gamma = -1.0 / in.Influence2;
      p[0] += c * alpha * alpha;
      p[1] += c * 2.0 * alpha * beta;
      p[2] += c * (beta * beta + 2.0 * alpha * gamma);
      p[3] += c * 2.0 * beta * gamma;
      p[4] += c * gamma * gamma;
    }
    if (!any)
    {
      continue;
    }
    const double u = FirstNonNegative(p, hi - lo);
    if (u >= 0.0)
    {
      hit = lo + u;
      inside = (e == 0 && u == 0.0);
    }
  }
  if (hit < 0.0)
  {
    return false;
  }
  t = hit / length;
  if (inside)
  {
    normal[0] = -d[0];
    normal[1] = -d[1];
    normal[2] = -d[2];
    return true;
  }
  // the gradient from the offsets to the centres along the ray: x - c_i = (t - t_i) d - perp_i
  double gradient[3] = { 0.0, 0.0, 0.0 };
  for (const Interval& in : intervals)
  {
    const double* center = internals.Influence[in.Index].C;
    const double rel[3] = { center[0] - origin[0], center[1] - origin[1], center[2] - origin[2] };
    double x[3];
    for (int j = 0; j < 3; ++j)
    {
      const double perp = rel[j] - in.Closest * d[j];
      x[j] = (hit - in.Closest) * d[j] - perp;
    }
    const double q = 1.0 - prReference::Dot(x, x) / in.Influence2;
    if (q > 0.0)
    {
      for (int j = 0; j < 3; ++j)
      {
        gradient[j] += -4.0 * c * q * x[j] / in.Influence2;
      }
      if (contributions)
      {
        contributions->push_back({ internals.Input[in.Index], c * q * q });
      }
    }
  }
  for (int j = 0; j < 3; ++j)
  {
    normal[j] = -gradient[j];
  }
  if (!prReference::NormalizeInPlace(normal))
  {
    normal[0] = -d[0];
    normal[1] = -d[1];
    normal[2] = -d[2];
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleReferenceMetaballs::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfParticles: " << this->Internals->Radii.size() << "\n";
  os << indent << "DefaultRadius: " << this->DefaultRadius << "\n";
  os << indent << "InfluenceFactor: " << this->InfluenceFactor << "\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
}
