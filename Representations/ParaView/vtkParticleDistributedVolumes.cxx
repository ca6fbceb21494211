#include "vtkParticleDistributedVolumes.h"

#include "vtkActor.h"
#include "vtkDensityVolumeAOPass.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVDataRepresentation.h"
#include "vtkParticleAmbientVolume.h"
#include "vtkParticleDensityVolume.h"
#include "vtkParticleDistributedPartition.h"
#include "vtkParticleProcessReduction.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkScalarsToColors.h"
#include "vtkVoxelConeAOPass.h"

#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkParticleDistributedVolumes);

//------------------------------------------------------------------------------
vtkParticleDistributedVolumes::vtkParticleDistributedVolumes() = default;

//------------------------------------------------------------------------------
vtkParticleDistributedVolumes::~vtkParticleDistributedVolumes() = default;

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::SetSource(vtkPVDataRepresentation* repr, bool spheres,
  vtkActor* actor, vtkParticleSphereMapper* mapper, vtkPolyData* particles,
  const std::string& radiusArray)
{
  const vtkSource source = { repr, spheres, actor, mapper, particles, radiusArray };
  for (vtkSource& existing : this->Sources)
  {
    if (existing.Representation == repr)
    {
      existing = source;
      return;
    }
  }
  this->Sources.push_back(source);
}

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::RemoveSource(vtkPVDataRepresentation* repr)
{
  for (auto it = this->Sources.begin(); it != this->Sources.end(); ++it)
  {
    if (it->Representation == repr)
    {
      vtkDensityVolumeAOPass::SetDistributedVolume(it->Actor, nullptr);
      vtkVoxelConeAOPass::SetDistributedVolume(it->Actor, nullptr);
      this->Sources.erase(it);
      return;
    }
  }
}

//------------------------------------------------------------------------------
std::vector<const vtkParticleDistributedVolumes::vtkSource*>
vtkParticleDistributedVolumes::SphereSources() const
{
  std::vector<const vtkSource*> sources;
  for (const vtkSource& source : this->Sources)
  {
    if (source.Spheres && source.Representation->GetVisibility())
    {
      sources.push_back(&source);
    }
  }
  return sources;
}

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::Update(
  bool distributed, vtkDensityVolumeAOPass* density, vtkVoxelConeAOPass* voxelCone)
{
  if (!distributed)
  {
    // one process, or a client rendering gathered data alone: the passes voxelise what they draw
    this->SetDensityVolumeOnActors(nullptr);
    this->SetAmbientVolumeOnActors(nullptr);
    return;
  }
  const std::vector<const vtkSource*> sources = this->SphereSources();
  this->UpdateDensityVolume(sources, density);
  this->UpdateAmbientVolume(sources, voxelCone);
}

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::SetDensityVolumeOnActors(vtkParticleDensityVolume* volume)
{
  for (const vtkSource& source : this->Sources)
  {
    const bool shown = source.Spheres && source.Representation->GetVisibility();
    vtkDensityVolumeAOPass::SetDistributedVolume(source.Actor, shown ? volume : nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::SetAmbientVolumeOnActors(vtkParticleAmbientVolume* volume)
{
  for (const vtkSource& source : this->Sources)
  {
    const bool shown = source.Spheres && source.Representation->GetVisibility();
    vtkVoxelConeAOPass::SetDistributedVolume(source.Actor, shown ? volume : nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::UpdateDensityVolume(
  const std::vector<const vtkSource*>& sources, vtkDensityVolumeAOPass* pass)
{
  auto controller = vtkMultiProcessController::GetGlobalController();
  const bool needed = pass != nullptr && !sources.empty();
  vtkParticleDensityVolume* settings = needed ? pass->GetDensityVolume() : nullptr;
  std::ostringstream key;
  key.precision(17);
  key << needed << ";" << (settings ? settings->GetMTime() : 0);
  for (const vtkSource* source : sources)
  {
    vtkPolyData* particles = source->Particles;
    key << "|" << particles << ";" << (particles ? particles->GetMTime() : 0) << ";"
        << source->RadiusArray << ";" << source->Mapper->GetRadius() << ";"
        << source->Mapper->GetRadiusScaleVC(source->Actor);
    vtkMatrix4x4* matrix = source->Actor->GetMatrix();
    for (int i = 0; i < 16; ++i)
    {
      key << ";" << matrix->GetData()[i];
    }
  }
  if (!vtkParticleProcessReduction::StaleOnAnyProcess(key.str(), this->DensityVolumeKey))
  {
    this->SetDensityVolumeOnActors(needed ? this->DensityVolume.Get() : nullptr);
    return;
  }
  if (!needed)
  {
    this->SetDensityVolumeOnActors(nullptr);
    return;
  }

  // this process's particles of every source (each is in exactly one process's piece) in world
  // coordinates, radii as drawn; what vtkParticleDensityVolume::EndParticles gathers on one
  // process
  vtkNew<vtkDoubleArray> positions;
  positions->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> radii;
  vtkParticleProcessReduction::Extent extent; // of the centres
  for (const vtkSource* source : sources)
  {
    vtkPolyData* particles = source->Particles;
    const vtkIdType n = particles && particles->GetPoints() ? particles->GetNumberOfPoints() : 0;
    vtkDataArray* radiusValues = n > 0
      ? vtkParticleDistributedPartition::GetRadiusValues(particles, source->RadiusArray)
      : nullptr;
    const double scale = source->Mapper->GetRadiusScaleVC(source->Actor);
    const double constant = source->Mapper->GetRadius();
    const double* m = source->Actor->GetMatrix()->GetData();
    for (vtkIdType i = 0; i < n; ++i)
    {
      double q[3];
      particles->GetPoint(i, q);
      const double r = (radiusValues ? radiusValues->GetComponent(i, 0) : constant) * scale;
      double p[3];
      for (int k = 0; k < 3; ++k)
      {
        p[k] = m[4 * k] * q[0] + m[4 * k + 1] * q[1] + m[4 * k + 2] * q[2] + m[4 * k + 3];
      }
      if (!(r > 0.0) || !std::isfinite(r) || !std::isfinite(p[0] + p[1] + p[2]))
      {
        continue;
      }
      positions->InsertNextTuple(p);
      radii->InsertNextValue(static_cast<float>(r));
      extent.AddParticle(p, 0.0, r);
    }
  }
  extent.Reduce(controller);
  vtkParticleDensityVolume* volume = this->DensityVolume;
  volume->SetResolution(settings->GetResolution());
  volume->SetMaximumResolution(settings->GetMaximumResolution());
  volume->SetMaximumVoxelCount(settings->GetMaximumVoxelCount());
  volume->SetSplatMode(settings->GetSplatMode());
  volume->SetDensityFactor(settings->GetDensityFactor());
  // (the grid depends on global values only: the same on every process)
  const bool ok = extent.Count > 0.0 && volume->SetUpGrid(extent.Bounds, extent.MeanRadius()) &&
    volume->ComputeSumsOnCPU(positions, radii);
  if (!vtkParticleProcessReduction::OnEveryProcess(controller, ok))
  {
    this->SetDensityVolumeOnActors(nullptr);
    return;
  }
  // the sum over the processes, then g and the clamp (Eq. 5)
  vtkParticleProcessReduction::SumOverProcesses(controller, volume->GetMutableVolume());
  volume->FinishSums();
  volume->Modified();
  this->SetDensityVolumeOnActors(volume);
}

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::UpdateAmbientVolume(
  const std::vector<const vtkSource*>& sources, vtkVoxelConeAOPass* pass)
{
  auto controller = vtkMultiProcessController::GetGlobalController();
  const bool needed = pass != nullptr && !sources.empty();
  vtkParticleAmbientVolume* settings = needed ? pass->GetAmbientVolume() : nullptr;
  // what the voxels depend on: the spheres (data, radii, matrix), their colours and opacities
  // (mapper, lookup table, property) and the volume's settings
  std::ostringstream key;
  key << needed << ";" << (settings ? settings->GetMTime() : 0);
  for (const vtkSource* source : sources)
  {
    vtkParticleSphereMapper* mapper = source->Mapper;
    vtkPolyData* input = mapper->GetInput();
    key << "|" << input << ";" << (input ? input->GetMTime() : 0) << ";" << mapper->GetMTime()
        << ";" << (mapper->GetLookupTable() ? mapper->GetLookupTable()->GetMTime() : 0) << ";"
        << source->Actor->GetProperty()->GetMTime() << ";"
        << source->Actor->GetMatrix()->GetMTime();
  }
  if (!vtkParticleProcessReduction::StaleOnAnyProcess(key.str(), this->AmbientVolumeKey))
  {
    this->SetAmbientVolumeOnActors(needed ? this->AmbientVolume.Get() : nullptr);
    return;
  }
  if (!needed)
  {
    this->SetAmbientVolumeOnActors(nullptr);
    return;
  }
  // this process's own spheres of every source as the pass would gather them (ghost copies left
  // out)
  std::vector<double> centers;
  std::vector<double> radii;
  std::vector<double> colors;
  std::vector<double> opacities;
  for (const vtkSource* source : sources)
  {
    vtkPolyData* input = source->Mapper->GetInput();
    if (input && input->GetNumberOfPoints() > 0)
    {
      source->Mapper->GetBounds(); // prepares the radii
      vtkParticleAmbientVolume::GatherSpheres(
        source->Actor, source->Mapper, true, centers, radii, colors, opacities);
    }
  }
  // the grid of all processes' spheres: bounds and mean radius of the drawn ones (as
  // vtkParticleAmbientVolume sets it up from one process's)
  vtkParticleProcessReduction::Extent extent;
  for (size_t i = 0; i < radii.size(); ++i)
  {
    const double* c = &centers[3 * i];
    const double r = radii[i];
    if (r > 0.0 && std::isfinite(r) && std::isfinite(c[0] + c[1] + c[2]) && opacities[i] > 0.0)
    {
      extent.AddParticle(c, r, r);
    }
  }
  extent.Reduce(controller);
  vtkParticleAmbientVolume* volume = this->AmbientVolume;
  volume->SetResolution(settings->GetResolution());
  volume->SetMaximumResolution(settings->GetMaximumResolution());
  volume->SetSubGridSamples(settings->GetSubGridSamples());
  volume->SetAmbientEmission(settings->GetAmbientEmission());
  volume->SetMaximumMemory(settings->GetMaximumMemory());
  const bool ok = extent.Count > 0.0 &&
    volume->VoxeliseLevelZero(
      centers, radii, colors, opacities, extent.Bounds, extent.MeanRadius());
  if (!vtkParticleProcessReduction::OnEveryProcess(controller, ok))
  {
    this->SetAmbientVolumeOnActors(nullptr);
    return;
  }
  // level 0 summed over the processes (extinction and emission add up); the pass builds the mips
  vtkParticleProcessReduction::SumOverProcesses(controller, volume->GetMutableLevelZero());
  volume->Modified();
  this->SetAmbientVolumeOnActors(volume);
}

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Sources: " << this->Sources.size() << "\n";
  os << indent << "DensityVolume: " << this->DensityVolume.Get() << "\n";
  os << indent << "AmbientVolume: " << this->AmbientVolume.Get() << "\n";
}
