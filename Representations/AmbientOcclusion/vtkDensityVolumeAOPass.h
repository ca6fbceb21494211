/**
 * @class   vtkDensityVolumeAOPass
 * @brief   object-space ambient occlusion of particles from a coarse density volume
 *
 * vtkDensityVolumeAOPass implements the ambient occlusion of Grottel, Krone, Scharnowski, Ertl
 * 2012, "Object-Space Ambient Occlusion for Molecular Dynamics": the particles of every
 * vtkParticleSphereMapper (and vtkTransparentSphereMapper) among the renderer's props are
 * aggregated into a coarse density volume (vtkParticleDensityVolume, Eq. 5, in world
 * coordinates, all particle props together), and the sphere shading multiplies its lighting by
 * the ambient-occlusion factor A = 1 - D(p + eps n) (Eq. 4): the density fetched with trilinear
 * filtering one step eps along the normal from the visible point (per-fragment retrieval, Sec. 5).
 * eps is FetchDistance voxel edges. Default 0.5: the paper (Sec. 3) takes eps as half a voxel
 * edge, the radius of the hemisphere of Eq. 3 whose diameter is one voxel; against ray-traced AO
 * (Benchmarks/README.md) half a voxel also gives the lowest error of 0.5, 1 and 2 voxels on the
 * liquid film and the FCC block.
 *
 * RetrievalMode PER_SPHERE is the paper's other variant: six fetches per sphere in the vertex
 * stage at the centre +- eps along the world axes, blended per fragment by the squared
 * components of the world normal (f = nx^2 A(+-x) + ny^2 A(+-y) + nz^2 A(+-z), the sign of each
 * component choosing the side). The paper's fetch includes the sphere's own density, which sits
 * in the voxels around its centre: an isolated sphere darkens itself, and with voxels finer than
 * the spheres every sphere finds its own volume. Our choice: each fetch subtracts the sphere's
 * own splat share (Shaders/AmbientOcclusion/DensityVolumeOwn.glsl; exact below the volume's clamp
 * to 1, grid boundaries excepted), so A measures the other particles only, as Eq. 3 intends.
 *
 * The mappers know nothing about AO beyond their //PR::AmbientOcclusion::Impl hook: the pass
 * fills it through vtkOpenGLRenderPass::PostReplaceShaderValues and binds the volume and the
 * view-to-volume matrix in SetShaderParameters. Like every vtkParticleVolumeAOPass it is a
 * render pass with a delegate (e.g. vtkRenderStepsPass; in ParaView the Particle Render View's
 * pass chain) that renders the scene directly, without an intermediate image.
 *
 * The volume is rebuilt only when the particles' positions or radii, the set of particle props,
 * their matrices or the pass's settings change -- never when only the camera moves
 * (GetNumberOfVolumeBuilds counts). Generation on the CPU (vtkSMPTools) or the GPU (compute
 * shader over the mappers' own vertex buffers), see GenerationMode; the voxelisation itself
 * (gathering the props' particles, the grid, the splat, the texture) is
 * vtkParticleDensityVolume's BeginParticles / AddParticles / EndParticles, which other
 * volume-based techniques reuse.
 *
 * Interactive frames (GetFrameBudget(), vtkParticleFrameBudget): with RetrievalMode
 * PER_FRAGMENT two levels, PER_SPHERE retrieval (level 0) and per fragment (exact); the volume is
 * the same at both. The delegate's whole draw is timed (the retrieval runs in the particles'
 * shaders).
 *
 * @sa vtkParticleDensityVolume vtkParticleSphereMapper vtkSSAOPass
 */
#ifndef vtkDensityVolumeAOPass_h
#define vtkDensityVolumeAOPass_h

#include "vtkParticleRenderingAmbientOcclusionModule.h" // for export macro
#include "vtkParticleVolumeAOPass.h"

class vtkParticleDensityVolume;

class VTKPARTICLERENDERINGAMBIENTOCCLUSION_EXPORT vtkDensityVolumeAOPass
  : public vtkParticleVolumeAOPass
{
public:
  static vtkDensityVolumeAOPass* New();
  vtkTypeMacro(vtkDensityVolumeAOPass, vtkParticleVolumeAOPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Distributed rendering: a density volume of the particle props' spheres together with those
   * of every other process (ParaView's Particle Render View builds it over the global bounds and
   * sums it over the processes, vtkParticleDistributedVolumes), carried in the props' property
   * keys under DISTRIBUTED_VOLUME(). When every particle prop carries the same one, the pass uses
   * it instead of voxelising the particles this process holds, so that occlusion does not stop
   * at the processes' boundaries. nullptr (the default) removes it: the pass voxelises.
   */
  static vtkInformationObjectBaseKey* DISTRIBUTED_VOLUME();
  static void SetDistributedVolume(vtkProp* prop, vtkParticleDensityVolume* volume);
  static vtkParticleDensityVolume* GetDistributedVolume(vtkProp* prop);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* w) override;

  enum RetrievalModes
  {
    PER_FRAGMENT = 0, // one fetch at p + eps n per fragment (paper Sec. 5, second variant)
    PER_SPHERE = 1    // six fetches per sphere at the centre +- eps along the world axes,
                      // blended per fragment by the squared normal components (first variant)
  };

  enum GenerationModes
  {
    CPU_GENERATION = 0,
    GPU_GENERATION = 1
  };

  ///@{
  /**
   * Where the density volume is generated (paper Sec. 4): CPU_GENERATION (default; vtkSMPTools)
   * or GPU_GENERATION (compute shader reading the mappers' vertex buffers; needs OpenGL 4.3 and
   * falls back to the CPU for a build where a mapper has not drawn yet, e.g. the first frame).
   */
  vtkSetClampMacro(GenerationMode, int, CPU_GENERATION, GPU_GENERATION);
  vtkGetMacro(GenerationMode, int);
  ///@}

  /**
   * Where the last build ran: CPU_GENERATION or GPU_GENERATION.
   */
  vtkGetMacro(LastGenerationMode, int);

  ///@{
  /**
   * How the occlusion is fetched (paper Sec. 5). Default PER_FRAGMENT, which the paper found
   * slightly better looking and, for many small spheres, faster.
   */
  vtkSetClampMacro(RetrievalMode, int, PER_FRAGMENT, PER_SPHERE);
  vtkGetMacro(RetrievalMode, int);
  ///@}

  ///@{
  /**
   * Fetch distance eps along the normal (per fragment) or the axes (per sphere), in voxel edges.
   * Default 0.5 (the paper's half voxel).
   */
  vtkSetClampMacro(FetchDistance, double, 0.0, 100.0);
  vtkGetMacro(FetchDistance, double);
  ///@}

  ///@{
  /**
   * How much darker occluded places get: A = 1 - Strength D(p + eps n), clamped to [0, 1]
   * (Eq. 4 scaled; per sphere, the blend of the six fetches is scaled). 1 (default) is the
   * paper's; against ray-traced occlusion strength 2 is closest (measured:
   * Documentation/AmbientOcclusion.md). Changing it rebuilds nothing and recompiles nothing.
   */
  vtkSetClampMacro(Strength, double, 0.0, 100.0);
  vtkGetMacro(Strength, double);
  ///@}

  ///@{
  /**
   * The density volume (resolution, density factor g, ...). Changing its settings rebuilds it.
   * The pass makes its own; SetDensityVolume replaces it (ParaView hands over the VTK object of
   * the pass proxy's density-volume sub-proxy this way). nullptr is ignored.
   */
  vtkParticleDensityVolume* GetDensityVolume();
  void SetDensityVolume(vtkParticleDensityVolume* volume);
  ///@}

  ///@{
  /**
   * A volume build over at least ProgressThreshold particles (all particle props together;
   * default 2^20) reports its progress as a vtkAlgorithm does: vtkCommand::ProgressEvent on this
   * pass with the fraction done (a double) as call data, from 0 to 1, while GetProgressText()
   * names the work ("" otherwise). The Particle Render View passes it on to ParaView's progress
   * bar. 0 always reports, VTK_ID_MAX never. The fraction counts the gathering of the particles
   * (the first half) and the splat in 16 blocks (vtkParticleDensityVolume); on a GPU the
   * splat's blocks are counted when issued.
   */
  vtkSetClampMacro(ProgressThreshold, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(ProgressThreshold, vtkIdType);
  const char* GetProgressText();
  ///@}

  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

  /**
   * The frame budget's levels with these settings: "per-sphere retrieval|per-fragment retrieval"
   * (per fragment set), else "per-sphere retrieval".
   */
  std::string GetQualityLevelNames() override
  {
    return this->RetrievalMode == PER_FRAGMENT ? "per-sphere retrieval|per-fragment retrieval"
                                               : "per-sphere retrieval";
  }

protected:
  vtkDensityVolumeAOPass();
  ~vtkDensityVolumeAOPass() override;

  /**
   * Rebuild the volume and its texture when the particles or the settings changed.
   */
  void UpdateVolume(const vtkRenderState* s) override;

  // two levels when the retrieval is per fragment: per sphere while the camera moves
  int GetNumberOfQualityLevels() override { return this->RetrievalMode == PER_FRAGMENT ? 2 : 1; }

  int RetrievalMode = PER_FRAGMENT;
  int GenerationMode = CPU_GENERATION;
  int LastGenerationMode = CPU_GENERATION;
  double FetchDistance = 0.5;
  double Strength = 1.0;
  vtkIdType ProgressThreshold = vtkIdType(1) << 20;

private:
  vtkDensityVolumeAOPass(const vtkDensityVolumeAOPass&) = delete;
  void operator=(const vtkDensityVolumeAOPass&) = delete;

  // progress of a long volume build (ProgressThreshold)
  void ReportProgress(double fraction);
  void ForwardVolumeProgress(vtkObject*, unsigned long, void* callData);
  class vtkProgressScope;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
