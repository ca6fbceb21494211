#include "vtkSNDFViewPlacement.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"

#include <cmath>

//------------------------------------------------------------------------------
void vtkSNDFViewPlacement::Corner(
  vtkCamera* camera, int width, int height, double corner[2], double& along) const
{
  const double* focal = camera->GetFocalPoint();
  double plane[3] = { 0.0, 0.0, 0.0 };
  for (int row = 0; row < 3; ++row)
  {
    for (int a = 0; a < 3; ++a)
    {
      plane[row] += this->Rotation[row][a] * focal[a];
    }
  }
  const double* centre = camera->GetWindowCenter();
  const double scale = camera->GetParallelScale();
  corner[0] = plane[0] + (centre[0] - 1.0) * scale * width / height;
  corner[1] = plane[1] + (centre[1] - 1.0) * scale;
  along = plane[2];
}

//------------------------------------------------------------------------------
void vtkSNDFViewPlacement::Start(vtkCamera* camera, int width, int height)
{
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  for (int row = 0; row < 3; ++row)
  {
    for (int a = 0; a < 3; ++a)
    {
      this->Rotation[row][a] = view->GetElement(row, a);
    }
    this->Offset[row] = camera->GetPosition()[row] - camera->GetFocalPoint()[row];
  }
  this->TexelSize =
    camera->GetParallelProjection() ? 2.0 * camera->GetParallelScale() / height : 1.0;
  this->Corner(camera, width, height, this->Plane, this->Along);
}

//------------------------------------------------------------------------------
bool vtkSNDFViewPlacement::Place(vtkCamera* camera, int width, int height, int slots,
  bool allowBetween, vtkSNDFTileCache::Placement& placed, Between& between) const
{
  between = Between();
  if (!camera->GetParallelProjection())
  {
    placed = vtkSNDFTileCache::Placement();
    return true;
  }
  const double pixel = 2.0 * camera->GetParallelScale() / height;
  const double lod = std::log2(pixel / this->TexelSize);
  if (!std::isfinite(lod))
  {
    return false;
  }
  between.Active = std::abs(lod - std::round(lod)) > 1e-6;
  if (between.Active && !allowBetween)
  {
    return false;
  }
  // (between two levels: the finer one, its texels at most a pixel wide)
  const long level = between.Active ? static_cast<long>(std::floor(lod)) : std::lround(lod);
  if (level < vtkSNDFTileCache::MinimumLevel || level > vtkSNDFTileCache::MaximumLevel)
  {
    return false;
  }
  double reach = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    reach += this->Offset[a] * this->Offset[a];
  }
  reach = std::sqrt(reach);
  for (int a = 0; a < 3; ++a)
  {
    const double offset = camera->GetPosition()[a] - camera->GetFocalPoint()[a];
    if (std::abs(offset - this->Offset[a]) > 1e-9 * reach + 1e-6 * this->TexelSize)
    {
      return false;
    }
  }
  double corner[2];
  double along;
  this->Corner(camera, width, height, corner, along);
  if (std::abs(along - this->Along) > 1e-3 * this->TexelSize)
  {
    return false;
  }
  placed.Level = static_cast<int>(level);
  const long long texel = 1LL << (level + 8);
  for (int a = 0; a < 2; ++a)
  {
    // in 1/256 of a level-0 texel
    const double position = 256.0 * (corner[a] - this->Plane[a]) / this->TexelSize;
    if (!(std::abs(position) < 1e15))
    {
      return false;
    }
    if (between.Active)
    {
      const double at = position / static_cast<double>(texel); // in texels of the level
      placed.Phase[a] = 0;
      placed.Origin[a] = static_cast<long long>(std::floor(at)) - 1;
      between.Offset[a] = at - static_cast<double>(placed.Origin[a]);
      continue;
    }
    // (a grid of 1/256 pixel: the texels lie within 1/512 level-0 pixel of the view's pixels)
    const long long whole = std::llround(position);
    placed.Phase[a] = ((whole % texel) + texel) % texel;
    placed.Origin[a] = (whole - placed.Phase[a]) / texel;
  }
  if (between.Active)
  {
    between.Scale = pixel / (this->TexelSize * std::ldexp(1.0, static_cast<int>(level)));
    between.Size[0] = static_cast<int>(std::ceil(between.Offset[0] + width * between.Scale)) + 1;
    between.Size[1] = static_cast<int>(std::ceil(between.Offset[1] + height * between.Scale)) + 1;
    if (vtkSNDFTileCache::GetTilesForView(between.Size[0], between.Size[1]) > slots)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSNDFViewPlacement::SamplingWindow(vtkCamera* camera,
  const vtkSNDFTileCache::Placement& placed, int texelsX, int texelsY, double& scale,
  double centre[2]) const
{
  const double texel = this->TexelSize * std::ldexp(1.0, placed.Level);
  scale = 0.5 * texelsY * texel;
  const double aspect = static_cast<double>(texelsX) / texelsY;
  const double* focal = camera->GetFocalPoint();
  for (int a = 0; a < 2; ++a)
  {
    double plane = 0.0; // the focal point in the frame's rotation
    for (int k = 0; k < 3; ++k)
    {
      plane += this->Rotation[a][k] * focal[k];
    }
    const double corner = this->Plane[a] + static_cast<double>(placed.Origin[a]) * texel;
    centre[a] = (corner - plane) / (scale * (a == 0 ? aspect : 1.0)) + 1.0;
  }
}
