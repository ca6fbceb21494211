#include "vtkParticleProcessReduction.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <algorithm>

//------------------------------------------------------------------------------
void vtkParticleProcessReduction::Extent::AddBox(const double lo[3], const double hi[3])
{
  for (int k = 0; k < 3; ++k)
  {
    this->Bounds[2 * k] = std::min(this->Bounds[2 * k], lo[k]);
    this->Bounds[2 * k + 1] = std::max(this->Bounds[2 * k + 1], hi[k]);
  }
}

//------------------------------------------------------------------------------
void vtkParticleProcessReduction::Extent::AddParticle(
  const double center[3], double grow, double radius)
{
  const double lo[3] = { center[0] - grow, center[1] - grow, center[2] - grow };
  const double hi[3] = { center[0] + grow, center[1] + grow, center[2] + grow };
  this->AddBox(lo, hi);
  this->Count += 1.0;
  this->RadiusSum += radius;
}

//------------------------------------------------------------------------------
void vtkParticleProcessReduction::Extent::Reduce(vtkMultiProcessController* controller)
{
  double local[8] = { this->Count, this->RadiusSum, this->Bounds[0], this->Bounds[2],
    this->Bounds[4], -this->Bounds[1], -this->Bounds[3], -this->Bounds[5] };
  double global[8];
  controller->AllReduce(local, global, 2, vtkCommunicator::SUM_OP);
  controller->AllReduce(local + 2, global + 2, 6, vtkCommunicator::MIN_OP);
  this->Count = global[0];
  this->RadiusSum = global[1];
  for (int k = 0; k < 3; ++k)
  {
    this->Bounds[2 * k] = global[2 + k];
    this->Bounds[2 * k + 1] = -global[5 + k];
  }
}

//------------------------------------------------------------------------------
bool vtkParticleProcessReduction::Distributed()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller && controller->GetNumberOfProcesses() > 1;
}

//------------------------------------------------------------------------------
bool vtkParticleProcessReduction::OnEveryProcess(vtkMultiProcessController* controller, bool ok)
{
  int local = ok ? 1 : 0;
  int global = local;
  controller->AllReduce(&local, &global, 1, vtkCommunicator::MIN_OP);
  return global != 0;
}

//------------------------------------------------------------------------------
void vtkParticleProcessReduction::SumOverProcesses(
  vtkMultiProcessController* controller, std::vector<float>& values)
{
  std::vector<float> total(values.size());
  controller->AllReduce(
    values.data(), total.data(), static_cast<vtkIdType>(values.size()), vtkCommunicator::SUM_OP);
  values.swap(total);
}

//------------------------------------------------------------------------------
bool vtkParticleProcessReduction::StaleOnAnyProcess(const std::string& key, std::string& stored)
{
  int stale = key != stored ? 1 : 0;
  int anyStale = stale;
  vtkMultiProcessController::GetGlobalController()->AllReduce(
    &stale, &anyStale, 1, vtkCommunicator::MAX_OP);
  stored = key;
  return anyStale != 0;
}
