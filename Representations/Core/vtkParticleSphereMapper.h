/**
 * @class   vtkParticleSphereMapper
 * @brief   draws every point of a vtkPolyData as an exactly ray-cast, lit sphere
 *
 * vtkParticleSphereMapper is the sphere imposter core of ParticleRendering. Every point of the
 * input (cells are ignored) becomes a sphere whose
 * - radius is taken from a one-component point array (RadiusArrayName, any numeric type) or is
 *   the constant Radius, multiplied by RadiusScaleFactor and by the actor's scale;
 * - colour comes from the scalars through the lookup table (the usual vtkMapper colouring:
 *   ScalarVisibility, ScalarMode, ColorByArrayComponent, ...) or from the actor's property;
 * - shading is VTK's Phong model with the renderer's lights (headlight, light kit, positional
 *   and spot lights) and the property's ambient/diffuse/specular material, see
 *   Shaders/Lighting.glsl. For parallel projection the view vector is the true (0,0,1); VTK's
 *   polygon shader uses the perspective formula in both cases.
 *
 * Geometry: a GL_POINTS draw of the particles with plain vertex attributes (centre with VTK's
 * VBO shift/scale, radius, colour: 20 bytes per particle, plus 4 for the culler's index); from
 * OcclusionCullingThreshold particles on, vtkParticleOcclusionCuller draws them by spatial cells
 * nearest first and skips hidden cells and spheres (exact depth writes turn early depth tests
 * off, so without it every hidden sphere is shaded). The vertex stage runs once per sphere and
 * the geometry stage
 * emits one camera-facing triangle per sphere (3 pulled vertices or 4-vertex instances per
 * particle would repeat the billboard set-up per vertex; measured: Documentation/Core.md). In
 * perspective the triangle circumscribes the sphere's silhouette circle, so it covers the
 * projected sphere exactly also far off-axis (Shaders/SphereImposter.glsl). The fragment shader
 * intersects the fragment's ray with the sphere in coordinates relative to the sphere centre
 * (Shaders/RaySphere.glsl), which stays exact in single precision with the camera 1e7 radii away,
 * and writes the true depth of the hit to gl_FragDepth, so spheres intersect each other and any
 * other VTK geometry correctly.
 *
 * Visible surface rule: the first intersection in front of the eye and between the near and far
 * planes. With the eye inside a sphere (or the near plane cutting one) the inner side of its back
 * surface is shown, lit with the normal facing the viewer; nothing of a sphere is drawn when both
 * intersections are clipped.
 *
 * Bad input never crashes and never draws garbage; each case gets one warning per input change:
 * - no points: nothing is drawn;
 * - RadiusArrayName names a missing array, a non-numeric array or an array with more than one
 *   component: the constant Radius is used for every particle;
 * - radius <= 0, NaN or Inf, or a position with NaN/Inf: that particle is skipped;
 * - the fragment stage discards any NaN/Inf colour, so no NaN or Inf reaches the framebuffer.
 *
 * Hooks for render passes and subclasses: the three shader templates carry //PR:: hooks (per
 * sphere in the vertex and geometry stages; surface, coverage, normal, ambient occlusion and
 * shading in the fragment stage), all present before the mapper fills VTK's tags, so
 * vtkOpenGLRenderPass::PreReplaceShaderValues and PostReplaceShaderValues both see them. The
 * contract (hooks, names in scope, per-sphere varyings, warnings) is vtkParticleShaderHooks.
 *
 * Oriented ellipsoids (Shape ELLIPSOID): every particle is the unit sphere under the affine map
 * x = centre + A u with A = L R(q) diag(a) -- a the semi-axes (a 3-component point array, or
 * three components of a wider one; halved when AxesAreDiameters), q the unit quaternion
 * (w, x, y, z) of the particle's body frame (LAMMPS's convention: body vector b is R(q) b in the
 * data), L the linear part of the actor's matrix and the camera's view times RadiusScaleFactor.
 * An affine map keeps rays and their parameters, so the sphere core generalises exactly
 * (Shaders/Core/EllipsoidFrame.glsl, RaySphere.glsl, SphereImposter.glsl): the fragment's ray
 * is intersected with the unit sphere in the ellipsoid's frame (exact entry and exit, depth
 * written as for spheres, relative to the centre, so a far camera stays exact), the normal is
 * A^-T A^-1 x, and the imposter is the sphere's triangle around the unit sphere's silhouette
 * mapped back by A: it circumscribes the ellipsoid's silhouette ellipse with the sphere's
 * fragment overhead at any axis ratio. The radius used for bounds, occlusion culling, clip boxes
 * and partitions is the largest semi-axis. With equal axes and a uniform actor scale the picture
 * is the sphere core's. Bad input, one warning per change: no usable axes array (missing, not
 * numeric, fewer than AxesArrayComponent + 3 components): spheres as without Shape; an axis that
 * is zero, negative, NaN or infinite: the particle is skipped; no orientation array: every
 * ellipsoid axis-aligned (the array named but unusable: the same, with a warning); a quaternion
 * that is zero or not finite: axis-aligned; one whose length is not 1 within 1e-3: normalised.
 *
 * Picking: the hardware selector's point and cell ids are the particle (point) index. Above
 * MaximumNumberOfParticles every k-th particle is drawn, with a warning.
 * Clipping planes clip whole particles by their centre.
 *
 * @sa vtkOpenGLSphereMapper vtkParticleReferenceRenderer vtkParticleShaderHooks
 */
#ifndef vtkParticleSphereMapper_h
#define vtkParticleSphereMapper_h

#include "vtkOpenGLPolyDataMapper.h"
#include "vtkParticleRenderingCoreModule.h" // for export macro

#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <string> // for std::string
#include <vector> // for std::vector

class vtkDoubleArray;
class vtkFloatArray;
class vtkMatrix4x4;
class vtkOpenGLBufferObject;
class vtkOpenGLVertexBufferObject;
class vtkParticleFrameBudget;
class vtkParticleOcclusionCuller;
class vtkShaderProgram;

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleSphereMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkParticleSphereMapper* New();
  vtkTypeMacro(vtkParticleSphereMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Name of a one-component numeric point array holding the particle radii. When empty (the
   * default), or when the array is missing or unusable (a warning says which), every particle
   * has the constant Radius.
   */
  vtkSetStringMacro(RadiusArrayName);
  vtkGetStringMacro(RadiusArrayName);
  ///@}

  enum ShapeType
  {
    SPHERE = 0,
    ELLIPSOID = 1
  };

  ///@{
  /**
   * The particle shape: SPHERE (default; RadiusArrayName or Radius) or ELLIPSOID (oriented
   * ellipsoids from AxesArrayName and OrientationArrayName; see the class description).
   */
  vtkSetClampMacro(Shape, int, SPHERE, ELLIPSOID);
  vtkGetMacro(Shape, int);
  void SetShapeToSphere() { this->SetShape(SPHERE); }
  void SetShapeToEllipsoid() { this->SetShape(ELLIPSOID); }
  ///@}

  ///@{
  /**
   * Ellipsoids: the numeric point array holding each particle's three semi-axes (along its body
   * x, y, z) in components AxesArrayComponent .. AxesArrayComponent + 2 (default 0), e.g. the
   * columns c_ID[1..3] of a LAMMPS compute property/atom that the dump reader gathers into one
   * array. AxesAreDiameters (default off) halves them (LAMMPS's shapex/y/z are diameters).
   */
  vtkSetStringMacro(AxesArrayName);
  vtkGetStringMacro(AxesArrayName);
  vtkSetClampMacro(AxesArrayComponent, int, 0, VTK_INT_MAX);
  vtkGetMacro(AxesArrayComponent, int);
  vtkSetMacro(AxesAreDiameters, bool);
  vtkGetMacro(AxesAreDiameters, bool);
  vtkBooleanMacro(AxesAreDiameters, bool);
  ///@}

  ///@{
  /**
   * Ellipsoids: the numeric point array holding each particle's orientation as a quaternion
   * (w, x, y, z) in components OrientationArrayComponent .. + 3 (default 0; LAMMPS's quatw, quati,
   * quatj, quatk). Empty (the default): axis-aligned ellipsoids.
   */
  vtkSetStringMacro(OrientationArrayName);
  vtkGetStringMacro(OrientationArrayName);
  vtkSetClampMacro(OrientationArrayComponent, int, 0, VTK_INT_MAX);
  vtkGetMacro(OrientationArrayComponent, int);
  ///@}

  ///@{
  /**
   * Ellipsoids from a 3x3 tensor per particle (a 9-component point array), as ParaView's Tensor
   * Glyph draws them with Extract Eigenvalues (vtkTensorGlyph): the semi-axes are the absolute
   * eigenvalues of the tensor's symmetric part, the orientation its eigenvectors (made
   * right-handed). When set it replaces AxesArrayName and OrientationArrayName; a tensor with a
   * non-finite entry or an eigenvalue below 1e-6 of its largest skips its particle (a flat or
   * degenerate glyph), with the bad axes' warning. Empty (the default): the axes and orientation
   * arrays.
   */
  vtkSetStringMacro(TensorArrayName);
  vtkGetStringMacro(TensorArrayName);
  ///@}

  /**
   * Whether the last prepared input is drawn as ellipsoids: Shape is ELLIPSOID and the axes array
   * is usable (valid after a render or GetBounds()).
   */
  bool GetDrawsEllipsoids();

  /**
   * Ellipsoids as drawn, valid with GetDrawsEllipsoids(): the semi-axes (3 components, model
   * units before RadiusScaleFactor, 0 for skipped particles) and the unit quaternions (w, x, y,
   * z) of every input point. nullptr when spheres are drawn. For the reference renderer and
   * passes that deposit the particles' volume.
   */
  vtkFloatArray* GetParticleAxes();
  vtkFloatArray* GetParticleOrientations();

  /**
   * The map of ellipsoid semi-axes to view coordinates: the linear part of camera view * actor
   * matrix (no VBO shift/scale: axes are model-unit lengths) times RadiusScaleFactor, in double.
   * The reference renderer and the ellipsoid uniforms use it.
   */
  void GetAxesToViewMatrix(vtkRenderer* ren, vtkActor* actor, double axesToView[3][3]);

  ///@{
  /**
   * Constant radius used when no radius array is in use. Default 0.5.
   */
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  ///@}

  ///@{
  /**
   * Factor applied to every radius (array or constant). Default 1. Changing it does not re-upload
   * the particles (it is a uniform).
   */
  virtual void SetRadiusScaleFactor(double factor);
  vtkGetMacro(RadiusScaleFactor, double);
  ///@}

  /**
   * Number of particle uploads (validation + VBO build) so far. Uploads happen when the input, the
   * radius source or the colour mapping change; never when only the camera, the actor, its
   * material or RadiusScaleFactor change.
   */
  vtkGetMacro(NumberOfUploads, vtkIdType);

  /**
   * Number of times the shader sources were assembled (vtkOpenGLPolyDataMapper::BuildShaders:
   * a new variant, a new render pass or light set-up, a changed mapper). For tests: a frame that
   * changes none of these builds nothing.
   */
  vtkGetMacro(NumberOfShaderBuilds, vtkIdType);

  /**
   * Number of particles skipped at the last upload because of an invalid radius or position.
   */
  vtkGetMacro(NumberOfSkippedParticles, vtkIdType);

  /**
   * The warning of the last input preparation (what is wrong with the input: no points, an
   * unusable radius array, invalid radii or positions), "" when the input was fine. The warning
   * itself is issued once, when it changes; this keeps it for ParaView and tests.
   */
  const char* GetLastInputWarning();

  ///@{
  /**
   * Per-stage timings for benchmarks (off by default; costs a GPU timer query per frame when on).
   * GetLastUploadSeconds(): CPU wall time of the last particle upload (validation + VBO build).
   * GetLastDrawGPUSeconds(): GPU time of the last sphere draw call, from a timer query; blocks
   * until the GPU has finished that draw.
   */
  vtkSetMacro(CollectTimings, bool);
  vtkGetMacro(CollectTimings, bool);
  vtkBooleanMacro(CollectTimings, bool);
  vtkGetMacro(LastUploadSeconds, double);
  double GetLastDrawGPUSeconds();
  ///@}

  ///@{
  /**
   * Long work reports its progress as a vtkAlgorithm does: vtkCommand::ProgressEvent with the
   * fraction done as call data (UpdateProgress()), GetProgressText() naming the work while it
   * runs. In ParaView the particle representation passes it on to the progress bar. Work on at
   * least ProgressThreshold particles reports (default 2^20, about a second of depth sorting on a
   * software rasteriser); 0 always reports, VTK_ID_MAX never. Reported today: the upload of the
   * particles (validation, colour mapping, buffers) and the depth sort of
   * vtkTransparentSphereMapper (per radix pass). A draw call is one GPU command whose progress
   * cannot be observed; it is not reported.
   */
  vtkSetClampMacro(ProgressThreshold, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(ProgressThreshold, vtkIdType);
  ///@}

  ///@{
  /**
   * The most particles the vertex buffers take (default 150 000 000: 1.8 GB of positions; vertex
   * buffers beyond 2 GiB fail or crash on common OpenGL drivers, Mesa's llvmpipe among them).
   * Above it every k-th particle is drawn, k = ceil(N / MaximumNumberOfParticles), with a warning;
   * picking still reports input point ids. GetParticleStride(): k of the last upload (1 when all
   * are drawn).
   */
  vtkSetClampMacro(MaximumNumberOfParticles, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfParticles, vtkIdType);
  vtkIdType GetParticleStride();
  ///@}

  ///@{
  /**
   * Occlusion culling of opaque particles (vtkParticleOcclusionCuller; on by default): the
   * particles are drawn by spatial cells, nearest first, and cells hidden behind what is already
   * in the depth buffer are skipped. The picture is the same; dense data draws several times
   * faster where early depth tests do not work with exact sphere depths (software rasterisers).
   * Used from OcclusionCullingThreshold particles on (default 8192). Never used for picking or
   * for the translucent stage of vtkTransparentSphereMapper.
   */
  vtkSetMacro(OcclusionCulling, bool);
  vtkGetMacro(OcclusionCulling, bool);
  vtkBooleanMacro(OcclusionCulling, bool);
  vtkSetClampMacro(OcclusionCullingThreshold, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(OcclusionCullingThreshold, vtkIdType);
  ///@}

  ///@{
  /**
   * The bounds of the particle centres over all the data the input is a piece of (e.g. every
   * process's particles under MPI; ParaView's Particles representation sets them on every
   * process, one process included). When set, the positions' vertex buffer shift and scale, and
   * the choice between them and the focal-point shift, come from these bounds instead of the
   * input's own centres, with VTK's AUTO_SHIFT_SCALE rule: every piece then rounds a particle's
   * centre to float exactly as the whole data does, and a ray that grazes a sphere within that
   * rounding hits or misses it in every piece alike. Uninitialized bounds (the default) unset
   * them. They must contain the input's valid centres.
   */
  void SetPositionBounds(const double bounds[6]);
  void GetPositionBounds(double bounds[6]);
  ///@}

  /**
   * The culler of the opaque draw (statistics of the last frame: GetLastNumberOfDrawnParticles()
   * etc.; its cells are built on the first culled draw after an upload).
   */
  vtkParticleOcclusionCuller* GetOcclusionCuller();

  /**
   * The mapper's quality while the camera moves: its quality setting (ADAPTIVE, EXACT,
   * INTERACTIVE), the GPU times it measured per level and its last choice (see
   * vtkParticleFrameBudget). The opaque core has one level (exact); subclasses with cheaper
   * levels describe them.
   */
  vtkParticleFrameBudget* GetFrameBudget();

  /**
   * The names of the quality levels, cheapest first, separated by '|' ("exact" for the core),
   * and one line saying which the last frame drew, why, and what each cost
   * (vtkParticleFrameBudget::GetLastChoiceText).
   */
  virtual std::string GetQualityLevelNames() { return "exact"; }
  std::string GetQualityText();

  void ReleaseGraphicsResources(vtkWindow* window) override;

  /**
   * Bounds of the spheres (centres grown by the largest radius), ignoring skipped particles.
   */
  using Superclass::GetBounds;
  double* GetBounds() override;

  /**
   * Selection ids: a point selection returns the particle index; a cell selection returns the
   * vertex cell that holds the particle when the input has vertex cells (mapped through the
   * selector's cell id array when set), else the particle index.
   */
  void ProcessSelectorPixelBuffers(
    vtkHardwareSelector* sel, std::vector<unsigned int>& pixeloffsets, vtkProp* prop) override;

  /**
   * Spheres are drawn for every point, whatever the cells are.
   */
  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;

  /**
   * The radius of every particle as used for drawing (before RadiusScaleFactor and the actor's
   * scale), 0 for skipped particles. Valid after the mapper has prepared its input (a render or
   * GetBounds()). Used by the reference renderer and by passes that need the radii.
   */
  vtkFloatArray* GetParticleRadii();

  /**
   * The radius of the sphere of each particle's volume, as GetParticleRadii(): the radius for a
   * sphere, cbrt(a b c) for an ellipsoid. What volumes that deposit the particles' mass use
   * (vtkParticleDensityVolume, vtkParticleAmbientVolume).
   */
  vtkFloatArray* GetParticleVolumeRadii();

  /**
   * The particle vertex buffers for compute passes: the positions (float, stride in floats) and
   * volume radii (float, model-coordinate GetParticleVolumeRadii(), 0 for skipped particles;
   * for spheres the radius buffer the draw uses) as VTK's buffer objects
   * (bind them with vtkParticleComputeProgram::BindStorage), and the matrix from buffer to model
   * coordinates (VTK's VBO shift/scale undone), valid once the mapper has drawn. Returns false
   * before that.
   */
  bool GetParticleBuffers(vtkOpenGLBufferObject*& positions, unsigned int& positionStride,
    vtkOpenGLBufferObject*& radii, vtkIdType& count, vtkMatrix4x4* bufferToModel);

  /**
   * Time of the last change of the particles' positions or radii (the input's points, the radius
   * array or the radius settings); colour, opacity and shading settings do not change it.
   */
  vtkMTimeType GetParticleGeometryTime();

  /**
   * The radius scale from model to view coordinates applied on the GPU: RadiusScaleFactor times
   * the actor's scale (the cube root of the determinant of its matrix).
   */
  double GetRadiusScaleVC(vtkActor* actor) const;

  /**
   * The GLSL that sums VTK's lights as this mapper shades (Shaders/Lighting.glsl): it declares
   * `vec3 diffuse, specular` and adds each light's terms for the unit normal normalVCVSOutput at
   * vertexVC with specularPower, for a renderer's LightingComplexity and LightingCount (the
   * light uniforms are the renderer's GetLightingUniforms()). Complexity 0 (no lights) gives
   * diffuse = 1, specular = 0, i.e. the unlit colour. vtkSNDFRenderPass pre-integrates with it.
   */
  static std::string GetLightSumCode(int complexity, int count);

  ///@{
  /**
   * Draw only what lies inside an axis-aligned box of the input's coordinates (distributed
   * rendering: each process draws its box of a k-d partition, with ghost copies of the spheres
   * that reach into it, and IceT composites the boxes in visibility order without depth, see
   * vtkParticlePartition). Opaque spheres keep a fragment when its visible point is inside the
   * box; translucent spheres (vtkTransparentSphereMapper) integrate the part of the chord
   * inside the box, with the colour of the whole sphere, so the boxes' images composite to the
   * single-process picture. Uninitialised bounds (vtkMath::UninitializeBounds, the default)
   * switch it off. The shader variant with the test is compiled only while a box is set
   * (Shaders/ClipBox.glsl).
   */
  void SetClipBox(const double box[6]);
  bool GetClipBox(double box[6]) const;
  ///@}

  ///@{
  /**
   * The glyphs' emission-absorption model (vtkParticleEmissionModel), for passes that integrate
   * light through the particles (the ambient volume of vtkVoxelConeAOPass weighs each particle
   * by its mean disc opacity). The core draws solid spheres with a flat opacity over the disc:
   * no emission-absorption profile, a constant density, no hollow core, no per-particle
   * opacities (nullptr). A translucent subclass (vtkTransparentSphereMapper) returns its own;
   * GetEmissionOpacities() prepares them from the input.
   */
  virtual bool GetEmissionAbsorptionGlyphs();
  virtual int GetEmissionDensityModel();
  virtual double GetEmissionHollowFraction();
  virtual vtkDoubleArray* GetEmissionOpacities();
  ///@}

  /**
   * Whether the mapper draws its particles as sphere glyphs through the core's opaque path
   * (true, also vtkTransparentSphereMapper's opaque particles) or a surface of its own
   * (vtkMetaballMapper: false). Passes that sample the drawn spheres (vtkSNDFRenderPass) ask.
   */
  virtual bool GetDrawsSphereGlyphs();

protected:
  vtkParticleSphereMapper();
  ~vtkParticleSphereMapper() override;

  // shader assembly
  void GetShaderTemplate(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderPositionVC(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderNormal(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderCoincidentOffset(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderDepth(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderTCoord(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderEdges(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;

  void BuildShaders(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  // a new variant also when the input switches between spheres and ellipsoids
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  // per-frame uniforms (camera, radius scale, depth split)
  void SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  // picking: point and cell ids are both the particle index
  void UpdateMaximumPointCellIds(vtkRenderer* ren, vtkActor* act) override;

  // buffers and drawing
  bool GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;
  void BuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;

  /**
   * The point array `name` of `input` when it is numeric with one component; otherwise nullptr
   * and the reason appended to `warnings`, as "<role> array '<name>' is not a point array of the
   * input / is not numeric / has N components...: <fallback>. ". nullptr without a warning when
   * no name is given.
   */
  static vtkDataArray* GetScalarPointArray(vtkPolyData* input, const char* name, const char* role,
    const std::string& fallback, std::ostream& warnings);

  /**
   * Issue `warning` (vtkWarningMacro) when it is not empty and differs from `lastWarning`, then
   * remember it: a problem with the input is said once per change, not every frame.
   */
  void WarnOnChange(const std::string& warning, std::string& lastWarning);

  /**
   * The matrix from the position buffer to view coordinates (row-major, points as columns):
   * camera view * actor matrix * VBO shift/scale undone, composed in double. The one place this
   * precision-critical product is formed (shaders, depth sort).
   */
  void GetBufferToViewMatrix(vtkRenderer* ren, vtkActor* actor, vtkMatrix4x4* bufferToView);

  // the uniforms axesToVC and vcToAxes of the ellipsoid variant (EllipsoidFrame.glsl)
  void SetEllipsoidUniforms(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* actor);

  /**
   * Whether the geometry stage being built gets the per-sphere occlusion test
   * (vtkParticleOcclusionCuller; PR_OCCLUSION_CULLING): OcclusionCulling is on, no picking, and
   * at least OcclusionCullingThreshold particles. A subclass drawing a variant without depth
   * writes (translucency) returns false for it.
   */
  virtual bool GetOcclusionCullingCompiled(vtkRenderer* ren);

  /**
   * Whether the variant being built clips the segments of the spheres' chords to the clip box
   * itself (a translucent variant, see TransparentSphereShading.glsl) instead of testing the
   * visible point (the default, false).
   */
  virtual bool GetClipBoxBySegment() { return false; }

  /**
   * Switch the default shift/scale method (AUTO_SHIFT_SCALE) to VTK's FOCAL_POINT_SHIFT_SCALE
   * while the data's extent puts the float spacing of one origin above a thousandth of the
   * smallest radius (a lost atom far from the rest), with a warning; back when the data no
   * longer needs it. Otherwise, when the float spacing at the data's centre is above a
   * thousandth of the smallest radius (a lone small particle or a tight group away from the
   * origin, which AUTO_SHIFT_SCALE leaves unshifted), to VTK's AUTO_SHIFT (positions relative to
   * the centre of their bounds). Called before each upload.
   */
  void UpdateFocalPointShift();

  /**
   * The positions' vertex buffer shift/scale method, and with PositionBounds set, VTK's
   * automatic shift and scale computed from them (MANUAL_SHIFT_SCALE). Before each upload.
   */
  void SetPositionShiftScale(vtkOpenGLVertexBufferObject* positions);

  /**
   * The array to upload for a per-particle array of the input's length: the array itself, or
   * every GetParticleStride()-th tuple of it (kept alive until the next upload). Subclasses
   * adding attributes in CacheParticleAttributes() pass their arrays through it.
   */
  vtkDataArray* StrideForUpload(vtkDataArray* array);

  /**
   * Hook for subclasses: add per-particle vertex attributes with this->VBOs->CacheDataArray()
   * (called while the buffers are built, before the upload).
   */
  virtual void CacheParticleAttributes(vtkRenderer*, vtkActor*) {}

  /**
   * The particles in the vertex buffers (every GetParticleStride()-th of the input): positions
   * and radii (model coordinates, 0 for skipped particles), valid from CacheParticleAttributes()
   * on until the next upload.
   */
  vtkDataArray* GetUploadedPositions();
  vtkFloatArray* GetUploadedRadii();

  /**
   * The radius (model coordinates, before RadiusScaleFactor) of the sphere each uploaded
   * particle's imposter covers, for the occlusion culler: the particle radii here; a subclass
   * that draws larger imposters returns those.
   */
  virtual const float* GetCullingRadii();

  /**
   * Modification time of what the uploaded particle buffers depend on: the mapper's MTime (which
   * includes the lookup table's) except when its last change was RadiusScaleFactor alone.
   */
  vtkMTimeType GetParticleDataMTime();

  /**
   * Validate the input: radii, skipped particles, bounds, warnings. Cached on the input's and the
   * mapper's modification times. Returns the number of points of the input.
   */
  vtkIdType PrepareParticles();

  /**
   * With Shape ELLIPSOID and a usable axes array: the semi-axes and unit quaternions of every
   * particle (the internal arrays behind GetParticleAxes()), the largest semi-axis per particle
   * in boundingRadii (NaN where an axis is bad), problems appended to warnings; returns true.
   * Otherwise false (spheres).
   */
  bool PrepareEllipsoids(vtkPolyData* input, vtkFloatArray* boundingRadii, std::ostream& warnings);

  char* RadiusArrayName = nullptr;
  double Radius = 0.5;
  int Shape = SPHERE;
  char* AxesArrayName = nullptr;
  int AxesArrayComponent = 0;
  bool AxesAreDiameters = false;
  char* OrientationArrayName = nullptr;
  int OrientationArrayComponent = 0;
  char* TensorArrayName = nullptr;
  double RadiusScaleFactor = 1.0;
  // the clip box (SetClipBox) and whether it is set
  double ClipBox[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  bool UseClipBox = false;
  vtkMTimeType ScaleOnlyMTime = 0;
  vtkMTimeType DataMTimeBeforeScale = 0;
  vtkIdType NumberOfSkippedParticles = 0;
  bool CollectTimings = false;
  vtkIdType MaximumNumberOfParticles = 150000000;
  bool OcclusionCulling = true;
  double PositionBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 }; // unset
  vtkIdType OcclusionCullingThreshold = 8192;
  vtkIdType ProgressThreshold = vtkIdType(1) << 20;
  vtkIdType NumberOfUploads = 0;
  vtkIdType NumberOfShaderBuilds = 0;
  double LastUploadSeconds = 0.0;

private:
  vtkParticleSphereMapper(const vtkParticleSphereMapper&) = delete;
  void operator=(const vtkParticleSphereMapper&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
