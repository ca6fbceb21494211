/**
 * @class   vtkParticleShaderHooks
 * @brief   the contract between the particle shader templates and the passes and subclasses
 *          that extend them: the //PR:: hooks, the names in scope, warnings for missing hooks
 *
 * vtkParticleSphereMapper draws every sphere with three template stages (Shaders/
 * ParticleSphereVS.glsl, ParticleSphereGS.glsl, ParticleSphereFS.glsl). Besides VTK's own
 * //VTK:: tags they carry //PR:: hook tags, all present in the templates from the start, so a
 * render pass can use them in vtkOpenGLRenderPass::PreReplaceShaderValues as well as in
 * PostReplaceShaderValues, and a mapper subclass in ReplaceShaderValues. A user inserts its code
 * before a tag and leaves the tag in place (Insert()), so any number of users chain.
 *
 * | stage    | hook                        | where, and what it may do |
 * |----------|-----------------------------|---------------------------|
 * | vertex   | //PR::Sphere::Dec           | before main(): uniforms, inputs, outputs, functions |
 * | vertex   | //PR::Sphere::Impl          | end of main(), once per sphere: centerVC, radiusVC
 * (view coordinates), vertexMC, particleIdVSOutput set; write per-sphere outputs | | geometry |
 * //PR::Sphere::Dec           | before main() | | geometry | //PR::Sphere::Cull          | before
 * the billboard is emitted: `return` draws nothing for this sphere (centerVC, radiusVC) | |
 * geometry | //PR::Sphere::Impl          | per emitted vertex: copy per-sphere outputs | | fragment
 * | //PR::Sphere::Dec           | before main() (after RaySphere.glsl) | | fragment |
 * //PR::Surface::Impl         | after the ray-sphere intersection: may change prHit, prT0, prT1
 * (another surface inside the sphere, e.g. metaballs) | | fragment | //PR::Coverage::Impl        |
 * just before a miss is discarded: prHit says whether the ray meets the surface (sub-pixel
 * coverage) | | fragment | //PR::Surface::Normal       | after the visible point: vertexVC,
 * normalVCVSOutput (unit, facing the viewer), prInside; may replace the normal | | fragment |
 * //PR::AmbientOcclusion::Impl| after lighting: multiply prAmbientOcclusion (visibility in [0, 1];
 * sources compose) and add to prAmbientLight | | fragment | //PR::Shading::Impl         | after
 * gl_FragData[0] = vec4(prAmbientOcclusion * prSurfaceColor + prAmbientLight, opacity): replace or
 * discard the result |
 *
 * (//PR::Lighting::Impl, before //PR::AmbientOcclusion::Impl, is the mapper's own: it writes
 * prSurfaceColor. VTK's //VTK::Light::Impl comes after //PR::Shading::Impl, so VTK passes and
 * shader replacements that edit gl_FragData[0] there act on the final colour.)
 *
 * Names a user may rely on. Vertex: vertexMC, radiusMC, radiusScaleVC, MCVCMatrix, centerVC,
 * radiusVC, centerRadiusVCVSOutput, centerOffsetVCVSOutput, particleIdVSOutput (the particle's
 * index). Geometry: centerRadiusVCVSOutput[0], centerOffsetVCVSOutput[0], particleIdVSOutput[0],
 * VCDCMatrix, DCVCMatrix, cameraParallel. Fragment: centerVC, radiusVC, prRayS (ray start relative
 * to the centre), prRayD (unit direction), prHit, prT0, prT1 (entry and exit along prRayD), depth
 * (window depth of the visible point), prInside, vertexVC, normalVCVSOutput, particleIdVSOutput,
 * centerOffsetVCVSOutput, clipZWOfTranslation, VCDCMatrix, cameraParallel; after lighting
 * prSurfaceColor, ambientColor, diffuseColor, specularColor, opacity, prAmbientOcclusion,
 * prAmbientLight. The functions of RaySphere.glsl (prIntersectSphere, prIntersectEllipsoid,
 * prEllipsoidNormal, prDepthOfSplitPointVC, prClipZWOfSplitPointVC) are in scope in the fragment
 * stage. With ellipsoids (PR_ELLIPSOID defined in every stage) radiusVC bounds the particle (its
 * largest semi-axis), the intersection and normal are the ellipsoid's, and
 * ellipsoidToUnitVSOutput (vertex and fragment; mat3 taking view-coordinate offsets from the
 * centre to the unit sphere's frame) and ellipsoidToVCVSOutput (vertex and geometry; its inverse)
 * are in scope: code that measures along the ray in radii works in that frame (see
 * TransparentSphereShading.glsl). Defining PR_NO_DEPTH_WRITE in the
 * fragment //PR::Sphere::Dec leaves gl_FragDepth unwritten (a translucent variant whose
 * early-termination mask must be tested before shading).
 *
 * Per-sphere values: AddSphereVarying("vec3", "prFoo") declares `flat out vec3 prFooVSOutput` in
 * the vertex stage (assign it in //PR::Sphere::Impl), passes it through the geometry stage, and
 * declares `flat in vec3 prFooVSOutput` in the fragment stage (VTK's shader cache renames the
 * fragment inputs to the geometry outputs).
 *
 * A hook that a user asks for and does not find (a mapper without it, a typo) is reported once
 * per user and hook with vtkWarningWithObjectMacro on the owner; the code is then not applied.
 *
 * Use: a member of the pass or mapper, Begin() with the three sources of the shader being built,
 * then Insert() / AddSphereVarying().
 * @code
 *   this->Hooks.Begin(vertexShader, geometryShader, fragmentShader);
 *   this->Hooks.Insert(vtkParticleShaderHooks::Fragment, "//PR::Sphere::Dec", "uniform float
 * f;\n"); this->Hooks.Insert(vtkParticleShaderHooks::Fragment, "//PR::AmbientOcclusion::Impl",
 *     "prAmbientOcclusion *= f;\n");
 * @endcode
 *
 * @sa vtkParticleSphereMapper vtkDensityVolumeAOPass vtkTransparentSphereMapper vtkParticleShaders
 */
#ifndef vtkParticleShaderHooks_h
#define vtkParticleShaderHooks_h

#include "vtkParticleRenderingCoreModule.h" // for export macro

#include <set>    // for std::set
#include <string> // for std::string

class vtkObject;

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleShaderHooks
{
public:
  enum Stage
  {
    Vertex = 0,
    Geometry = 1,
    Fragment = 2
  };

  /**
   * owner: the pass or mapper that uses the hooks (warnings name it); not reference-counted.
   */
  explicit vtkParticleShaderHooks(vtkObject* owner);

  /**
   * The sources of the shader being built; they are edited in place until the next Begin().
   */
  void Begin(std::string& vertexShader, std::string& geometryShader, std::string& fragmentShader);

  /**
   * Insert code before the hook tag of the stage (the tag stays, for the next user). False, with
   * a warning the first time for this hook, when the stage has no such tag.
   */
  bool Insert(Stage stage, const std::string& hook, const std::string& code);

  /**
   * A per-sphere value from the vertex stage to the fragment stage (see the class description).
   * type is a GLSL type that may be flat-interpolated (float, vec3, int, ...).
   */
  bool AddSphereVarying(const std::string& type, const std::string& name);

  /**
   * The hook names of the templates, in the order of the table above (for tests and tools).
   */
  static const std::set<std::string>& GetHookNames(Stage stage);

private:
  vtkObject* Owner;
  std::string* Sources[3] = { nullptr, nullptr, nullptr };
  std::set<std::string> Warned;
};

#endif
