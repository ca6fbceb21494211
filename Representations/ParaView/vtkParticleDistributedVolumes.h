/**
 * @class   vtkParticleDistributedVolumes
 * @brief   the ambient-occlusion volumes of every process's particles under distributed rendering
 *
 * With more than one process rendering (pvbatch, pvserver with MPI), each process holds a piece
 * of the particles, and an object-space AO pass that voxelised only its own piece would let
 * occlusion stop at the pieces' boundaries. vtkParticleDistributedVolumes builds, for the
 * Particle Render View's AO method, the volume of all processes' particles over the global
 * bounds and puts it on the representation's actor, where the pass finds it:
 *
 * - density-volume AO (Grottel et al. 2012, Eq. 5): each process splats its own particles
 *   (vtkParticleDensityVolume::ComputeSumsOnCPU), the voxel sums are added over the processes
 *   (all-reduce), then g and the clamp are applied (FinishSums);
 *   vtkDensityVolumeAOPass::SetDistributedVolume(actor, volume).
 * - voxel-cone AO (Staib et al. 2015, Sec. 6): level 0 of an ambient volume over all processes'
 *   spheres (own particles, not ghost copies; colours and opacities as drawn), summed over the
 *   processes (extinction and emission add up); the pass builds the mips.
 *   vtkVoxelConeAOPass::SetDistributedVolume(actor, volume).
 *
 * Update() runs in REQUEST_RENDER, never in a render pass (IceT may run those zero or several
 * times per frame). It is collective when every process renders (IsDistributedRender) and
 * rebuilds only when the data, radii, colours, opacities, the actor's matrix or the pass's
 * volume settings changed on some process. Otherwise (one process, a client rendering gathered
 * data, another AO method, metaballs) it takes the volumes off the actor and the passes
 * voxelise what they draw.
 *
 * @sa vtkParticleRepresentation vtkDensityVolumeAOPass vtkVoxelConeAOPass
 */
#ifndef vtkParticleDistributedVolumes_h
#define vtkParticleDistributedVolumes_h

#include "vtkNew.h" // for vtkNew
#include "vtkObject.h"
#include "vtkParticleRenderingParaViewModule.h" // for export macro

#include <string> // for std::string

class vtkActor;
class vtkInformation;
class vtkParticleAmbientVolume;
class vtkParticleDensityVolume;
class vtkParticleSphereMapper;
class vtkPolyData;

class VTKPARTICLERENDERINGPARAVIEW_EXPORT vtkParticleDistributedVolumes : public vtkObject
{
public:
  static vtkParticleDistributedVolumes* New();
  vtkTypeMacro(vtkParticleDistributedVolumes, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Bring the volume of the view's AO method (inInfo: the REQUEST_RENDER information) up to
   * date and set it on the actor, or take it off. spheres: the representation draws spheres
   * (not metaballs); particles: this process's particles (each in exactly one process's piece)
   * with the radius array in use ("" for the mapper's constant radius).
   */
  void Update(vtkInformation* inInfo, bool spheres, vtkActor* actor,
    vtkParticleSphereMapper* mapper, vtkPolyData* particles, const std::string& radiusArray);

  /**
   * Whether every process renders this frame (distributed rendering), so that sums over the
   * processes are safe in REQUEST_RENDER.
   */
  static bool IsDistributedRender(vtkInformation* inInfo);

protected:
  vtkParticleDistributedVolumes();
  ~vtkParticleDistributedVolumes() override;

  void UpdateDensityVolume(vtkInformation* inInfo, bool spheres, vtkActor* actor,
    vtkParticleSphereMapper* mapper, vtkPolyData* particles, const std::string& radiusArray);
  void UpdateAmbientVolume(
    vtkInformation* inInfo, bool spheres, vtkActor* actor, vtkParticleSphereMapper* mapper);

  vtkNew<vtkParticleDensityVolume> DensityVolume;
  std::string DensityVolumeKey;
  vtkNew<vtkParticleAmbientVolume> AmbientVolume;
  std::string AmbientVolumeKey;

private:
  vtkParticleDistributedVolumes(const vtkParticleDistributedVolumes&) = delete;
  void operator=(const vtkParticleDistributedVolumes&) = delete;
};

#endif
