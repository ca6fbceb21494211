// Private header of ParticleRendering::Reference (vtkParticleReferenceRenderer): rays and the
// sphere grid -- the camera as the rays see it, spheres in view coordinates, the ray-sphere
// intersection of RaySphere.glsl in double, and the uniform grid that finds the spheres along a
// ray.
#ifndef vtkParticleReferenceRays_h
#define vtkParticleReferenceRays_h

#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace prReference
{
//------------------------------------------------------------------------------
// small double-precision vector helpers
inline double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline bool NormalizeInPlace(double v[3])
{
  const double len = std::sqrt(Dot(v, v));
  if (!(len > 0.0) || !std::isfinite(len))
  {
    return false;
  }
  v[0] /= len;
  v[1] /= len;
  v[2] /= len;
  return true;
}

// p' = M * (p, w) for a row-major 4x4 matrix (VTK convention, column vectors)
inline void MultiplyPoint(const double m[16], const double p[4], double out[4])
{
  for (int i = 0; i < 4; ++i)
  {
    out[i] = m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3] * p[3];
  }
}

//------------------------------------------------------------------------------
// The camera as the rays see it: projection, its inverse, image size.
struct RayCamera
{
  double P[16];
  double PInv[16];
  bool Parallel = false;
  int Width = 0;
  int Height = 0;

  // Ray of the point (px, py) in pixel units (pixel centres at +0.5): origin o and unit direction
  // d in view coordinates, and the ray parameters of the near and far planes.
  void PixelRay(double px, double py, double o[3], double d[3], double& tNear, double& tFar) const
  {
    const double x = 2.0 * px / this->Width - 1.0;
    const double y = 2.0 * py / this->Height - 1.0;
    double nearPt[3];
    double farPt[3];
    this->Unproject(x, y, -1.0, nearPt);
    this->Unproject(x, y, 1.0, farPt);
    if (this->Parallel)
    {
      // for an affine inverse the direction is the third column (no cancellation between the
      // near and far points, which may both be far from the origin)
      d[0] = this->PInv[2];
      d[1] = this->PInv[6];
      d[2] = this->PInv[10];
      NormalizeInPlace(d);
      if (farPt[0] * d[0] + farPt[1] * d[1] + farPt[2] * d[2] <
        nearPt[0] * d[0] + nearPt[1] * d[1] + nearPt[2] * d[2])
      {
        d[0] = -d[0];
        d[1] = -d[1];
        d[2] = -d[2];
      }
      // origin: the point of the ray in the plane z_VC = 0
      const double s = (std::abs(d[2]) > 0.0) ? -nearPt[2] / d[2] : 0.0;
      for (int k = 0; k < 3; ++k)
      {
        o[k] = nearPt[k] + s * d[k];
      }
    }
    else
    {
      o[0] = o[1] = o[2] = 0.0;
      d[0] = nearPt[0];
      d[1] = nearPt[1];
      d[2] = nearPt[2];
      NormalizeInPlace(d);
    }
    double rel[3];
    for (int k = 0; k < 3; ++k)
    {
      rel[k] = nearPt[k] - o[k];
    }
    tNear = Dot(rel, d);
    for (int k = 0; k < 3; ++k)
    {
      rel[k] = farPt[k] - o[k];
    }
    tFar = Dot(rel, d);
  }

  void Unproject(double x, double y, double z, double out[3]) const
  {
    const double ndc[4] = { x, y, z, 1.0 };
    double h[4];
    MultiplyPoint(this->PInv, ndc, h);
    const double w = (h[3] != 0.0) ? h[3] : 1e-300;
    out[0] = h[0] / w;
    out[1] = h[1] / w;
    out[2] = h[2] / w;
  }

  // Ray parameter of the point of window depth `depth` on the ray (o, d) of the pixel point
  // (px, py): unprojection in double through the inverse projection.
  double WindowDepthToT(
    double px, double py, double depth, const double o[3], const double d[3]) const
  {
    double p[3];
    this->Unproject(
      2.0 * px / this->Width - 1.0, 2.0 * py / this->Height - 1.0, 2.0 * depth - 1.0, p);
    const double rel[3] = { p[0] - o[0], p[1] - o[1], p[2] - o[2] };
    return Dot(rel, d);
  }

  // The visibility rule of Depth(), telling on which side a rejected point lies: 0 visible,
  // -1 in front of the near plane (or behind the eye), +1 beyond the far plane, 2 undefined.
  int Classify(const double p[3]) const
  {
    const double* P = this->P;
    const double clipZ = P[8] * p[0] + P[9] * p[1] + P[10] * p[2] + P[11];
    const double clipW = P[12] * p[0] + P[13] * p[1] + P[14] * p[2] + P[15];
    if (!(clipW > 0.0))
    {
      return clipW <= 0.0 ? -1 : 2;
    }
    const double ndcZ = clipZ / clipW;
    if (ndcZ >= -1.0 && ndcZ <= 1.0)
    {
      return 0;
    }
    return ndcZ < -1.0 ? -1 : (ndcZ > 1.0 ? 1 : 2);
  }

  // The GPU's visibility rule and window depth of a view-coordinate point.
  bool Depth(const double p[3], double& depth) const
  {
    const double* P = this->P;
    const double clipZ = P[8] * p[0] + P[9] * p[1] + P[10] * p[2] + P[11];
    const double clipW = P[12] * p[0] + P[13] * p[1] + P[14] * p[2] + P[15];
    if (!(clipW > 0.0))
    {
      return false;
    }
    const double ndcZ = clipZ / clipW;
    if (!(ndcZ >= -1.0 && ndcZ <= 1.0))
    {
      return false;
    }
    depth = 0.5 * ndcZ + 0.5;
    return true;
  }
};

//------------------------------------------------------------------------------
struct SphereVC
{
  double C[3];
  double R; // the radius; for an ellipsoid the radius of the smallest sphere about C holding it
  // an oriented ellipsoid x = C + ToVC u, |u| <= 1 (ToUnit = ToVC^-1), when Ellipsoid is set
  bool Ellipsoid = false;
  double ToVC[3][3];
  double ToUnit[3][3];
};

inline void Apply3x3(const double m[3][3], const double v[3], double out[3])
{
  for (int i = 0; i < 3; ++i)
  {
    out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
  }
}

// A hit along a ray
struct Hit
{
  double T = std::numeric_limits<double>::infinity();
  double Depth = 1.0;
  double Rel[3] = { 0, 0, 0 }; // hit point relative to the centre
  vtkIdType Index = -1;        // index into the sphere list
  bool Inside = false;
};

// The unit normal (facing the viewer: inward for a hit from inside) and the view-coordinate
// point of a hit on the sphere s.
inline void HitGeometry(const Hit& hit, const SphereVC& s, double n[3], double p[3])
{
  for (int k = 0; k < 3; ++k)
  {
    n[k] = (hit.Inside ? -hit.Rel[k] : hit.Rel[k]) / s.R;
    p[k] = s.C[k] + hit.Rel[k];
  }
  if (s.Ellipsoid)
  {
    // the gradient of |ToUnit x|^2: ToUnit^T ToUnit x
    double u[3];
    Apply3x3(s.ToUnit, hit.Rel, u);
    for (int k = 0; k < 3; ++k)
    {
      const double g = s.ToUnit[0][k] * u[0] + s.ToUnit[1][k] * u[1] + s.ToUnit[2][k] * u[2];
      n[k] = hit.Inside ? -g : g;
    }
    NormalizeInPlace(n);
  }
}

// The ray (o, d) against the ellipsoid s in its unit frame: false when it misses; otherwise the
// unit-frame closest approach q to the centre, the unit-frame direction dd (unit), its length
// scale L (a ray parameter t is u / L for the unit-frame parameter u from q) and the half chord
// h (unit frame): the hits are at u = -b -+ h, b = the unit-frame parameter of q from o.
inline bool EllipsoidChord(const double o[3], const double d[3], const SphereVC& s, double q[3],
  double dd[3], double& length, double& b, double& h)
{
  const double rel[3] = { o[0] - s.C[0], o[1] - s.C[1], o[2] - s.C[2] };
  double su[3];
  Apply3x3(s.ToUnit, rel, su);
  Apply3x3(s.ToUnit, d, dd);
  length = std::sqrt(Dot(dd, dd));
  if (!(length > 0.0))
  {
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    dd[k] /= length;
  }
  b = Dot(su, dd);
  for (int k = 0; k < 3; ++k)
  {
    q[k] = su[k] - b * dd[k];
  }
  const double h2 = 1.0 - Dot(q, q);
  if (!(h2 >= 0.0))
  {
    return false;
  }
  h = std::sqrt(h2);
  return true;
}

// The chord of the ray (o, d) through the sphere or ellipsoid s, relative to the closest approach
// of the ray to the centre: the ray parameter Tc of that point, its position Q relative to the
// centre (view coordinates), the half chord H, and the sphere that has the same chord and density
// profile along this ray -- for a sphere itself; for an ellipsoid the unit frame's chord scaled by
// Radius = 1 / |A^-1 d|, at Impact = |q_u| Radius from its centre. MaximumScale: how its I_max
// scales (densityPower 1 for the constant density model, 3 for the squared distance): an
// ellipsoid's physical optical depth is kappa (I_u / |A^-1 d|) / (I_max,u a_max) (a_max = s.R
// its longest semi-axis), the equivalent sphere's own ratio I'/(I_max,u R^p), so I_max scales by
// (R / a_max)^(p-1). False when the ray misses (or only touches: no length).
struct Chord
{
  double Tc = 0.0;
  double Q[3] = { 0, 0, 0 };
  double H = 0.0;
  double Radius = 0.0;
  double Impact = 0.0;
  double MaximumScale = 1.0;
};

inline bool ChordOf(
  const double o[3], const double d[3], const SphereVC& s, int densityPower, Chord& chord)
{
  if (s.Ellipsoid)
  {
    double qu[3];
    double dd[3];
    double length;
    double b;
    double hu;
    if (!EllipsoidChord(o, d, s, qu, dd, length, b, hu))
    {
      return false;
    }
    chord.Tc = -b / length;
    Apply3x3(s.ToVC, qu, chord.Q); // the unit frame's closest approach, without cancellation
    chord.H = hu / length;
    chord.Radius = 1.0 / length;
    chord.Impact = std::sqrt(Dot(qu, qu)) / length;
    chord.MaximumScale = std::pow(chord.Radius / s.R, densityPower - 1);
    return true;
  }
  // relative to the centre: the textbook |o - c|^2 - r^2 cancels with a far camera
  const double oc[3] = { s.C[0] - o[0], s.C[1] - o[1], s.C[2] - o[2] };
  chord.Tc = Dot(oc, d);
  for (int k = 0; k < 3; ++k)
  {
    chord.Q[k] = chord.Tc * d[k] - oc[k];
  }
  const double h2 = s.R * s.R - Dot(chord.Q, chord.Q);
  if (!(h2 >= 0.0))
  {
    return false;
  }
  chord.H = std::sqrt(h2);
  chord.Radius = s.R;
  chord.Impact = std::sqrt(Dot(chord.Q, chord.Q));
  chord.MaximumScale = 1.0;
  return true;
}

// Intersect the ray (o, d) with a sphere or ellipsoid (ChordOf) and keep the first visible
// intersection if it is nearer than best (ties: larger index, as the GPU's GL_LEQUAL depth test
// with instances drawn in id order).
inline void IntersectSphere(const RayCamera& cam, const double o[3], const double d[3],
  const SphereVC& s, vtkIdType index, Hit& best)
{
  Chord chord;
  if (!ChordOf(o, d, s, 1, chord))
  {
    return;
  }
  for (int side = 0; side < 2; ++side)
  {
    const double sign = side == 0 ? -1.0 : 1.0;
    const double t = chord.Tc + sign * chord.H;
    if (t > best.T || (t == best.T && index < best.Index))
    {
      return; // the exit is even further
    }
    const double rel[3] = { chord.Q[0] + sign * chord.H * d[0], chord.Q[1] + sign * chord.H * d[1],
      chord.Q[2] + sign * chord.H * d[2] };
    const double p[3] = { s.C[0] + rel[0], s.C[1] + rel[1], s.C[2] + rel[2] };
    double depth;
    if (cam.Depth(p, depth))
    {
      best.T = t;
      best.Depth = depth;
      std::copy(rel, rel + 3, best.Rel);
      best.Index = index;
      best.Inside = side == 1;
      return;
    }
  }
}

//------------------------------------------------------------------------------
// Uniform grid over the spheres' bounding boxes, 3D-DDA traversal.
class SphereGrid
{
public:
  void Build(const std::vector<SphereVC>& spheres)
  {
    this->Cells.clear();
    this->References.clear();
    this->Large.clear();
    this->N[0] = this->N[1] = this->N[2] = 0;
    const size_t count = spheres.size();
    if (count == 0)
    {
      return;
    }
    double meanRadius = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      this->Lo[k] = std::numeric_limits<double>::infinity();
      this->Hi[k] = -std::numeric_limits<double>::infinity();
    }
    for (const SphereVC& s : spheres)
    {
      for (int k = 0; k < 3; ++k)
      {
        this->Lo[k] = std::min(this->Lo[k], s.C[k] - s.R);
        this->Hi[k] = std::max(this->Hi[k], s.C[k] + s.R);
      }
      meanRadius += s.R;
    }
    meanRadius /= static_cast<double>(count);
    double extent[3];
    for (int k = 0; k < 3; ++k)
    {
      // a little margin so that no rounding puts a box outside the grid
      const double margin = 1e-9 * (this->Hi[k] - this->Lo[k]) + 1e-12 * std::abs(this->Lo[k]) +
        1e-12 * std::abs(this->Hi[k]);
      this->Lo[k] -= margin;
      this->Hi[k] += margin;
      extent[k] = std::max(this->Hi[k] - this->Lo[k], 1e-300);
    }
    // about two cells per sphere, but cells no smaller than a sphere radius
    const double volume = extent[0] * extent[1] * extent[2];
    double cell = std::max(std::cbrt(volume / (2.0 * count)), meanRadius);
    const double maxCells = std::min(16.0 * count + 64.0, 16777216.0);
    for (;;)
    {
      double total = 1.0;
      for (int k = 0; k < 3; ++k)
      {
        this->N[k] = static_cast<int>(std::min(std::ceil(extent[k] / cell), 4096.0));
        this->N[k] = std::max(this->N[k], 1);
        total *= this->N[k];
      }
      if (total <= maxCells)
      {
        break;
      }
      cell *= 1.25;
    }
    for (int k = 0; k < 3; ++k)
    {
      this->CellSize[k] = extent[k] / this->N[k];
    }

    // counting sort of the sphere references by cell; spheres over too many cells go to Large
    const size_t numCells = static_cast<size_t>(this->N[0]) * this->N[1] * this->N[2];
    const double largeCells = std::max(512.0, 0.05 * numCells);
    std::vector<int> range(6 * count);
    std::vector<std::uint64_t> start(numCells + 1, 0);
    for (size_t i = 0; i < count; ++i)
    {
      int* r = &range[6 * i];
      double cells = 1.0;
      for (int k = 0; k < 3; ++k)
      {
        r[2 * k] = this->CellIndex(spheres[i].C[k] - spheres[i].R, k);
        r[2 * k + 1] = this->CellIndex(spheres[i].C[k] + spheres[i].R, k);
        cells *= r[2 * k + 1] - r[2 * k] + 1;
      }
      if (cells > largeCells && numCells > 1)
      {
        r[0] = -1; // marker
        this->Large.push_back(static_cast<std::uint32_t>(i));
        continue;
      }
      for (int kk = r[4]; kk <= r[5]; ++kk)
      {
        for (int jj = r[2]; jj <= r[3]; ++jj)
        {
          for (int ii = r[0]; ii <= r[1]; ++ii)
          {
            ++start[this->Flat(ii, jj, kk) + 1];
          }
        }
      }
    }
    for (size_t c = 0; c < numCells; ++c)
    {
      start[c + 1] += start[c];
    }
    this->References.resize(start[numCells]);
    std::vector<std::uint64_t> fill(start.begin(), start.end() - 1);
    for (size_t i = 0; i < count; ++i)
    {
      const int* r = &range[6 * i];
      if (r[0] < 0)
      {
        continue;
      }
      for (int kk = r[4]; kk <= r[5]; ++kk)
      {
        for (int jj = r[2]; jj <= r[3]; ++jj)
        {
          for (int ii = r[0]; ii <= r[1]; ++ii)
          {
            this->References[fill[this->Flat(ii, jj, kk)]++] = static_cast<std::uint32_t>(i);
          }
        }
      }
    }
    this->Cells = std::move(start);
  }

  // Nearest visible hit along the ray between tMin and tMax.
  void Trace(const RayCamera& cam, const std::vector<SphereVC>& spheres, const double o[3],
    const double d[3], double tMin, double tMax, Hit& best) const
  {
    for (std::uint32_t i : this->Large)
    {
      IntersectSphere(cam, o, d, spheres[i], i, best);
    }
    this->Walk(o, d, tMin, tMax,
      [&](size_t c, double cellExit, double t1)
      {
        for (std::uint64_t r = this->Cells[c]; r < this->Cells[c + 1]; ++r)
        {
          const std::uint32_t i = this->References[r];
          IntersectSphere(cam, o, d, spheres[i], i, best);
        }
        // a hit inside this cell cannot be beaten by spheres of later cells; the margin covers
        // the rounding of the cell boundaries
        return !(best.T <= cellExit - 1e-12 * std::abs(cellExit) || cellExit > t1);
      });
  }

  // Every sphere referenced by a cell the ray crosses between tMin and tMax, plus the large
  // spheres (with repetitions: a sphere is listed once per cell).
  void Collect(const double o[3], const double d[3], double tMin, double tMax,
    std::vector<std::uint32_t>& out) const
  {
    out.insert(out.end(), this->Large.begin(), this->Large.end());
    this->Walk(o, d, tMin, tMax,
      [&](size_t c, double cellExit, double t1)
      {
        out.insert(out.end(),
          this->References.begin() + static_cast<std::ptrdiff_t>(this->Cells[c]),
          this->References.begin() + static_cast<std::ptrdiff_t>(this->Cells[c + 1]));
        // the cell boundaries are rounded: continue a little past t1
        return !(cellExit > t1 + 1e-12 * std::abs(t1));
      });
  }

  const int* GetResolution() const { return this->N; }
  size_t GetNumberOfReferences() const { return this->References.size(); }
  size_t GetNumberOfLarge() const { return this->Large.size(); }

private:
  // 3D-DDA through the cells the ray crosses between tMin and tMax (clipped to the grid box),
  // front to back: visit(cell, t where the ray leaves it, end of the clipped ray) returns
  // whether to go on.
  template <class Visit>
  void Walk(const double o[3], const double d[3], double tMin, double tMax, Visit visit) const
  {
    if (this->Cells.empty())
    {
      return;
    }
    double t0 = tMin;
    double t1 = tMax;
    for (int k = 0; k < 3; ++k)
    {
      if (d[k] != 0.0)
      {
        double a = (this->Lo[k] - o[k]) / d[k];
        double b = (this->Hi[k] - o[k]) / d[k];
        if (a > b)
        {
          std::swap(a, b);
        }
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
      }
      else if (o[k] < this->Lo[k] || o[k] > this->Hi[k])
      {
        return;
      }
    }
    if (!(t0 <= t1))
    {
      return;
    }
    int cell[3];
    int step[3];
    double tNext[3];
    double tDelta[3];
    for (int k = 0; k < 3; ++k)
    {
      cell[k] = this->CellIndex(o[k] + t0 * d[k], k);
      if (d[k] > 0.0)
      {
        step[k] = 1;
        tNext[k] = (this->Lo[k] + (cell[k] + 1) * this->CellSize[k] - o[k]) / d[k];
        tDelta[k] = this->CellSize[k] / d[k];
      }
      else if (d[k] < 0.0)
      {
        step[k] = -1;
        tNext[k] = (this->Lo[k] + cell[k] * this->CellSize[k] - o[k]) / d[k];
        tDelta[k] = -this->CellSize[k] / d[k];
      }
      else
      {
        step[k] = 0;
        tNext[k] = std::numeric_limits<double>::infinity();
        tDelta[k] = std::numeric_limits<double>::infinity();
      }
    }
    for (;;)
    {
      const int axis =
        (tNext[0] < tNext[1]) ? (tNext[0] < tNext[2] ? 0 : 2) : (tNext[1] < tNext[2] ? 1 : 2);
      if (!visit(this->Flat(cell[0], cell[1], cell[2]), tNext[axis], t1))
      {
        return;
      }
      cell[axis] += step[axis];
      if (cell[axis] < 0 || cell[axis] >= this->N[axis])
      {
        return;
      }
      tNext[axis] += tDelta[axis];
    }
  }

  int CellIndex(double x, int k) const
  {
    const double f = (x - this->Lo[k]) / this->CellSize[k];
    if (!(f >= 0.0))
    {
      return 0;
    }
    return static_cast<int>(std::min(f, static_cast<double>(this->N[k] - 1)));
  }
  size_t Flat(int i, int j, int k) const
  {
    return static_cast<size_t>(i) +
      static_cast<size_t>(this->N[0]) *
      (static_cast<size_t>(j) + static_cast<size_t>(this->N[1]) * k);
  }

  double Lo[3] = { 0, 0, 0 };
  double Hi[3] = { 0, 0, 0 };
  double CellSize[3] = { 1, 1, 1 };
  int N[3] = { 0, 0, 0 };
  std::vector<std::uint64_t> Cells; // reference range of each cell (size cells + 1)
  std::vector<std::uint32_t> References;
  std::vector<std::uint32_t> Large;
};
} // namespace prReference

#endif
