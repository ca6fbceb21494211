#include "vtkParticleAmbientLightPass.h"

//------------------------------------------------------------------------------
bool vtkParticleAmbientLightPass::GetAddsColouredAmbientLight()
{
  return false;
}

//------------------------------------------------------------------------------
void vtkParticleAmbientLightPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OcclusionSpace: "
     << (this->GetOcclusionSpace() == SCREEN_SPACE ? "SCREEN_SPACE" : "PER_FRAGMENT") << "\n";
  os << indent << "AddsColouredAmbientLight: " << this->GetAddsColouredAmbientLight() << "\n";
}
