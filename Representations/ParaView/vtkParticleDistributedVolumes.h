/**
 * @class   vtkParticleDistributedVolumes
 * @brief   the ambient-occlusion volume of every process's particles, of all the view's Particles
 *          representations, under distributed rendering
 *
 * With more than one process rendering (pvbatch, pvserver with MPI), each process holds a piece
 * of the particles, and an object-space AO pass that voxelised only its own piece would let
 * occlusion stop at the pieces' boundaries. The Particle Render View owns one
 * vtkParticleDistributedVolumes; each Particles representation tells it what it draws
 * (SetSource, in REQUEST_RENDER), and before the frame the view (Update, every process together)
 * builds the volume of its AO method from all shown representations' particles of all processes
 * over their global bounds, and puts it on each of their actors, where the pass finds it (one
 * volume shared by all particle props, as one process voxelises them all together):
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
 * Update() runs in the view before the local render, never in a render pass (IceT may run those
 * zero or several times per frame). It is collective when every process renders and rebuilds
 * only when the data, radii, colours, opacities, the actors' matrices, which representations
 * are shown or the pass's volume settings changed on some process. Otherwise (one process, a
 * client rendering gathered data, another AO method) it takes the volumes off the actors and the
 * passes voxelise what they draw. Metaballs take no part (the AO passes shade spheres).
 *
 * @sa vtkParticleRepresentation vtkDensityVolumeAOPass vtkVoxelConeAOPass
 */
#ifndef vtkParticleDistributedVolumes_h
#define vtkParticleDistributedVolumes_h

#include "vtkNew.h" // for vtkNew
#include "vtkObject.h"
#include "vtkParticleRenderingParaViewModule.h" // for export macro

#include <string> // for std::string
#include <vector> // for std::vector

class vtkActor;
class vtkDensityVolumeAOPass;
class vtkPVDataRepresentation;
class vtkParticleAmbientVolume;
class vtkParticleDensityVolume;
class vtkParticleSphereMapper;
class vtkPolyData;
class vtkVoxelConeAOPass;

class VTKPARTICLERENDERINGPARAVIEW_EXPORT vtkParticleDistributedVolumes : public vtkObject
{
public:
  static vtkParticleDistributedVolumes* New();
  vtkTypeMacro(vtkParticleDistributedVolumes, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * What representation `repr` draws (its REQUEST_RENDER; it replaces the earlier entry):
   * spheres (not metaballs), its actor and mapper, and this process's particles (each in
   * exactly one process's piece) with the radius array in use ("" for the mapper's constant
   * radius). Not referenced: the representation removes itself (RemoveSource) before it goes.
   */
  void SetSource(vtkPVDataRepresentation* repr, bool spheres, vtkActor* actor,
    vtkParticleSphereMapper* mapper, vtkPolyData* particles, const std::string& radiusArray);
  void RemoveSource(vtkPVDataRepresentation* repr);
  ///@}

  /**
   * Bring the volume of the view's AO method up to date over the shown sources that draw
   * spheres and put it on their actors, or take it off: `distributed` (every process renders
   * this frame; then collective), `density` / `voxelCone`: the pass of the method in use (the
   * other one null, both null without object-space AO).
   */
  void Update(bool distributed, vtkDensityVolumeAOPass* density, vtkVoxelConeAOPass* voxelCone);

protected:
  vtkParticleDistributedVolumes();
  ~vtkParticleDistributedVolumes() override;

  struct vtkSource
  {
    vtkPVDataRepresentation* Representation;
    bool Spheres;
    vtkActor* Actor;
    vtkParticleSphereMapper* Mapper;
    vtkPolyData* Particles;
    std::string RadiusArray;
  };
  // the shown sources that draw spheres
  std::vector<const vtkSource*> SphereSources() const;
  void UpdateDensityVolume(
    const std::vector<const vtkSource*>& sources, vtkDensityVolumeAOPass* pass);
  void UpdateAmbientVolume(const std::vector<const vtkSource*>& sources, vtkVoxelConeAOPass* pass);
  // the volumes on the sources' actors (null: taken off); metaballs' actors never carry one
  void SetDensityVolumeOnActors(vtkParticleDensityVolume* volume);
  void SetAmbientVolumeOnActors(vtkParticleAmbientVolume* volume);

  std::vector<vtkSource> Sources;
  vtkNew<vtkParticleDensityVolume> DensityVolume;
  std::string DensityVolumeKey;
  vtkNew<vtkParticleAmbientVolume> AmbientVolume;
  std::string AmbientVolumeKey;

private:
  vtkParticleDistributedVolumes(const vtkParticleDistributedVolumes&) = delete;
  void operator=(const vtkParticleDistributedVolumes&) = delete;
};

#endif
