/**
 * @class   vtkMetaballMapper
 * @brief   draws the metaball surface of particles: isolated particles stay their spheres,
 *          neighbouring ones merge into closed shapes (Mueller, Grottel, Ertl 2007)
 *
 * vtkMetaballMapper draws the iso-surface D = IsoValue of the sum over all particles of the
 * kernel of Mueller et al. 2007, Eq. 2, with the influence radius K = k R generalised from the
 * paper's 2 R to InfluenceFactor k:
 *
 *   D_i(r) = c (1 - (r / (k R_i))^2)^2 for r <= k R_i, 0 beyond,  c = 1 / (1 - 1/k^2)^2
 *
 * (k = 2: c = 16/9, Eq. 2). D_i(R_i) = 1, so with IsoValue 1 an isolated particle is exactly its
 * sphere. It is a vtkParticleSphereMapper: the same input handling (radius array or constant,
 * RadiusScaleFactor, bad positions and radii skipped with a warning), colouring, lights and
 * material, picking (the particle whose influence sphere drew the pixel), clipping planes and
 * the shader hooks through which the AO passes reach it (vtkParticleShaderHooks).
 *
 * Method (SetMethod): VICINITY (default) or WALKING_DEPTH_PLANE, the paper's two.
 *
 * VICINITY, the paper's Sec. 3.1, with an exact search along the ray instead of fixed samples:
 * one pass, per-particle neighbour lists (memory O(N M), rebuilt per time step), exact for
 * isolated particles, the cost per fragment grows with the neighbours the ray meets.
 * - Per particle a view-independent list of the particles whose influence spheres overlap its
 *   own (|c_i - c_j| < k (R_i + R_j)), built on the CPU from vtkParticleCellList (the occupied
 *   cells of a grid of edge 2 k R_max: a particle far away from the others does not slow the
 *   search) and vtkSMPTools, kept in shader storage buffers (entries: the neighbour's centre
 *   relative to the particle, formed in double, and its radius). Rebuilt only when the
 *   positions, the radii, RadiusScaleFactor, InfluenceFactor or MaximumNumberOfNeighbors
 *   change; never when the camera, IsoValue, colours or material change.
 * - A particle without neighbours is drawn by the plain sphere imposter of the core, with the
 *   radius of its own iso-sphere, k R sqrt(1 - sqrt(IsoValue / c)) (R for IsoValue 1): exact.
 * - The others draw the part of their influence sphere where they can hold the largest kernel
 *   of a surface point: there the field is IsoValue, a sum of at most 1 + n kernels (n: the
 *   particle's list; no other particle reaches it), so the largest kernel is at least
 *   IsoValue / (1 + n), which bounds the radius to K sqrt(1 - sqrt(IsoValue / (c (1 + n))))
 *   (+ 0.02 R, as coincident particles reach the bound; the whole influence sphere for a list
 *   that was cut). Every surface point lies in the sphere of the particle with its largest
 *   kernel. With k = 2 and IsoValue 1 a particle with 1 neighbour draws 1.39 R instead of
 *   2 R, one with 15 neighbours 1.82 R. The fragment gathers the kernels its ray meets and
 *   finds the first crossing of the iso-value in the ray's chord (Shaders/Metaballs.glsl). Along a
 * ray every kernel is unimodal, so every interval has certified bounds of the field (the sums of
 * the kernels' maxima and minima over it). The chord is subdivided depth first, left half first: an
 * interval that cannot hold a crossing is passed whole, the others are halved down to Tolerance x
 * R, where the field at the interval's end decides: across, the first crossing is in it (it is
 * bisected RefinementSteps times and finished with a secant step); not across, it is passed. Unlike
 *   the paper's fixed samples (its Fig. 11 holes), no part of the surface thicker than
 *   Tolerance x R along the ray is missed. The depth test keeps the nearest crossing over all
 *   influence spheres, which is the surface: outside every influence sphere the field is 0.
 * - Normals: the field's analytic gradient at the hit (the paper interpolates the particles'
 *   normals by their density share; the gradient is the surface's true normal and costs the
 *   same). Colour: the scalar colours of the particles blended by their field contribution D_j
 *   at the hit (the paper's weights), so colour by type shows which atoms form which part.
 * - Depth pre-pass (DepthPrePass, default on; our addition to Sec. 3.1): every particle's own
 *   iso-sphere is drawn first by the core. It lies inside the surface (the other kernels only
 *   add), so the surface is never behind its depth: the depth is copied to a texture, the
 *   influence spheres' fragments search only in front of it and are dropped before gathering
 *   their kernels when their chord starts behind it, and the occlusion culler skips the cells
 *   hidden behind the iso-spheres. Where the iso-sphere is the surface (only the particle's own
 *   kernel there) its pixel is already right (measured: Documentation/Metaballs.md).
 * - True depth is written (composites with other geometry; ambient occlusion passes see it).
 * - Where the near plane cuts a metaball the search starts on the near plane and, inside,
 *   finds the exit: the inner side is shown, lit facing the viewer (as the sphere core does).
 *
 * WALKING_DEPTH_PLANE, the paper's Sec. 3.2 (vtkMetaballWalkingPlane holds its buffers and
 * loop): no lists and no shader storage (OpenGL 3.3 is enough), memory O(pixels), nothing to
 * rebuild per time step; every particle's influence sphere is drawn once per pass, and the
 * number of passes grows with the depth the plane has to walk. Per pixel a plane depth lambda
 * starts at the nearest front of an influence sphere (not before the near plane); each pass
 * sums the kernels, their derivative along lambda and the kernels one largest step deeper by
 * additive blending (a shader variant without depth writes), and a step pass
 * moves lambda with the oracle (StepOracle: the paper's Sec. 3.2.3 attenuation, or by default
 * Newton's step within the bracket of the sample one largest step ahead, the largest step
 * being MaximumStepFactor times the smallest radius); finished pixels are masked in a shared
 * depth buffer so that later passes skip them before the fragment stage; a pixel is finished when
 * Newton's estimate of its distance to the surface is at most WalkingTolerance times the smallest
 * radius (where the field does not rise with depth, a ray touching the surface: when |D/t - 1| <=
 * WalkingTolerance). The walk stops (Sec. 3.2.4) when no pixel is active, when FinishedShare of the
 * covered pixels are finished, when the last few (at most 1 %) stall (vtkMetaballWalkingPlane),
 * after MaximumPasses, or, in interactive frames only, after
 * TimeBudget seconds (the paper's bound on a frame; a still frame walks to convergence, so that
 * it is the exact picture whatever the machine's speed; a still frame that MaximumPasses cuts
 * warns with the number of unfinished pixels). Shading is
 * deferred (Sec. 3.2.5): one more pass sums the field's gradient (the normal) and one the colours
 * weighted by the kernels; the final draw is the core's imposter draw, each fragment placing
 * its point where lambda is when its influence sphere holds it, so lights, AO hooks, picking
 * and depth are the core's. Differences from VICINITY: isolated particles are found to the
 * tolerance, not exactly; a part of the surface thinner than half of the largest step along
 * the ray can be missed (the paper's remark); where the near plane cuts a metaball the pixels
 * stay empty; occlusion culling is off (the splat passes need every particle). lambda is a view
 * depth measured from the vertex buffer's origin, so the method keeps float precision with the
 * camera far away and the data far from the origin.
 *
 * Settings that bound the cost of VICINITY:
 * - MaximumNumberOfNeighbors (default 64): a list keeps at most this many, the nearest (a
 *   warning counts the particles that had more: a huge InfluenceFactor makes every particle a
 *   neighbour of every other, which this bounds to O(N M) time and memory).
 * - MaximumListMemory (MiB, default 1024): the lists together; beyond, every list is cut to the
 *   share that fits, with a warning.
 * - IterationLimit (default 100) bounds the intervals examined per fragment: a fragment that
 *   runs out of them before it finds its bracket draws nothing (a grazing ray that stays just
 *   below the iso-value over a long stretch is the costly case); RefinementSteps (default 6)
 *   bisections follow a bracket.
 *
 * VICINITY needs OpenGL 4.3 (shader storage buffers in the fragment stage). Below it an error
 * says so once and every particle is drawn as its plain sphere; WALKING_DEPTH_PLANE works there.
 *
 * Occlusion culling (vtkParticleOcclusionCuller) tests each particle with the sphere it draws
 * (its influence sphere when it has neighbours).
 *
 * Not done (yet): translucent metaballs. The surface is opaque whatever the colours' alpha
 * (HasOpaqueGeometry() is true, HasTranslucentPolygonalGeometry() false): a partial alpha would
 * blend it with what was drawn before it, a picture that depends on the draw order and, under
 * MPI, on the partition. An actor whose opacity is below 1 is drawn by VTK in its translucent
 * pass; there the surface has that opacity, blended by VTK's translucency method, with a warning
 * (ForceOpaqueOn() or opacity 1 draws the opaque surface; ParaView's Particles representation
 * does that).
 *
 * Interactive frames (GetFrameBudget(), vtkParticleFrameBudget): with the vicinity method and
 * shader storage buffers, two levels, every particle's own iso-sphere alone (level 0: the depth
 * pre-pass's spheres, shaded, no search; exact where a particle is isolated, the merged shapes
 * shown as their spheres) and the exact surface. Coarser Tolerance, fewer RefinementSteps or
 * neighbours save at most 30 % of the frame (measured: Documentation/Performance.md), the
 * iso-spheres ~90 %. The walking depth plane has two levels: the walk within TimeBudget (level 0)
 * and the walk to convergence (the exact level, still frames).
 *
 * @sa vtkParticleSphereMapper vtkMetaballWalkingPlane vtkParticleReferenceMetaballs
 * vtkParticleShaderHooks
 */
#ifndef vtkMetaballMapper_h
#define vtkMetaballMapper_h

#include "vtkParticleRenderingMetaballsModule.h" // for export macro
#include "vtkParticleSphereMapper.h"

#include <string> // for std::string

class vtkMetaballWalkingPlane;

class VTKPARTICLERENDERINGMETABALLS_EXPORT vtkMetaballMapper : public vtkParticleSphereMapper
{
public:
  static vtkMetaballMapper* New();
  vtkTypeMacro(vtkMetaballMapper, vtkParticleSphereMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * False: metaballs draw a surface through their own targets, not sphere glyphs.
   */
  bool GetDrawsSphereGlyphs() override;

  /**
   * The frame budget's levels: "iso-spheres|exact surface" (one, "exact surface", for the walking
   * depth plane or without shader storage buffers).
   */
  std::string GetQualityLevelNames() override;

  enum MethodType
  {
    VICINITY = 0,
    WALKING_DEPTH_PLANE = 1
  };
  enum StepOracleType
  {
    PAPER_ORACLE = 0,
    BRACKETING_ORACLE = 1
  };

  ///@{
  /**
   * The method: VICINITY (default, neighbour lists, one pass) or WALKING_DEPTH_PLANE (no lists,
   * several passes). See the class comment for the trade-off.
   */
  vtkSetClampMacro(Method, int, VICINITY, WALKING_DEPTH_PLANE);
  vtkGetMacro(Method, int);
  void SetMethodToVicinity() { this->SetMethod(VICINITY); }
  void SetMethodToWalkingDepthPlane() { this->SetMethod(WALKING_DEPTH_PLANE); }
  ///@}

  ///@{
  /**
   * Influence radius over particle radius, k (the paper: 2). Larger values merge particles
   * farther apart and make the neighbour lists longer. Default 2, clamped to [1.05, 10].
   */
  vtkSetClampMacro(InfluenceFactor, double, 1.05, 10.0);
  vtkGetMacro(InfluenceFactor, double);
  ///@}

  ///@{
  /**
   * The iso-value of the surface (the paper's threshold t). 1 (default): an isolated particle
   * is its sphere; smaller values grow and merge the shapes, larger ones shrink them (an
   * isolated particle vanishes at c = 1 / (1 - 1/k^2)^2 and above). Clamped to [1e-3, 1e3].
   */
  vtkSetClampMacro(IsoValue, double, 1e-3, 1e3);
  vtkGetMacro(IsoValue, double);
  ///@}

  ///@{
  /**
   * The search's resolution along the ray, in units of the drawing particle's radius: a part of
   * the surface thinner than this along the ray can be missed, nothing thicker; the bracket of
   * the crossing has this width before its refinement. Default 0.01, clamped to [1e-6, 0.5].
   */
  vtkSetClampMacro(Tolerance, double, 1e-6, 0.5);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * Bisections of the bracket before the final secant step (the depth error falls about 4x per
   * step on smooth parts). Default 6, clamped to [0, 30].
   */
  vtkSetClampMacro(RefinementSteps, int, 0, 30);
  vtkGetMacro(RefinementSteps, int);
  ///@}

  ///@{
  /**
   * Most intervals the search examines per fragment. Default 100, clamped to [1, 10000].
   */
  vtkSetClampMacro(IterationLimit, int, 1, 10000);
  vtkGetMacro(IterationLimit, int);
  ///@}

  ///@{
  /**
   * Vicinity method: draw every particle's own iso-sphere first (exact where the particle is
   * isolated, inside the surface elsewhere, since the other kernels only add), copy the depth,
   * and let each influence-sphere fragment search only in front of that depth: fragments whose
   * chord starts behind it are dropped before they gather their kernels, and the occlusion
   * culler skips the cells hidden behind the spheres. The picture is the same (up to the
   * search's tolerance). Default on. Not used with a multisampled framebuffer, without depth
   * test or depth writes, or with a depth range other than [0, 1] (one pass then).
   */
  vtkSetMacro(DepthPrePass, bool);
  vtkGetMacro(DepthPrePass, bool);
  vtkBooleanMacro(DepthPrePass, bool);
  /**
   * Whether the last vicinity draw used the depth pre-pass.
   */
  vtkGetMacro(LastDrawUsedDepthPrePass, bool);
  ///@}

  ///@{
  /**
   * Most neighbours per list (the nearest are kept). Default 64, clamped to [1, 255]; it is
   * also the size of the fragment stage's kernel array.
   */
  vtkSetClampMacro(MaximumNumberOfNeighbors, int, 1, 255);
  vtkGetMacro(MaximumNumberOfNeighbors, int);
  ///@}

  ///@{
  /**
   * Most memory of the neighbour lists, in MiB (20 bytes per entry, 8 per particle).
   * Default 1024.
   */
  vtkSetClampMacro(MaximumListMemory, double, 1.0, 1e7);
  vtkGetMacro(MaximumListMemory, double);
  ///@}

  ///@{
  /**
   * Walking depth plane: a pixel is finished when Newton's estimate of its distance to the
   * surface, |IsoValue - D| / (dD/dlambda), is at most this times the smallest radius (or, where
   * the field does not rise with depth, when |D / IsoValue - 1| is at most this). Default 1e-3,
   * clamped to [1e-6, 0.5].
   */
  vtkSetClampMacro(WalkingTolerance, double, 1e-6, 0.5);
  vtkGetMacro(WalkingTolerance, double);
  ///@}

  ///@{
  /**
   * Walking depth plane: the step oracle, BRACKETING_ORACLE (default) or PAPER_ORACLE.
   */
  vtkSetClampMacro(StepOracle, int, PAPER_ORACLE, BRACKETING_ORACLE);
  vtkGetMacro(StepOracle, int);
  ///@}

  ///@{
  /**
   * Walking depth plane: the largest step over the smallest particle radius (the paper: 1).
   * Default 1, clamped to [0.01, 10].
   */
  vtkSetClampMacro(MaximumStepFactor, double, 0.01, 10.0);
  vtkGetMacro(MaximumStepFactor, double);
  ///@}

  ///@{
  /**
   * Walking depth plane: most passes per frame (default 1000, clamped to [1, 10000]: the hang
   * guard; a still frame cut by it warns), most seconds of walking per interactive frame
   * (default 1: the paper's minimum frame rate of 1 FPS; 0 is one pass; still frames walk to
   * convergence, see the class description), the share of covered pixels whose finishing ends
   * the walk (default 1: all).
   */
  vtkSetClampMacro(MaximumPasses, int, 1, 10000);
  vtkGetMacro(MaximumPasses, int);
  vtkSetClampMacro(TimeBudget, double, 0.0, 1e6);
  vtkGetMacro(TimeBudget, double);
  vtkSetClampMacro(FinishedShare, double, 0.0, 1.0);
  vtkGetMacro(FinishedShare, double);
  ///@}

  /**
   * The walking depth plane's buffers and the statistics of the last walk (passes, seconds,
   * covered and active pixels, why it stopped).
   */
  vtkMetaballWalkingPlane* GetWalkingPlane();

  ///@{
  /**
   * Statistics of the last neighbour-list build: builds so far, its CPU seconds, list entries,
   * particles drawn as plain spheres (no neighbour), particles whose list was cut (more
   * neighbours than MaximumNumberOfNeighbors or than MaximumListMemory allows).
   */
  vtkGetMacro(NumberOfListBuilds, vtkIdType);
  vtkGetMacro(LastListBuildSeconds, double);
  vtkGetMacro(NumberOfListEntries, vtkIdType);
  vtkGetMacro(NumberOfIsolatedParticles, vtkIdType);
  vtkGetMacro(NumberOfTruncatedLists, vtkIdType);
  ///@}

  /**
   * The kernel scale c = 1 / (1 - 1/k^2)^2 for influence factor k, and the radius of an
   * isolated particle's iso-sphere over its radius, k sqrt(1 - sqrt(iso / c)) (0 when iso >= c).
   */
  static double KernelScale(double influenceFactor);
  static double IsolatedRadiusFactor(double influenceFactor, double isoValue);

  /**
   * Bounds of the surface: the centres grown by the largest influence radius.
   */
  using Superclass::GetBounds;
  double* GetBounds() override;

  ///@{
  /**
   * The surface is opaque, whatever the colours' alpha (see the class description).
   */
  bool HasOpaqueGeometry() override;
  bool HasTranslucentPolygonalGeometry() override;
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkMetaballMapper();
  ~vtkMetaballMapper() override;

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;
  void CacheParticleAttributes(vtkRenderer* ren, vtkActor* act) override;
  const float* GetCullingRadii() override;
  bool GetOcclusionCullingCompiled(vtkRenderer* ren) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;

  // the shader replacements of each method
  void ReplaceWalkingShaderValues(std::string& vs, std::string& gs, std::string& fs);
  void ReplaceVicinityShaderValues(std::string& vs, std::string& gs, std::string& fs);

  // the walking depth plane: its uniforms; its passes, then the final draw
  void SetWalkingShaderParameters(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act);
  void RenderWalkingPlane(vtkRenderer* ren, vtkActor* act);

  // the vicinity method with its depth pre-pass; false when the pre-pass cannot be used
  bool RenderVicinityWithPrePass(vtkRenderer* ren, vtkActor* act);

  // (re)build the neighbour lists of the uploaded particles when what they depend on changed
  void UpdateNeighborLists();

  int Method = VICINITY;
  double InfluenceFactor = 2.0;
  double IsoValue = 1.0;
  double Tolerance = 0.01;
  int RefinementSteps = 6;
  int IterationLimit = 100;
  int MaximumNumberOfNeighbors = 64;
  double MaximumListMemory = 1024.0;
  bool DepthPrePass = true;
  bool LastDrawUsedDepthPrePass = false;
  double WalkingTolerance = 1e-3;
  int StepOracle = BRACKETING_ORACLE;
  double MaximumStepFactor = 1.0;
  int MaximumPasses = 1000;
  double TimeBudget = 1.0;
  double FinishedShare = 1.0;
  vtkIdType NumberOfListBuilds = 0;
  double LastListBuildSeconds = 0.0;
  vtkIdType NumberOfListEntries = 0;
  vtkIdType NumberOfIsolatedParticles = 0;
  vtkIdType NumberOfTruncatedLists = 0;

private:
  vtkMetaballMapper(const vtkMetaballMapper&) = delete;
  void operator=(const vtkMetaballMapper&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
