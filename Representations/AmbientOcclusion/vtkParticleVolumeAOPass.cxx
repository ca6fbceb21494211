#include "vtkParticleVolumeAOPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkMatrix4x4.h"
#include "vtkParticleShaderHooks.h"
#include "vtkParticleSphereMapper.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cstdint>

//------------------------------------------------------------------------------
vtkParticleVolumeAOPass::vtkParticleVolumeAOPass()
  : VolumeTexture(vtkTextureObject::New())
  , Hooks(new vtkParticleShaderHooks(this))
{
}

//------------------------------------------------------------------------------
vtkParticleVolumeAOPass::~vtkParticleVolumeAOPass()
{
  this->VolumeTexture->Delete();
  delete this->Hooks;
}

//------------------------------------------------------------------------------
void vtkParticleVolumeAOPass::GatherParticleProps(
  const vtkRenderState* s, ParticleProps& props, std::vector<double>& state)
{
  props.clear();
  state.clear();
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    vtkParticleSphereMapper* mapper =
      actor ? vtkParticleSphereMapper::SafeDownCast(actor->GetMapper()) : nullptr;
    if (!mapper || !mapper->GetInput() || !actor->GetVisibility())
    {
      continue;
    }
    props.emplace_back(actor, mapper);
    state.push_back(static_cast<double>(reinterpret_cast<uintptr_t>(mapper)));
    state.push_back(static_cast<double>(mapper->GetParticleGeometryTime()));
    state.push_back(mapper->GetRadiusScaleVC(actor));
    vtkMatrix4x4* m = actor->GetMatrix();
    state.insert(state.end(), m->GetData(), m->GetData() + 16);
    this->AppendPropState(actor, mapper, state);
  }
}

//------------------------------------------------------------------------------
vtkObject* vtkParticleVolumeAOPass::FindDistributedVolume(
  const ParticleProps& props, vtkInformationObjectBaseKey* key, std::vector<double>& state)
{
  vtkObject* distributed = vtkParticleVolumeAOPass::SharedPropVolume(props, key, nullptr);
  state.push_back(static_cast<double>(reinterpret_cast<uintptr_t>(distributed)));
  state.push_back(distributed ? static_cast<double>(distributed->GetMTime()) : 0.0);
  return distributed;
}

//------------------------------------------------------------------------------
vtkObject* vtkParticleVolumeAOPass::SharedPropVolume(
  const ParticleProps& props, vtkInformationObjectBaseKey* key, bool* some)
{
  vtkObject* shared =
    props.empty() ? nullptr : vtkParticleVolumeAOPass::GetPropVolume(props.front().first, key);
  bool any = false;
  for (const auto& prop : props)
  {
    vtkObject* volume = vtkParticleVolumeAOPass::GetPropVolume(prop.first, key);
    any = any || volume != nullptr;
    if (volume != shared)
    {
      shared = nullptr; // not one volume of all the props
    }
  }
  if (some)
  {
    *some = any;
  }
  return shared;
}

//------------------------------------------------------------------------------
bool vtkParticleVolumeAOPass::CheckParticleProps(const ParticleProps& props,
  vtkInformationObjectBaseKey* key, const char* without, const char* volumeName)
{
  if (props.empty())
  {
    if (this->WarnWithoutParticles)
    {
      vtkWarningMacro(<< "No visible props with a vtkParticleSphereMapper (or subclass) and input "
                         "in the renderer: "
                      << without << ".");
    }
    return false;
  }
  bool some = false;
  if (!vtkParticleVolumeAOPass::SharedPropVolume(props, key, &some) && some)
  {
    vtkWarningMacro(<< "Several particle props under distributed rendering: each process's "
                    << volumeName << " holds only its own particles.");
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleVolumeAOPass::NeedsBuild(const std::vector<double>& state)
{
  if (state == this->BuiltState && this->Attempted)
  {
    return false;
  }
  this->BuiltState = state;
  this->Attempted = true;
  this->VolumeValid = false;
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleVolumeAOPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass: nothing is rendered.");
    return;
  }
  this->UpdateVolume(s);
  const bool bound = this->VolumeValid;
  if (bound)
  {
    // the frame's level, then the scene drawn with it timed (the shaders change with the level)
    const int level =
      this->FrameBudget->ChooseFrameLevel(s->GetRenderer(), this->GetNumberOfQualityLevels());
    if (level != this->QualityLevel)
    {
      this->QualityLevel = level;
      this->LevelTime.Modified();
    }
    this->FrameBudget->StartTiming();
    this->VolumeTexture->Activate();
    this->CurrentRenderer = s->GetRenderer();
    this->PreRender(s);
  }
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  if (bound)
  {
    this->FrameBudget->EndFrame();
    this->PostRender(s);
    this->VolumeTexture->Deactivate();
    this->CurrentRenderer = nullptr;
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkParticleVolumeAOPass::GetShaderStageMTime()
{
  return std::max(this->GetMTime(), this->LevelTime.GetMTime());
}

//------------------------------------------------------------------------------
bool vtkParticleVolumeAOPass::SetVolumeSampler(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, const char* sampler)
{
  if (!vtkParticleSphereMapper::SafeDownCast(mapper) || !this->VolumeValid ||
    !program->IsUniformUsed(sampler))
  {
    return false;
  }
  program->SetUniformi(sampler, this->VolumeTexture->GetTextureUnit());
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleVolumeAOPass::SetViewToGridUniform(
  vtkShaderProgram* program, const char* name, const double origin[3], const double scale[3])
{
  vtkCamera* camera = this->CurrentRenderer ? this->CurrentRenderer->GetActiveCamera() : nullptr;
  if (!camera)
  {
    return false;
  }
  vtkNew<vtkMatrix4x4> viewToWorld;
  vtkMatrix4x4::Invert(camera->GetModelViewTransformMatrix(), viewToWorld);
  vtkNew<vtkMatrix4x4> worldToGrid;
  for (int k = 0; k < 3; ++k)
  {
    worldToGrid->SetElement(k, k, scale[k]);
    worldToGrid->SetElement(k, 3, -origin[k] * scale[k]);
  }
  vtkNew<vtkMatrix4x4> viewToGrid;
  vtkMatrix4x4::Multiply4x4(worldToGrid, viewToWorld, viewToGrid);
  vtkNew<vtkMatrix4x4> transposed; // vtkShaderProgram uploads row-major data as columns
  vtkMatrix4x4::Transpose(viewToGrid, transposed);
  return program->SetUniformMatrix(name, transposed);
}

//------------------------------------------------------------------------------
bool vtkParticleVolumeAOPass::SetViewToWorldRotationUniform(
  vtkShaderProgram* program, const char* name)
{
  vtkCamera* camera = this->CurrentRenderer ? this->CurrentRenderer->GetActiveCamera() : nullptr;
  if (!camera)
  {
    return false;
  }
  vtkNew<vtkMatrix4x4> viewToWorld;
  vtkMatrix4x4::Invert(camera->GetModelViewTransformMatrix(), viewToWorld);
  // the rotation part (row-major data uploaded as columns: transposed)
  float rotation[9];
  for (int row = 0; row < 3; ++row)
  {
    for (int col = 0; col < 3; ++col)
    {
      rotation[col * 3 + row] = static_cast<float>(viewToWorld->GetElement(row, col));
    }
  }
  return program->SetUniformMatrix3x3(name, rotation);
}

//------------------------------------------------------------------------------
void vtkParticleVolumeAOPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->VolumeTexture->ReleaseGraphicsResources(w);
  this->VolumeValid = false;
  this->Attempted = false;
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
int vtkParticleVolumeAOPass::GetOcclusionSpace()
{
  return PER_FRAGMENT;
}

//------------------------------------------------------------------------------
void vtkParticleVolumeAOPass::SetPropVolume(
  vtkProp* prop, vtkInformationObjectBaseKey* key, vtkObject* volume)
{
  if (!prop)
  {
    return;
  }
  vtkInformation* keys = prop->GetPropertyKeys();
  if (!volume)
  {
    if (keys)
    {
      keys->Remove(key);
    }
    return;
  }
  if (!keys)
  {
    vtkNew<vtkInformation> created;
    prop->SetPropertyKeys(created);
    keys = created;
  }
  keys->Set(key, volume);
}

//------------------------------------------------------------------------------
vtkObject* vtkParticleVolumeAOPass::GetPropVolume(vtkProp* prop, vtkInformationObjectBaseKey* key)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  return keys ? vtkObject::SafeDownCast(keys->Get(key)) : nullptr;
}

//------------------------------------------------------------------------------
void vtkParticleVolumeAOPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfVolumeBuilds: " << this->NumberOfVolumeBuilds << "\n";
  os << indent << "VolumeValid: " << this->VolumeValid << "\n";
}
