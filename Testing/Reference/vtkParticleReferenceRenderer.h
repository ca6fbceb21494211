/**
 * @class   vtkParticleReferenceRenderer
 * @brief   double-precision CPU ray caster that renders what vtkParticleSphereMapper should draw
 *
 * vtkParticleReferenceRenderer is the ground truth for the GPU sphere core and for the translucent
 * glyphs of vtkTransparentSphereMapper (see "Transparent mode" below). It renders the spheres
 * of one actor whose mapper is a vtkParticleSphereMapper, seen through the active camera of a
 * renderer and lit by that renderer's lights, entirely in double precision on the CPU:
 *
 * - Rays: one per pixel, through the pixel centre (x+0.5, y+0.5). The ray is obtained by
 *   unprojecting the pixel's near- and far-plane points through the inverse of the camera's
 *   projection matrix, GetProjectionTransformMatrix(aspect, -1, 1), and lives in view coordinates
 *   (camera->GetModelViewTransformMatrix()), like the GPU's. Perspective rays start at the eye;
 *   parallel rays start at the plane z_VC = 0 (the plane of the camera position).
 * - Spheres: the centres are the input points transformed by the actor's matrix and the view
 *   matrix in double (the mapper uploads float positions, so for data far from the origin the
 *   GPU's spheres are displaced by that rounding and the reference's are not); the radii are the
 * mapper's GetParticleRadii() times GetRadiusScaleVC(actor), or, with SetParticleAttributes(), the
 * caller's radii times |det(actor matrix)|^(1/3). Skipped particles (radius 0), particles clipped
 * by the mapper's clipping planes (by their centre, as on the GPU) and particles with opacity 0
 * (all their fragments are discarded on the GPU) are not drawn.
 * - Intersection: in the sphere-relative form of Shaders/Core/RaySphere.glsl (closest approach
 * point relative to the centre, no cancellation). The visible surface is the first intersection
 * that lies in front of the eye and within the near and far planes (tested with the projection
 *   matrix exactly like the GPU: clip w > 0 and -1 <= z/w <= 1). When the entry point is clipped
 *   the exit point is used and the normal is flipped towards the viewer. Between spheres the
 *   nearest visible hit wins; on an exact tie the larger particle id wins (the GPU's depth test is
 *   GL_LEQUAL and particles are drawn in id order).
 * - Shading: VTK 9.2's Phong model exactly as the mapper's fragment shader evaluates it
 *   (Shaders/Core/Lighting.glsl, vtkParticleSphereMapper::ReplaceShaderLight), with the lighting
 *   complexity and light uniforms derived as vtkOpenGLRenderer::UpdateLights and
 *   UpdateLightingUniforms do (headlights and camera lights follow the camera when the
 *   renderer's LightFollowCamera is on; a headlight is assumed when no light is on and
 *   AutomaticLightCreation is on). Material as vtkOpenGLPolyDataMapper: ambient = Ambient *
 *   (AmbientColor or scalar rgb), diffuse = Diffuse * (DiffuseColor or scalar rgb), specular =
 *   Specular * SpecularColor, opacity = Opacity * scalar alpha; scalar colours are the mapper's
 *   MapScalars(1.0), 8-bit RGBA exactly as uploaded to the GPU. The colour is clamped to [0,1]
 *   like an 8-bit framebuffer, but not quantised.
 *
 * Outputs (all images bottom-up, x fastest, like vtkRenderWindow::GetRGBAPixelData):
 * - GetColorImage(): 4-component double RGBA in [0,1]; the background colour and
 *   BackgroundAlpha where no sphere is hit (what vtkOpenGLRenderer clears to), the fragment's
 *   opacity as alpha on spheres.
 * - GetDepthImage(): window depth in [0,1] computed as the GPU does (clip = P * hitVC,
 *   depth = 0.5 * z/w + 0.5), 1 for the background.
 * - GetViewDepthImage(): distance along the ray from its origin to the hit (eye distance in
 *   perspective, distance from the camera plane in parallel projection), -1 for the background.
 * - GetIdImage(): the particle (point) id, -1 for the background.
 * - GetNormalImage(): 3-component double, the unit normal (view coordinates) used for shading,
 *   facing the viewer also on inner surfaces; (0,0,0) for the background. With the pixel rays
 *   (GetPixelRay) it gives the incidence angle, i.e. how ill-conditioned a pixel's depth is: a
 *   ray perturbed sideways by e changes the hit distance by about e / cos(incidence).
 * - GetInsideImage(): 1 where the visible surface is the inner side of a sphere (its entry point
 *   is clipped by the near plane, or the eye is inside), 0 elsewhere. Where this changes within
 *   one particle the image is discontinuous like at a silhouette: comparisons should mask
 *   changes of (id, inside), see GetSurfaceIdImage().
 *
 * Acceleration: a uniform grid over the spheres' bounding boxes in view coordinates, traversed
 * with a 3D-DDA from the near to the far plane; spheres that would cover very many cells are kept
 * in a separate list tested by every ray. Image rows are rendered in parallel with vtkSMPTools
 * (Debian's VTK defaults to the Sequential backend: select STDThread with
 * vtkSMPTools::SetBackend("STDThread") or VTK_SMP_BACKEND_IN_USE=STDThread). 1e5 spheres at
 * 512x512 take about 0.1 s on 2 cores (opaque mode); in the transparent mode, which visits every
 * cell along each ray and integrates every segment, 1e4 translucent spheres at 512x512 take
 * about 0.7 s.
 * No output value is ever NaN: a non-finite shading result (degenerate lights) is treated like the
 * GPU's discard (background).
 *
 * Metaball mode: when the actor's mapper is a vtkMetaballMapper, Render() draws the exact metaball
 * surface of the same spheres (vtkParticleReferenceMetaballs with the mapper's InfluenceFactor and
 * IsoValue): per pixel the first crossing between the near and far planes, the gradient normal,
 * the colour blended from the contributing particles' 8-bit colours by their field share D_j,
 * lit as in the opaque mode; the id image holds the particle with the largest share. Pixels
 * whose ray starts inside the surface (the near plane cuts it) are background with Inside = 1.
 *
 * Transparent mode: when the actor's mapper is a vtkTransparentSphereMapper, Render() evaluates
 * the emission-absorption model of that class (Staib et al. 2015, Sec. 3.1 and 4) exactly, in
 * double, and composites every particle a pixel ray meets:
 * - Theta_i = Theta_a (the mapper's GetParticleOpacities()) * property Opacity * scalar alpha.
 *   With the mapper's COLUMN_OPACITY, I_max below is multiplied by its
 *   GetEffectiveColumnLayers() (the opacity of a column of that many particles).
 *   Particles with Theta_i <= 0 are not drawn. Particles with Theta_i >= 1 are opaque: their
 *   visible surface and colour are exactly those of the opaque mode; like the GPU's opaque pass
 *   (depth writes) they end every translucent segment at their hit and their colour replaces the
 *   background (for spheres that do not intersect this is "composite, then stop").
 * - Segments: every sphere the ray crosses (all grid cells between the near and far plane and the
 *   large-sphere list, deduplicated) gives its chord [t_n, t_f], clipped to the visible part of
 *   the ray with the opaque mode's rule (clip w > 0, -1 <= z/w <= 1: when the entry point fails
 *   it, the segment starts at the near plane, or is hidden when the entry lies beyond the far
 *   plane; when the exit point fails it, the segment ends at the far plane) and to the opaque
 *   depth (SetOpaqueLayer(), opaque particles).
 * - Opacity of a segment: Theta = -expm1(log1p(-Theta_i) I / I_max(r)), I the density integral
 *   along the segment (IntegrateDensity()), I_max the maximum over all rays of the full-chord
 *   integral (NumericalMaximumPathIntegral(), r or r^3 times the value for r = 1). Both are
 *   numerical: adaptive Gauss-Kronrod (7/15 points) with relative tolerance 1e-12 and breakpoints
 *   at the sphere's and the hollow core's boundaries, in the ray parameter tau measured from the
 *   closest approach to the centre (impact parameter b), so that a camera far away loses
 *   nothing; I_max by a scan of b in [0, 1] followed by a golden-section search. They do not use
 *   the closed forms of vtkTransparentSphereMapper (the tests compare the two). Between the
 *   breakpoints the density is a polynomial of degree <= 2 in tau, so the 15-point rule is exact
 *   up to rounding and the adaptive bisection is only a safeguard.
 * - Emission (Eq. 2): L_RV = Theta ((1 - VolumeMix) L_R + VolumeMix c_i). L_R is the opaque mode's
 *   colour at the entry point (lights and material, VTK's ambient term included, not clamped:
 *   the GPU accumulates in a float buffer); c_i is the diffuse colour of VTK's shader, Diffuse *
 *   (scalar rgb, or DiffuseColor without scalars). A segment whose start is clipped (eye inside
 *   the sphere, near plane cutting it) has no entry surface: L_RV = Theta c_i. A non-finite L_R
 *   discards the segment (like the GPU's discard).
 * - Overlaps (the mapper's OverlapCompositing other than SORTED_SPHERES, i.e. its AUTOMATIC
 *   default too: where nothing overlaps both agree): the exact integral through the summed
 *   densities. Between consecutive boundaries along the ray (segment starts and ends, hollow-core
 *   boundaries) the set of spheres is fixed; the interval's optical depths D_j are the numerical
 *   integrals above, its opacity 1 - exp(-D) (D = sum D_j) and its colour the mix of the
 *   spheres' L_RV / Theta weighted by int sigma_j T over the interval: D_j / D for constant
 *   densities, adaptive Gauss-Kronrod quadrature of sigma_j(t) exp(-S(t)) (S the optical depth
 *   from the interval's start, a polynomial in t) for squared-distance densities; C += T (1 -
 *   exp(-D)) L_mix, T *= exp(-D).
 * - Order (SORTED_SPHERES): segments are composited front to back by increasing t_n (ties:
 *   smaller particle id first), C += T L_RV, T *= 1 - Theta (evaluated as exp(log1p(-Theta_i) I /
 *   I_max), accurate also for Theta near 1), all in double. For spheres that do not intersect this
 *   is the exact visibility order. Intersecting translucent spheres are each composited whole in
 *   that order (the one whose visible part starts first is entirely in front), which is also
 *   what the GPU's depth sort does, although its sort key (the power of the eye) may order them
 *   differently.
 * - Result: colour = C + T * background (the renderer's background colour, or the opaque
 *   layer's or the opaque particle's colour), clamped to [0,1] per channel; alpha =
 *   1 - T (1 - background alpha) (the "over" operator; background alpha is the renderer's
 *   BackgroundAlpha, the opaque layer's alpha, or 1 behind an opaque particle).
 *   GetTranslucentAlphaImage() holds 1 - T, the accumulated opacity of the particles alone.
 *   The depth, view depth, id, normal and inside images describe the front-most composited
 *   particle: the start of its segment (the entry point, or the clipped start), its entry normal
 *   ((0,0,0) and inside = 1 when the start is clipped), or the opaque particle's hit when no
 *   translucent segment lies in front of it.
 *
 * Ambient occlusion and ambient illumination (Sec. 3.2 of the paper), ray traced in both modes:
 * see SetAmbientOcclusionSamples().
 *
 * Not modelled: gradient or textured backgrounds, image-based lighting, user light transforms
 * (VR), off-axis/stereo projections, render passes (shadows), other props of the renderer
 * (neither as occluders of the ambient rays), early termination
 * (the reference always composites every segment). In the opaque mode (plain
 * vtkParticleSphereMapper) an opacity < 1 is shaded as an opaque surface and the opaque layer is
 * ignored.
 *
 * Implementation, one file per concern (private headers of the module): the camera, spheres and
 * the grid along rays (vtkParticleReferenceRays.h), lights, material and the opaque pass
 * (vtkParticleReferenceShading), the emission-absorption model and the transparent pass
 * (vtkParticleReferenceEmissionAbsorption), ray-traced ambient occlusion
 * (vtkParticleReferenceAmbientOcclusion), and the frame they share (vtkParticleReferenceFrame.h).
 * Render() sets the frame up and runs one pass; a new term (metaballs, super-sampling) gets its
 * own file and its own stage.
 *
 * @sa vtkParticleSphereMapper vtkParticleImageComparison
 */
#ifndef vtkParticleReferenceRenderer_h
#define vtkParticleReferenceRenderer_h

#include "vtkObject.h"
#include "vtkParticleRenderingReferenceModule.h" // for export macro
#include "vtkSmartPointer.h"                     // for vtkSmartPointer

class vtkActor;
class vtkDataArray;
class vtkIdTypeArray;
class vtkImageData;
class vtkRenderer;
class vtkUnsignedCharArray;

class VTKPARTICLERENDERINGREFERENCE_EXPORT vtkParticleReferenceRenderer : public vtkObject
{
public:
  static vtkParticleReferenceRenderer* New();
  vtkTypeMacro(vtkParticleReferenceRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The renderer whose active camera, lights, background and (tiled) viewport size are used.
   */
  virtual void SetRenderer(vtkRenderer* renderer);
  vtkGetObjectMacro(Renderer, vtkRenderer);
  ///@}

  ///@{
  /**
   * The actor to render. Its mapper must be a vtkParticleSphereMapper (opaque mode) or a
   * vtkTransparentSphereMapper (transparent mode).
   */
  virtual void SetActor(vtkActor* actor);
  vtkGetObjectMacro(Actor, vtkActor);
  ///@}

  ///@{
  /**
   * Image size in pixels. (0, 0), the default, uses the renderer's tiled viewport size and aspect
   * ratio (what the GPU uses); otherwise the aspect ratio is width / height.
   */
  vtkSetVector2Macro(ImageSize, int);
  vtkGetVector2Macro(ImageSize, int);
  ///@}

  /**
   * Optional opaque layer for the transparent mode: per-pixel colours (4 components, RGBA in
   * [0,1]) and window depths (1 component in [0,1]), bottom-up, x fastest, of the image's size.
   * Where the depth is < 1 there is an opaque surface at that window depth: it is converted to a
   * distance along the pixel ray in double (as WindowDepthToViewDepth()), every translucent
   * segment ends there (a sphere entirely behind it is hidden, one cut by it contributes its
   * front part only) and its colour and alpha replace the background. Pixels at depth 1 show the
   * renderer's background. nullptr (either array) clears the layer. Render() fails when the
   * sizes do not match. Ignored in the opaque mode.
   */
  void SetOpaqueLayer(vtkDataArray* rgba, vtkDataArray* windowDepth);

  /**
   * Particle attributes computed by the caller from the raw arrays, so that a test's reference
   * does not depend on how the mapper under test prepares them. When radii is set, Render() uses
   * these instead of the mapper's GetParticleRadii(), MapScalars() and GetParticleOpacities():
   * - radii: one value per input point, in data units; the reference scales them by
   *   |det(actor matrix)|^(1/3) like the GPU (the mapper's RadiusScaleFactor is not applied:
   *   include it). Values <= 0 or non-finite skip the particle.
   * - colors: 4-component 8-bit RGBA per point, or nullptr for no scalar colours (the
   *   property's colours, opacity 1).
   * - opacities (transparent mode): Theta_a per point in [0, 1]; nullptr gives 1.
   * The input positions are still the mapper's input points; the density model, hollow fraction
   * and volume mix are still the mapper's settings. SetParticleAttributes(nullptr, nullptr,
   * nullptr) returns to the mapper's attributes. Render() fails when an array does not have one
   * tuple per point.
   */
  void SetParticleAttributes(
    vtkDataArray* radii, vtkUnsignedCharArray* colors, vtkDataArray* opacities);

  /**
   * Render the images. Returns true on success; on failure (no renderer, no actor, not a
   * vtkParticleSphereMapper, empty viewport, an opaque layer of the wrong size) an error is
   * reported and the images are emptied.
   */
  bool Render();

  ///@{
  /**
   * Results of the last Render(), see the class description.
   */
  vtkImageData* GetColorImage();
  vtkImageData* GetDepthImage();
  vtkImageData* GetViewDepthImage();
  vtkImageData* GetNormalImage();
  vtkIdTypeArray* GetIdImage();
  vtkUnsignedCharArray* GetInsideImage();
  ///@}

  /**
   * 1 - T per pixel (1 component, double): the accumulated opacity of the particles alone,
   * without the background or the opaque layer (transparent mode). In the opaque mode 1 where a
   * sphere is drawn, 0 elsewhere.
   */
  vtkImageData* GetTranslucentAlphaImage();

  ///@{
  /**
   * Ray-traced ambient occlusion and ambient illumination (Staib et al. 2015, Eq. 3-7; the
   * ground truth for vtkDensityVolumeAOPass and vtkVoxelConeAOPass): with
   * AmbientOcclusionSamples > 0, every visible surface point -- the opaque hit, and in the
   * transparent mode the entry point of every composited segment (a segment that starts clipped
   * has no surface point and gets none) and of an opaque particle -- casts that many rays into
   * the hemisphere of its normal, cosine-distributed (a stratified Hammersley set rotated per
   * pixel, deterministic), through the real spheres (all of them but its own) up to
   * AmbientOcclusionDistance (0, the default: four mean radii -- of an ellipsoid the radius of
   * the sphere of its volume --, one voxel of vtkParticleDensityVolume's automatic grid):
   * - A_O (Eq. 5) is the mean transmittance of the rays. An opaque sphere (the opaque mode, or
   *   Theta_i >= 1) stops a ray (binary visibility, Eq. 3); a translucent one attenuates it by
   *   its exact emission-absorption transmittance exp(-kappa_i I / I_max) over its part of the
   *   ray, I the density integral of its model (IntegrateDensity()), so optical depths of
   *   overlapping spheres add.
   * - L_A (Eq. 6) is the mean radiance the spheres emit into the rays, e_A c_j
   *   (AmbientEmission times the particle's scalar colour, or the property's colour -- what
   *   vtkParticleAmbientVolume voxelises), composited front to back in the order of the
   *   spheres' entries along the ray with their segment opacities (an opaque sphere emits e_A c_j
   *   with what transmittance is left).
   * The front-most composited surface's A_O goes to GetAmbientOcclusionImage() (1 component; 1
   * for the background) and its L_A to GetAmbientLightImage() (3 components; 0 for the
   * background). With ApplyAmbientOcclusion every such surface's colour becomes Eq. 7,
   * A_O L + AmbientIllumination L_A, where L is the lit colour (opaque) or the segment's colour
   * of Eq. 2 ((1 - VolumeMix) L_R + VolumeMix c_i, before its opacity Theta multiplies it), as
   * the mappers' //PR::AmbientOcclusion::Impl hook applies it.
   */
  vtkSetClampMacro(AmbientOcclusionSamples, int, 0, 65536);
  vtkGetMacro(AmbientOcclusionSamples, int);
  vtkSetClampMacro(AmbientOcclusionDistance, double, 0.0, 1e300);
  vtkGetMacro(AmbientOcclusionDistance, double);
  vtkSetMacro(ApplyAmbientOcclusion, bool);
  vtkGetMacro(ApplyAmbientOcclusion, bool);
  vtkSetClampMacro(AmbientIllumination, double, 0.0, 1e3);
  vtkGetMacro(AmbientIllumination, double);
  vtkSetClampMacro(AmbientEmission, double, 0.0, 1e3);
  vtkGetMacro(AmbientEmission, double);
  vtkImageData* GetAmbientOcclusionImage();
  vtkImageData* GetAmbientLightImage();
  ///@}

  /**
   * Numerical integral of a density model (vtkTransparentSphereMapper::CONSTANT_DENSITY: rho = 1,
   * SQUARED_DISTANCE_DENSITY: rho = |x - centre|^2; rho = 0 inside the core of radius
   * hollowFraction * radius and outside the sphere) along the segment [tau0, tau1] of a ray
   * with impact parameter |impact| (distance of the ray from the centre), tau measured along the
   * ray from its closest approach to the centre. The segment is clipped to the sphere (infinite
   * ends are allowed); 0 when it is empty or the ray misses. Adaptive Gauss-Kronrod 7/15 with
   * breakpoints at the sphere's and the core's boundaries, relative tolerance 1e-12.
   */
  static double IntegrateDensity(
    int model, double hollowFraction, double radius, double impact, double tau0, double tau1);

  /**
   * Numerical maximum over impact parameters b in [0, 1] of the full-chord IntegrateDensity()
   * through a sphere of radius 1 (scan of b, then golden-section search around the best sample);
   * scale by r (constant density) or r^3 (squared distance) for radius r. It should equal
   * vtkTransparentSphereMapper::GetMaximumPathIntegral() (the tests check 1e-9 relative).
   */
  static double NumericalMaximumPathIntegral(int model, double hollowFraction);

  /**
   * The opacity of one ray segment, all in double: -expm1(log1p(-thetaMax) * I / I_max) with
   * I = IntegrateDensity(model, hollowFraction, radius, impact, tau0, tau1) and I_max =
   * NumericalMaximumPathIntegral() scaled to the radius. 0 for thetaMax <= 0 or I = 0, 1 for
   * thetaMax >= 1 and I > 0.
   */
  static double SegmentOpacity(int model, double hollowFraction, double radius, double impact,
    double tau0, double tau1, double thetaMax);

  /**
   * The ray of the last Render() through the point (x, y) in pixel units of the image (pixel
   * centres at +0.5): origin (the eye in perspective, the point in the plane z_VC = 0 in parallel
   * projection) and unit direction, in view coordinates. Returns false before any Render().
   */
  bool GetPixelRay(double x, double y, double origin[3], double direction[3]);

  /**
   * A visible-surface id per pixel, -1 for the background: (2 * id + inside) * 2^16 + the bits of
   * the spot lights (the first 16 positional lights with a cone angle below 90 degrees, lighting
   * complexity 3) whose cone contains the hit. Its changes are the discontinuities of the image:
   * silhouettes, occlusion edges, intersection curves, the curves where the near plane cuts a
   * sphere and the edges of spot-light cones. Pass it to
   * vtkParticleImageComparison::MakeSilhouetteMask. The array is filled in surfaceIds.
   * (Not included: the specular jump at a light's terminator in VTK's model, sign(df), which is
   * negligible unless the specular power is very low.)
   */
  void GetSurfaceIdImage(vtkIdTypeArray* surfaceIds);

  /**
   * Convert a window-depth image (e.g. a GPU z-buffer, as read by
   * vtkParticleImageComparison::GrabDepthBuffer) of the size of the last Render() into the
   * distance along the same pixel rays the reference uses (unprojection in double through the
   * inverse projection matrix). Pixels at depth 1 (background) get -1. Returns false when the
   * sizes differ or nothing was rendered yet.
   */
  bool WindowDepthToViewDepth(vtkImageData* windowDepth, vtkImageData* viewDepth);

  ///@{
  /**
   * Statistics of the last Render(): the lighting complexity (0 unlit, 1 headlight, 2 directional
   * lights, 3 positional lights) and number of lights used, the number of spheres that could be
   * drawn, the grid resolution, the number of sphere references in the grid cells, the number of
   * spheres kept out of the grid as too large, and the wall time of the render (grid build
   * included) and of the grid build alone.
   */
  vtkGetMacro(LightingComplexity, int);
  vtkGetMacro(LightingCount, int);
  vtkGetMacro(NumberOfSpheres, vtkIdType);
  vtkGetVector3Macro(GridResolution, int);
  vtkGetMacro(NumberOfGridReferences, vtkIdType);
  vtkGetMacro(NumberOfLargeSpheres, vtkIdType);
  vtkGetMacro(LastRenderSeconds, double);
  vtkGetMacro(LastGridBuildSeconds, double);
  ///@}

protected:
  vtkParticleReferenceRenderer();
  ~vtkParticleReferenceRenderer() override;

  vtkRenderer* Renderer = nullptr;
  vtkActor* Actor = nullptr;
  int ImageSize[2] = { 0, 0 };

  int LightingComplexity = 0;
  int LightingCount = 0;
  vtkIdType NumberOfSpheres = 0;
  int GridResolution[3] = { 0, 0, 0 };
  vtkIdType NumberOfGridReferences = 0;
  vtkIdType NumberOfLargeSpheres = 0;
  double LastRenderSeconds = 0.0;
  double LastGridBuildSeconds = 0.0;

  vtkSmartPointer<vtkImageData> ColorImage;
  vtkSmartPointer<vtkImageData> DepthImage;
  vtkSmartPointer<vtkImageData> ViewDepthImage;
  vtkSmartPointer<vtkImageData> NormalImage;
  vtkSmartPointer<vtkIdTypeArray> IdImage;
  vtkSmartPointer<vtkUnsignedCharArray> InsideImage;
  vtkSmartPointer<vtkImageData> TranslucentAlphaImage;
  vtkSmartPointer<vtkImageData> AmbientOcclusionImage;
  int AmbientOcclusionSamples = 0;
  double AmbientOcclusionDistance = 0.0;
  bool ApplyAmbientOcclusion = false;
  double AmbientIllumination = 0.0;
  double AmbientEmission = 1.0;
  vtkSmartPointer<vtkImageData> AmbientLightImage;
  vtkSmartPointer<vtkDataArray> ParticleRadii;
  vtkSmartPointer<vtkUnsignedCharArray> ParticleColors;
  vtkSmartPointer<vtkDataArray> ParticleOpacities;
  vtkSmartPointer<vtkDataArray> OpaqueLayerColors;
  vtkSmartPointer<vtkDataArray> OpaqueLayerDepth;

private:
  vtkParticleReferenceRenderer(const vtkParticleReferenceRenderer&) = delete;
  void operator=(const vtkParticleReferenceRenderer&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
