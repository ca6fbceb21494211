#include "vtkParticleAmbientLightPass.h"

//------------------------------------------------------------------------------
bool vtkParticleAmbientLightPass::GetAddsColouredAmbientLight()
{
  return false;
}

//------------------------------------------------------------------------------
void vtkParticleAmbientLightPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->FrameBudget->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkParticleAmbientLightPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OcclusionSpace: "
     << (this->GetOcclusionSpace() == SCREEN_SPACE ? "SCREEN_SPACE" : "PER_FRAGMENT") << "\n";
  os << indent << "AddsColouredAmbientLight: " << this->GetAddsColouredAmbientLight() << "\n";
  os << indent << "FrameBudget:\n";
  this->FrameBudget->PrintSelf(os, indent.GetNextIndent());
}
