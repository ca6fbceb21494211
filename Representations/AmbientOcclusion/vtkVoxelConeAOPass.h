/**
 * @class   vtkVoxelConeAOPass
 * @brief   transparency-aware ambient occlusion and ambient illumination of particles by voxel
 *          cone tracing (Staib, Grottel, Gumhold 2015)
 *
 * vtkVoxelConeAOPass implements the illumination model of Staib, Grottel, Gumhold 2015,
 * "Visualization of Particle-based Data with Transparency and Ambient Occlusion", Sec. 3.2 and
 * 5: the spheres of every vtkParticleSphereMapper and vtkTransparentSphereMapper among the
 * renderer's props are voxelised into an RGBA volume with a mip pyramid
 * (vtkParticleAmbientVolume, Sec. 5.1: overlap weights, ambient transfer functions
 * pre-classified; translucent particles occlude less), and every visible sphere fragment -- the
 * opaque spheres and the entry point of every emission-absorption glyph (its L_RV of Eq. 2,
 * surface and volume part, is occluded; its alpha_A L_A is emitted with its opacity, see
 * vtkTransparentSphereMapper) -- traces ConeCount cones around its normal through it (Sec. 5.2,
 * Shaders/AmbientOcclusion/VoxelConeTrace.glsl):
 *
 *   A_O = sum_k w_k tau_k   (Eq. 5: the transmittance along the cones, not binary visibility)
 *   L_A = sum_k w_k L_k     (Eq. 6: the ambient emission that reaches the point)
 *   L_E = A_O L_RV + alpha_A L_A   (Eq. 7; alpha_A is AmbientIllumination)
 *
 * with cosine weights w_k. The cones: one along the normal (ConeCount 1); 2 to 4 in a ring tilted
 * by 0.6 x ConeAperture from the normal (the paper's three "tightly aligned around the normal");
 * 5 to 16 as one along the normal and the rest in a ring tilted by ConeAperture (at most 70
 * degrees). A cone starts StartOffset voxel edges from the surface (skipping the sphere's own
 * voxels), samples the mip level whose voxel is its diameter, steps one diameter, and ends at
 * ConeLength times the largest extent of the particles (paper: 25 %).
 *
 * Like vtkDensityVolumeAOPass it is a vtkParticleVolumeAOPass (a render pass whose delegate
 * renders the scene); the mappers' //PR::AmbientOcclusion::Impl hook receives the cone tracing. The
 * volume is rebuilt only when the particles (positions, radii, colours, opacities), the set of
 * particle props, their matrices or the volume's settings change -- a camera move re-traces the
 * cones only (GetNumberOfVolumeBuilds counts). The voxelisation, the mips and the texture are made
 * by compute shaders (OpenGL 4.3); in a context without them the volume says so once and builds
 * on the CPU (vtkSMPTools) and uploads -- the same picture, slower per time step.
 *
 * Memory: see vtkParticleAmbientVolume (256^3 voxels with mips: 153 MB as RGBA16F, plus 307 MB
 * for the float pyramid it is built from; MaximumMemory bounds both with a warning).
 *
 * Accuracy against vtkParticleReferenceRenderer's transparency-aware ray-traced Eq. 5/7
 * (measured: Documentation/AmbientOcclusion.md). The cone length acts in whole steps (the diameter
 * about doubles per step with the default aperture).
 *
 * Interactive frames (GetFrameBudget(), vtkParticleFrameBudget): up to three levels, one cone
 * traced per sphere (level 0: along six axis directions per sphere in the vertex stage, blended
 * by the normal), ConeCount cones per sphere (when ConeCount > 1), and per fragment (when
 * RetrievalMode is PER_FRAGMENT; the last level is the settings as set). The volume is the same
 * at every level. The delegate's whole draw is timed (the cones are traced in the particles'
 * shaders).
 *
 * @sa vtkParticleAmbientVolume vtkDensityVolumeAOPass vtkTransparentSphereMapper
 */
#ifndef vtkVoxelConeAOPass_h
#define vtkVoxelConeAOPass_h

#include "vtkParticleRenderingAmbientOcclusionModule.h" // for export macro
#include "vtkParticleVolumeAOPass.h"

class vtkParticleAmbientVolume;

class VTKPARTICLERENDERINGAMBIENTOCCLUSION_EXPORT vtkVoxelConeAOPass
  : public vtkParticleVolumeAOPass
{
public:
  static vtkVoxelConeAOPass* New();
  vtkTypeMacro(vtkVoxelConeAOPass, vtkParticleVolumeAOPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * True: the ambient term L_A (Eq. 7) carries the particles' colours.
   */
  bool GetAddsColouredAmbientLight() override;

  ///@{
  /**
   * Distributed rendering: an ambient volume whose level 0 holds the spheres of every process
   * and every particle prop (summed by ParaView's Particle Render View,
   * vtkParticleDistributedVolumes), carried in the props' property keys under
   * DISTRIBUTED_VOLUME(). When every particle prop carries the same one, the pass builds its mips
   * from it instead of voxelising the local particles. nullptr (the default) removes it.
   */
  static vtkInformationObjectBaseKey* DISTRIBUTED_VOLUME();
  static void SetDistributedVolume(vtkProp* prop, vtkParticleAmbientVolume* volume);
  static vtkParticleAmbientVolume* GetDistributedVolume(vtkProp* prop);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* w) override;

  enum RetrievalModes
  {
    PER_FRAGMENT = 0, // every visible fragment traces its cones around its normal
    PER_SPHERE = 1    // every sphere traces the cones of its six extreme points along the world
                      // axes once (vertex stage); fragments blend them by their normal
  };

  ///@{
  /**
   * Where the cones are traced. PER_FRAGMENT (default) is the paper's. PER_SPHERE traces
   * 6 x ConeCount cones per sphere in the vertex stage from the points centre +- r along the
   * world axes, and each fragment blends the six results by the squared components of its world
   * normal (as vtkDensityVolumeAOPass's PER_SPHERE): the cost no longer grows with the pixels a
   * sphere covers, at the price of the detail within a sphere.
   */
  vtkSetClampMacro(RetrievalMode, int, PER_FRAGMENT, PER_SPHERE);
  vtkGetMacro(RetrievalMode, int);
  ///@}

  ///@{
  /**
   * Number of cones per fragment, 1 to 16 (see the class description). Default 3 (the paper's).
   */
  vtkSetClampMacro(ConeCount, int, 1, 16);
  vtkGetMacro(ConeCount, int);
  ///@}

  ///@{
  /**
   * Full opening angle of each cone, in degrees (1 to 120). Default 60.
   */
  vtkSetClampMacro(ConeAperture, double, 1.0, 120.0);
  vtkGetMacro(ConeAperture, double);
  ///@}

  ///@{
  /**
   * Where the cones start, in voxel edges from the surface point. Default 1.
   */
  vtkSetClampMacro(StartOffset, double, 0.0, 100.0);
  vtkGetMacro(StartOffset, double);
  ///@}

  ///@{
  /**
   * Cone length as a fraction of the largest extent of the particles. Default 0.25 (the
   * paper's 25 % of the scene extent).
   */
  vtkSetClampMacro(ConeLength, double, 0.0, 10.0);
  vtkGetMacro(ConeLength, double);
  ///@}

  ///@{
  /**
   * alpha_A of Eq. 7: how much of the ambient illumination L_A is added. Default 0 (occlusion
   * only: the picture never gets brighter than without the pass).
   */
  vtkSetClampMacro(AmbientIllumination, double, 0.0, 100.0);
  vtkGetMacro(AmbientIllumination, double);
  ///@}

  ///@{
  /**
   * The voxel volume (resolution, sub-grid samples, ambient emission e_A, memory bound).
   * Changing its settings rebuilds it. nullptr is ignored.
   */
  vtkParticleAmbientVolume* GetAmbientVolume();
  void SetAmbientVolume(vtkParticleAmbientVolume* volume);
  ///@}

  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

  /**
   * The frame budget's levels with these settings (GetNumberOfQualityLevels): "one cone per
   * sphere", then "cones per sphere" (ConeCount > 1), then "cones per fragment" (per fragment
   * set).
   */
  std::string GetQualityLevelNames() override
  {
    return std::string("one cone per sphere") + (this->ConeCount > 1 ? "|cones per sphere" : "") +
      (this->RetrievalMode == PER_FRAGMENT ? "|cones per fragment" : "");
  }

protected:
  vtkVoxelConeAOPass();
  ~vtkVoxelConeAOPass() override;

  /**
   * Rebuild the volume and its texture when the particles or the settings changed.
   */
  void UpdateVolume(const vtkRenderState* s) override;

  // the levels: one cone per sphere; the cones as set per sphere (when more than one); per
  // fragment (when set)
  int GetNumberOfQualityLevels() override
  {
    return 1 + (this->ConeCount > 1 ? 1 : 0) + (this->RetrievalMode == PER_FRAGMENT ? 1 : 0);
  }

  // colours, opacities and the transparency model also change the voxels
  void AppendPropState(
    vtkActor* actor, vtkParticleSphereMapper* mapper, std::vector<double>& state) override;

  int RetrievalMode = PER_FRAGMENT;
  int ConeCount = 3;
  double ConeAperture = 60.0;
  double StartOffset = 1.0;
  double ConeLength = 0.25;
  double AmbientIllumination = 0.0;

private:
  vtkVoxelConeAOPass(const vtkVoxelConeAOPass&) = delete;
  void operator=(const vtkVoxelConeAOPass&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
