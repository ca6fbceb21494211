#include "vtkParticleDistributedVolumes.h"

#include "vtkActor.h"
#include "vtkDensityVolumeAOPass.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkParticleAmbientVolume.h"
#include "vtkParticleDensityVolume.h"
#include "vtkParticleDistributedPartition.h"
#include "vtkParticleProcessReduction.h"
#include "vtkParticleRenderView.h"
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
void vtkParticleDistributedVolumes::Update(vtkInformation* inInfo, bool spheres, vtkActor* actor,
  vtkParticleSphereMapper* mapper, vtkPolyData* particles, const std::string& radiusArray)
{
  this->UpdateDensityVolume(inInfo, spheres, actor, mapper, particles, radiusArray);
  this->UpdateAmbientVolume(inInfo, spheres, actor, mapper);
}

//------------------------------------------------------------------------------
bool vtkParticleDistributedVolumes::IsDistributedRender(vtkInformation* inInfo)
{
  // Every process renders (distributed rendering): all of them are in REQUEST_RENDER together,
  // so sums over the processes are safe. A client that renders gathered data alone does not
  // need them (its passes voxelise everything).
  auto controller = vtkMultiProcessController::GetGlobalController();
  auto view = vtkPVRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW()));
  const bool lod =
    inInfo->Has(vtkPVRenderView::USE_LOD()) && inInfo->Get(vtkPVRenderView::USE_LOD());
  return controller && controller->GetNumberOfProcesses() > 1 && view &&
    (lod ? view->GetUseDistributedRenderingForLODRender()
         : view->GetUseDistributedRenderingForRender());
}

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::UpdateDensityVolume(vtkInformation* inInfo, bool spheres,
  vtkActor* actor, vtkParticleSphereMapper* mapper, vtkPolyData* particles,
  const std::string& radiusArray)
{
  auto controller = vtkMultiProcessController::GetGlobalController();
  auto view = vtkParticleRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW()));
  // only when the view's ambient occlusion is the density volume
  const bool distributed = vtkParticleDistributedVolumes::IsDistributedRender(inInfo);
  vtkDensityVolumeAOPass* pass = view ? view->GetDensityVolumeAOPass() : nullptr;
  const bool needed = distributed && pass &&
    view->GetAmbientOcclusion() == vtkParticleRenderView::DENSITY_VOLUME && spheres;
  if (!distributed)
  {
    vtkDensityVolumeAOPass::SetDistributedVolume(actor, nullptr);
    return;
  }
  vtkParticleDensityVolume* settings = needed ? pass->GetDensityVolume() : nullptr;
  std::ostringstream key;
  key.precision(17);
  key << needed << ";" << particles << ";" << (particles ? particles->GetMTime() : 0) << ";"
      << radiusArray << ";" << mapper->GetRadius() << ";" << mapper->GetRadiusScaleVC(actor) << ";"
      << (settings ? settings->GetMTime() : 0);
  vtkMatrix4x4* matrix = actor->GetMatrix();
  for (int i = 0; i < 16; ++i)
  {
    key << ";" << matrix->GetData()[i];
  }
  if (!vtkParticleProcessReduction::StaleOnAnyProcess(key.str(), this->DensityVolumeKey))
  {
    vtkDensityVolumeAOPass::SetDistributedVolume(
      actor, needed ? this->DensityVolume.Get() : nullptr);
    return;
  }
  if (!needed)
  {
    vtkDensityVolumeAOPass::SetDistributedVolume(actor, nullptr);
    return;
  }

  // this process's particles (each is in exactly one process's piece) in world coordinates,
  // radii as drawn; what vtkParticleDensityVolume::EndParticles gathers on one process
  const vtkIdType n = particles && particles->GetPoints() ? particles->GetNumberOfPoints() : 0;
  vtkDataArray* radiusValues =
    n > 0 ? vtkParticleDistributedPartition::GetRadiusValues(particles, radiusArray) : nullptr;
  const double scale = mapper->GetRadiusScaleVC(actor);
  const double constant = mapper->GetRadius();
  vtkNew<vtkDoubleArray> positions;
  positions->SetNumberOfComponents(3);
  positions->Allocate(3 * n);
  vtkNew<vtkFloatArray> radii;
  radii->Allocate(n);
  vtkParticleProcessReduction::Extent extent; // of the centres
  const double* m = matrix->GetData();
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
    vtkDensityVolumeAOPass::SetDistributedVolume(actor, nullptr);
    return;
  }
  // the sum over the processes, then g and the clamp (Eq. 5)
  vtkParticleProcessReduction::SumOverProcesses(controller, volume->GetMutableVolume());
  volume->FinishSums();
  volume->Modified();
  vtkDensityVolumeAOPass::SetDistributedVolume(actor, volume);
}

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::UpdateAmbientVolume(
  vtkInformation* inInfo, bool spheres, vtkActor* actor, vtkParticleSphereMapper* mapper)
{
  auto view = vtkParticleRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW()));
  if (!vtkParticleDistributedVolumes::IsDistributedRender(inInfo) || !view)
  {
    vtkVoxelConeAOPass::SetDistributedVolume(actor, nullptr);
    return;
  }
  auto controller = vtkMultiProcessController::GetGlobalController();
  vtkVoxelConeAOPass* pass = view->GetVoxelConeAOPass();
  const bool needed =
    pass && view->GetAmbientOcclusion() == vtkParticleRenderView::VOXEL_CONE_TRACING && spheres;
  vtkParticleAmbientVolume* settings = needed ? pass->GetAmbientVolume() : nullptr;
  // what the voxels depend on: the spheres (data, radii, matrix), their colours and opacities
  // (mapper, lookup table, property) and the volume's settings
  vtkPolyData* input = mapper->GetInput();
  std::ostringstream key;
  key << needed << ";" << input << ";" << (input ? input->GetMTime() : 0) << ";"
      << mapper->GetMTime() << ";"
      << (mapper->GetLookupTable() ? mapper->GetLookupTable()->GetMTime() : 0) << ";"
      << actor->GetProperty()->GetMTime() << ";" << actor->GetMatrix()->GetMTime() << ";"
      << (settings ? settings->GetMTime() : 0);
  if (!vtkParticleProcessReduction::StaleOnAnyProcess(key.str(), this->AmbientVolumeKey))
  {
    vtkVoxelConeAOPass::SetDistributedVolume(actor, needed ? this->AmbientVolume.Get() : nullptr);
    return;
  }
  if (!needed)
  {
    vtkVoxelConeAOPass::SetDistributedVolume(actor, nullptr);
    return;
  }
  // this process's own spheres as the pass would gather them (ghost copies left out)
  std::vector<double> centers;
  std::vector<double> radii;
  std::vector<double> colors;
  std::vector<double> opacities;
  if (input && input->GetNumberOfPoints() > 0)
  {
    mapper->GetBounds(); // prepares the radii
    vtkParticleAmbientVolume::GatherSpheres(actor, mapper, true, centers, radii, colors, opacities);
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
    vtkVoxelConeAOPass::SetDistributedVolume(actor, nullptr);
    return;
  }
  // level 0 summed over the processes (extinction and emission add up); the pass builds the mips
  vtkParticleProcessReduction::SumOverProcesses(controller, volume->GetMutableLevelZero());
  volume->Modified();
  vtkVoxelConeAOPass::SetDistributedVolume(actor, volume);
}

//------------------------------------------------------------------------------
void vtkParticleDistributedVolumes::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DensityVolume: " << this->DensityVolume.Get() << "\n";
  os << indent << "AmbientVolume: " << this->AmbientVolume.Get() << "\n";
}
