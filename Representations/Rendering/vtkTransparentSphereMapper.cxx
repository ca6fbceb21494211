#include "vtkTransparentSphereMapper.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkTransparentSphereMapper);

// Work in progress: the real implementation replaces this file.
class vtkTransparentSphereMapper::vtkInternals
{
public:
  vtkNew<vtkDoubleArray> Opacities;
};

vtkTransparentSphereMapper::vtkTransparentSphereMapper()
  : Internals(new vtkInternals)
{
}

vtkTransparentSphereMapper::~vtkTransparentSphereMapper()
{
  this->SetOpacityArrayName(nullptr);
  delete this->Internals;
}

double vtkTransparentSphereMapper::GetMaximumPathIntegral(int model, double f)
{
  const double g = std::sqrt(std::max(0.0, 1.0 - f * f));
  if (model == CONSTANT_DENSITY)
  {
    return 2.0 * g;
  }
  if (f <= std::sqrt(0.5))
  {
    return 2.0 * std::sqrt(2.0) / 3.0;
  }
  return 2.0 * g * (1.0 + 2.0 * f * f) / 3.0;
}

vtkDoubleArray* vtkTransparentSphereMapper::GetParticleOpacities()
{
  this->PrepareOpacities();
  return this->Internals->Opacities;
}

void vtkTransparentSphereMapper::PrepareOpacities()
{
  vtkIdType n = this->GetParticleRadii()->GetNumberOfTuples();
  this->Internals->Opacities->SetNumberOfTuples(n);
  this->Internals->Opacities->Fill(1.0);
}

bool vtkTransparentSphereMapper::HasOpaqueGeometry()
{
  return true;
}
bool vtkTransparentSphereMapper::HasTranslucentPolygonalGeometry()
{
  return false;
}
void vtkTransparentSphereMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
}
void vtkTransparentSphereMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
}
bool vtkTransparentSphereMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
}
void vtkTransparentSphereMapper::BuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::BuildBufferObjects(ren, act);
}
void vtkTransparentSphereMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceDraw(ren, act);
}
void vtkTransparentSphereMapper::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
}
void vtkTransparentSphereMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
