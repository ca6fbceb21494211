/**
 * @class   vtkParticleAmbientVolume
 * @brief   RGBA voxelisation of particles with overlap weights and a mip pyramid, for voxel cone
 *          tracing (Staib, Grottel, Gumhold 2015, Sec. 3.2 and 5.1)
 *
 * vtkParticleAmbientVolume voxelises the spheres of several particle props into a 3D texture
 * whose voxels hold the ambient transfer functions pre-classified (paper Sec. 5.1): alpha is an
 * extinction coefficient (optical depth per voxel edge), RGB the emission e_A c_i times that
 * extinction, both summed over the particles weighted by the overlap w of sphere and voxel:
 *
 *   w = V_sphere / V_voxel   when the voxel holds the whole sphere,
 *   w = 1                    when the voxel lies inside the sphere,
 *   w = hits / s^3           otherwise, from an s x s x s sub-grid of the voxel (SubGridSamples,
 *                            default 3 as in the paper); the partial voxels of a sphere are then
 *                            scaled so that its weights add up to its volume exactly (a sphere
 *                            smaller than the sub-grid spacing that no sample hits goes whole
 *                            into the voxel of its centre).
 *
 * The paper leaves the classification open ("absorption from the particle's Theta_i"). Our
 * choice, so that a cone sees the right transmittance tau_A of Eq. 5 through a neighbourhood of
 * many particles: each particle contributes the extinction of a random medium of such particles
 * at volume fraction w, sigma_i = w * (3 / (4 r_i)) * <Theta_i>, where (3 / (4 r)) w is the
 * number density times the cross-section pi r^2 and <Theta_i> the particle's opacity averaged
 * over its projected disc (its emission-absorption profile, Eq. 12-19: for constant density
 * with optical depth T through the centre, <Theta> = 1 - 2 (1 - e^-T (1 + T)) / T^2; for the
 * other models a 16-point Gauss-Legendre rule over the impact parameter). A translucent particle
 * therefore occludes less than an opaque one of the same size (paper Fig. 2), an opaque one
 * blocks exactly its cross-section, and in the optically thin limit sigma is the homogenised
 * extinction w Theta-derived sigma of the glyph. The cone (vtkVoxelConeAOPass) turns a sample into
 * the opacity 1 - exp(-sigma d) of its step length d. Because alpha is an extinction, not an
 * opacity, the mip levels average it exactly (the mean extinction of the 2x2x2 children), and
 * the result does not depend on the voxel size.
 *
 * Grid: cubic voxels over the bounds of the spheres (centres grown by the largest radius), a
 * power of two per axis so that every mip level halves exactly. Resolution 0 (automatic, the
 * default) takes a voxel edge of one mean radius, the longest axis clamped to 32...
 * MaximumResolution (default 256) voxels; a user Resolution sets the voxels along the longest
 * axis (rounded up to a power of two). GPU memory of the texture with all mips is about 8/7 x
 * 8 bytes per voxel (RGBA16F): 256^3 takes 153 MB; the float pyramid it is built from takes
 * another 8/7 x 16 bytes per voxel (307 MB at 256^3; kept on the GPU between builds, so that a
 * time series does not reallocate it). MaximumMemory (MiB, default 512) bounds both together:
 * a larger grid is halved with a warning. The GPU's largest 3D texture bounds every axis.
 *
 * Where it runs (GPUVoxelisation, default on): the voxelisation, the mips and the conversion to
 * half floats run in OpenGL 4.3 compute shaders (Shaders/AmbientOcclusion/AmbientVolume.glsl): only
 * the spheres (32 bytes each, centres in voxel units formed in double) go to the GPU, one
 * invocation per sphere and voxel slice sums the sphere's weights and then deposits them with float
 * additions by compare-and-swap, one per voxel averages 2x2x2 children into the next level, and one
 * per voxel stores each level into the texture. Off, or in a context below OpenGL 4.3 (with one
 * warning), the same arithmetic runs on the CPU (vtkSMPTools, slab by slab along z, no races)
 * and the levels are converted to half floats in parallel and uploaded. The two agree to float
 * rounding (the order of the GPU's additions varies); Voxelise() is the CPU path without a
 * texture, for tests.
 *
 * @sa vtkVoxelConeAOPass vtkParticleDensityVolume
 */
#ifndef vtkParticleAmbientVolume_h
#define vtkParticleAmbientVolume_h

#include "vtkObject.h"
#include "vtkParticleRenderingAmbientOcclusionModule.h" // for export macro

#include <vector> // for std::vector

class vtkActor;
class vtkOpenGLRenderWindow;
class vtkParticleSphereMapper;
class vtkTextureObject;
class vtkWindow;

class VTKPARTICLERENDERINGAMBIENTOCCLUSION_EXPORT vtkParticleAmbientVolume : public vtkObject
{
public:
  static vtkParticleAmbientVolume* New();
  vtkTypeMacro(vtkParticleAmbientVolume, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Voxels along the longest axis (rounded up to a power of two); 0 (default): automatic, a
   * voxel edge of one mean radius.
   */
  vtkSetClampMacro(Resolution, int, 0, 4096);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Largest number of voxels along any axis. Default 256.
   */
  vtkSetClampMacro(MaximumResolution, int, 1, 4096);
  vtkGetMacro(MaximumResolution, int);
  ///@}

  ///@{
  /**
   * Sub-grid samples per axis for voxels that hold part of a sphere (paper: 3). Default 3.
   */
  vtkSetClampMacro(SubGridSamples, int, 1, 16);
  vtkGetMacro(SubGridSamples, int);
  ///@}

  ///@{
  /**
   * The ambient emission e_A (paper Eq. 6, Fig. 2 d): the particles' colour times this is the
   * radiance they give off into the cones. Default 1.
   */
  vtkSetClampMacro(AmbientEmission, double, 0.0, 1e3);
  vtkGetMacro(AmbientEmission, double);
  ///@}

  ///@{
  /**
   * GPU memory bound of the texture with its mips, in MiB. Default 512.
   */
  vtkSetClampMacro(MaximumMemory, double, 1.0, 1e7);
  vtkGetMacro(MaximumMemory, double);
  ///@}

  ///@{
  /**
   * Voxelise, build the mips and fill the texture with compute shaders (default on); off: on the
   * CPU with an upload (see the class description).
   */
  vtkSetMacro(GPUVoxelisation, bool);
  vtkGetMacro(GPUVoxelisation, bool);
  vtkBooleanMacro(GPUVoxelisation, bool);
  ///@}

  ///@{
  /**
   * Voxelise the particles of several props: BeginParticles() forgets the previous ones,
   * AddParticles() adds the spheres a vtkParticleSphereMapper (or vtkTransparentSphereMapper)
   * draws for an actor (world coordinates, radii as drawn, colours as mapped, Theta_i as
   * drawn), EndParticles() builds the grid, the voxels and the mips and fills texture. False,
   * with a message, when there is nothing to voxelise or the texture cannot be made.
   */
  void BeginParticles();
  void AddParticles(vtkActor* actor, vtkParticleSphereMapper* mapper);
  vtkIdType GetNumberOfParticles();
  bool EndParticles(vtkOpenGLRenderWindow* context, vtkTextureObject* texture);
  ///@}

  /**
   * Voxelise given spheres (as Voxelise()) into the texture in the context (made current by the
   * caller), on the GPU or the CPU as GPUVoxelisation and the context allow. EndParticles()
   * calls it with the spheres of its props.
   */
  bool BuildTexture(vtkOpenGLRenderWindow* context, vtkTextureObject* texture,
    const std::vector<double>& centers, const std::vector<double>& radii,
    const std::vector<double>& colors, const std::vector<double>& meanOpacities);

  ///@{
  /**
   * Distributed building (vtkParticleRepresentation under MPI; the sums are linear in the
   * particles): GatherSpheres() appends the spheres of one prop as EndParticles() gathers them
   * (ownedOnly: points flagged as ghosts by vtkGhostType are left out);
   * VoxeliseLevelZero() deposits them on the CPU into level 0 of the grid set up for the given
   * sphere bounds and mean radius (those of all processes, so every process gets the same grid;
   * no spheres is fine); after level 0 (GetMutableLevelZero()) has been summed over the
   * processes, UploadVolumeOf() on the pass's volume takes that grid and level, builds the mips
   * and fills the texture.
   */
  static void GatherSpheres(vtkActor* actor, vtkParticleSphereMapper* mapper, bool ownedOnly,
    std::vector<double>& centers, std::vector<double>& radii, std::vector<double>& colors,
    std::vector<double>& meanOpacities);
  bool VoxeliseLevelZero(const std::vector<double>& centers, const std::vector<double>& radii,
    const std::vector<double>& colors, const std::vector<double>& meanOpacities,
    const double sphereBounds[6], double meanRadius);
  std::vector<float>& GetMutableLevelZero();
  bool UploadVolumeOf(
    vtkParticleAmbientVolume* other, vtkOpenGLRenderWindow* context, vtkTextureObject* texture);
  ///@}

  /**
   * Whether the last build ran on the GPU.
   */
  vtkGetMacro(LastBuildOnGPU, bool);

  /**
   * After a GPU build: read its float pyramid back (context current), so that GetLevel() shows
   * it. After a CPU build GetLevel() holds it already. False when there is none.
   */
  bool ReadLevels(vtkOpenGLRenderWindow* context);

  /**
   * Release the compute programs and buffers of the GPU voxelisation.
   */
  void ReleaseGraphicsResources(vtkWindow* window);

  /**
   * Voxelise given spheres (world coordinates; colours RGB in [0,1], 3 per sphere; opacities are
   * the mean disc opacities <Theta_i>) into the grid set up for their bounds, on the CPU, without
   * a texture (EndParticles uses it; tests call it directly). Spheres with a radius <= 0, a mean
   * opacity <= 0 (clear: not drawn) or a non-finite value are skipped. deviceAxisLimit > 0
   * caps the voxels per axis further.
   */
  bool Voxelise(const std::vector<double>& centers, const std::vector<double>& radii,
    const std::vector<double>& colors, const std::vector<double>& meanOpacities,
    int deviceAxisLimit = 0);

  /**
   * The mean opacity over the projected disc of a sphere whose most opaque ray has opacity
   * theta, for the density models of vtkTransparentSphereMapper (CONSTANT_DENSITY = 0,
   * SQUARED_DISTANCE_DENSITY = 1) and a hollow core of the given fraction of the radius.
   */
  static double MeanDiscOpacity(double theta, int densityModel, double hollowFraction);

  vtkGetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Origin, double);
  vtkGetMacro(VoxelSize, double);
  /**
   * Number of mip levels (level 0 included) and the bytes of the texture with all of them.
   */
  vtkGetMacro(NumberOfLevels, int);
  vtkGetMacro(TextureBytes, double);

  /**
   * IEEE half-float bits of a float, rounded to nearest even (the texture upload's conversion):
   * beyond the largest half (65504) and Inf give 65504, NaN gives 0, subnormals are kept.
   */
  static unsigned short FloatToHalf(float value);

  ///@{
  /**
   * Wall times of the stages of the last build, in seconds (for benchmarks): gathering the
   * spheres from the props (EndParticles), voxelising level 0 (grid and sphere set-up included),
   * building the mips, uploading. On the GPU (each stage finished with glFinish): upload is the
   * spheres' (and the accumulator's clearing), mips include storing every level into the
   * texture; on the CPU upload is the conversion to half floats and the texture upload.
   */
  vtkGetMacro(LastGatherSeconds, double);
  vtkGetMacro(LastVoxeliseSeconds, double);
  vtkGetMacro(LastMipSeconds, double);
  vtkGetMacro(LastUploadSeconds, double);
  ///@}

  /**
   * Level l of the pyramid (RGBA floats, x fastest), as last voxelised on the CPU or read back
   * with ReadLevels(); empty otherwise.
   */
  const std::vector<float>& GetLevel(int level) const;

protected:
  vtkParticleAmbientVolume();
  ~vtkParticleAmbientVolume() override;

  bool SetUpGrid(const double sphereBounds[6], double meanRadius, int deviceAxisLimit);
  // the valid spheres, the grid for their bounds and the spheres in voxel units
  bool PrepareSpheres(const std::vector<double>& centers, const std::vector<double>& radii,
    const std::vector<double>& colors, const std::vector<double>& meanOpacities,
    int deviceAxisLimit);
  // level 0 of the prepared spheres on the CPU; the mips on the CPU
  void DepositOnCPU();
  void BuildMips();
  // the texture's levels (no data) and sampling parameters; the CPU levels into it
  bool AllocateTexture(vtkOpenGLRenderWindow* context, vtkTextureObject* texture);
  bool UploadLevels(vtkOpenGLRenderWindow* context, vtkTextureObject* texture);
  // the prepared spheres voxelised, mipped and stored into the texture by compute shaders
  bool VoxeliseOnGPU(vtkOpenGLRenderWindow* context, vtkTextureObject* texture);
  // The four compute stages of VoxeliseOnGPU (weights, deposit, mip, store) built in `context`
  // (the resources of another context released first).
  bool BuildGPUPrograms(vtkOpenGLRenderWindow* context);

  int Resolution = 0;
  int MaximumResolution = 256;
  int SubGridSamples = 3;
  double AmbientEmission = 1.0;
  double MaximumMemory = 512.0;
  bool GPUVoxelisation = true;
  bool LastBuildOnGPU = false;
  int Dimensions[3] = { 0, 0, 0 };
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double VoxelSize = 0.0;
  int NumberOfLevels = 0;
  double LastGatherSeconds = 0.0;
  double LastVoxeliseSeconds = 0.0;
  double LastMipSeconds = 0.0;
  double LastUploadSeconds = 0.0;
  double TextureBytes = 0.0;

private:
  vtkParticleAmbientVolume(const vtkParticleAmbientVolume&) = delete;
  void operator=(const vtkParticleAmbientVolume&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
