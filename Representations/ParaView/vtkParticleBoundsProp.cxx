#include "vtkParticleBoundsProp.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkParticleBoundsProp);

//------------------------------------------------------------------------------
vtkParticleBoundsProp::vtkParticleBoundsProp()
{
  vtkMath::UninitializeBounds(this->Bounds);
  // never picked, never drawn
  this->PickableOff();
  this->DragableOff();
}

//------------------------------------------------------------------------------
void vtkParticleBoundsProp::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Bounds: (" << this->Bounds[0] << ", " << this->Bounds[1] << ", "
     << this->Bounds[2] << ", " << this->Bounds[3] << ", " << this->Bounds[4] << ", "
     << this->Bounds[5] << ")\n";
}
