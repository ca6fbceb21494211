// TestSNDFViewPlacement: vtkSNDFViewPlacement alone (no OpenGL): where a view lies in the S-MIP of
// vtkSNDFRenderPass, exactly.
//   a) the view that started the frame: level 0, origin 0, phase 0;
//   b) pans by whole pixels shift the origin, by part of a pixel set the phase (1/256 texel),
//      negative pans included;
//   c) zooms by powers of two change the level (out and in), with the origin of the new grid;
//   d) a zoom between two levels is placed at the finer level with its rectangle of texels,
//      only where allowed, and not beyond the cache's slots;
//   e) SamplingWindow's camera has the placed level's texels as its pixels, at the placed origin;
//   f) moves that leave the frame (dolly, a new view direction, the focal point moved along the
//      view) and a degenerate scale are not placed; a perspective view takes the default.
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkSNDFTileCache.h"
#include "vtkSNDFViewPlacement.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++Failures;
  }
}

// a parallel camera looking down -z at (x, y, 0) from distance 10, parallel scale `scale`
void Parallel(vtkCamera* camera, double x, double y, double scale)
{
  camera->SetParallelProjection(1);
  camera->SetFocalPoint(x, y, 0.0);
  camera->SetPosition(x, y, 10.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(scale);
  camera->SetWindowCenter(0.0, 0.0);
}

bool Same(const vtkSNDFTileCache::Placement& p, int level, long long ox, long long oy, long long px,
  long long py)
{
  return p.Level == level && p.Origin[0] == ox && p.Origin[1] == oy && p.Phase[0] == px &&
    p.Phase[1] == py;
}
}

int TestSNDFViewPlacement(int, char*[])
{
  const int width = 200;
  const int height = 100;
  const int slots = 1 << 20;
  vtkNew<vtkCamera> camera;
  Parallel(camera, 0.0, 0.0, 10.0); // a pixel 2 * 10 / 100 = 0.2 wide
  vtkSNDFViewPlacement view;
  view.Start(camera, width, height);
  Check(view.GetTexelSize() == 0.2, "level-0 texel = the starting view's pixel (0.2)");
  vtkSNDFTileCache::Placement placed;
  vtkSNDFViewPlacement::Between between;

  // a) the starting view
  Check(view.Place(camera, width, height, slots, true, placed, between) &&
      Same(placed, 0, 0, 0, 0, 0) && !between.Active,
    "a) the starting view: level 0, origin 0, phase 0");

  // b) pans: 3 pixels right (origin 3), half a pixel right (phase 128), 2.5 pixels down
  Parallel(camera, 0.6, 0.0, 10.0);
  Check(
    view.Place(camera, width, height, slots, true, placed, between) && Same(placed, 0, 3, 0, 0, 0),
    "b) a pan by 3 pixels: origin 3");
  Parallel(camera, 0.1, 0.0, 10.0);
  Check(view.Place(camera, width, height, slots, true, placed, between) &&
      Same(placed, 0, 0, 0, 128, 0),
    "b) a pan by half a pixel: phase 128/256");
  Parallel(camera, 0.0, -0.5, 10.0);
  Check(view.Place(camera, width, height, slots, true, placed, between) &&
      Same(placed, 0, 0, -3, 0, 128),
    "b) a pan by 2.5 pixels down: origin -3, phase 128");

  // c) zooms by powers of two: out (level 1: the window's corner (-40, -20) lies (-20, -10) from
  // the start's, 100 x 50 level-0 texels of 0.2, i.e. level 1's texel (-50, -25)) and in
  // (level -1: the corner (-10, -5), level -1's texel (100, 50))
  Parallel(camera, 0.0, 0.0, 20.0);
  Check(view.Place(camera, width, height, slots, true, placed, between) &&
      Same(placed, 1, -50, -25, 0, 0) && !between.Active,
    "c) a zoom out by 2: level 1, origin (-50, -25)");
  Parallel(camera, 0.0, 0.0, 5.0);
  Check(view.Place(camera, width, height, slots, true, placed, between) &&
      Same(placed, -1, 100, 50, 0, 0) && !between.Active,
    "c) a zoom in by 2: level -1, origin (100, 50)");
  Parallel(camera, 0.0, 0.0, 10.0 * std::ldexp(1.0, vtkSNDFTileCache::MaximumLevel + 1));
  Check(!view.Place(camera, width, height, slots, true, placed, between),
    "c) a zoom out beyond the last level is not placed");

  // d) between two levels: pixels 1.5 level-0 texels wide
  Parallel(camera, 0.0, 0.0, 15.0);
  Check(!view.Place(camera, width, height, slots, false, placed, between),
    "d) between two levels: not placed unless allowed");
  const bool placedBetween = view.Place(camera, width, height, slots, true, placed, between);
  Check(placedBetween && between.Active && placed.Level == 0 && placed.Phase[0] == 0 &&
      placed.Phase[1] == 0 && std::abs(between.Scale - 1.5) < 1e-12,
    "d) between two levels: the finer level, phase 0, 1.5 texels per pixel");
  // the window's corner (-30, -15) is level 0's texel (-50, -25) from the start's corner
  // (-20, -10); the rectangle starts a texel before it and covers the window and a texel more
  Check(placed.Origin[0] == -51 && placed.Origin[1] == -26 &&
      std::abs(between.Offset[0] - 1.0) < 1e-9 && std::abs(between.Offset[1] - 1.0) < 1e-9 &&
      between.Size[0] == 302 && between.Size[1] == 152,
    "d) between two levels: rectangle at (-51, -26), 302 x 152 texels, window at (1, 1)");
  Check(!view.Place(camera, width, height, 1, true, placed, between),
    "d) between two levels: not placed when the rectangle needs more tiles than the slots");

  // e) the sampling camera of that view: its pixels are level 0's texels from the origin
  view.Place(camera, width, height, slots, true, placed, between);
  double scale = 0.0;
  double centre[2] = { 0.0, 0.0 };
  view.SamplingWindow(camera, placed, between.Size[0], between.Size[1], scale, centre);
  vtkNew<vtkCamera> sampling;
  sampling->DeepCopy(camera);
  sampling->SetParallelScale(scale);
  sampling->SetWindowCenter(centre[0], centre[1]);
  vtkSNDFTileCache::Placement samplingPlaced;
  vtkSNDFViewPlacement::Between samplingBetween;
  Check(view.Place(sampling, between.Size[0], between.Size[1], slots, false, samplingPlaced,
          samplingBetween) &&
      Same(samplingPlaced, placed.Level, placed.Origin[0], placed.Origin[1], 0, 0),
    "e) the sampling camera's pixels are the placed texels");

  // f) moves that leave the frame, a degenerate scale, perspective
  Parallel(camera, 0.0, 0.0, 10.0);
  camera->SetPosition(0.0, 0.0, 20.0); // dolly: the offset from the focal point changed
  Check(!view.Place(camera, width, height, slots, true, placed, between), "f) a dolly");
  Parallel(camera, 0.0, 0.0, 10.0);
  camera->SetPosition(1.0, 0.0, 10.0); // another view direction
  Check(!view.Place(camera, width, height, slots, true, placed, between), "f) a new direction");
  Parallel(camera, 0.0, 0.0, 10.0);
  camera->SetFocalPoint(0.0, 0.0, -1.0); // along the view, the offset kept
  camera->SetPosition(0.0, 0.0, 9.0);
  Check(!view.Place(camera, width, height, slots, true, placed, between),
    "f) the focal point moved along the view");
  Parallel(camera, 0.0, 0.0, 0.0);
  Check(!view.Place(camera, width, height, slots, true, placed, between), "f) parallel scale 0");
  Parallel(camera, 0.6, 0.0, 10.0);
  camera->SetParallelProjection(0);
  placed.Level = 3;
  Check(view.Place(camera, width, height, slots, true, placed, between) &&
      Same(placed, 0, 0, 0, 0, 0) && !between.Active,
    "f) a perspective view takes the default placement");

  std::cout << "TestSNDFViewPlacement: " << Failures << " failures\n";
  return Failures == 0 ? 0 : 1;
}
