#include "vtkParticleRenderView.h"

#include "vtkAlgorithm.h"
#include "vtkCameraPass.h"
#include "vtkCommand.h"
#include "vtkDensityVolumeAOPass.h"
#include "vtkImageProcessingPass.h"
#include "vtkObjectFactory.h"
#include "vtkPVDefaultPass.h"
#include "vtkPVProgressHandler.h"
#include "vtkPVSession.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkParticlePassChain.h"
#include "vtkProcessModule.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkParticleRenderView);

//------------------------------------------------------------------------------
vtkParticleRenderView::vtkParticleRenderView()
{
  vtkNew<vtkPVDefaultPass> defaultPass;
  this->ParticlePassChain->SetInnerPass(defaultPass);
  // The synchronized renderer keeps this pass in its render-pass slot through every rebuild of
  // the renderer's pass tree (see the class documentation).
  this->SynchronizedRenderers->SetRenderPass(this->ParticlePassChain);

  // ParaView's progress bar listens to algorithms registered with the session's progress
  // handler; a render pass is not one, so its long work (the AO volume build) is reported
  // through a stand-in algorithm registered here.
  this->SetDensityVolumeAOPass(vtkSmartPointer<vtkDensityVolumeAOPass>::New());
  vtkProcessModule* processModule = vtkProcessModule::GetProcessModule();
  vtkPVSession* session =
    processModule ? vtkPVSession::SafeDownCast(processModule->GetActiveSession()) : nullptr;
  if (session && session->GetProgressHandler())
  {
    session->GetProgressHandler()->RegisterProgressEvent(this->PassProgress, 0);
  }
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::ForwardPassProgress(vtkObject* caller, unsigned long, void* callData)
{
  auto* pass = vtkDensityVolumeAOPass::SafeDownCast(caller);
  this->PassProgress->SetProgressText(pass ? pass->GetProgressText() : nullptr);
  this->PassProgress->UpdateProgress(*static_cast<double*>(callData));
  this->PassProgress->SetProgressText(nullptr);
}

//------------------------------------------------------------------------------
vtkAlgorithm* vtkParticleRenderView::GetPassProgressReporter()
{
  return this->PassProgress;
}

//------------------------------------------------------------------------------
vtkParticleRenderView::~vtkParticleRenderView() = default;

//------------------------------------------------------------------------------
void vtkParticleRenderView::SetDensityVolumeAmbientOcclusion(int on)
{
  const bool installed = this->ParticlePassChain->HasPass(this->DensityVolumeAOPass);
  if (on && !installed)
  {
    this->ParticlePassChain->AddPass(this->DensityVolumeAOPass);
  }
  else if (!on && installed)
  {
    this->ParticlePassChain->RemovePass(this->DensityVolumeAOPass);
  }
  else
  {
    return;
  }
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkParticleRenderView::GetDensityVolumeAmbientOcclusion()
{
  return this->ParticlePassChain->HasPass(this->DensityVolumeAOPass) ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::SetDensityVolumeAOPass(vtkDensityVolumeAOPass* pass)
{
  if (!pass || pass == this->DensityVolumeAOPass)
  {
    return;
  }
  const bool installed = this->GetDensityVolumeAmbientOcclusion() != 0;
  if (installed)
  {
    this->ParticlePassChain->RemovePass(this->DensityVolumeAOPass);
  }
  if (this->DensityVolumeAOPass)
  {
    this->DensityVolumeAOPass->RemoveObserver(this->PassProgressTag);
  }
  this->DensityVolumeAOPass = pass;
  this->PassProgressTag = pass->AddObserver(
    vtkCommand::ProgressEvent, this, &vtkParticleRenderView::ForwardPassProgress);
  if (installed)
  {
    this->ParticlePassChain->AddPass(pass);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkDensityVolumeAOPass* vtkParticleRenderView::GetDensityVolumeAOPass()
{
  return this->DensityVolumeAOPass;
}

//------------------------------------------------------------------------------
vtkParticlePassChain* vtkParticleRenderView::GetParticlePassChain()
{
  return this->ParticlePassChain;
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::AboutToRenderOnLocalProcess(bool interactive)
{
  // OSPRay and value passes put their own pass in the slot and restore ours afterwards; only an
  // empty slot means the chain was lost.
  if (this->SynchronizedRenderers->GetRenderPass() == nullptr)
  {
    this->SynchronizedRenderers->SetRenderPass(this->ParticlePassChain);
  }
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
}

//------------------------------------------------------------------------------
int vtkParticleRenderView::GetParticlePassChainInstalled()
{
  vtkRenderer* renderer = this->GetRenderer();
  vtkRenderPass* pass = renderer ? renderer->GetPass() : nullptr;
  // [FXAA] -> [image processing] -> camera -> render pass; a few more levels for safety.
  for (int depth = 0; pass != nullptr && depth < 16; ++depth)
  {
    if (pass == this->ParticlePassChain.GetPointer())
    {
      return 1;
    }
    if (auto imageProcessing = vtkImageProcessingPass::SafeDownCast(pass))
    {
      pass = imageProcessing->GetDelegatePass();
    }
    else if (auto camera = vtkCameraPass::SafeDownCast(pass))
    {
      pass = camera->GetDelegatePass();
    }
    else
    {
      // A pass of a type we cannot see through (IceT's composite pass in parallel): it runs
      // the synchronized renderer's render-pass slot.
      return (this->SynchronizedRenderers->GetRenderPass() ==
               this->ParticlePassChain.GetPointer() &&
               !this->GetEnableOSPRay())
        ? 1
        : 0;
    }
  }
  return 0;
}

//------------------------------------------------------------------------------
int vtkParticleRenderView::GetNumberOfParticlePasses()
{
  return this->ParticlePassChain->GetNumberOfPasses();
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ParticlePassChain:\n";
  this->ParticlePassChain->PrintSelf(os, indent.GetNextIndent());
}
