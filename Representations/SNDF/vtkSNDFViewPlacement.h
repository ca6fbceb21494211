/**
 * @class   vtkSNDFViewPlacement
 * @brief   where a view lies in the S-MIP of vtkSNDFRenderPass: its level and texel grid
 *
 * The S-MIP (Ibrahim et al. 2017, Sec. 5; vtkSNDFTileCache) keeps the samples of a parallel
 * view on a virtual plane fixed at the view that started it (Start()): the view rotation, the
 * camera's offset from the focal point, the focal point's distance along the view, the size of
 * a level-0 texel (one pixel of that view) and the plane position of texel (0, 0)'s lower-left
 * corner. A later parallel view of the same frame -- moved in the view plane only, the
 * direction kept -- is placed on that plane (Place()): its level (pixel size 2^L level-0
 * texels) and its grid's origin and phase (to 1/256 level-0 texel), so that a pan or a zoom by
 * whole levels keeps the samples. A view whose pixel size lies between two levels can be placed
 * at the finer level with a rectangle of texels around the window whose box filter makes the
 * window's pixels (Between); SamplingWindow() gives the camera whose pixels are those texels.
 * A perspective view is always at the default placement (its samples are its own).
 *
 * Plain C++ (no OpenGL, no vtkObject); vtkSNDFRenderPass holds one per S-MIP frame.
 * TestSNDFViewPlacement checks pans, zooms, views between levels and the moves that leave the
 * frame.
 *
 * @sa vtkSNDFRenderPass vtkSNDFTileCache
 */
#ifndef vtkSNDFViewPlacement_h
#define vtkSNDFViewPlacement_h

#include "vtkParticleRenderingSNDFModule.h" // for export macro
#include "vtkSNDFTileCache.h"               // for vtkSNDFTileCache::Placement

class vtkCamera;

class VTKPARTICLERENDERINGSNDF_EXPORT vtkSNDFViewPlacement
{
public:
  /**
   * A view between two levels of the S-MIP (Place()): its pixels are Scale texels of the
   * placed level wide, the window's lower-left corner lies at Offset in the rectangle of Size
   * texels that is sampled and shaded (SNDFBoxFilter.glsl makes the window's pixels).
   */
  struct Between
  {
    bool Active = false;
    double Scale = 1.0;
    double Offset[2] = { 0.0, 0.0 };
    int Size[2] = { 0, 0 };
  };

  /**
   * Start the S-MIP's frame at this width x height view: its pixels are the level-0 texels.
   */
  void Start(vtkCamera* camera, int width, int height);

  /**
   * Where a parallel view of the frame lies in the S-MIP: false unless its pixels are the texels
   * of a level (pixel size 2^L level-0 texels; the camera moved in the view plane only, the
   * direction kept). Its grid is placed to 1/256 level-0 texel.
   *
   * A parallel view whose pixel size is not a power of two times the level-0 texel lies between
   * two levels (allowBetween: vtkSNDFRenderPass's ZoomBetweenLevels; otherwise false): it is
   * placed at the finer of the two, L (its pixels 1 to 2 texels of L wide: the coarser level
   * would be magnified; measured in Documentation/SNDF.md), on the phase-0 grid of that level,
   * with a rectangle of texels that covers the window and a texel more on each side; the samples
   * go into those texels and the window shows their box filter (`between`). False where the
   * rectangle needs more than `slots` tiles. A perspective view: true, the default placement.
   */
  bool Place(vtkCamera* camera, int width, int height, int slots, bool allowBetween,
    vtkSNDFTileCache::Placement& placed, Between& between) const;

  /**
   * The parallel scale and window centre of a camera whose texelsX x texelsY pixels are the
   * texels of the rectangle of a view between two levels (`placed`: on the level's phase-0
   * grid, its lower-left texel at Origin); the aspect ratio is texelsX / texelsY.
   */
  void SamplingWindow(vtkCamera* camera, const vtkSNDFTileCache::Placement& placed, int texelsX,
    int texelsY, double& scale, double centre[2]) const;

  /**
   * The size of a level-0 texel in world units (parallel views; 1 in perspective).
   */
  double GetTexelSize() const { return this->TexelSize; }

private:
  // The lower-left corner of a width x height parallel view in the coordinates of the frame's
  // rotation (right, up) and the distance of its focal point along the view: VTK's orthographic
  // window spans (WindowCenter -/+ 1) * (parallel scale * aspect, parallel scale) around the
  // focal point.
  void Corner(vtkCamera* camera, int width, int height, double corner[2], double& along) const;

  // the frame: the view rotation, the camera's offset from the focal point, the focal point's
  // distance along the view, the size of a level-0 texel, the plane position of texel (0, 0)'s
  // lower-left corner
  double Rotation[3][3] = { { 0.0 } };
  double Offset[3] = { 0.0, 0.0, 0.0 };
  double Along = 0.0;
  double TexelSize = 1.0;
  double Plane[2] = { 0.0, 0.0 };
};

#endif
