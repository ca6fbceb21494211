/**
 * @class   vtkSNDFTileCache
 * @brief   the S-MIP of vtkSNDFRenderPass: S-NDF tiles of a virtual screen-space mipmap in a
 *          fixed pool of GPU memory with a page table and least-recently-used replacement
 *          (Ibrahim et al. 2017, Sec. 6.1, Fig. 9 and 10)
 *
 * The S-NDFs of a view are texels of a virtual image plane parallel to the screen. Level L of the
 * screen-space mipmap (S-MIP) has texels 2^L times the size of level 0 (the level the pass started
 * at; -8 <= L <= 24); it is cut into TileSize^2 = 64^2 tiles (the paper's T_L). Only the tiles a
 * view needs are kept, in a pool of slots allocated once (Allocate()); a CPU page table maps a tile
 * (its level, the phase of its level's grid and its position) to its slot, and for each dispatch
 * a small GPU table maps the rectangle of tiles the dispatch reads to slots (Shaders/SNDFTiles.glsl
 * has the addressing). A slot holds, per texel, the bin words and four vec4 sums of
 * Shaders/SNDFAccumulate.glsl.
 *
 * MapView() makes every tile of a view resident:
 * - a tile in the cache is used as it is (a pan back, a zoom back in: no sample is taken again);
 * - a tile that is not takes a free slot, or the least recently used slot that the view does not
 *   show (LRU, Sec. 6.1.1), is cleared, and is computed by averaging the finer level one or two
 *   levels down where that level has tiles in the cache (2 x 2 or 4 x 4 texels per texel, Sec.
 *   6.1.2; Shaders/SNDFDownsample.glsl): zooming out needs no new samples where the finer level
 *   was sampled. Texels whose finer texels are missing stay empty and are sampled;
 * - a tile whose shaded sums were formed with an older lighting table than the current one is
 *   rebaked (Shaders/SNDFRebake.glsl) before it is shown or averaged: re-lighting visits the tiles
 *   when they are used, never a stale tile.
 * A view needs at most (ceil(W / 64) + 1) (ceil(H / 64) + 1) tiles (GetTilesForView()); a pool
 * with fewer slots is refused (MapView() returns false) rather than showing a wrong tile.
 *
 * Storage. A texel's bins and its sums live in two families of shader-storage buffers, each
 * buffer a whole number of tiles within the context's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (128 MB
 * on llvmpipe: 42 tiles of 8 x 8 bins, 512 tiles of sums), so that no shader addresses beyond a
 * block. A (bin buffer, sum buffer) pair is a part of the pool; the per-frame shaders
 * (accumulation, shade, sample count, rebake) bind one part and run one dispatch per part over
 * the list of the view's tiles in it, one invocation per texel; the zoom's averaging gathers a
 * tile's children part by part into per-texel records, then writes the tile from them.
 *
 * Levels are placed by the integer position of their grid on the virtual plane in units of 1/256
 * of a level-0 texel; the phase of a level's grid (its origin modulo its texel size) is part of a
 * tile's key, so that views reached by different pans and zooms never share a texel that covers a
 * different footprint.
 *
 * Every method that talks to OpenGL expects the context given to Allocate() to be current.
 *
 * @sa vtkSNDFRenderPass
 */
#ifndef vtkSNDFTileCache_h
#define vtkSNDFTileCache_h

#include "vtkObject.h"
#include "vtkParticleRenderingSNDFModule.h" // for export macro

#include <string> // for std::string

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkParticleComputeProgram;
class vtkTextureObject;
class vtkWindow;

class VTKPARTICLERENDERINGSNDF_EXPORT vtkSNDFTileCache : public vtkObject
{
public:
  static vtkSNDFTileCache* New();
  vtkTypeMacro(vtkSNDFTileCache, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Texels per tile side (64), and the finest and coarsest level.
   */
  static constexpr int TileSize = 64;
  static constexpr int MinimumLevel = -8;
  static constexpr int MaximumLevel = 24;

  /**
   * 32-bit words per texel for the bins (three per bin and the occupancy bits, and two more per
   * bin with `moments`: the colour coordinates' moments of Shaders/SNDFBins.glsl), and bytes per
   * tile.
   */
  static int GetWordsPerTexel(int bins, bool moments = false);
  static double GetTileBytes(int bins, bool moments = false);

  /**
   * The most tiles a width x height view can touch.
   */
  static int GetTilesForView(int width, int height);

  /**
   * The most tiles a pool can hold in the current `context` with `bins` x `bins` bins: the bins
   * and the sums are split over shader-storage buffers of whole tiles, each within the
   * context's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (GetBlockBytes(); at most 2^31 - 1 bytes), up to
   * 64 buffers of bins and 16 of sums. llvmpipe: 128 MB blocks, 4032 tiles of 8 x 8 bins.
   */
  int GetMaximumSlots(vtkOpenGLRenderWindow* context, int bins, bool moments = false);
  double GetBlockBytes() const;

  /**
   * The GLSL source `name` of Shaders/ with the pool's storage declarations and accessors
   * (the //PR::SNDFStorage tag of SNDFTiles.glsl) for the context of the last
   * GetMaximumSlots() or Allocate(). The shaders see one part of the pool per dispatch (one
   * bin buffer and one sum buffer, no branch per access: BindViewPart()).
   */
  std::string GetShaderSource(const std::string& name);

  /**
   * (Re)allocate a pool of `slots` tiles for `bins` x `bins` bins, with the colour coordinates'
   * moments per bin or without, dropping every tile. False (with the pool released) when the GPU
   * refuses the memory.
   */
  bool Allocate(vtkOpenGLRenderWindow* context, int bins, int slots, bool moments = false);

  /**
   * Drop every tile (a restart: the view direction, the data or the size changed).
   */
  void Clear();

  ///@{
  /**
   * The pool: slots, bins, bytes; tiles resident now.
   */
  vtkGetMacro(NumberOfSlots, int);
  vtkGetMacro(Bins, int);
  vtkGetMacro(Moments, bool);
  double GetBytes() const;
  int GetNumberOfTiles() const;
  ///@}

  /**
   * Where a view lies on the virtual plane: its level, the phase of the level's grid (in 1/256
   * of a level-0 texel, in [0, 2^(level + 8))) and the level's texel under the view's lower-left
   * pixel.
   */
  struct Placement
  {
    int Level = 0;
    long long Phase[2] = { 0, 0 };
    long long Origin[2] = { 0, 0 };
    bool operator==(const Placement& o) const
    {
      return this->Level == o.Level && this->Phase[0] == o.Phase[0] &&
        this->Phase[1] == o.Phase[1] && this->Origin[0] == o.Origin[0] &&
        this->Origin[1] == o.Origin[1];
    }
  };

  /**
   * Make every tile of a width x height view placed at `view` resident (see the class comment)
   * and load its page table for BindView(). `table` and `tableVersion` are the lighting table
   * and its build number (tiles shaded with another one are rebaked). False when the pool holds
   * fewer slots than the view has tiles. A call for the view, size and table version of the
   * last one does nothing (nothing but MapView() changes the tiles' residency).
   */
  bool MapView(
    const Placement& view, int width, int height, vtkTextureObject* table, long long tableVersion);

  /**
   * Apply the 3 x 3 colour matrix `m` (row-major) to the mean colour of every occupied bin of
   * every tile in the cache (Shaders/SNDFRecolour.glsl) and mark the tiles for rebaking with the
   * next MapView(): a colour-map change whose new particle colours are the old ones times `m`
   * (vtkSNDFRenderPass) re-shades without sampling. Returns the number of tiles recoloured.
   */
  int Recolour(const double m[3][3]);

  /**
   * A new colour map of the colour coordinate t in [0, 1] (a pool with moments): `ramps` is a
   * `size` x 2 RGBA float texture of the stored colour as a function of t at size equally spaced
   * values, for the old map (row 0) and the new one (row 1). Every occupied bin's mean colour m
   * becomes A Q_new + R (m - A Q_old), Q the Gauss quadrature of the ramp under the bin's moments
   * of t and R = `residual` (row-major; carries the old map's quadrature error into the new
   * one, Shaders/SNDFRecolour.glsl); the tiles are marked for rebaking. Returns the number of
   * tiles recoloured (0 without moments).
   */
  int RecolourMap(vtkTextureObject* ramps, int size, const double residual[3][3]);

  /**
   * How many tiles of a view the cache has, or could average from a finer level (no GPU work).
   */
  int CountAvailable(const Placement& view, int width, int height);

  /**
   * For dispatches over the view's texels with `program` (in use): the page table of the last
   * MapView() and its uniforms (prTexelOffset, prTilesX). Then one tile-list dispatch per part
   * of the pool the view's tiles lie in: BindViewPart(program, k) for k < GetNumberOfViewParts()
   * binds the part's buffers and its list of tiles and returns the number of tiles n; dispatch
   * (4, 4, n) groups of 16 x 16 (prSNDFTileInvocation() of SNDFTiles.glsl).
   */
  void BindView(vtkParticleComputeProgram* program);
  int GetNumberOfViewParts() const;
  unsigned int BindViewPart(vtkParticleComputeProgram* program, int part);

  /**
   * The fewest samples a pixel of the last mapped view holds (a dispatch and a read-back).
   */
  unsigned int CountMinimumSamples(int width, int height);

  ///@{
  /**
   * Counters since the pool was allocated: tiles averaged from a finer level, tiles that came
   * empty, tiles evicted (least recently used), tiles rebaked after a table change or a
   * recolouring, tiles recoloured.
   */
  vtkGetMacro(NumberOfDownsampledTiles, long long);
  vtkGetMacro(NumberOfClearedTiles, long long);
  vtkGetMacro(NumberOfEvictedTiles, long long);
  vtkGetMacro(NumberOfRebakedTiles, long long);
  vtkGetMacro(NumberOfRecolouredTiles, long long);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* w);

protected:
  vtkSNDFTileCache();
  ~vtkSNDFTileCache() override;

  int NumberOfSlots = 0;
  int Bins = 0;
  bool Moments = false;
  long long NumberOfDownsampledTiles = 0;
  long long NumberOfClearedTiles = 0;
  long long NumberOfEvictedTiles = 0;
  long long NumberOfRebakedTiles = 0;
  long long NumberOfRecolouredTiles = 0;

private:
  vtkSNDFTileCache(const vtkSNDFTileCache&) = delete;
  void operator=(const vtkSNDFTileCache&) = delete;

  void QueryLimits(vtkOpenGLRenderWindow* context);

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
