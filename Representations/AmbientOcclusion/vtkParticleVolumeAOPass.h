/**
 * @class   vtkParticleVolumeAOPass
 * @brief   base of the render passes that shade particles from a 3D texture built over the
 *          renderer's particle props (object-space ambient occlusion)
 *
 * vtkParticleVolumeAOPass is what vtkDensityVolumeAOPass (Grottel et al. 2012) and
 * vtkVoxelConeAOPass (Staib et al. 2015) share: a vtkImageProcessingPass whose delegate (e.g.
 * vtkRenderStepsPass; in ParaView the Particle Render View's pass chain) renders the scene
 * directly, while the pass
 * - finds the visible props drawn by a vtkParticleSphereMapper (or subclass) and what their
 *   volume depends on (GatherParticleProps, with AppendPropState for a subclass's own inputs),
 * - lets the subclass rebuild its volume texture only when that changed (UpdateVolume; a camera
 *   move rebuilds nothing),
 * - binds the texture around the delegate's rendering, so that the mappers' shaders, extended
 *   through their //PR:: hooks in PostReplaceShaderValues, can sample it,
 * - gives the view-to-grid matrix for the shaders in double precision (SetViewToGridUniform).
 *
 * @sa vtkDensityVolumeAOPass vtkVoxelConeAOPass vtkParticleShaderHooks
 */
#ifndef vtkParticleVolumeAOPass_h
#define vtkParticleVolumeAOPass_h

#include "vtkParticleAmbientLightPass.h"
#include "vtkParticleRenderingAmbientOcclusionModule.h" // for export macro

#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkActor;
class vtkInformationObjectBaseKey;
class vtkObject;
class vtkProp;
class vtkParticleShaderHooks;
class vtkParticleSphereMapper;
class vtkShaderProgram;
class vtkTextureObject;

class VTKPARTICLERENDERINGAMBIENTOCCLUSION_EXPORT vtkParticleVolumeAOPass
  : public vtkParticleAmbientLightPass
{
public:
  vtkTypeMacro(vtkParticleVolumeAOPass, vtkParticleAmbientLightPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * PER_FRAGMENT: the volume is sampled in the particle shaders.
   */
  int GetOcclusionSpace() override;

  /**
   * Update the volume if needed, then render the delegate with the volume texture bound.
   */
  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /**
   * The shader code depends on the settings and on the frame's quality level: mappers rebuild
   * their shaders when either changes (the shader cache keeps both programs).
   */
  vtkMTimeType GetShaderStageMTime() override;

  /**
   * Number of volume builds so far.
   */
  vtkGetMacro(NumberOfVolumeBuilds, vtkIdType);

  ///@{
  /**
   * Warn when the renderer has no visible particle prop to build the volume from (default on).
   * ParaView's Particle Render View switches it off: a process without particles is normal
   * there (a client of a remote server, a rank with an empty piece).
   */
  vtkSetMacro(WarnWithoutParticles, bool);
  vtkGetMacro(WarnWithoutParticles, bool);
  ///@}

protected:
  vtkParticleVolumeAOPass();
  ~vtkParticleVolumeAOPass() override;

  ///@{
  /**
   * A volume a prop carries under distributed rendering, stored in the prop's property keys
   * (vtkProp::GetPropertyKeys) under a subclass's key; nullptr removes it.
   */
  static void SetPropVolume(vtkProp* prop, vtkInformationObjectBaseKey* key, vtkObject* volume);
  static vtkObject* GetPropVolume(vtkProp* prop, vtkInformationObjectBaseKey* key);
  ///@}

  using ParticleProps = std::vector<std::pair<vtkActor*, vtkParticleSphereMapper*>>;

  /**
   * The quality levels of the frame budget (GetFrameBudget()): 1 (default) when the settings are
   * already the cheapest, else as many as the subclass describes, the last exact. Render chooses
   * the level before the delegate draws and times the delegate; GetQualityLevel() and
   * GetExactLevel() say which level the shaders of this frame are for.
   */
  virtual int GetNumberOfQualityLevels() { return 1; }
  int GetQualityLevel() { return this->QualityLevel; }
  bool GetExactLevel() { return this->QualityLevel == this->GetNumberOfQualityLevels() - 1; }

  /**
   * Rebuild the volume texture when what it depends on changed (see NeedsBuild); set
   * VolumeValid and count NumberOfVolumeBuilds when it succeeds.
   */
  virtual void UpdateVolume(const vtkRenderState* s) = 0;

  /**
   * The visible particle props of the render state and the state their volume depends on (the
   * mapper, its geometry time, radius scale, the actor's matrix, and what AppendPropState adds).
   */
  void GatherParticleProps(
    const vtkRenderState* s, ParticleProps& props, std::vector<double>& state);
  virtual void AppendPropState(vtkActor*, vtkParticleSphereMapper*, std::vector<double>&) {}

  /**
   * True (and the state remembered) when state differs from the last build's or no build was
   * attempted since the volume object or the graphics resources changed. A failed build is not
   * retried for the same state (no repeated message).
   */
  bool NeedsBuild(const std::vector<double>& state);
  void ForgetBuild() { this->Attempted = false; }

  /**
   * Distributed rendering: the volume of all processes' particles that every particle prop
   * carries under `key` (one volume of all of them; nullptr when a prop carries none or they
   * carry different ones), its address and modification time appended to `state`.
   */
  vtkObject* FindDistributedVolume(
    const ParticleProps& props, vtkInformationObjectBaseKey* key, std::vector<double>& state);

  /**
   * The volume that every prop of `props` carries under `key` (nullptr when they carry different
   * ones or some carry none); `some` (may be null): whether any of them carries one.
   */
  static vtkObject* SharedPropVolume(
    const ParticleProps& props, vtkInformationObjectBaseKey* key, bool* some);

  /**
   * False, with a warning (WarnWithoutParticles) ending in `without`, when there is no particle
   * prop; when some props carry a volume under `key` but not all the same one (several particle
   * props of which not all carry the view's volume), warns that each process's `volumeName`
   * holds only its own particles.
   */
  bool CheckParticleProps(const ParticleProps& props, vtkInformationObjectBaseKey* key,
    const char* without, const char* volumeName);

  /**
   * For SetShaderParameters: true when the program is a particle mapper's that samples the
   * volume texture through the sampler `sampler` and the volume is valid; then the sampler is
   * set to the texture's unit. False: nothing of this pass to set.
   */
  bool SetVolumeSampler(vtkShaderProgram* program, vtkAbstractMapper* mapper, const char* sampler);

  /**
   * Set the mat4 uniform `name` to the map view -> world -> grid, grid = (world - origin) * scale
   * per axis, composed in double precision from the current renderer's camera. False without a
   * camera.
   */
  bool SetViewToGridUniform(
    vtkShaderProgram* program, const char* name, const double origin[3], const double scale[3]);

  /**
   * The rotation view -> world, for normals, as a mat3 uniform.
   */
  bool SetViewToWorldRotationUniform(vtkShaderProgram* program, const char* name);

  vtkTextureObject* VolumeTexture;
  bool VolumeValid = false;
  vtkIdType NumberOfVolumeBuilds = 0;
  bool WarnWithoutParticles = true;
  // the renderer being drawn (between PreRender and PostRender)
  vtkRenderer* CurrentRenderer = nullptr;
  // the shader hooks the pass fills (warns once per missing hook)
  vtkParticleShaderHooks* Hooks;

private:
  vtkParticleVolumeAOPass(const vtkParticleVolumeAOPass&) = delete;
  void operator=(const vtkParticleVolumeAOPass&) = delete;

  std::vector<double> BuiltState;
  bool Attempted = false;
  int QualityLevel = 0;
  vtkTimeStamp LevelTime; // when QualityLevel last changed
};

#endif
