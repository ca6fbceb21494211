/**
 * @class   vtkPointAOPass
 * @brief   screen-space ambient occlusion for glyphs and any opaque geometry: PointAO
 *          (Eichelbaum, Scheuermann, Hlawitschka 2013)
 *
 * vtkPointAOPass is a vtkImageProcessingPass. Its delegate (in ParaView the Particle Render
 * View's chain, in VTK e.g. a vtkRenderStepsPass inside a vtkCameraPass) renders the scene into a
 * G-buffer -- colour, window depth and view-space normal -- and the pass then computes, per
 * pixel, the ambient occlusion from the depth buffer, blurs it depth-aware and darkens the colour
 * with it. Cost is per pixel, not per fragment or particle, and nothing is precomputed: it works
 * for any opaque geometry in the view. The particle mappers give exact sphere normals and depths;
 * other VTK geometry writes its own interpolated normal, and geometry without one (unlit lines,
 * points) gets the normal of its depth buffer.
 *
 * The method (paper Sec. 3-4, after LineAO, Eichelbaum et al. 2013, Eqs. 1, 6-7). For a pixel
 * P with view-space position p and normal n, L hemispheres of growing radius R_1 < ... < R_L
 * ("distance levels", j = 1..L) each give an occlusion
 *
 *     AO_j(P) = sum_i (1 - V_j(w_i)) <w_i, n>  /  sum_i <w_i, n>                   (Eq. 1)
 *
 * and the pixel's colour is multiplied by A = clamp(1 - Strength * (1/L) sum_j AO_j, 0, 1)
 * (LineAO's mean over the levels). The directions w_i (SamplesPerLevel of them) are stratified
 * in cos(theta) -- uniform in the solid angle -- with golden-ratio azimuths and a per-pixel
 * random rotation; the weight <w, n> is the paper's replacement of LineAO's light-based weight,
 * and dividing by its sum makes a fully occluded hemisphere 1: the cosine-weighted occlusion the
 * reference ray tracer computes. Level j samples each direction at j points spread over its
 * shell (R_{j-1}, R_j] -- j SamplesPerLevel samples, more on the outer levels as the paper asks;
 * more, up to 4 j, where the shell is wider than the pixel's particle radius, so that a ray
 * does not step over a particle -- and 1 - V_j(w) is how much of the ray p + t w, t <= R_j,
 * is blocked so far (once blocked
 * it stays blocked for the outer levels). A sample point S is tested against the depth buffer
 * at its pixel, where the surface o is seen:
 * - S in front of o, or o on the pixel's own sphere: open;
 * - o on a particle: S inside that (visible) sphere blocks the ray; S behind it but within
 *   Thickness of o lies in a hidden sphere with the probability HiddenFraction (the packing
 *   of the particles behind the visible ones): the ray's transmittance is multiplied by
 *   1 - HiddenFraction;
 * - o on other geometry: S behind o within Thickness blocks (the surface is taken to be
 *   Thickness deep); farther behind, the ray passes behind it.
 * This is the paper's depth-based weight made exact where the G-buffer knows the geometry: the
 * particle mappers write, with the normal, the sphere's radius, so the sphere behind each
 * pixel is known. An occluder far in front of P (across a depth gap) is never "inside", so a
 * near object does not darken a far one: no halo around silhouettes.
 *
 * Choices where the paper is vague (written down as asked by the project):
 * - Radius rule. The paper's radius of level j is (1 / (1 - d(P))) z(P) (j^2 + j r0), z the zoom
 *   and d the depth. Here the hemispheres live in world (view) units, which makes the result
 *   independent of the zoom and of the window size by construction (the paper's z(P) is the
 *   projected size of a world unit): R_j = Radius * f(P) * (j^2 + j r0) / (L^2 + L r0), so the
 *   outermost level has radius Radius (like vtkSSAOPass's radius and the reference's AO
 *   distance) and r0 = BaseRadius shapes the spacing (r0 = 1: R_j = Radius / 3, Radius for
 *   L = 2; Radius * 2/12, 6/12, 12/12 for L = 3). The paper's depth term 1 / (1 - d), d = 1 at the
 * far plane, is unbounded and, with window depth, depends on the clipping planes (a perspective
 * scene's middle sits at d > 0.9); f(P) = 1 / (1 - d/2) with d the linear depth over the clipping
 * range keeps its intent -- crisp local shading in front, wider shadows behind -- bounded to [1,
 * 2]. DepthScaling off gives f = 1 (the radius of the reference's AO everywhere).
 * - Rays through the levels instead of independent points per level (LineAO's samples are
 *   points in the hemisphere): independent points measure how much of the hemisphere's volume
 *   is filled, not whether the directions are blocked.
 * - No Gaussian pyramid: every level reads the full-resolution buffers (LineAO's
 *   implementation default too; the per-pixel rotation and the blur take the noise).
 * - Strength 1.4 by default: the mean over the levels counts an occluder at distance t once
 *   per level whose radius exceeds t, i.e. less than the ray-traced occlusion within Radius;
 *   (measured best strengths against that reference: Documentation/AmbientOcclusion.md).
 * - Blur. A separable 9 x 9 Gaussian whose taps are weighted by 1 / (1 + (dz / t)^2), dz their
 *   view-depth difference to the centre pixel and t half the innermost radius: it does not
 *   smear the occlusion across silhouettes. The vertical half runs in the composite (one
 *   full-screen pass less). Off: the raw, noisy estimate.
 * - Radius 0 (default) means automatic: four mean particle radii (over the visible
 *   vtkParticleSphereMapper props, at most 65536 of each mapper's drawn radii, read again only
 *   when the particles, radii or actor placement change), or 2 % of the visible props'
 *   bounding-box diagonal when there are no particles.
 * - Translucent geometry (ParaView's depth peeling, vtkTransparentSphereMapper) is drawn over
 *   the opaque scene by the delegate; the occlusion of the opaque surface behind a translucent
 *   layer darkens the composited pixel (as vtkSSAOPass does). Translucent surfaces are not
 *   occluders and are not darkened where nothing opaque lies behind them: translucent
 *   particles get a warning (once) pointing to the object-space passes.
 *
 * The same frame gives the same picture. The G-buffer holds, besides colour and depth, the
 * normal (times 3 + the sphere's radius) and a stamp of the fragment that wrote it (its window
 * depth plus a key): a normal is used only where the stamp matches the depth buffer. The normal
 * targets are drawn only while every visible prop is an opaque vtkActor: the passes that draw
 * translucent geometry (depth peeling), volumes and 2D overlays write into the G-buffer with
 * shaders that leave those targets undefined -- garbage or the old value, by tile and thread on
 * llvmpipe -- so with any of them in view the occlusion takes the depth buffer's normals (no
 * own-sphere exclusion: a little more occlusion on the particles' rims). The renderer's FXAA
 * (vtkRenderer::UseFXAA, on in ParaView by default) would run inside the delegate over every
 * G-buffer target: it is held back and applied to the composited picture instead
 * (vtkParticleGBufferGuard), so a renderer that asks for FXAA gets it on PointAO's picture even
 * under a delegate that ignores it (vtkRenderStepsPass).
 *
 * A renderer whose viewport does not fill its window (several renderers side by side in one
 * plain VTK window) is drawn without ambient occlusion, with a warning: the delegate's camera
 * pass sets up the window's viewport, not the G-buffer's. ParaView's views fill their windows.
 *
 * Interactive frames (GetFrameBudget(), vtkParticleFrameBudget): two levels, HalfResolution
 * (level 0) and the resolution set (exact). The occlusion and its composite are timed, not the
 * scene the delegate draws.
 *
 * The shader code does not depend on the settings (uniforms), so changing them recompiles
 * nothing. Needs OpenGL 3.2 (fragment shaders only). GetStageSeconds() gives GPU times of the
 * stages (timer queries) when CollectTimings is on.
 *
 * @sa vtkSSAOPass vtkDensityVolumeAOPass vtkVoxelConeAOPass vtkParticleSphereMapper
 */
#ifndef vtkPointAOPass_h
#define vtkPointAOPass_h

#include "vtkParticleAmbientLightPass.h"
#include "vtkParticleRenderingAmbientOcclusionModule.h" // for export macro

class vtkMultiProcessController;

class VTKPARTICLERENDERINGAMBIENTOCCLUSION_EXPORT vtkPointAOPass
  : public vtkParticleAmbientLightPass
{
public:
  static vtkPointAOPass* New();
  vtkTypeMacro(vtkPointAOPass, vtkParticleAmbientLightPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * SCREEN_SPACE: the occlusion darkens the composited image.
   */
  int GetOcclusionSpace() override;

  ///@{
  /**
   * Number of hemispheres L (paper: "distance levels"). Default 3 (LineAO's default).
   */
  vtkSetClampMacro(NumberOfLevels, int, 1, 16);
  vtkGetMacro(NumberOfLevels, int);
  ///@}

  ///@{
  /**
   * Directions per pixel; level j takes j samples along each, so j SamplesPerLevel in all
   * (more on the outer levels). Default 4 (24 samples per pixel with 3 levels at the automatic
   * radius; fewer where a ray is blocked early or leaves the view).
   */
  vtkSetClampMacro(SamplesPerLevel, int, 1, 256);
  vtkGetMacro(SamplesPerLevel, int);
  ///@}

  ///@{
  /**
   * Radius of the outermost hemisphere in world units (before DepthScaling). 0 (default):
   * automatic, see the class comment; GetEffectiveRadius() says what the last frame used.
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);
  vtkGetMacro(EffectiveRadius, double);
  ///@}

  ///@{
  /**
   * The paper's r0 in R_j ~ j^2 + j r0: larger values space the levels more evenly (r0 -> inf:
   * linear). Default 1.
   */
  vtkSetClampMacro(BaseRadius, double, 0.0, 1000.0);
  vtkGetMacro(BaseRadius, double);
  ///@}

  ///@{
  /**
   * How deep the scene is taken to be behind the surface the depth buffer shows, as a fraction
   * of Radius (see the class comment): a sample point less than this behind the visible
   * surface at its pixel may be inside an occluder, a point farther behind passes behind it.
   * Default 2 (with the automatic Radius eight mean particle radii; chosen against ray-traced
   * occlusion, measured: Documentation/AmbientOcclusion.md).
   */
  vtkSetClampMacro(Thickness, double, 0.0, 100.0);
  vtkGetMacro(Thickness, double);
  ///@}

  ///@{
  /**
   * The probability that a sample point behind a visible sphere (within Thickness, not inside
   * it) lies in a hidden particle: the packing fraction behind the visible surface. Default 0.5
   * (a dense liquid; an FCC crystal packs 0.74).
   */
  vtkSetClampMacro(HiddenFraction, double, 0.0, 1.0);
  vtkGetMacro(HiddenFraction, double);
  ///@}

  ///@{
  /**
   * The paper's depth term: radii grow from 1x at the near clipping plane to 2x at the far one.
   * Default on.
   */
  vtkSetMacro(DepthScaling, bool);
  vtkGetMacro(DepthScaling, bool);
  vtkBooleanMacro(DepthScaling, bool);
  ///@}

  ///@{
  /**
   * A = clamp(1 - Strength * occlusion, 0, 1). Default 1.4 (see the class comment).
   */
  vtkSetClampMacro(Strength, double, 0.0, 100.0);
  vtkGetMacro(Strength, double);
  ///@}

  ///@{
  /**
   * Depth-aware blur of the occlusion. Default on.
   */
  vtkSetMacro(Blur, bool);
  vtkGetMacro(Blur, bool);
  vtkBooleanMacro(Blur, bool);
  ///@}

  ///@{
  /**
   * Occlusion and blur at half the window's size (every second pixel of the G-buffer), brought
   * back to full size by a depth-aware upsampling in the composite: about a quarter of their
   * cost. Default off.
   */
  vtkSetMacro(HalfResolution, bool);
  vtkGetMacro(HalfResolution, bool);
  vtkBooleanMacro(HalfResolution, bool);
  ///@}

  /**
   * The frame budget's levels: "half resolution|full resolution".
   */
  std::string GetQualityLevelNames() override { return "half resolution|full resolution"; }

  ///@{
  /**
   * GPU time of the last Render()'s stages (timer queries, read at the next Render() or by
   * GetStageSeconds): 0 the scene into the G-buffer, 1 the occlusion, 2 the horizontal blur,
   * 3 the composite with the vertical blur (and the renderer's FXAA, when it asks for it).
   * Off by default (the queries cost a little).
   */
  vtkSetMacro(CollectTimings, bool);
  vtkGetMacro(CollectTimings, bool);
  double GetStageSeconds(int stage);
  ///@}

  ///@{
  /**
   * Distributed rendering: the processes whose pictures are composited by depth after this pass
   * (IceT in ParaView; the Particle Render View sets it for each distributed render). With more
   * than one, every process's G-buffer depth and normals are composited over all of them before
   * the occlusion (vtkParticleGBufferExchange), so each process sees the occluders the others
   * draw, and the automatic Radius is the mean over all processes' particles; each process
   * darkens its whole premultiplied colour by the occlusion of that composited front surface
   * (so translucent particles in front of another process's surface are darkened as one process
   * darkens them) and writes its own depth. Collective: every
   * process must render the pass each frame. nullptr (default): this process's G-buffer only.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController();
  ///@}

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;

protected:
  vtkPointAOPass();
  ~vtkPointAOPass() override;

  int NumberOfLevels = 3;
  int SamplesPerLevel = 4;
  double Radius = 0.0;
  double EffectiveRadius = 0.0;
  double BaseRadius = 1.0;
  double Thickness = 2.0;
  double HiddenFraction = 0.5;
  bool DepthScaling = true;
  double Strength = 1.4;
  bool Blur = true;
  bool HalfResolution = false;
  bool CollectTimings = false;

private:
  vtkPointAOPass(const vtkPointAOPass&) = delete;
  void operator=(const vtkPointAOPass&) = delete;

  ///@{
  /**
   * The stages of Render(), in order. PrepareFrame returns false when the frame is drawn
   * without occlusion (no OpenGL window, an empty or partial viewport).
   */
  bool PrepareFrame(const vtkRenderState* s);
  void InspectProps(const vtkRenderState* s);
  void UpdateEffectiveRadius(const vtkRenderState* s);
  void RenderGBuffer(const vtkRenderState* s);
  void ExchangeGBuffer();
  void SetUpProjection();
  void ComputeOcclusion();
  void BlurOcclusion();
  void Composite();
  void ApplyHeldBackFXAA();
  ///@}

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
