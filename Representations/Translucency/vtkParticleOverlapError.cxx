#include "vtkParticleOverlapError.h"

#include "vtkCamera.h"
#include "vtkParticleCellList.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
double vtkParticleOverlapError::Amplitude(const Sphere& a, const Sphere& b, double pathIntegral,
  double shadingRange, double* lensRadius, double* lensCentre)
{
  double centres[3];
  double distance2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    centres[k] = b.Centre[k] - a.Centre[k];
    distance2 += centres[k] * centres[k];
  }
  const double distance = std::sqrt(distance2);
  const double depth = a.Radius + b.Radius - distance; // penetration along the centre line
  if (!(depth > 0.0))
  {
    return 0.0;
  }
  const double smaller = std::min(a.Radius, b.Radius);
  // the lens circle: at x from a's centre along the centre line, radius sqrt(Ra^2 - x^2); one
  // sphere inside the other: the smaller whole
  double circle = smaller;
  double x = 0.0;
  if (distance > std::abs(a.Radius - b.Radius))
  {
    x = (distance2 + a.Radius * a.Radius - b.Radius * b.Radius) / (2.0 * distance);
    circle = std::sqrt(std::max(0.0, a.Radius * a.Radius - x * x));
  }
  else
  {
    x = a.Radius <= b.Radius ? 0.0 : distance;
  }
  const double chord = std::min(std::max(depth, 2.0 * circle), 2.0 * smaller);
  auto lensOpacity = [&](const Sphere& s)
  { return -std::expm1(-s.OpticalDepth * std::min(1.0, chord / (pathIntegral * s.Radius))); };
  double contrast = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    contrast = std::max(contrast, std::abs(a.Colour[k] - b.Colour[k]));
  }
  if (lensRadius)
  {
    *lensRadius = std::max(circle, 0.5 * std::min(depth, 2.0 * smaller));
  }
  if (lensCentre)
  {
    const double t = distance > 0.0 ? x / distance : 0.0;
    for (int k = 0; k < 3; ++k)
    {
      lensCentre[k] = a.Centre[k] + t * centres[k];
    }
  }
  return lensOpacity(a) * lensOpacity(b) * (contrast + shadingRange);
}

//------------------------------------------------------------------------------
void vtkParticleOverlapError::Build(const std::vector<Sphere>& spheres, double pathIntegral,
  double shadingRange, double tolerance, double floor)
{
  this->Lenses.clear();
  this->LargestAmplitude = 0.0;
  const vtkIdType count = static_cast<vtkIdType>(spheres.size());
  double largest = 0.0;
  std::vector<double> xyz(3 * spheres.size());
  std::vector<float> binned(spheres.size(), 1.0f);
  for (vtkIdType i = 0; i < count; ++i)
  {
    std::copy(spheres[i].Centre, spheres[i].Centre + 3, xyz.begin() + 3 * i);
    largest = std::max(largest, spheres[i].Radius);
  }
  const double edge = 2.0 * largest;
  if (count < 2 || !(edge > 0.0) || !std::isfinite(edge))
  {
    return;
  }
  // every penetrating pair lies within 2 max(R) (vtkParticleCellList: 27 cells around each)
  vtkParticleCellList cells;
  cells.Build(xyz.data(), count, binned.data(), edge);
  struct Found
  {
    std::vector<Lens> Lenses;
    double Largest = 0.0;
  };
  vtkSMPThreadLocal<Found> found;
  vtkSMPTools::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      Found& mine = found.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        cells.ForEachCandidate(i,
          [&](vtkIdType j, double d2)
          {
            const Sphere& a = spheres[i];
            const Sphere& b = spheres[j];
            const double reach = a.Radius + b.Radius - floor * std::min(a.Radius, b.Radius);
            if (j < i || !(d2 < reach * reach * (1.0 - 1e-12)))
            {
              return;
            }
            Lens lens;
            const double amplitude =
              Amplitude(a, b, pathIntegral, shadingRange, &lens.Radius, lens.Centre);
            mine.Largest = std::max(mine.Largest, amplitude);
            if (amplitude > tolerance)
            {
              mine.Lenses.push_back(lens);
            }
          });
      }
    });
  for (Found& mine : found)
  {
    this->Lenses.insert(this->Lenses.end(), mine.Lenses.begin(), mine.Lenses.end());
    this->LargestAmplitude = std::max(this->LargestAmplitude, mine.Largest);
  }
}

//------------------------------------------------------------------------------
double vtkParticleOverlapError::EstimatePixels(vtkRenderer* ren) const
{
  vtkCamera* camera = ren ? ren->GetActiveCamera() : nullptr;
  int width = 0;
  int height = 0;
  int x0 = 0;
  int y0 = 0;
  if (!camera || this->Lenses.empty())
  {
    return 0.0;
  }
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  double eye[3];
  double direction[3];
  double up[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(direction);
  camera->GetViewUp(up);
  const bool parallel = camera->GetParallelProjection() != 0;
  // the view angle spans the height, or the width with UseHorizontalViewAngle
  const double span = camera->GetUseHorizontalViewAngle() ? width : height;
  const double pixelsPerUnit = parallel
    ? height / (2.0 * camera->GetParallelScale())
    : span / (2.0 * std::tan(0.5 * camera->GetViewAngle() * 3.14159265358979323846 / 180.0));
  return this->EstimatePixels(eye, direction, up, pixelsPerUnit, parallel, width, height);
}

//------------------------------------------------------------------------------
double vtkParticleOverlapError::EstimatePixels(const double eye[3], const double direction[3],
  const double up[3], double pixelsPerUnit, bool parallel, int width, int height) const
{
  const double viewportPixels = static_cast<double>(width) * static_cast<double>(height);
  // the view's right and (orthogonalised) up axes
  double right[3] = { direction[1] * up[2] - direction[2] * up[1],
    direction[2] * up[0] - direction[0] * up[2], direction[0] * up[1] - direction[1] * up[0] };
  const double rightLength =
    std::sqrt(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
  const bool haveAxes = rightLength > 0.0 && pixelsPerUnit > 0.0;
  double upward[3] = { 0.0, 0.0, 0.0 };
  if (haveAxes)
  {
    for (double& c : right)
    {
      c /= rightLength;
    }
    upward[0] = right[1] * direction[2] - right[2] * direction[1];
    upward[1] = right[2] * direction[0] - right[0] * direction[2];
    upward[2] = right[0] * direction[1] - right[1] * direction[0];
  }
  // the frustum's half extents: tangents of the half angles (perspective) or world units
  // (parallel)
  const double halfX = haveAxes ? 0.5 * width / pixelsPerUnit : 0.0;
  const double halfY = haveAxes ? 0.5 * height / pixelsPerUnit : 0.0;
  auto outside = [&](const Lens& lens, double along)
  {
    if (!haveAxes)
    {
      return false;
    }
    const double v[3] = { lens.Centre[0] - eye[0], lens.Centre[1] - eye[1],
      lens.Centre[2] - eye[2] };
    const double x = std::abs(v[0] * right[0] + v[1] * right[1] + v[2] * right[2]);
    const double y = std::abs(v[0] * upward[0] + v[1] * upward[1] + v[2] * upward[2]);
    if (parallel)
    {
      return x - lens.Radius > halfX || y - lens.Radius > halfY;
    }
    // beyond a side plane x = t along (signed distance (x - t along) / sqrt(1 + t^2))
    return x - halfX * along > lens.Radius * std::sqrt(1.0 + halfX * halfX) ||
      y - halfY * along > lens.Radius * std::sqrt(1.0 + halfY * halfY);
  };
  double pixels = 0.0;
  for (const Lens& lens : this->Lenses)
  {
    const double along = (lens.Centre[0] - eye[0]) * direction[0] +
      (lens.Centre[1] - eye[1]) * direction[1] + (lens.Centre[2] - eye[2]) * direction[2];
    if (!parallel && !(along + lens.Radius > 0.0))
    {
      continue; // behind the camera
    }
    if (outside(lens, along))
    {
      continue; // beside the view
    }
    // a lens the eye is in or near covers the view
    const double scale = parallel ? pixelsPerUnit : pixelsPerUnit / std::max(along, 1e-300);
    const double r = lens.Radius * scale;
    pixels += std::min(3.14159265358979323846 * r * r, viewportPixels);
    if (pixels >= viewportPixels)
    {
      return viewportPixels;
    }
  }
  return pixels;
}
