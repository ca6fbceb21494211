#include "vtkParticleReferenceRenderer.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkTransparentSphereMapper.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkParticleReferenceRenderer);
vtkCxxSetObjectMacro(vtkParticleReferenceRenderer, Renderer, vtkRenderer);
vtkCxxSetObjectMacro(vtkParticleReferenceRenderer, Actor, vtkActor);

namespace
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
    this->Unproject(2.0 * px / this->Width - 1.0, 2.0 * py / this->Height - 1.0,
      2.0 * depth - 1.0, p);
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
  double R;
};

// A hit along a ray
struct Hit
{
  double T = std::numeric_limits<double>::infinity();
  double Depth = 1.0;
  double Rel[3] = { 0, 0, 0 }; // hit point relative to the centre
  vtkIdType Index = -1;        // index into the sphere list
  bool Inside = false;
};

// Intersect the ray (o, d) with a sphere in the sphere-relative form of RaySphere.glsl and keep
// the first visible intersection if it is nearer than best (ties: larger index, as the GPU's
// GL_LEQUAL depth test with instances drawn in id order).
inline void IntersectSphere(const RayCamera& cam, const double o[3], const double d[3],
  const SphereVC& s, vtkIdType index, Hit& best)
{
  const double oc[3] = { s.C[0] - o[0], s.C[1] - o[1], s.C[2] - o[2] };
  const double tc = Dot(oc, d);
  // closest approach point of the ray, relative to the centre
  const double q[3] = { tc * d[0] - oc[0], tc * d[1] - oc[1], tc * d[2] - oc[2] };
  const double h2 = s.R * s.R - Dot(q, q);
  if (!(h2 >= 0.0))
  {
    return;
  }
  const double h = std::sqrt(h2);
  for (int side = 0; side < 2; ++side)
  {
    const double sign = side == 0 ? -1.0 : 1.0;
    const double t = tc + sign * h;
    if (t > best.T || (t == best.T && index < best.Index))
    {
      return; // the exit is even further
    }
    const double rel[3] = { q[0] + sign * h * d[0], q[1] + sign * h * d[1],
      q[2] + sign * h * d[2] };
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
    this->Walk(o, d, tMin, tMax, [&](size_t c, double cellExit, double t1) {
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
    this->Walk(o, d, tMin, tMax, [&](size_t c, double cellExit, double t1) {
      out.insert(out.end(), this->References.begin() + static_cast<std::ptrdiff_t>(this->Cells[c]),
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

//------------------------------------------------------------------------------
// spot lights whose cones take part in the surface ids
const unsigned int MaximumConeBits = 16;

// A light as the fragment shader sees it (uniform values in double).
struct LightVC
{
  double Color[3] = { 0, 0, 0 };
  double Direction[3] = { 0, 0, -1 };
  bool Positional = false;
  double Position[3] = { 0, 0, 0 };
  double Attenuation[3] = { 1, 0, 0 };
  double ConeAngle = 180.0;
  double Exponent = 1.0;
};

// Lighting.glsl, prSceneLight (VTK's view vector normalize(-p), in either projection, and its
// 1e-5 floor of the specular base). Returns true when the point is inside the light's spot cone
// (or the light is not a spot).
bool SceneLight(const double n[3], const double p[3], const LightVC& light,
  bool usePositional, double specularPower, double diffuse[3], double specular[3])
{
  bool inCone = true;
  double attenuation = 1.0;
  double l[3] = { light.Direction[0], light.Direction[1], light.Direction[2] };
  if (usePositional && light.Positional)
  {
    for (int k = 0; k < 3; ++k)
    {
      l[k] = p[k] - light.Position[k];
    }
    const double distance = std::sqrt(Dot(l, l));
    for (double& c : l)
    {
      c /= distance;
    }
    attenuation = 1.0 /
      (light.Attenuation[0] + light.Attenuation[1] * distance +
        light.Attenuation[2] * distance * distance);
    if (light.ConeAngle < 90.0)
    {
      const double coneDot = Dot(l, light.Direction);
      inCone = coneDot >= std::cos(vtkMath::RadiansFromDegrees(light.ConeAngle));
      attenuation = inCone ? attenuation * std::pow(coneDot, light.Exponent) : 0.0;
    }
  }
  const double minusL[3] = { -l[0], -l[1], -l[2] };
  const double df = std::max(0.0, attenuation * Dot(n, minusL));
  const double nl = Dot(n, l);
  const double r[3] = { l[0] - 2.0 * nl * n[0], l[1] - 2.0 * nl * n[1], l[2] - 2.0 * nl * n[2] };
  const double signDf = df > 0.0 ? 1.0 : (df < 0.0 ? -1.0 : 0.0);
  double v[3] = { -p[0], -p[1], -p[2] };
  NormalizeInPlace(v);
  const double sf = signDf * attenuation * std::pow(std::max(1e-5, Dot(r, v)), specularPower);
  for (int k = 0; k < 3; ++k)
  {
    diffuse[k] += df * light.Color[k];
    specular[k] += sf * light.Color[k];
  }
  return inCone;
}

//------------------------------------------------------------------------------
// Numerical integration (transparent mode). Gauss-Kronrod 7/15 nodes and weights (QUADPACK qk15).
const double GKNodes[8] = { 0.991455371120812639206854697526329,
  0.949107912342758524526189684047851, 0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
  0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
  0.207784955007898467600689403773245, 0.000000000000000000000000000000000 };
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
double AdaptiveIntegrate(const F& f, const double pieces[][2], int numPieces, double relTol)
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
double IntegrateDensityImpl(
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
    return AdaptiveIntegrate([b2](double tau) { return b2 + tau * tau; }, pieces, numPieces,
      IntegrationTolerance);
  }
  return AdaptiveIntegrate(
    [](double) { return 1.0; }, pieces, numPieces, IntegrationTolerance);
}

// See vtkParticleReferenceRenderer::NumericalMaximumPathIntegral.
double NumericalMaximumPathIntegralImpl(int model, double f)
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
// the centre (tau = t - Tc).
struct Segment
{
  double Key;     // ray parameter of the segment's start (t_n after clipping)
  double Tc;      // ray parameter of the closest approach
  double Q[3];    // closest approach point relative to the centre
  double H;       // half chord
  double Tau0;    // start (-inf: the entry point)
  double Tau1;    // end (+inf: the exit point)
  std::uint32_t Index;
  bool Entry;     // the segment starts at the visible entry point
};

// The chord of a sphere clipped to the visible part of the ray with the GPU's rule (see the
// class description). Returns false when no part of it is visible.
inline bool MakeSegment(const RayCamera& cam, const double o[3], const double d[3],
  const SphereVC& s, double tNear, double tFar, std::uint32_t index, Segment& seg)
{
  const double oc[3] = { s.C[0] - o[0], s.C[1] - o[1], s.C[2] - o[2] };
  const double tc = Dot(oc, d);
  const double q[3] = { tc * d[0] - oc[0], tc * d[1] - oc[1], tc * d[2] - oc[2] };
  const double h2 = s.R * s.R - Dot(q, q);
  if (!(h2 > 0.0))
  {
    return false; // missed, or tangent (no length)
  }
  const double h = std::sqrt(h2);
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

// new image data of the given size and components
vtkSmartPointer<vtkImageData> NewImage(int w, int h, int components, const char* name)
{
  vtkSmartPointer<vtkImageData> image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkDoubleArray> values;
  values->SetName(name);
  values->SetNumberOfComponents(components);
  values->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  image->GetPointData()->SetScalars(values);
  return image;
}
}

//------------------------------------------------------------------------------
class vtkParticleReferenceRenderer::vtkInternals
{
public:
  RayCamera Camera;
  bool HaveCamera = false;
  // per pixel, bit i: the hit is inside the cone of the i-th spot light
  std::vector<std::uint32_t> ConeBits;
  SphereGrid Grid;
};

//------------------------------------------------------------------------------
vtkParticleReferenceRenderer::vtkParticleReferenceRenderer()
  : Internals(new vtkInternals)
{
  this->ColorImage = NewImage(0, 0, 4, "Color");
  this->DepthImage = NewImage(0, 0, 1, "Depth");
  this->ViewDepthImage = NewImage(0, 0, 1, "ViewDepth");
  this->NormalImage = NewImage(0, 0, 3, "Normal");
  this->IdImage = vtkSmartPointer<vtkIdTypeArray>::New();
  this->IdImage->SetName("ParticleId");
  this->InsideImage = vtkSmartPointer<vtkUnsignedCharArray>::New();
  this->InsideImage->SetName("Inside");
  this->TranslucentAlphaImage = NewImage(0, 0, 1, "TranslucentAlpha");
  this->AmbientOcclusionImage = NewImage(0, 0, 1, "AmbientOcclusion");
}

//------------------------------------------------------------------------------
vtkParticleReferenceRenderer::~vtkParticleReferenceRenderer()
{
  this->SetRenderer(nullptr);
  this->SetActor(nullptr);
  delete this->Internals;
}

//------------------------------------------------------------------------------
vtkImageData* vtkParticleReferenceRenderer::GetColorImage()
{
  return this->ColorImage;
}

vtkImageData* vtkParticleReferenceRenderer::GetDepthImage()
{
  return this->DepthImage;
}

vtkImageData* vtkParticleReferenceRenderer::GetViewDepthImage()
{
  return this->ViewDepthImage;
}

vtkImageData* vtkParticleReferenceRenderer::GetNormalImage()
{
  return this->NormalImage;
}

vtkImageData* vtkParticleReferenceRenderer::GetAmbientOcclusionImage()
{
  return this->AmbientOcclusionImage;
}

//------------------------------------------------------------------------------
vtkImageData* vtkParticleReferenceRenderer::GetTranslucentAlphaImage()
{
  return this->TranslucentAlphaImage;
}

//------------------------------------------------------------------------------
void vtkParticleReferenceRenderer::SetParticleAttributes(
  vtkDataArray* radii, vtkUnsignedCharArray* colors, vtkDataArray* opacities)
{
  if (!radii)
  {
    colors = nullptr;
    opacities = nullptr;
  }
  if (this->ParticleRadii != radii || this->ParticleColors != colors ||
    this->ParticleOpacities != opacities)
  {
    this->ParticleRadii = radii;
    this->ParticleColors = colors;
    this->ParticleOpacities = opacities;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkParticleReferenceRenderer::SetOpaqueLayer(vtkDataArray* rgba, vtkDataArray* windowDepth)
{
  if (!rgba || !windowDepth)
  {
    rgba = nullptr;
    windowDepth = nullptr;
  }
  if (this->OpaqueLayerColors != rgba || this->OpaqueLayerDepth != windowDepth)
  {
    this->OpaqueLayerColors = rgba;
    this->OpaqueLayerDepth = windowDepth;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
double vtkParticleReferenceRenderer::IntegrateDensity(
  int model, double hollowFraction, double radius, double impact, double tau0, double tau1)
{
  return IntegrateDensityImpl(model, hollowFraction, radius, impact, tau0, tau1);
}

double vtkParticleReferenceRenderer::NumericalMaximumPathIntegral(int model, double hollowFraction)
{
  return NumericalMaximumPathIntegralImpl(model, hollowFraction);
}

double vtkParticleReferenceRenderer::SegmentOpacity(int model, double hollowFraction,
  double radius, double impact, double tau0, double tau1, double thetaMax)
{
  if (!(thetaMax > 0.0))
  {
    return 0.0;
  }
  const double integral = IntegrateDensityImpl(model, hollowFraction, radius, impact, tau0, tau1);
  if (!(integral > 0.0))
  {
    return 0.0;
  }
  if (thetaMax >= 1.0)
  {
    return 1.0;
  }
  const bool squared = model == vtkTransparentSphereMapper::SQUARED_DISTANCE_DENSITY;
  const double scale = squared ? radius * radius * radius : radius;
  const double maximum = NumericalMaximumPathIntegralImpl(model, hollowFraction) * scale;
  if (!(maximum > 0.0))
  {
    return 0.0;
  }
  return OpacityFromOpticalDepth(-std::log1p(-thetaMax) * (integral / maximum));
}

//------------------------------------------------------------------------------
bool vtkParticleReferenceRenderer::GetPixelRay(
  double x, double y, double origin[3], double direction[3])
{
  if (!this->Internals->HaveCamera)
  {
    return false;
  }
  double tNear;
  double tFar;
  this->Internals->Camera.PixelRay(x, y, origin, direction, tNear, tFar);
  return true;
}

//------------------------------------------------------------------------------
vtkIdTypeArray* vtkParticleReferenceRenderer::GetIdImage()
{
  return this->IdImage;
}

vtkUnsignedCharArray* vtkParticleReferenceRenderer::GetInsideImage()
{
  return this->InsideImage;
}

//------------------------------------------------------------------------------
void vtkParticleReferenceRenderer::GetSurfaceIdImage(vtkIdTypeArray* surfaceIds)
{
  if (!surfaceIds)
  {
    return;
  }
  const vtkIdType n = this->IdImage->GetNumberOfTuples();
  const std::vector<std::uint32_t>& cones = this->Internals->ConeBits;
  const bool haveCones = cones.size() == static_cast<size_t>(n);
  surfaceIds->SetNumberOfComponents(1);
  surfaceIds->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkIdType id = this->IdImage->GetValue(i);
    const vtkIdType surface = 2 * id + this->InsideImage->GetValue(i);
    const vtkIdType cone = haveCones ? static_cast<vtkIdType>(cones[i]) : 0;
    surfaceIds->SetValue(i, id < 0 ? -1 : (surface << MaximumConeBits) + cone);
  }
}

//------------------------------------------------------------------------------
bool vtkParticleReferenceRenderer::Render()
{
  const double startTime = vtkTimerLog::GetUniversalTime();
  vtkInternals& internals = *this->Internals;
  internals.HaveCamera = false;
  auto fail = [this](const char* why)
  {
    vtkErrorMacro(<< why);
    this->ColorImage = NewImage(0, 0, 4, "Color");
    this->DepthImage = NewImage(0, 0, 1, "Depth");
    this->ViewDepthImage = NewImage(0, 0, 1, "ViewDepth");
    this->NormalImage = NewImage(0, 0, 3, "Normal");
    this->IdImage->SetNumberOfTuples(0);
    this->InsideImage->SetNumberOfTuples(0);
    this->TranslucentAlphaImage = NewImage(0, 0, 1, "TranslucentAlpha");
    this->AmbientOcclusionImage = NewImage(0, 0, 1, "AmbientOcclusion");
  this->AmbientOcclusionImage = NewImage(0, 0, 1, "AmbientOcclusion");
    return false;
  };
  if (!this->Renderer)
  {
    return fail("No renderer.");
  }
  if (!this->Actor)
  {
    return fail("No actor.");
  }
  vtkParticleSphereMapper* mapper = vtkParticleSphereMapper::SafeDownCast(this->Actor->GetMapper());
  if (!mapper)
  {
    return fail("The actor's mapper is not a vtkParticleSphereMapper.");
  }
  vtkCamera* camera = this->Renderer->GetActiveCamera();

  // image size and aspect ratio, as vtkOpenGLCamera::GetKeyMatrices
  int width = this->ImageSize[0];
  int height = this->ImageSize[1];
  double aspect;
  if (width > 0 && height > 0)
  {
    aspect = static_cast<double>(width) / height;
  }
  else
  {
    int x0, y0;
    this->Renderer->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
    if (width <= 0 || height <= 0)
    {
      return fail("The renderer's viewport is empty (no render window?): set ImageSize.");
    }
    aspect = this->Renderer->GetTiledAspectRatio();
  }

  // matrices (VTK: row-major, column vectors)
  RayCamera& cam = internals.Camera;
  cam.Width = width;
  cam.Height = height;
  cam.Parallel = camera->GetParallelProjection() != 0;
  vtkMatrix4x4* projection = camera->GetProjectionTransformMatrix(aspect, -1, 1);
  vtkMatrix4x4::DeepCopy(cam.P, projection);
  vtkMatrix4x4::Invert(cam.P, cam.PInv);
  internals.HaveCamera = true;
  double viewMatrix[16];
  vtkMatrix4x4::DeepCopy(viewMatrix, camera->GetModelViewTransformMatrix());
  double mcvc[16];
  vtkMatrix4x4::Multiply4x4(viewMatrix, &this->Actor->GetMatrix()->Element[0][0], mcvc);
  // normal matrix of the view transform (inverse transpose of its 3x3 part)
  double viewInverse[16];
  vtkMatrix4x4::Invert(viewMatrix, viewInverse);

  // ---- spheres in view coordinates
  if (!mapper->GetStatic() && mapper->GetInputAlgorithm())
  {
    mapper->GetInputAlgorithm()->Update(); // as the mapper does before drawing
  }
  vtkPolyData* input = mapper->GetInput();
  const vtkIdType numPts =
    (input && input->GetPoints()) ? input->GetNumberOfPoints() : static_cast<vtkIdType>(0);
  const bool given = this->ParticleRadii != nullptr; // the caller's attributes
  vtkDataArray* radii = nullptr;
  double radiusScale = 1.0;
  vtkUnsignedCharArray* colors = nullptr;
  if (given)
  {
    radii = this->ParticleRadii;
    colors = this->ParticleColors;
    const vtkDataArray* opacities = this->ParticleOpacities;
    if (radii->GetNumberOfTuples() != numPts ||
      (colors && (colors->GetNumberOfTuples() != numPts || colors->GetNumberOfComponents() != 4)) ||
      (opacities && opacities->GetNumberOfTuples() != numPts))
    {
      return fail("The particle attributes do not have one tuple (RGBA colours) per point.");
    }
    radiusScale =
      this->Actor->GetIsIdentity() ? 1.0 : std::cbrt(std::abs(this->Actor->GetMatrix()->Determinant()));
  }
  else
  {
    radii = mapper->GetParticleRadii(); // validates the input
    radiusScale = mapper->GetRadiusScaleVC(this->Actor);
    colors = numPts > 0 ? mapper->MapScalars(1.0) : nullptr;
    if (colors && (colors->GetNumberOfTuples() != numPts || colors->GetNumberOfComponents() != 4))
    {
      colors = nullptr; // cell scalars do not colour particles (as on the GPU)
    }
  }
  vtkProperty* property = this->Actor->GetProperty();
  const double opacity = property->GetOpacity();

  // ---- transparent mode: the model's parameters and Theta_a
  vtkTransparentSphereMapper* transparentMapper = vtkTransparentSphereMapper::SafeDownCast(mapper);
  const bool transparent = transparentMapper != nullptr;
  int densityModel = vtkTransparentSphereMapper::CONSTANT_DENSITY;
  double hollowFraction = 0.0;
  double volumeMix = 0.0;
  double maximumPathIntegral = 0.0; // for radius 1
  vtkDataArray* opacityArray = nullptr;
  std::vector<double> layerColors;
  std::vector<double> layerDepths;
  if (transparent)
  {
    densityModel = transparentMapper->GetDensityModel();
    hollowFraction = transparentMapper->GetHollowFraction();
    volumeMix = transparentMapper->GetVolumeMix();
    // COLUMN_OPACITY: Theta_i is the opacity of a column of L particles, i.e. I_max x L
    maximumPathIntegral = NumericalMaximumPathIntegralImpl(densityModel, hollowFraction) *
      transparentMapper->GetEffectiveColumnLayers();
    if (given)
    {
      opacityArray = this->ParticleOpacities; // nullptr: Theta_a = 1
    }
    else if (numPts > 0)
    {
      transparentMapper->GetBounds(); // prepares the opacities (see GetParticleOpacities())
      opacityArray = transparentMapper->GetParticleOpacities();
      if (!opacityArray || opacityArray->GetNumberOfTuples() != numPts)
      {
        return fail("The mapper's particle opacities do not match its input.");
      }
    }
    if (this->OpaqueLayerColors && this->OpaqueLayerDepth)
    {
      const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
      if (this->OpaqueLayerColors->GetNumberOfComponents() != 4 ||
        this->OpaqueLayerColors->GetNumberOfTuples() != pixels ||
        this->OpaqueLayerDepth->GetNumberOfComponents() != 1 ||
        this->OpaqueLayerDepth->GetNumberOfTuples() != pixels)
      {
        return fail("The opaque layer is not a 4-component colour and a 1-component depth array "
                    "of the image's size.");
      }
      layerColors.resize(4 * static_cast<size_t>(pixels));
      layerDepths.resize(static_cast<size_t>(pixels));
      for (vtkIdType i = 0; i < pixels; ++i)
      {
        for (int k = 0; k < 4; ++k)
        {
          layerColors[4 * i + k] = this->OpaqueLayerColors->GetComponent(i, k);
        }
        layerDepths[i] = this->OpaqueLayerDepth->GetComponent(i, 0);
      }
    }
  }
  // per sphere (transparent mode): Theta_i, kappa_i = -ln(1 - Theta_i), I_max at its radius
  std::vector<double> sphereTheta;
  std::vector<double> sphereKappa;
  std::vector<double> sphereMaximum;

  std::vector<double> planes;
  for (int i = 0; i < mapper->GetNumberOfClippingPlanes(); ++i)
  {
    double eq[4];
    mapper->GetClippingPlaneInDataCoords(this->Actor->GetMatrix(), i, eq);
    planes.insert(planes.end(), eq, eq + 4);
  }

  std::vector<SphereVC> spheres;
  std::vector<vtkIdType> ids;
  if (numPts > 0 && radii && radii->GetNumberOfTuples() == numPts && opacity > 0.0)
  {
    spheres.reserve(numPts);
    ids.reserve(numPts);
    vtkPoints* points = input->GetPoints();
    for (vtkIdType i = 0; i < numPts; ++i)
    {
      const double r = radii->GetComponent(i, 0) * radiusScale;
      if (!(r > 0.0) || !std::isfinite(r))
      {
        continue; // skipped particle
      }
      if (colors && colors->GetValue(4 * i + 3) == 0)
      {
        continue; // opacity 0: every fragment is discarded
      }
      double p[4] = { 0, 0, 0, 1 };
      points->GetPoint(i, p);
      bool clipped = false;
      for (size_t k = 0; k < planes.size(); k += 4)
      {
        clipped |=
          planes[k] * p[0] + planes[k + 1] * p[1] + planes[k + 2] * p[2] + planes[k + 3] < 0.0;
      }
      if (clipped)
      {
        continue;
      }
      double c[4];
      MultiplyPoint(mcvc, p, c);
      SphereVC s;
      for (int k = 0; k < 3; ++k)
      {
        s.C[k] = c[k] / c[3];
      }
      s.R = r;
      if (!std::isfinite(s.C[0]) || !std::isfinite(s.C[1]) || !std::isfinite(s.C[2]))
      {
        continue;
      }
      if (transparent)
      {
        double theta = (opacityArray ? opacityArray->GetComponent(i, 0) : 1.0) * opacity;
        if (colors)
        {
          theta *= colors->GetValue(4 * i + 3) / 255.0;
        }
        if (!(theta > 0.0))
        {
          continue; // not drawn at all
        }
        theta = std::min(theta, 1.0);
        sphereTheta.push_back(theta);
        sphereKappa.push_back(theta < 1.0 ? -std::log1p(-theta) : 0.0);
        sphereMaximum.push_back(maximumPathIntegral *
          (densityModel == vtkTransparentSphereMapper::SQUARED_DISTANCE_DENSITY ? r * r * r : r));
      }
      spheres.push_back(s);
      ids.push_back(i);
    }
  }
  if (spheres.size() > std::numeric_limits<std::uint32_t>::max())
  {
    return fail("Too many particles for the reference renderer.");
  }
  this->NumberOfSpheres = static_cast<vtkIdType>(spheres.size());

  const double gridStart = vtkTimerLog::GetUniversalTime();
  internals.Grid.Build(spheres);
  this->LastGridBuildSeconds = vtkTimerLog::GetUniversalTime() - gridStart;
  for (int k = 0; k < 3; ++k)
  {
    this->GridResolution[k] = internals.Grid.GetResolution()[k];
  }
  this->NumberOfGridReferences = static_cast<vtkIdType>(internals.Grid.GetNumberOfReferences());
  this->NumberOfLargeSpheres = static_cast<vtkIdType>(internals.Grid.GetNumberOfLarge());

  // ---- lights, as vtkOpenGLRenderer::UpdateLights / UpdateLightingUniforms
  std::vector<LightVC> lights;
  int complexity = 0;
  {
    vtkLightCollection* collection = this->Renderer->GetLights();
    vtkLight* first = nullptr;
    int count = 0;
    vtkCollectionSimpleIterator it;
    collection->InitTraversal(it);
    while (vtkLight* light = collection->GetNextLight(it))
    {
      first = first ? first : light;
      if (light->GetSwitch())
      {
        ++count;
        complexity = std::max(complexity, 1);
      }
      if (complexity == 1 && (count > 1 || light->GetLightType() != VTK_LIGHT_TYPE_HEADLIGHT))
      {
        complexity = 2;
      }
      if (complexity < 3 && light->GetPositional())
      {
        complexity = 3;
      }
    }
    const bool followCamera = this->Renderer->GetLightFollowCamera() != 0;
    vtkMatrix4x4* cameraLightMatrix = camera->GetCameraLightTransformMatrix();
    auto addLight = [&](vtkLight* light, bool isCreatedHeadlight)
    {
      LightVC l;
      double color[3] = { 1, 1, 1 };
      double intensity = 1.0;
      if (light)
      {
        light->GetDiffuseColor(color);
        intensity = light->GetIntensity();
      }
      for (int k = 0; k < 3; ++k)
      {
        l.Color[k] = color[k] * intensity;
      }
      // transformed position and focal point at render time
      double pos[4] = { 0, 0, 0, 1 };
      double focal[4] = { 0, 0, -1, 1 };
      const bool headlight = isCreatedHeadlight || light->LightTypeIsHeadlight();
      vtkMatrix4x4* lightMatrix = light ? light->GetTransformMatrix() : nullptr;
      if (followCamera && headlight)
      {
        camera->GetPosition(pos);
        camera->GetFocalPoint(focal);
      }
      else if (light)
      {
        light->GetPosition(pos);
        light->GetFocalPoint(focal);
      }
      if (followCamera && light && light->LightTypeIsCameraLight())
      {
        lightMatrix = cameraLightMatrix;
      }
      if (lightMatrix)
      {
        double tp[4];
        double tf[4];
        lightMatrix->MultiplyPoint(pos, tp);
        lightMatrix->MultiplyPoint(focal, tf);
        for (int k = 0; k < 3; ++k)
        {
          pos[k] = tp[k] / tp[3];
          focal[k] = tf[k] / tf[3];
        }
      }
      double dir[3] = { focal[0] - pos[0], focal[1] - pos[1], focal[2] - pos[2] };
      NormalizeInPlace(dir);
      // normal transform: inverse transpose of the view matrix
      for (int i = 0; i < 3; ++i)
      {
        l.Direction[i] =
          viewInverse[i] * dir[0] + viewInverse[4 + i] * dir[1] + viewInverse[8 + i] * dir[2];
      }
      NormalizeInPlace(l.Direction);
      double posVC[4];
      MultiplyPoint(viewMatrix, pos, posVC);
      for (int k = 0; k < 3; ++k)
      {
        l.Position[k] = posVC[k] / posVC[3];
      }
      if (light)
      {
        l.Positional = light->GetPositional() != 0;
        light->GetAttenuationValues(l.Attenuation);
        l.ConeAngle = light->GetConeAngle();
        l.Exponent = light->GetExponent();
      }
      lights.push_back(l);
    };
    if (count == 0 && this->Renderer->GetAutomaticLightCreation())
    {
      // the renderer creates a headlight and adds it at the end of the collection
      complexity = (!first || first->LightTypeIsHeadlight()) ? 1 : 2;
      addLight(nullptr, true);
    }
    else
    {
      collection->InitTraversal(it);
      while (vtkLight* light = collection->GetNextLight(it))
      {
        if (light->GetSwitch())
        {
          addLight(light, false);
        }
      }
    }
  }
  // lighting off, or the representation of unlit points (vtkOpenGLPolyDataMapper's rules)
  bool needLighting = true;
  if (property->GetRepresentation() == VTK_POINTS)
  {
    const bool haveNormals = input && input->GetPointData()->GetNormals() != nullptr;
    needLighting = (property->GetInterpolation() != VTK_FLAT && haveNormals) ||
      property->GetRenderPointsAsSpheres();
  }
  if (!property->GetLighting() || !needLighting || lights.empty())
  {
    complexity = 0;
  }
  this->LightingComplexity = complexity;
  this->LightingCount = complexity > 0 ? static_cast<int>(lights.size()) : 0;

  // ---- material
  double ambientK = property->GetAmbient();
  double diffuseK = property->GetDiffuse();
  double ambientColor[3];
  double diffuseColor[3];
  double specularColor[3];
  property->GetAmbientColor(ambientColor);
  property->GetDiffuseColor(diffuseColor);
  property->GetSpecularColor(specularColor);
  const double specularK = property->GetSpecular();
  for (double& c : specularColor)
  {
    c *= specularK;
  }
  const double specularPower = property->GetSpecularPower();
  double background[3];
  this->Renderer->GetBackground(background);
  const double backgroundAlpha = this->Renderer->GetBackgroundAlpha();

  // ---- outputs
  this->ColorImage = NewImage(width, height, 4, "Color");
  this->DepthImage = NewImage(width, height, 1, "Depth");
  this->ViewDepthImage = NewImage(width, height, 1, "ViewDepth");
  this->NormalImage = NewImage(width, height, 3, "Normal");
  this->IdImage->SetNumberOfComponents(1);
  this->IdImage->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  double* colorOut =
    vtkDoubleArray::SafeDownCast(this->ColorImage->GetPointData()->GetScalars())->GetPointer(0);
  double* depthOut =
    vtkDoubleArray::SafeDownCast(this->DepthImage->GetPointData()->GetScalars())->GetPointer(0);
  double* viewDepthOut =
    vtkDoubleArray::SafeDownCast(this->ViewDepthImage->GetPointData()->GetScalars())->GetPointer(0);
  double* normalOut =
    vtkDoubleArray::SafeDownCast(this->NormalImage->GetPointData()->GetScalars())->GetPointer(0);
  vtkIdType* idOut = this->IdImage->GetPointer(0);
  this->InsideImage->SetNumberOfComponents(1);
  this->InsideImage->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  unsigned char* insideOut = this->InsideImage->GetPointer(0);
  internals.ConeBits.assign(static_cast<size_t>(width) * height, 0);
  std::uint32_t* coneOut = internals.ConeBits.data();
  this->TranslucentAlphaImage = NewImage(width, height, 1, "TranslucentAlpha");
  this->AmbientOcclusionImage = NewImage(width, height, 1, "AmbientOcclusion");
  double* aoOut = vtkDoubleArray::SafeDownCast(
    this->AmbientOcclusionImage->GetPointData()->GetScalars())->GetPointer(0);
  std::fill(aoOut, aoOut + static_cast<size_t>(width) * height, 1.0);
  double* translucentAlphaOut = vtkDoubleArray::SafeDownCast(
    this->TranslucentAlphaImage->GetPointData()->GetScalars())
                                  ->GetPointer(0);

  const SphereGrid& grid = internals.Grid;
  const unsigned char* rgba = colors ? colors->GetPointer(0) : nullptr;

  // material of a particle as vtkOpenGLPolyDataMapper: ambient and diffuse colours (with their
  // coefficients) and the fragment opacity
  auto material = [&](vtkIdType pid, double amb[3], double dif[3], double& alpha)
  {
    alpha = opacity;
    if (rgba)
    {
      const unsigned char* c = rgba + 4 * pid;
      for (int k = 0; k < 3; ++k)
      {
        amb[k] = ambientK * (c[k] / 255.0);
        dif[k] = diffuseK * (c[k] / 255.0);
      }
      alpha *= c[3] / 255.0;
    }
    else
    {
      for (int k = 0; k < 3; ++k)
      {
        amb[k] = ambientK * ambientColor[k];
        dif[k] = diffuseK * diffuseColor[k];
      }
    }
  };
  // VTK's lit colour (not clamped) at the surface point p (view coordinates) with unit normal n;
  // returns the bits of the spot cones containing p
  auto shade = [&](const double n[3], const double p[3], const double amb[3],
                 const double dif[3], double color[3]) -> std::uint32_t
  {
    std::uint32_t cones = 0;
    if (complexity == 0)
    {
      for (int k = 0; k < 3; ++k)
      {
        color[k] = amb[k] + dif[k];
      }
      return cones;
    }
    double diffuse[3] = { 0, 0, 0 };
    double specular[3] = { 0, 0, 0 };
    unsigned int bit = 0;
    for (const LightVC& light : lights)
    {
      if (complexity == 1)
      {
        // Lighting.glsl, prHeadlight
        const double df = std::max(0.000001, n[2]);
        const double sf = std::pow(df, specularPower);
        for (int k = 0; k < 3; ++k)
        {
          diffuse[k] += df * light.Color[k];
          specular[k] += sf * light.Color[k];
        }
      }
      else
      {
        const bool inCone =
          SceneLight(n, p, light, complexity == 3, specularPower, diffuse, specular);
        if (complexity == 3 && light.Positional && light.ConeAngle < 90.0 &&
          bit < MaximumConeBits)
        {
          cones |= (inCone ? 1u : 0u) << bit++;
        }
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      color[k] = amb[k] + diffuse[k] * dif[k] + specular[k] * specularColor[k];
    }
    return cones;
  };

  if (transparent)
  {
    const double inf = std::numeric_limits<double>::infinity();
    const bool haveLayer = !layerDepths.empty();
    vtkSMPTools::For(0, height,
      [&](vtkIdType rowBegin, vtkIdType rowEnd)
      {
        std::vector<std::uint32_t> candidates;
        std::vector<Segment> segments;
        for (vtkIdType y = rowBegin; y < rowEnd; ++y)
        {
          for (int x = 0; x < width; ++x)
          {
            const size_t pixel = static_cast<size_t>(y) * width + x;
            double o[3];
            double d[3];
            double tNear;
            double tFar;
            cam.PixelRay(x + 0.5, y + 0.5, o, d, tNear, tFar);

            // what lies behind the particles: background, opaque layer or opaque particle
            double back[4] = { background[0], background[1], background[2], backgroundAlpha };
            double tStop = inf;
            if (haveLayer)
            {
              const double depth = layerDepths[pixel];
              if (depth >= 0.0 && depth < 1.0)
              {
                const double t = cam.WindowDepthToT(x + 0.5, y + 0.5, depth, o, d);
                if (std::isfinite(t))
                {
                  tStop = t;
                  std::copy(&layerColors[4 * pixel], &layerColors[4 * pixel] + 4, back);
                }
              }
            }
            const double tMin = tNear - 1e-9 * std::abs(tNear) - 1e-300;
            double tMax = tFar + 1e-9 * std::abs(tFar) + 1e-300;
            if (tStop < inf)
            {
              tMax = std::min(tMax, tStop + 1e-9 * std::abs(tStop) + 1e-300);
            }
            candidates.clear();
            grid.Collect(o, d, tMin, tMax, candidates);
            std::sort(candidates.begin(), candidates.end());
            candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

            // opaque particles: the opaque mode's visible surface; translucent ones: segments
            Hit opaqueHit;
            segments.clear();
            for (std::uint32_t i : candidates)
            {
              if (sphereTheta[i] >= 1.0)
              {
                IntersectSphere(cam, o, d, spheres[i], i, opaqueHit);
              }
              else
              {
                Segment seg;
                if (MakeSegment(cam, o, d, spheres[i], tNear, tFar, i, seg))
                {
                  segments.push_back(seg);
                }
              }
            }

            // front-most composited particle, for the depth/id/normal images
            double depthFront = 1.0;
            double viewDepthFront = -1.0;
            vtkIdType idFront = -1;
            unsigned char insideFront = 0;
            std::uint32_t conesFront = 0;
            double normalFront[3] = { 0, 0, 0 };
            double tOpaqueFront = inf;
            if (opaqueHit.Index >= 0)
            {
              const SphereVC& s = spheres[opaqueHit.Index];
              const vtkIdType pid = ids[opaqueHit.Index];
              double n[3];
              for (int k = 0; k < 3; ++k)
              {
                n[k] = (opaqueHit.Inside ? -opaqueHit.Rel[k] : opaqueHit.Rel[k]) / s.R;
              }
              const double p[3] = { s.C[0] + opaqueHit.Rel[0], s.C[1] + opaqueHit.Rel[1],
                s.C[2] + opaqueHit.Rel[2] };
              double amb[3];
              double dif[3];
              double alpha;
              material(pid, amb, dif, alpha);
              double color[3];
              const std::uint32_t cones = shade(n, p, amb, dif, color);
              const bool finite = std::isfinite(color[0]) && std::isfinite(color[1]) &&
                std::isfinite(color[2]) && std::isfinite(alpha);
              // otherwise the GPU discards the fragment; at a tie the particle (drawn later,
              // GL_LEQUAL) wins over the opaque layer
              if (finite && alpha > 0.0 && opaqueHit.T <= tStop)
              {
                tStop = opaqueHit.T;
                for (int k = 0; k < 3; ++k)
                {
                  back[k] = std::min(1.0, std::max(0.0, color[k]));
                }
                back[3] = std::min(1.0, std::max(0.0, alpha));
                tOpaqueFront = opaqueHit.T;
                depthFront = opaqueHit.Depth;
                viewDepthFront = opaqueHit.T;
                idFront = pid;
                insideFront = opaqueHit.Inside ? 1 : 0;
                conesFront = cones;
                std::copy(n, n + 3, normalFront);
              }
            }

            // cut the segments at the opaque depth, order them by their start
            size_t kept = 0;
            for (Segment& seg : segments)
            {
              if (seg.Key < tStop)
              {
                seg.Tau1 = std::min(seg.Tau1, tStop - seg.Tc);
                segments[kept++] = seg;
              }
            }
            segments.resize(kept);
            std::sort(segments.begin(), segments.end(),
              [&](const Segment& a, const Segment& b)
              { return a.Key < b.Key || (a.Key == b.Key && ids[a.Index] < ids[b.Index]); });

            // front-to-back compositing
            double accumulated[3] = { 0, 0, 0 };
            double transmittance = 1.0;
            bool haveFront = false;
            for (const Segment& seg : segments)
            {
              const SphereVC& s = spheres[seg.Index];
              const double impact = std::sqrt(Dot(seg.Q, seg.Q));
              const double integral =
                IntegrateDensityImpl(densityModel, hollowFraction, s.R, impact, seg.Tau0, seg.Tau1);
              const double opticalDepth =
                sphereKappa[seg.Index] * (integral / sphereMaximum[seg.Index]);
              const double theta = OpacityFromOpticalDepth(opticalDepth);
              if (!(theta > 0.0) || !std::isfinite(opticalDepth))
              {
                continue;
              }
              const vtkIdType pid = ids[seg.Index];
              double amb[3];
              double dif[3];
              double alpha;
              material(pid, amb, dif, alpha);
              double emitted[3];
              std::uint32_t cones = 0;
              double n[3] = { 0, 0, 0 };
              double depth = 0.0;
              if (seg.Entry)
              {
                double rel[3];
                double p[3];
                for (int k = 0; k < 3; ++k)
                {
                  rel[k] = seg.Q[k] - seg.H * d[k];
                  n[k] = rel[k] / s.R;
                  p[k] = s.C[k] + rel[k];
                }
                double surface[3];
                cones = shade(n, p, amb, dif, surface);
                if (!std::isfinite(surface[0]) || !std::isfinite(surface[1]) ||
                  !std::isfinite(surface[2]))
                {
                  continue; // discarded
                }
                for (int k = 0; k < 3; ++k)
                {
                  emitted[k] = theta * ((1.0 - volumeMix) * surface[k] + volumeMix * dif[k]);
                }
                cam.Depth(p, depth);
              }
              else
              {
                for (int k = 0; k < 3; ++k)
                {
                  emitted[k] = theta * dif[k];
                }
                double p[3];
                for (int k = 0; k < 3; ++k)
                {
                  p[k] = s.C[k] + seg.Q[k] + seg.Tau0 * d[k];
                }
                if (!cam.Depth(p, depth))
                {
                  depth = 0.0; // the start is the near plane
                }
              }
              if (!haveFront)
              {
                haveFront = true;
                depthFront = depth;
                viewDepthFront = seg.Key;
                idFront = pid;
                insideFront = seg.Entry ? 0 : 1;
                conesFront = cones;
                std::copy(n, n + 3, normalFront);
              }
              for (int k = 0; k < 3; ++k)
              {
                accumulated[k] += transmittance * emitted[k];
              }
              transmittance *= std::exp(-opticalDepth);
              if (transmittance == 0.0)
              {
                break;
              }
            }
            if (!haveFront && tOpaqueFront == inf)
            {
              idFront = -1;
            }
            const double particleOpacity = tOpaqueFront < inf ? 1.0 : 1.0 - transmittance;

            double* out = colorOut + 4 * pixel;
            for (int k = 0; k < 3; ++k)
            {
              out[k] = std::min(1.0, std::max(0.0, accumulated[k] + transmittance * back[k]));
            }
            out[3] = std::min(1.0, std::max(0.0, 1.0 - transmittance * (1.0 - back[3])));
            depthOut[pixel] = depthFront;
            viewDepthOut[pixel] = viewDepthFront;
            idOut[pixel] = idFront;
            insideOut[pixel] = insideFront;
            coneOut[pixel] = idFront >= 0 ? conesFront : 0;
            std::copy(normalFront, normalFront + 3, normalOut + 3 * pixel);
            translucentAlphaOut[pixel] = particleOpacity;
          }
        }
      });
    this->LastRenderSeconds = vtkTimerLog::GetUniversalTime() - startTime;
    this->Modified();
    return true;
  }

  // Ray-traced ambient occlusion: cosine-distributed rays from a visible point, binary
  // visibility against the real spheres (all of them, the visible one excepted) up to the
  // distance.
  const int aoSamples = this->AmbientOcclusionSamples;
  double aoDistance = this->AmbientOcclusionDistance;
  if (aoSamples > 0 && !(aoDistance > 0.0))
  {
    double sum = 0.0;
    for (const SphereVC& sv : spheres)
    {
      sum += sv.R;
    }
    aoDistance = spheres.empty() ? 1.0 : 4.0 * sum / spheres.size();
  }
  auto ambientOcclusion = [&](const double p[3], const double n[3], vtkIdType own, int px,
                            int py, std::vector<std::uint32_t>& candidates) -> double {
    // orthonormal basis around n
    double t1[3];
    const double helper[3] = { std::abs(n[0]) < 0.9 ? 1.0 : 0.0, std::abs(n[0]) < 0.9 ? 0.0 : 1.0,
      0.0 };
    vtkMath::Cross(n, helper, t1);
    vtkMath::Normalize(t1);
    double t2[3];
    vtkMath::Cross(n, t1, t2);
    // per-pixel Cranley-Patterson rotation from a hash of the pixel
    std::uint32_t h = static_cast<std::uint32_t>(px) * 73856093u ^
      static_cast<std::uint32_t>(py) * 19349663u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    const double rotU = (h & 0xffffu) / 65536.0;
    const double rotV = (h >> 16) / 65536.0;
    int free = 0;
    for (int k = 0; k < aoSamples; ++k)
    {
      // Hammersley point (k / N, radical inverse of k), rotated
      std::uint32_t bits = static_cast<std::uint32_t>(k);
      bits = (bits << 16u) | (bits >> 16u);
      bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
      bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
      bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
      bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
      double u = (k + 0.5) / aoSamples + rotU;
      double w = bits * 2.3283064365386963e-10 + rotV;
      u -= std::floor(u);
      w -= std::floor(w);
      // cosine-weighted direction
      const double sinTheta = std::sqrt(u);
      const double cosTheta = std::sqrt(std::max(0.0, 1.0 - u));
      const double phi = 2.0 * vtkMath::Pi() * w;
      double dir[3];
      for (int c = 0; c < 3; ++c)
      {
        dir[c] = sinTheta * (std::cos(phi) * t1[c] + std::sin(phi) * t2[c]) + cosTheta * n[c];
      }
      candidates.clear();
      grid.Collect(p, dir, 0.0, aoDistance, candidates);
      bool blocked = false;
      for (std::uint32_t j : candidates)
      {
        if (static_cast<vtkIdType>(j) == own)
        {
          continue;
        }
        const SphereVC& sv = spheres[j];
        const double oc[3] = { p[0] - sv.C[0], p[1] - sv.C[1], p[2] - sv.C[2] };
        const double b = vtkMath::Dot(oc, dir);
        // closest approach relative to the centre (no cancellation), as everywhere here
        const double q[3] = { oc[0] - b * dir[0], oc[1] - b * dir[1], oc[2] - b * dir[2] };
        const double h2 = sv.R * sv.R - vtkMath::Dot(q, q);
        if (!(h2 >= 0.0))
        {
          continue;
        }
        const double hh = std::sqrt(h2);
        const double tIn = -b - hh;
        const double tOut = -b + hh;
        if (tOut > 1e-9 * sv.R && tIn < aoDistance)
        {
          blocked = true;
          break;
        }
      }
      free += blocked ? 0 : 1;
    }
    return static_cast<double>(free) / aoSamples;
  };

  vtkSMPTools::For(0, height,
    [&](vtkIdType rowBegin, vtkIdType rowEnd)
    {
      std::vector<std::uint32_t> aoCandidates;
      for (vtkIdType y = rowBegin; y < rowEnd; ++y)
      {
        for (int x = 0; x < width; ++x)
        {
          const size_t pixel = static_cast<size_t>(y) * width + x;
          double o[3];
          double d[3];
          double tNear;
          double tFar;
          cam.PixelRay(x + 0.5, y + 0.5, o, d, tNear, tFar);
          Hit hit;
          const double tMin = tNear - 1e-9 * std::abs(tNear) - 1e-300;
          const double tMax = tFar + 1e-9 * std::abs(tFar) + 1e-300;
          grid.Trace(cam, spheres, o, d, tMin, tMax, hit);

          double rgbaOut[4] = { background[0], background[1], background[2], backgroundAlpha };
          double depth = 1.0;
          double viewDepth = -1.0;
          vtkIdType id = -1;
          unsigned char inside = 0;
          std::uint32_t cones = 0;
          double normal[3] = { 0, 0, 0 };
          if (hit.Index >= 0)
          {
            const SphereVC& s = spheres[hit.Index];
            const vtkIdType pid = ids[hit.Index];
            double n[3];
            for (int k = 0; k < 3; ++k)
            {
              n[k] = (hit.Inside ? -hit.Rel[k] : hit.Rel[k]) / s.R;
            }
            const double p[3] = { s.C[0] + hit.Rel[0], s.C[1] + hit.Rel[1], s.C[2] + hit.Rel[2] };
            double amb[3];
            double dif[3];
            double alpha;
            material(pid, amb, dif, alpha);
            double color[3];
            cones = shade(n, p, amb, dif, color);
            double occlusion = 1.0;
            if (aoSamples > 0)
            {
              occlusion = ambientOcclusion(p, n, hit.Index, x, y, aoCandidates);
              if (this->ApplyAmbientOcclusion)
              {
                for (int k = 0; k < 3; ++k)
                {
                  color[k] *= occlusion;
                }
              }
            }
            const bool finite = std::isfinite(color[0]) && std::isfinite(color[1]) &&
              std::isfinite(color[2]) && std::isfinite(alpha);
            if (finite && alpha > 0.0) // otherwise the GPU discards the fragment
            {
              aoOut[pixel] = occlusion;
              for (int k = 0; k < 3; ++k)
              {
                rgbaOut[k] = std::min(1.0, std::max(0.0, color[k]));
              }
              rgbaOut[3] = std::min(1.0, std::max(0.0, alpha));
              depth = hit.Depth;
              viewDepth = hit.T;
              id = pid;
              inside = hit.Inside ? 1 : 0;
              std::copy(n, n + 3, normal);
            }
          }
          std::copy(rgbaOut, rgbaOut + 4, colorOut + 4 * pixel);
          depthOut[pixel] = depth;
          viewDepthOut[pixel] = viewDepth;
          idOut[pixel] = id;
          insideOut[pixel] = inside;
          coneOut[pixel] = id >= 0 ? cones : 0;
          std::copy(normal, normal + 3, normalOut + 3 * pixel);
          translucentAlphaOut[pixel] = id >= 0 ? 1.0 : 0.0;
        }
      }
    });

  this->LastRenderSeconds = vtkTimerLog::GetUniversalTime() - startTime;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleReferenceRenderer::WindowDepthToViewDepth(
  vtkImageData* windowDepth, vtkImageData* viewDepth)
{
  const vtkInternals& internals = *this->Internals;
  if (!internals.HaveCamera || !windowDepth || !viewDepth)
  {
    vtkErrorMacro(<< "Nothing rendered yet, or no image.");
    return false;
  }
  const RayCamera& cam = internals.Camera;
  int dims[3];
  windowDepth->GetDimensions(dims);
  vtkDataArray* in = windowDepth->GetPointData()->GetScalars();
  if (dims[0] != cam.Width || dims[1] != cam.Height || !in || in->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro(<< "The depth image is not a one-component " << cam.Width << "x" << cam.Height
                  << " image.");
    return false;
  }
  vtkSmartPointer<vtkImageData> out = NewImage(cam.Width, cam.Height, 1, "ViewDepth");
  double* values = vtkDoubleArray::SafeDownCast(out->GetPointData()->GetScalars())->GetPointer(0);
  vtkSMPTools::For(0, cam.Height,
    [&](vtkIdType rowBegin, vtkIdType rowEnd)
    {
      for (vtkIdType y = rowBegin; y < rowEnd; ++y)
      {
        for (int x = 0; x < cam.Width; ++x)
        {
          const vtkIdType pixel = y * cam.Width + x;
          const double depth = in->GetComponent(pixel, 0);
          if (!(depth < 1.0) || !(depth >= 0.0))
          {
            values[pixel] = -1.0;
            continue;
          }
          double o[3];
          double d[3];
          double tNear;
          double tFar;
          cam.PixelRay(x + 0.5, y + 0.5, o, d, tNear, tFar);
          const double t = cam.WindowDepthToT(x + 0.5, y + 0.5, depth, o, d);
          values[pixel] = std::isfinite(t) ? t : -1.0;
        }
      }
    });
  viewDepth->ShallowCopy(out);
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "Actor: " << this->Actor << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " " << this->ImageSize[1] << "\n";
  os << indent << "ParticleAttributes: " << (this->ParticleRadii ? "given" : "the mapper's")
     << "\n";
  os << indent << "LightingComplexity: " << this->LightingComplexity << "\n";
  os << indent << "LightingCount: " << this->LightingCount << "\n";
  os << indent << "NumberOfSpheres: " << this->NumberOfSpheres << "\n";
  os << indent << "GridResolution: " << this->GridResolution[0] << " " << this->GridResolution[1]
     << " " << this->GridResolution[2] << "\n";
  os << indent << "NumberOfGridReferences: " << this->NumberOfGridReferences << "\n";
  os << indent << "NumberOfLargeSpheres: " << this->NumberOfLargeSpheres << "\n";
  os << indent << "LastRenderSeconds: " << this->LastRenderSeconds << "\n";
  os << indent << "LastGridBuildSeconds: " << this->LastGridBuildSeconds << "\n";
  os << indent << "OpaqueLayer: " << (this->OpaqueLayerColors ? "set" : "none") << "\n";
}
