#include "vtkParticleViewPartition.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVDataRepresentation.h"
#include "vtkParticleDistributedPartition.h"
#include "vtkParticleProcessReduction.h"

#include <sstream>

vtkStandardNewMacro(vtkParticleViewPartition);

//------------------------------------------------------------------------------
vtkParticleViewPartition::vtkParticleViewPartition() = default;

//------------------------------------------------------------------------------
vtkParticleViewPartition::~vtkParticleViewPartition() = default;

//------------------------------------------------------------------------------
void vtkParticleViewPartition::AddRepresentation(
  vtkPVDataRepresentation* repr, vtkParticleDistributedPartition* partition)
{
  this->RemoveRepresentation(repr);
  if (repr && partition)
  {
    this->Members.push_back({ repr, partition });
  }
}

//------------------------------------------------------------------------------
void vtkParticleViewPartition::RemoveRepresentation(vtkPVDataRepresentation* repr)
{
  for (auto it = this->Members.begin(); it != this->Members.end(); ++it)
  {
    if (it->Representation == repr)
    {
      // on its own again from its next update
      it->Partition->SetPartitionedByView(false);
      this->Members.erase(it);
      return;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkParticleViewPartition::Update(bool orderedCompositing)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    return false;
  }
  // the same decision on every process (the representations are added in the same order)
  int local = orderedCompositing ? 1 : 0;
  int ordered = local;
  controller->AllReduce(&local, &ordered, 1, vtkCommunicator::MAX_OP);
  std::vector<vtkParticleDistributedPartition*> shown;
  std::ostringstream key;
  key << ordered;
  for (const vtkMember& member : this->Members)
  {
    if (member.Representation->GetVisibility())
    {
      shown.push_back(member.Partition);
      key << "|" << member.Representation->GetUniqueIdentifier() << ":"
          << member.Partition->GetInputKey();
    }
  }
  if (!vtkParticleProcessReduction::StaleOnAnyProcess(key.str(), this->Key))
  {
    return false;
  }
  bool changed = false;
  this->Shared = ordered && !shown.empty();
  if (this->Shared)
  {
    for (vtkParticleDistributedPartition* partition : shown)
    {
      partition->SetPartitionedByView(true);
    }
    vtkParticleDistributedPartition::PartitionTogether(shown);
    changed = true;
  }
  else
  {
    for (vtkParticleDistributedPartition* partition : shown)
    {
      if (partition->GetPartitionedByView())
      {
        partition->SetPartitionedByView(false);
        partition->PartitionAlone();
        changed = true;
      }
    }
  }
  return changed;
}

//------------------------------------------------------------------------------
void vtkParticleViewPartition::Redeliver()
{
  for (const vtkMember& member : this->Members)
  {
    if (member.Representation->GetVisibility())
    {
      member.Partition->SetRedelivery(true);
      member.Representation->MarkModified();
    }
  }
}

//------------------------------------------------------------------------------
void vtkParticleViewPartition::FinishRedelivery()
{
  for (const vtkMember& member : this->Members)
  {
    member.Partition->TakeRedelivery();
  }
}

//------------------------------------------------------------------------------
void vtkParticleViewPartition::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Representations: " << this->Members.size() << "\n";
  os << indent << "Shared: " << this->Shared << "\n";
}
