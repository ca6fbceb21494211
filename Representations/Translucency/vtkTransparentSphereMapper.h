/**
 * @class   vtkTransparentSphereMapper
 * @brief   particles as exact emission-absorption sphere glyphs, composited in depth order
 *
 * vtkTransparentSphereMapper implements the transparent sphere glyphs of Staib, Grottel and
 * Gumhold 2015, "Visualization of Particle-based Data with Transparency and Ambient Occlusion",
 * Sec. 3.1, 4 and 5 (Eq. 1, 2, 8-19), on the sphere imposter core of vtkParticleSphereMapper
 * (positions, radii, colours, lights, picking and bad-input handling are the core's).
 *
 * Opacity. Every particle has a maximum opacity Theta_i = Theta_a * opacity, where Theta_a comes
 * from the point array OpacityArrayName mapped linearly from OpacityRange to [0,1] and clamped
 * (1 without an array), and opacity is VTK's usual fragment opacity: the actor property's Opacity
 * times the alpha of the scalar colour (so a lookup table with opacity mapping also works).
 * Theta_i is the opacity of the most opaque ray through the glyph (paper Sec. 3.1).
 *
 * Density models (paper Sec. 4), rho along the ray inside the sphere, with the linear transfer
 * functions sigma = lambda rho, E = lambda c_i rho (Eq. 8-12), so that the emitted colour is
 * L_V = c_i Theta(t_n, t_f) and Theta = 1 - exp(-lambda (P(t_f) - P(t_n))):
 * - CONSTANT_DENSITY: rho = 1 (Eq. 13-15), the most opaque ray is a diameter,
 *   lambda = -ln(1 - Theta_i) / (2 r).
 * - SQUARED_DISTANCE_DENSITY: rho = |x - p_i|^2 (Eq. 16-19), the most opaque ray has impact
 *   parameter r / sqrt(2), lambda = -3 ln(1 - Theta_i) / (2 sqrt(2) r^3).
 * - HollowFraction f > 0 (Sec. 4.3): rho = 0 inside the concentric sphere of radius r_s = f r. The
 *   ray's two segments outside the core are composited; since both emit c_i this equals one
 *   segment with the summed integral. lambda is derived from the exact maximum of that integral
 *   over all rays (not the solid sphere's): with b the impact parameter, the integral is
 *   increasing in b on [0, r_s] for both models (its derivative is positive there), so the
 *   maximum is at b = r_s for the constant model, chord 2 r sqrt(1 - f^2), and at
 *   b = max(r_s, r / sqrt(2)) for the squared-distance model, i.e. the solid value 2 sqrt(2) r^3 /
 * 3 for f <= 1/sqrt(2) and 2 r^3 sqrt(1 - f^2) (1 + 2 f^2) / 3 above. See GetMaximumPathIntegral();
 * the tests check it against a numerical maximisation.
 *
 * Numerics. Along a ray the integral is evaluated relative to the ray's closest approach to the
 * centre (impact parameter b, parameter tau from that point), never from the eye: Eq. 17 written
 * from the eye position cancels all its digits with the camera 1e7 radii away. The per-particle
 * optical depth kappa_i = -ln(1 - Theta_i) is computed in double on the CPU (Theta_i = 1 - 1e-7
 * is not a float), and Theta = -expm1(-kappa_i I / I_max) uses series-based expm1/log1p
 * (Shaders/Translucency/EmissionAbsorption.glsl), so the relative error stays below 1e-5 from
 * Theta_i = 1e-6 to 1 - 1e-7 and for grazing rays.
 *
 * Shading (Eq. 2): L_RV = Theta (t_n, t_f) ((1 - VolumeMix) L_R(x_0) + VolumeMix c_i), where
 * L_R is the core's lit surface colour at the entry point x_0 (VTK's lights and material:
 * diffuse = c_i, specular white by default, the ambient coefficient is VTK's and 0 by default,
 * which is the paper's "no ambient term"; VTK's Phong specular lobe is used rather than
 * Blinn-Phong so that opaque and translucent particles match). When the segment starts inside
 * the sphere (eye inside, near plane cutting it) there is no entry surface and L_RV = Theta c_i.
 * With an ambient-occlusion pass (vtkDensityVolumeAOPass, vtkVoxelConeAOPass) the emitted
 * radiance is Eq. 7 evaluated at the entry point, L_E = Theta (A_O ((1 - VolumeMix) L_R +
 * VolumeMix c_i) + alpha_A L_A): the occlusion darkens the surface and the volume part alike,
 * and the ambient illumination scales with the segment's opacity like any emission of the
 * glyph (the paper adds alpha_A L_A without Theta; for a nearly clear particle that would make
 * it glow brighter than an opaque one). A segment without entry surface gets no ambient terms.
 * The background seen through a particle is attenuated by 1 - Theta (front-to-back compositing).
 *
 * Ellipsoids (the core's Shape ELLIPSOID, x = c + A u): the model holds through the affine map.
 * Along a ray the chord, impact parameter and density profile are those of the unit sphere in the
 * ellipsoid's frame (the density is rho(u): constant, or |u|^2, the squared distance measured in
 * the ellipsoid's own proportions; a hollow core is the ellipsoid scaled by f), and one unit of
 * tau is 1 / |A^-1 d| long. The optical depth is a physical density integrated over length: a
 * ray's integral is I_u / |A^-1 d|, and the most opaque ray lies along the longest semi-axis
 * a_max with I_max,u a_max, so Theta_i is the opacity along that axis and a ray along axis k
 * through the centre has 1 - (1 - Theta_i)^(a_k / a_max) (constant density; the tests check this
 * and the squared model's sqrt(2) variant). The sort by centre is no visibility order for
 * ellipsoids (two separate rods can cross in depth), so AUTOMATIC always composites ellipsoids
 * with the exact-overlap lists; SORTED_SPHERES, when asked for, composites each whole in the
 * order of its bounding sphere.
 *
 * Opaque particles (Theta_i = 1) are drawn in the opaque pass exactly as the core draws them,
 * with depth writes; particles with Theta_i = 0 are not drawn at all; only the others take the
 * translucent path. Picking selects every particle with Theta_i > 0.
 *
 * Ordering (paper Sec. 5): the translucent particles are drawn front to back in the order of a
 * GPU radix sort of the particle indices (vtkParticleDepthSort, compute shaders). The key is the
 * power of the eye with respect to the sphere, |p - e|^2 - r^2 (perspective), or the centre depth
 * (parallel projection): for spheres that do not intersect this is an exact visibility order.
 * The sort runs only when the camera, the actor's matrix, the positions or the radii changed;
 * never for colour, opacity or shading changes, and never when no particle is translucent.
 * With SORTED_SPHERES, intersecting spheres (out of the paper's scope) are each composited as a
 * whole in that order, so where two spheres overlap the nearer-by-power one is drawn completely
 * in front (measured error: Documentation/Translucency.md).
 *
 * Overlapping spheres, exactly (OverlapCompositing; beyond the paper, whose Sec. 7 names
 * intersecting spheres as the method's limitation). With EXACT_OVERLAP the translucent fragments
 * go to per-pixel lists (vtkParticleFragmentLists) and each pixel's ray is integrated through
 * the summed densities: where k spheres overlap, sigma = sum_j lambda_j rho_j (Eq. 8 with the
 * densities of Eq. 13 / 16 added) and the emission is sum_j lambda_j rho_j L_j, where L_j is
 * sphere j's colour of Eq. 2 (its lit entry point mixed with c_j by VolumeMix, as for a sphere
 * alone). So a sphere alone, or spheres that do not overlap, give exactly the sorted result, and
 * no sort is needed. The opacity of every interval is exact (closed forms); the colour mix is
 * exact for constant densities and uses 4-point Gauss-Legendre quadrature for squared-distance
 * densities. The lists' GPU memory is bounded by FragmentListMemory (bands when a view does not
 * fit, see vtkParticleFragmentLists). AUTOMATIC (default) uses the lists when two drawn
 * translucent spheres penetrate each other by more than OverlapTolerance of the smaller radius
 * (|p_i - p_j| < s (r_i + r_j - t min(r_i, r_j)), s = RadiusScaleFactor; checked over the
 * occupied cells of a vtkParticleCellList when the positions, radii or opacities change) and
 * the error the sort would make there matters in this view: for every such pair a bound of the
 * sorted path's error in its lens (a_i a_j |L_i - L_j|, from the lens opacities, colours and
 * shading; vtkParticleOverlapError) is found when the particles change, and the lists are used
 * when the lenses whose bound exceeds AutomaticErrorTolerance (2/255) cover more than
 * AutomaticPixelShare (0.01 %) of the viewport in this view; the sort otherwise. Where spheres
 * do not overlap both paths agree; early termination applies to the
 * sorted path only. The lists cost more than the sorted path (measured:
 * Documentation/Translucency.md).
 *
 * Compositing with other geometry: the translucent particles are accumulated front to back in
 * an off-screen float buffer. Each ray segment ends at the opaque depth (a copy of the depth
 * buffer after the opaque pass, including opaque particles), so opaque surfaces inside the cloud
 * occlude what is behind them and cut through the glyphs they intersect. The result is blended
 * over the opaque image. This happens once per frame in the renderer's translucent stage, whether
 * VTK composites translucency with dual depth peeling (ParaView's default) or with its
 * order-independent pass; other translucent geometry is composited in front of the particles.
 *
 * Early termination (paper Sec. 5.2): with EarlyTermination on, the sorted particles are drawn in
 * NumberOfChunks depth chunks; after each chunk, pixels whose accumulated opacity exceeds
 * TerminationOpacity are masked in the depth buffer, so later chunks skip them (early depth
 * test). The image changes by at most 1 - TerminationOpacity per channel.
 *
 * Interactive frames (GetFrameBudget(), vtkParticleFrameBudget): three levels. The exact level
 * composites as OverlapCompositing and EarlyTermination say; the two interactive levels draw the
 * sorted spheres whatever they say: the cheapest into an accumulation of half the viewport's
 * resolution in each direction (a quarter of the fragments, the cost of this stage; composited
 * with bilinear upsampling over the full-resolution opaque image, so that only translucent
 * silhouettes and edges against opaque geometry blur by a pixel), the next at full resolution
 * with early termination (NumberOfChunks, TerminationOpacity). Still frames and frames whose
 * measured exact time fits the window's desired update rate are exact; the sort, the opaque
 * particles and the picking are the same at every level.
 *
 * Requires OpenGL 4.3 (compute shaders, shader storage buffers) for the translucent path; on an
 * older context an error says so and translucent particles are drawn opaque.
 *
 * @sa vtkParticleSphereMapper vtkParticleDepthSort vtkParticleReferenceRenderer
 */
#ifndef vtkTransparentSphereMapper_h
#define vtkTransparentSphereMapper_h

#include "vtkParticleEmissionModel.h"               // for DensityModels
#include "vtkParticleRenderingTranslucencyModule.h" // for export macro
#include "vtkParticleSphereMapper.h"

class vtkDoubleArray;
class vtkParticleDepthSort;
class vtkParticleFragmentLists;
class vtkParticleFrontToBackTarget;

class VTKPARTICLERENDERINGTRANSLUCENCY_EXPORT vtkTransparentSphereMapper
  : public vtkParticleSphereMapper
{
public:
  static vtkTransparentSphereMapper* New();
  vtkTypeMacro(vtkTransparentSphereMapper, vtkParticleSphereMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum DensityModels
  {
    CONSTANT_DENSITY = vtkParticleEmissionModel::CONSTANT_DENSITY,
    SQUARED_DISTANCE_DENSITY = vtkParticleEmissionModel::SQUARED_DISTANCE_DENSITY
  };

  ///@{
  /**
   * Density inside a glyph: CONSTANT_DENSITY (default) or SQUARED_DISTANCE_DENSITY.
   */
  vtkSetClampMacro(DensityModel, int, CONSTANT_DENSITY, SQUARED_DISTANCE_DENSITY);
  vtkGetMacro(DensityModel, int);
  void SetDensityModelToConstant() { this->SetDensityModel(CONSTANT_DENSITY); }
  void SetDensityModelToSquaredDistance() { this->SetDensityModel(SQUARED_DISTANCE_DENSITY); }
  ///@}

  ///@{
  /**
   * Radius of the empty core as a fraction of the radius, in [0, 0.999]. 0 (default): solid.
   */
  vtkSetClampMacro(HollowFraction, double, 0.0, 0.999);
  vtkGetMacro(HollowFraction, double);
  ///@}

  ///@{
  /**
   * alpha_RV of Eq. 2 in [0, 1]: 0 is pure surface reflection, 1 pure volume emission. Default
   * 0.5. The emitted colour c_i is the material's diffuse colour (the property's Diffuse times
   * the particle colour), so with Diffuse 0 the volume emits black.
   */
  vtkSetClampMacro(VolumeMix, double, 0.0, 1.0);
  vtkGetMacro(VolumeMix, double);
  ///@}

  enum OpacityReferences
  {
    PARTICLE_OPACITY = 0, // Theta_i: the densest chord through one particle (the paper)
    COLUMN_OPACITY = 1    // Theta_i: a column of ColumnLayers particles, one behind the other
  };

  ///@{
  /**
   * What Theta_i is the opacity of. PARTICLE_OPACITY (default, Staib et al. 2015 Sec. 3.1): the
   * densest chord through one particle. COLUMN_OPACITY: a column of L particles one behind the
   * other, so that the interior of dense data stays visible -- every particle's optical depth
   * -ln(1 - Theta_i) is divided by L (the same as L times the maximum path integral I_max of
   * Eq. 15/19), and L particles in a row compound to Theta_i. ColumnLayers is L; 0 (default)
   * estimates it from the data as the expected number of full chords a ray crosses along the
   * longest side of the particles' box: (N / A) pi r^2 (2/3), N the particles, A the area of the
   * box face across that side, r the mean radius, 2/3 a sphere's mean chord over its diameter
   * (exact for constant density, an approximation for the other models), at least 1. Opaque
   * particles (Theta_i = 1) stay opaque.
   */
  vtkSetClampMacro(OpacityReference, int, PARTICLE_OPACITY, COLUMN_OPACITY);
  vtkGetMacro(OpacityReference, int);
  vtkSetClampMacro(ColumnLayers, double, 0.0, 1e9);
  vtkGetMacro(ColumnLayers, double);
  /**
   * The L in use: 1 for PARTICLE_OPACITY, else ColumnLayers or its estimate (see above).
   */
  double GetEffectiveColumnLayers();

  /**
   * The layer estimate of COLUMN_OPACITY for `count` drawn particles whose radii (before the
   * scale factor) sum to `radiusSum`, in the sphere bounds `bounds` (radii included): the
   * expected number of full chords along the longest side, (N / A) pi r^2 (2/3), at least 1.
   * Public so that distributed rendering (vtkParticleRepresentation) can give every process
   * the estimate of all particles (SetColumnLayers).
   */
  static double EstimateColumnLayers(double count, double radiusSum, const double bounds[6]);
  ///@}

  ///@{
  /**
   * Name of a one-component numeric point array giving each particle's maximum opacity through
   * OpacityRange. Empty (default): every particle has Theta_a = 1 and the actor's opacity (and
   * scalar alpha) alone sets Theta_i. A missing or unusable array gives a warning and Theta_a = 1;
   * NaN values give Theta_a = 0.
   */
  vtkSetStringMacro(OpacityArrayName);
  vtkGetStringMacro(OpacityArrayName);
  ///@}

  ///@{
  /**
   * Array values mapped linearly to Theta_a = 0 and 1 (clamped outside). Default (0, 1). A range
   * with equal ends maps values below it to 0 and the others to 1.
   */
  vtkSetVector2Macro(OpacityRange, double);
  vtkGetVector2Macro(OpacityRange, double);
  ///@}

  ///@{
  /**
   * Early termination by depth chunks (paper Sec. 5.2). Default off: on llvmpipe it did not pay
   * (measured: Documentation/Translucency.md).
   */
  vtkSetMacro(EarlyTermination, bool);
  vtkGetMacro(EarlyTermination, bool);
  vtkBooleanMacro(EarlyTermination, bool);
  ///@}

  ///@{
  /**
   * Number of depth chunks with EarlyTermination (default 20) and the accumulated opacity above
   * which a pixel is masked (default 0.996, i.e. at most 1/255 of the colour is dropped).
   */
  vtkSetClampMacro(NumberOfChunks, int, 1, 1024);
  vtkGetMacro(NumberOfChunks, int);
  vtkSetClampMacro(TerminationOpacity, double, 0.5, 1.0);
  vtkGetMacro(TerminationOpacity, double);
  ///@}

  enum OverlapCompositingModes
  {
    AUTOMATIC = 0,      // exact where the data has overlapping translucent spheres, else sorted
    SORTED_SPHERES = 1, // the paper: each sphere composited whole in depth order
    EXACT_OVERLAP = 2   // per-pixel lists, overlaps integrated exactly
  };

  ///@{
  /**
   * How overlapping translucent spheres are composited (see the class description): AUTOMATIC
   * (default), SORTED_SPHERES or EXACT_OVERLAP.
   */
  vtkSetClampMacro(OverlapCompositing, int, AUTOMATIC, EXACT_OVERLAP);
  vtkGetMacro(OverlapCompositing, int);
  ///@}

  ///@{
  /**
   * AUTOMATIC composites exactly when two drawn translucent spheres penetrate each other by more
   * than this fraction of the smaller radius (|p_i - p_j| < s (r_i + r_j - t min(r_i, r_j))),
   * default 0.25. Below it the lens two spheres share is thin and the sorted path is close
   * (measured: Documentation/Translucency.md). 0 uses the lists for any
   * overlap.
   */
  vtkSetClampMacro(OverlapTolerance, double, 0.0, 2.0);
  vtkGetMacro(OverlapTolerance, double);
  ///@}

  ///@{
  /**
   * GPU memory for the exact-overlap lists in MiB (default 256): the head array (4 bytes per
   * pixel) and 40 bytes per translucent fragment. A view whose fragments do not fit is drawn in
   * bands (the particles drawn once per band).
   */
  vtkSetClampMacro(FragmentListMemory, double, 1.0, 1.0e7);
  vtkGetMacro(FragmentListMemory, double);
  ///@}

  /**
   * Whether the last translucent frame used the exact-overlap lists, and whether two drawn
   * spheres penetrate each other by more than OverlapTolerance (computed when the particles
   * changed; used by AUTOMATIC).
   */
  bool GetExactOverlapInUse();
  bool HasOverlappingSpheres();

  ///@{
  /**
   * AUTOMATIC's error estimate (see the class description): the lists are used when the sorted
   * spheres may be off by more than AutomaticErrorTolerance (in 1/255, default 2) on more than
   * AutomaticPixelShare of the viewport's pixels (default 1e-4): the suite's own image
   * criterion.
   */
  vtkSetClampMacro(AutomaticErrorTolerance, double, 0.0, 255.0);
  vtkGetMacro(AutomaticErrorTolerance, double);
  vtkSetClampMacro(AutomaticPixelShare, double, 0.0, 1.0);
  vtkGetMacro(AutomaticPixelShare, double);
  ///@}

  /**
   * The estimate of the last AUTOMATIC frame: pixels the sorted spheres may put over
   * AutomaticErrorTolerance (0 when no pair penetrates deeper than OverlapTolerance), and the
   * largest bound of a pair's error in 1/255 (vtkParticleOverlapError).
   */
  double GetEstimatedOverlapErrorPixels();

  /**
   * The frame budget's levels: "half resolution, sorted spheres|sorted spheres, early
   * termination|exact" (the first accumulates at half the viewport's resolution in each
   * direction, vtkParticleFrontToBackTarget::SetDownsampling, and upsamples bilinearly).
   */
  std::string GetQualityLevelNames() override;
  double GetLargestOverlapErrorBound();

  /**
   * The exact-overlap lists (statistics of the last frame: fragments, bands, incomplete pixels).
   */
  vtkParticleFragmentLists* GetFragmentLists();

  /**
   * The maximum over all rays of the density integral through a sphere of radius 1, the I_max
   * that sets lambda (see the class description): 2 sqrt(1 - f^2) for CONSTANT_DENSITY, for
   * SQUARED_DISTANCE_DENSITY 2 sqrt(2) / 3 when f <= 1/sqrt(2), else 2 sqrt(1 - f^2) (1 + 2 f^2)
   * / 3. For a sphere of radius r multiply by r (constant) or r^3 (squared distance).
   */
  static double GetMaximumPathIntegral(int densityModel, double hollowFraction);

  ///@{
  /**
   * The emission-absorption model of these glyphs, for passes that integrate light through the
   * particles (vtkParticleSphereMapper's contract): the density model, the hollow fraction and
   * GetParticleOpacities().
   */
  bool GetEmissionAbsorptionGlyphs() override;
  int GetEmissionDensityModel() override;
  double GetEmissionHollowFraction() override;
  vtkDoubleArray* GetEmissionOpacities() override;
  ///@}

  /**
   * Theta_a of every particle as used for drawing (the mapped opacity array, or 1), valid after
   * the mapper has prepared its input (a render or GetBounds()). Used by the reference renderer.
   */
  vtkDoubleArray* GetParticleOpacities();

  ///@{
  /**
   * Counters: the number of depth sorts and opacity uploads so far.
   */
  vtkGetMacro(NumberOfSorts, vtkIdType);
  vtkGetMacro(NumberOfOpacityUploads, vtkIdType);
  ///@}

  ///@{
  /**
   * Per-stage GPU times of the last translucent frame (with CollectTimings on, from timer
   * queries; the first call after a frame waits for the GPU to finish it): sort (keys and radix
   * sort, 0 when the sort was skipped), translucent drawing (all chunks and masks) and the rest
   * (copy of the opaque depth, clears, final blend). On llvmpipe a timer query around a draw
   * call measures little more than its submission.
   */
  double GetLastSortGPUSeconds();
  double GetLastTranslucentDrawGPUSeconds();
  double GetLastCompositeGPUSeconds();
  ///@}

  ///@{
  /**
   * The compositing target and the sort, for tests and benchmarks (e.g. to keep and read the
   * float accumulation of the last frame, or count masked pixels).
   */
  vtkParticleFrontToBackTarget* GetFrontToBackTarget();
  vtkParticleDepthSort* GetDepthSort();
  ///@}

  /**
   * Translucent particles are composited by the mapper, opaque ones like the core's.
   */
  bool HasOpaqueGeometry() override;
  bool HasTranslucentPolygonalGeometry() override;

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkTransparentSphereMapper();
  ~vtkTransparentSphereMapper() override;

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void BuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;
  void CacheParticleAttributes(vtkRenderer* ren, vtkActor* act) override;
  // the translucent variant writes no depth: no occlusion test there
  // translucent variants clip the chords' segments to the clip box themselves
  bool GetClipBoxBySegment() override;
  bool GetOcclusionCullingCompiled(vtkRenderer* ren) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;

  /**
   * Map the opacity array to Theta_a and the optical depths uploaded to the GPU. Cached on the
   * input's and the mapper's modification times.
   */
  void PrepareOpacities();

  /**
   * Read the timer queries of the last translucent frame (blocking).
   */
  void FetchTimings();

  /**
   * The translucent stage at the level the frame budget picks (GetFrameBudget(), timed there):
   * sort when needed, accumulate front to back, blend over the opaque image.
   */
  void RenderTranslucentParticles(vtkRenderer* ren, vtkActor* act, bool savedByPass);

  /**
   * The translucent stage at the exact level (OverlapCompositing and EarlyTermination as set) or
   * an interactive one (sorted spheres at the target's resolution; early termination at full
   * resolution).
   */
  void RenderTranslucentLevel(vtkRenderer* ren, vtkActor* act, bool savedByPass, bool exact);

  /**
   * AUTOMATIC: whether the sorted spheres may miss the image criterion in this view.
   */
  bool AutomaticNeedsExactOverlap(vtkRenderer* ren, vtkActor* act);

  /**
   * Compute the sort keys and sort, unless the camera, actor matrix and particle geometry are
   * those of the last sort. Returns false when the sort could not run.
   */
  bool UpdateSortedOrder(vtkRenderer* ren, vtkActor* act, vtkIdType count);

  /**
   * Select the translucent variant (sorted glyphs, or list appends), its culling and scalar
   * alpha for this frame, and build and bind its program.
   */
  void ReadyTranslucentVariant(vtkRenderer* ren, vtkActor* act, bool lists);

  /**
   * The translucent stage with exact overlaps: fragments to per-pixel lists, resolved into the
   * front-to-back target. False when the lists could not be made (nothing drawn).
   */
  bool RenderTranslucentLists(vtkRenderer* ren, vtkActor* act, bool savedByPass);

  int DensityModel = CONSTANT_DENSITY;
  double HollowFraction = 0.0;
  double VolumeMix = 0.5;
  int OpacityReference = PARTICLE_OPACITY;
  double ColumnLayers = 0.0;
  double EstimatedColumnLayers = 1.0;
  vtkMTimeType EstimatedColumnLayersTime = 0;
  char* OpacityArrayName = nullptr;
  double OpacityRange[2] = { 0.0, 1.0 };
  bool EarlyTermination = false;
  int NumberOfChunks = 20;
  double TerminationOpacity = 0.996;
  int OverlapCompositing = AUTOMATIC;
  double FragmentListMemory = 256.0;
  double OverlapTolerance = 0.25;
  double AutomaticErrorTolerance = 2.0;
  double AutomaticPixelShare = 1.0e-4;

  vtkIdType NumberOfSorts = 0;
  vtkIdType NumberOfOpacityUploads = 0;
  double LastSortGPUSeconds = 0.0;
  double LastTranslucentDrawGPUSeconds = 0.0;
  double LastCompositeGPUSeconds = 0.0;

private:
  vtkTransparentSphereMapper(const vtkTransparentSphereMapper&) = delete;
  void operator=(const vtkTransparentSphereMapper&) = delete;

  // the depth sort's ProgressEvent, passed on as this mapper's (ProgressThreshold)
  void ForwardSortProgress(vtkObject*, unsigned long, void* callData);

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
