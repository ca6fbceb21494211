#include "vtkLAMMPSReaderBase.h"
#include "vtkParticleReaderInternals.h"

#include "vtkDataObject.h"
#include "vtkInformation.h"

#include <cmath>

//------------------------------------------------------------------------------
vtkLAMMPSReaderBase::vtkLAMMPSReaderBase()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

vtkLAMMPSReaderBase::~vtkLAMMPSReaderBase() = default;

//------------------------------------------------------------------------------
int vtkLAMMPSReaderBase::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkLAMMPSReaderBase::SetTypeRadius(int type, double radius)
{
  auto it = this->TypeRadii.find(type);
  if (it == this->TypeRadii.end() || it->second != radius)
  {
    this->TypeRadii[type] = radius;
    this->Modified();
  }
}

void vtkLAMMPSReaderBase::SetTypeRadius(double type, double radius)
{
  if (std::isfinite(type) && std::abs(type) < 2e9)
  {
    this->SetTypeRadius(static_cast<int>(std::lround(type)), radius);
  }
}

double vtkLAMMPSReaderBase::GetTypeRadius(int type)
{
  auto it = this->TypeRadii.find(type);
  return it == this->TypeRadii.end() ? this->DefaultRadius : it->second;
}

void vtkLAMMPSReaderBase::RemoveAllTypeRadii()
{
  if (!this->TypeRadii.empty())
  {
    this->TypeRadii.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLAMMPSReaderBase::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SortById: " << this->SortById << "\n";
  os << indent << "GenerateRadius: " << this->GenerateRadius << "\n";
  os << indent << "DefaultRadius: " << this->DefaultRadius << "\n";
  os << indent << "TypeRadii:";
  for (const auto& item : this->TypeRadii)
  {
    os << " " << item.first << ":" << item.second;
  }
  os << "\n";
}

//------------------------------------------------------------------------------
vtkTypeBool vtkLAMMPSReaderBase::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo)
{
  return prReader::GuardMemory(
    this, outInfo, [&] { return this->Superclass::ProcessRequest(request, inInfo, outInfo); });
}
