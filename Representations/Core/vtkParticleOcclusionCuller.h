/**
 * @class   vtkParticleOcclusionCuller
 * @brief   front-to-back drawing of opaque particles by spatial cells, skipping hidden cells
 *
 * vtkParticleOcclusionCuller lets the sphere core draw dense particle data without shading the
 * particles that cannot be seen. An exact sphere imposter writes gl_FragDepth, which switches off
 * the early depth test on every OpenGL implementation that has no conservative-depth support
 * (Mesa's llvmpipe among them): every rasterised fragment of every hidden sphere is shaded. In a
 * LAMMPS liquid or a crystal block most spheres are hidden, so most of the frame is spent on
 * them. This class removes them before they reach the vertex stage:
 *
 * - Build() sorts the particles into a regular grid of cells over their bounds (about
 *   ParticlesPerCell per cell, at most MaximumNumberOfCells) and uploads the particle indices
 *   cell by cell as an element array (4 bytes per particle on the GPU). Drawing through it keeps
 *   gl_VertexID equal to the particle index, so picking and every shader hook see the same ids.
 * - Draw() orders the cells by the nearest depth of their bounds (each cell's box grown by its
 *   largest radius) and draws them in phases, nearest first. Before each later phase it reads the
 *   depth of the bound framebuffer (glReadPixels), reduces it to the largest depth per
 *   BlockSize x BlockSize pixel block, and skips every cell whose projected box lies behind the
 *   depth already there in all the blocks it covers. Cells outside the viewport or beyond the far
 *   plane are skipped in every phase.
 *
 * The result is exact: a skipped cell could only have produced fragments that fail the depth
 * test. The test is conservative throughout: the box is projected in double precision from its
 * eight corners (a corner at or behind the eye plane makes the cell visible), its rectangle is
 * grown by a pixel, and a cell is hidden only when its nearest depth exceeds every block's
 * largest depth by DepthMargin (2^-20, far above the float rounding of the shader's depth).
 * Only the order in which equal-depth fragments of two spheres arrive can differ from a plain
 * draw (touching spheres, to the last bit of depth).
 *
 * Draw() falls back to one plain draw of all particles (returning false) when culling cannot be
 * exact or cannot work: no depth test, no depth writes, a depth function other than GL_LESS or
 * GL_LEQUAL, a depth range other than [0, 1], a multisampled framebuffer (glReadPixels cannot
 * read it), no depth buffer.
 *
 * Cost: Build() is O(N) on the CPU (counting sort; measured: Documentation/Core.md). Draw() costs a
 * depth read-back per later phase (a 1024x768 window: ~3 MB) and a sort of the cells. On a GPU
 * the read-back stalls the pipeline (~1 ms); on llvmpipe it waits for rasterisation that has to
 * finish anyway.
 *
 * @sa vtkParticleSphereMapper
 */
#ifndef vtkParticleOcclusionCuller_h
#define vtkParticleOcclusionCuller_h

#include "vtkObject.h"
#include "vtkParticleRenderingCoreModule.h" // for export macro

class vtkDataArray;
class vtkMatrix4x4;
class vtkRenderer;
class vtkShaderProgram;
class vtkWindow;

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleOcclusionCuller : public vtkObject
{
public:
  static vtkParticleOcclusionCuller* New();
  vtkTypeMacro(vtkParticleOcclusionCuller, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Target number of particles per cell (default 512) and the largest number of cells (default
   * 4096; every visible cell is one range of one glMultiDrawElements call). Used by Build().
   */
  vtkSetClampMacro(ParticlesPerCell, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(ParticlesPerCell, vtkIdType);
  vtkSetClampMacro(MaximumNumberOfCells, int, 1, 1 << 20);
  vtkGetMacro(MaximumNumberOfCells, int);
  ///@}

  ///@{
  /**
   * Side of the pixel blocks of the depth read-back (default 8) and the depth margin of the
   * hidden test (default 2^-20 of the depth range).
   */
  vtkSetClampMacro(BlockSize, int, 1, 256);
  vtkGetMacro(BlockSize, int);
  vtkSetMacro(DepthMargin, double);
  vtkGetMacro(DepthMargin, double);
  ///@}

  ///@{
  /**
   * The depth buffer already bounds what Draw() will draw (a pre-pass drew something that lies
   * in front of it, e.g. vtkMetaballMapper's iso-spheres before the influence spheres): the depth
   * is read before the first phase too, so that cells hidden by the pre-pass are skipped from
   * the start. Default off (the first phase is drawn without a read-back).
   */
  vtkSetMacro(DepthPrimed, bool);
  vtkGetMacro(DepthPrimed, bool);
  vtkBooleanMacro(DepthPrimed, bool);
  ///@}

  /**
   * Partition `count` particles (positions in model coordinates, radii in model units; a
   * particle with radius <= 0 or a non-finite position is left out, as the sphere core does not
   * draw it) and upload the cell-ordered indices. The context of `ren` must be current.
   * Returns false (with an error) when the index buffer cannot be uploaded.
   */
  bool Build(vtkRenderer* ren, vtkDataArray* positions, const float* radii, vtkIdType count);

  /**
   * Whether Build() was called for the current data (the caller calls Modified() or Build()).
   */
  vtkGetMacro(NumberOfCells, int);
  vtkGetMacro(NumberOfParticles, vtkIdType);

  /**
   * Draw the particles with the caller's program and vertex array bound. The program's geometry
   * stage includes Shaders/Core/OcclusionCull.glsl and calls prSphereIsOccluded(): Draw() sets its
   * uniforms (the block map of the last depth read-back) so that single hidden spheres of visible
   * cells are dropped as well, and switches the test off again at the end. wcdcTransposed: the
   * world-to-clip matrix the program's camera uniforms were made from, as vtkOpenGLCamera's
   * GetKeyMatrices() returns it (transposed); the caller keeps it from the moment it set them
   * (the camera's cached matrices can have been recomputed for something else since). mcwc: the
   * actor's model-to-world matrix (row-major, points as columns); radiusScaleWC: the model-to-world
   * factor of the radii (the shader's radius scale). Returns true when the cells were culled, false
   * when everything was drawn with one plain draw (see the class description).
   */
  bool Draw(vtkRenderer* ren, vtkShaderProgram* program, vtkMatrix4x4* wcdcTransposed,
    vtkMatrix4x4* mcwc, double radiusScaleWC);

  /**
   * Draw the first `count` particles in index order with one draw call, without culling (the
   * program's per-sphere test, if compiled in, switched off).
   */
  void DrawAll(vtkRenderer* ren, vtkShaderProgram* program, vtkIdType count);

  ///@{
  /**
   * Statistics of the last Draw(): particles and cells drawn, depth read-backs, and the CPU
   * wall time spent in the read-backs and tests (including the wait for the GPU).
   */
  vtkGetMacro(LastNumberOfDrawnParticles, vtkIdType);
  vtkGetMacro(LastNumberOfDrawnCells, int);
  vtkGetMacro(LastNumberOfDepthReads, int);
  vtkGetMacro(LastCullSeconds, double);
  ///@}

  ///@{
  /**
   * For tests and benchmarks: count the spheres that leave the geometry stage (a
   * GL_PRIMITIVES_GENERATED query around the draws; off by default, as reading it waits for the
   * GPU). GetLastNumberOfEmittedSpheres() is -1 when not counted.
   */
  vtkSetMacro(CountEmittedSpheres, bool);
  vtkGetMacro(CountEmittedSpheres, bool);
  vtkGetMacro(LastNumberOfEmittedSpheres, vtkIdType);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkParticleOcclusionCuller();
  ~vtkParticleOcclusionCuller() override;

  vtkIdType ParticlesPerCell = 512;
  int MaximumNumberOfCells = 4096;
  int BlockSize = 8;
  double DepthMargin = 1.0 / 1048576.0;
  bool DepthPrimed = false;
  int NumberOfCells = 0;
  vtkIdType NumberOfParticles = 0;
  vtkIdType LastNumberOfDrawnParticles = 0;
  int LastNumberOfDrawnCells = 0;
  int LastNumberOfDepthReads = 0;
  double LastCullSeconds = 0.0;
  bool CountEmittedSpheres = false;
  vtkIdType LastNumberOfEmittedSpheres = -1;

private:
  // Build() after the grid is chosen: the counting sort, the boxes, the upload (may throw
  // std::bad_alloc, which Build() turns into an error)
  bool BuildCells(vtkRenderer* ren, vtkDataArray* positions, const float* radii, vtkIdType count,
    vtkIdType validCount, const double bounds[6], const int dims[3], const double scale[3]);
  void BeginCount();
  void EndCount();
  vtkParticleOcclusionCuller(const vtkParticleOcclusionCuller&) = delete;
  void operator=(const vtkParticleOcclusionCuller&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
