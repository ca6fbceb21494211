/**
 * @class   vtkParticleDensityVolume
 * @brief   coarse particle density volume of Grottel et al. 2012 (Eq. 5), on the CPU or the GPU
 *
 * vtkParticleDensityVolume aggregates particles into a coarse regular volume whose voxel value
 * is the volume of the spheres whose centre lies in the voxel, relative to the voxel's volume,
 * times a factor g and clamped to [0, 1] (Grottel, Krone, Scharnowski, Ertl 2012,
 * "Object-Space Ambient Occlusion for Molecular Dynamics", Sec. 4, Eq. 5):
 *
 *   v = min(1, g * sum_{p in voxel} (4/3) pi r_p^3 / v_size^3).
 *
 * SplatMode NEAREST_VOXEL_SPLAT is the paper's rule: a particle contributes entirely to the
 * voxel of its centre. The default, TRILINEAR_SPLAT, spreads it over the 8 voxels whose centres
 * surround it with tent (cloud-in-cell) weights -- the "smooth kernel splatting" the paper
 * proposes as future work against its Fig. 6 artefact: with nearest-voxel splatting a crystal
 * whose lattice constant does not divide the voxel edge puts 2 or 3 atomic planes into
 * alternate voxels, and the AO of its faces shows a blocky beat pattern; the trilinear splat
 * removes it (measured: Documentation/AmbientOcclusion.md). The total
 * is the same; near the grid's faces the weights of outside voxel centres fold onto the
 * boundary voxels. g = 1 by default; 1/0.74 makes a close-packed crystal
 * exactly opaque.
 *
 * Geometry: cubic voxels over the bounding box of the particle centres. The automatic resolution
 * (Resolution (0, 0, 0), the default) uses voxels of edge 4 mean radii, i.e. two particle
 * diameters, so that the neighbourhood a single trilinear fetch sees (about half a voxel around
 * the fetch point, paper Sec. 3) is the shell of nearest neighbours; each axis gets
 * ceil(extent / edge) voxels, at least 1. A user resolution sets the number of voxels of the
 * longest axis; the other axes get as many cubic voxels as they need. Either way no axis gets
 * more than MaximumResolution voxels (default 256) nor more than the GPU's largest 3D texture
 * (SetUpGrid's deviceAxisLimit), and the grid no more than MaximumVoxelCount voxels (default
 * 2^26): the edge grows instead, with a warning. Degenerate boxes (all particles in a
 * plane, on a line or at one point) get one voxel across each flat axis, centred on the data.
 *
 * Generation:
 * - ComputeOnCPU(): vtkSMPTools over the particles, each thread into its own partial volume,
 *   then a parallel sum over the voxels (the paper's multi-core scheme, without races).
 * - ComputeOnGPU(): one compute-shader invocation per particle adds its volume to its voxel
 *   with an integer atomicAdd in fixed point (2^-20 of a voxel volume; float atomics are not in
 *   core OpenGL), then a second pass converts, scales and clamps. It reads the positions and
 *   radii straight from a mapper's vertex buffers (after VTK's VBO shift/scale). Needs
 *   OpenGL 4.3.
 * Both give the same volume up to the fixed-point rounding (tested).
 *
 * Progress: with observers of vtkCommand::ProgressEvent, both splat the particles in up to 16
 * blocks (at least 65536 particles each) and invoke the event with the fraction of particles
 * done (a double; 0 first, 1 last). On the GPU a block counts when its dispatch is issued.
 *
 * @sa vtkParticleSphereMapper
 */
#ifndef vtkParticleDensityVolume_h
#define vtkParticleDensityVolume_h

#include "vtkObject.h"
#include "vtkParticleRenderingAmbientOcclusionModule.h" // for export macro

#include <vector> // for std::vector

class vtkActor;
class vtkDataArray;
class vtkFloatArray;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkParticleSphereMapper;
class vtkTextureObject;
class vtkWindow;

class VTKPARTICLERENDERINGAMBIENTOCCLUSION_EXPORT vtkParticleDensityVolume : public vtkObject
{
public:
  static vtkParticleDensityVolume* New();
  vtkTypeMacro(vtkParticleDensityVolume, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of voxels along the longest axis of the bounding box; 0 (default): automatic (see the
   * class description).
   */
  vtkSetClampMacro(Resolution, int, 0, 4096);
  vtkGetMacro(Resolution, int);
  ///@}

  enum SplatModes
  {
    NEAREST_VOXEL_SPLAT = 0, // the paper's Eq. 5: all of a particle into the voxel of its centre
    TRILINEAR_SPLAT = 1      // cloud in cell: tent weights over the 8 surrounding voxel centres
  };

  ///@{
  /**
   * How a particle's volume is distributed (see the class description). Default
   * TRILINEAR_SPLAT.
   */
  vtkSetClampMacro(SplatMode, int, NEAREST_VOXEL_SPLAT, TRILINEAR_SPLAT);
  vtkGetMacro(SplatMode, int);
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
   * Largest number of voxels in all (the volume is one float per voxel on the CPU and the GPU).
   * Default 2^26 (256 MiB); a larger grid grows its voxels instead, with a warning.
   */
  vtkSetClampMacro(MaximumVoxelCount, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumVoxelCount, vtkIdType);
  ///@}

  ///@{
  /**
   * The factor g of the density (paper Sec. 4). Default 1.
   */
  vtkSetClampMacro(DensityFactor, double, 0.0, 1e6);
  vtkGetMacro(DensityFactor, double);
  ///@}

  /**
   * Set up the grid for particles with these centre bounds and mean radius: dimensions, origin
   * and cubic voxel edge (GetDimensions, GetOrigin, GetVoxelSize). deviceAxisLimit > 0 caps the
   * voxels per axis further (the GPU's largest 3D texture), with a warning when it applies.
   * Returns false for invalid (or non-finite) bounds or a mean radius <= 0.
   */
  bool SetUpGrid(const double centerBounds[6], double meanRadius, int deviceAxisLimit = 0);

  vtkGetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Origin, double);
  vtkGetMacro(VoxelSize, double);

  /**
   * The density volume on the CPU from positions (3 components, any type) and radii (0 or less:
   * skipped), for the grid of the last SetUpGrid(). The result, x fastest, is in GetVolume().
   */
  bool ComputeOnCPU(vtkDataArray* positions, vtkFloatArray* radii);

  ///@{
  /**
   * Distributed building (vtkParticleRepresentation under MPI): ComputeSumsOnCPU() is
   * ComputeOnCPU() without the final step, so GetVolume() holds the sums of the sphere volumes
   * per voxel, in voxel volumes; after these have been summed over the processes,
   * FinishSums() applies the factor g and the clamp to 1 (Eq. 5). The result equals one
   * ComputeOnCPU() over all particles up to float rounding.
   */
  bool ComputeSumsOnCPU(vtkDataArray* positions, vtkFloatArray* radii);
  std::vector<float>& GetMutableVolume() { return this->Volume; }
  void FinishSums();
  ///@}

  /**
   * Take the grid and the volume of `other` (built elsewhere, e.g. summed over processes by
   * the pipeline) and fill `texture` with it (one-component float 3D texture). False, with a
   * message, when there is no volume or the texture cannot be made.
   */
  bool UploadVolumeOf(
    vtkParticleDensityVolume* other, vtkOpenGLRenderWindow* context, vtkTextureObject* texture);

  /**
   * The same on the GPU, from buffer objects holding float positions (positionStride floats per
   * particle, mapped by bufferToGrid -- row-major, e.g. VTK's VBO shift/scale undone and the
   * actor's matrix -- to the grid's coordinates) and float radii (times radiusScale). With
   * accumulate, the particles are added to those of the previous call (several props in one
   * volume). The result stays in GetVolumeBuffer() (floats, x fastest); ReadVolumeBuffer()
   * copies it to GetVolume() (for tests), CopyVolumeBufferToTexture() into a 3D texture.
   */
  bool ComputeOnGPU(vtkOpenGLRenderWindow* context, vtkOpenGLBufferObject* positionBuffer,
    unsigned int positionStride, const double bufferToGrid[16], vtkOpenGLBufferObject* radiusBuffer,
    double radiusScale, vtkIdType count, bool accumulate = false);
  bool CopyVolumeBufferToTexture(vtkTextureObject* texture3D);
  vtkOpenGLBufferObject* GetVolumeBuffer();
  bool ReadVolumeBuffer();

  ///@{
  /**
   * Voxelise the particles of several props into this volume, in MegaMol's start / insert / end
   * shape, for any technique that needs a particle volume (density AO, later voxel-cone AO):
   * BeginParticles() forgets the previous props; AddParticles() adds the spheres a
   * vtkParticleSphereMapper draws for an actor (world coordinates through the actor's matrix,
   * radii as drawn, skipped particles left out); EndParticles() gathers their bounds and mean
   * radius (vtkSMPTools), sets up the grid (capped by the context's largest 3D texture),
   * splats them on the GPU from the mappers' own vertex buffers (onGPU, OpenGL 4.3, once every
   * mapper has drawn) or else on the CPU, and fills texture (a one-component float 3D texture,
   * whose sampling parameters the caller sets). False, with a message, when there is nothing to
   * voxelise or the texture cannot be made. Progress: 0.5 once gathered, then the splat blocks.
   * GetNumberOfParticles() counts the particles added (for progress thresholds);
   * GetLastBuiltOnGPU() says where the last EndParticles() built the volume.
   */
  void BeginParticles();
  void AddParticles(vtkActor* actor, vtkParticleSphereMapper* mapper);
  vtkIdType GetNumberOfParticles();
  bool EndParticles(vtkOpenGLRenderWindow* context, bool onGPU, vtkTextureObject* texture);
  vtkGetMacro(LastBuiltOnGPU, bool);
  ///@}

  /**
   * The last volume computed on the CPU or read back from the GPU.
   */
  const std::vector<float>& GetVolume() const { return this->Volume; }

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkParticleDensityVolume();
  ~vtkParticleDensityVolume() override;

  int Resolution = 0;
  int MaximumResolution = 256;
  int SplatMode = TRILINEAR_SPLAT;
  vtkIdType MaximumVoxelCount = vtkIdType(1) << 26;
  double DensityFactor = 1.0;
  int Dimensions[3] = { 0, 0, 0 };
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double VoxelSize = 0.0;
  std::vector<float> Volume;
  bool LastBuiltOnGPU = false;

private:
  vtkParticleDensityVolume(const vtkParticleDensityVolume&) = delete;
  void operator=(const vtkParticleDensityVolume&) = delete;

  // the particles of the props added, in world coordinates (positions and radii only when
  // both are given); false when none is valid
  bool GatherParticles(
    vtkFloatArray* positions, vtkFloatArray* radii, double bounds[6], double& meanRadius);
  // a ProgressEvent for `done` of `n` particles, in the current progress window
  void ReportProgress(vtkIdType done, vtkIdType n);

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
