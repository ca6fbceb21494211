#include "vtkParticleRenderView.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkBoundingBox.h"
#include "vtkCameraPass.h"
#include "vtkCommand.h"
#include "vtkCommunicator.h"
#include "vtkDensityVolumeAOPass.h"
#include "vtkImageProcessingPass.h"
#include "vtkInformation.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVDefaultPass.h"
#include "vtkPVProgressHandler.h"
#include "vtkPVRenderViewDataDeliveryManager.h"
#include "vtkPVSession.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkParticleDistributedPartition.h"
#include "vtkParticlePassChain.h"
#include "vtkParticleProcessReduction.h"
#include "vtkPointAOPass.h"
#include "vtkProcessModule.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSNDFRenderPass.h"
#include "vtkVoxelConeAOPass.h"

#include <algorithm>

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
  this->SetVoxelConeAOPass(vtkSmartPointer<vtkVoxelConeAOPass>::New());
  this->SetPointAOPass(vtkSmartPointer<vtkPointAOPass>::New());
  this->SetSNDFRenderPass(vtkSmartPointer<vtkSNDFRenderPass>::New());
  // drawn never; visible (its bounds counted) only for distributed PointAO
  this->CompositeBounds->VisibilityOff();
  this->CompositeBounds->SetUseBounds(true);
  this->GetRenderer()->AddViewProp(this->CompositeBounds);
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
  const char* text = nullptr;
  if (auto* density = vtkDensityVolumeAOPass::SafeDownCast(caller))
  {
    text = density->GetProgressText();
  }
  else if (auto* sndf = vtkSNDFRenderPass::SafeDownCast(caller))
  {
    text = sndf->GetProgressText();
  }
  this->PassProgress->SetProgressText(text);
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
vtkImageProcessingPass* vtkParticleRenderView::GetAmbientOcclusionPass(int method)
{
  switch (method)
  {
    case DENSITY_VOLUME:
      return this->DensityVolumeAOPass;
    case VOXEL_CONE_TRACING:
      return this->VoxelConeAOPass;
    case POINT_AO:
      return this->PointAOPass;
    default:
      return nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::SetAmbientOcclusion(int method)
{
  if (method < NO_AMBIENT_OCCLUSION || method > POINT_AO)
  {
    vtkErrorMacro(<< "Unknown ambient-occlusion method " << method
                  << " (0 none, 1 density volume, 2 voxel cone tracing, 3 PointAO).");
    return;
  }
  if (method == this->AmbientOcclusion)
  {
    return;
  }
  if (vtkImageProcessingPass* old = this->GetAmbientOcclusionPass(this->AmbientOcclusion))
  {
    this->TakeOutOfChain(old);
  }
  this->AmbientOcclusion = method;
  if (vtkImageProcessingPass* pass = this->GetAmbientOcclusionPass(method))
  {
    this->ParticlePassChain->AddPass(pass);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkParticleRenderView::GetAmbientOcclusion()
{
  return this->AmbientOcclusion;
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::SetDensityVolumeAmbientOcclusion(int on)
{
  if (on)
  {
    this->SetAmbientOcclusion(DENSITY_VOLUME);
  }
  else if (this->AmbientOcclusion == DENSITY_VOLUME)
  {
    this->SetAmbientOcclusion(NO_AMBIENT_OCCLUSION);
  }
}

//------------------------------------------------------------------------------
int vtkParticleRenderView::GetDensityVolumeAmbientOcclusion()
{
  return this->AmbientOcclusion == DENSITY_VOLUME ? 1 : 0;
}

//------------------------------------------------------------------------------
template <typename PassType>
void vtkParticleRenderView::ReplaceAmbientOcclusionPass(
  vtkSmartPointer<PassType>& slot, PassType* pass, int method)
{
  // the chain holds the pass of the current method only: swap it there too
  const bool installed = this->AmbientOcclusion == method;
  if (installed)
  {
    this->TakeOutOfChain(slot);
  }
  slot = pass;
  if (installed)
  {
    this->ParticlePassChain->AddPass(pass);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::SetDensityVolumeAOPass(vtkDensityVolumeAOPass* pass)
{
  if (!pass || pass == this->DensityVolumeAOPass)
  {
    return;
  }
  if (this->DensityVolumeAOPass)
  {
    this->DensityVolumeAOPass->RemoveObserver(this->PassProgressTag);
  }
  this->PassProgressTag =
    pass->AddObserver(vtkCommand::ProgressEvent, this, &vtkParticleRenderView::ForwardPassProgress);
  pass->SetWarnWithoutParticles(false); // a process without particles is normal here
  this->ReplaceAmbientOcclusionPass(this->DensityVolumeAOPass, pass, DENSITY_VOLUME);
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::SetVoxelConeAOPass(vtkVoxelConeAOPass* pass)
{
  if (!pass || pass == this->VoxelConeAOPass)
  {
    return;
  }
  pass->SetWarnWithoutParticles(false); // a process without particles is normal here
  this->ReplaceAmbientOcclusionPass(this->VoxelConeAOPass, pass, VOXEL_CONE_TRACING);
}

//------------------------------------------------------------------------------
vtkVoxelConeAOPass* vtkParticleRenderView::GetVoxelConeAOPass()
{
  return this->VoxelConeAOPass;
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::SetPointAOPass(vtkPointAOPass* pass)
{
  if (!pass || pass == this->PointAOPass)
  {
    return;
  }
  this->ReplaceAmbientOcclusionPass(this->PointAOPass, pass, POINT_AO);
}

//------------------------------------------------------------------------------
vtkPointAOPass* vtkParticleRenderView::GetPointAOPass()
{
  return this->PointAOPass;
}

//------------------------------------------------------------------------------
vtkDensityVolumeAOPass* vtkParticleRenderView::GetDensityVolumeAOPass()
{
  return this->DensityVolumeAOPass;
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::TakeOutOfChain(vtkImageProcessingPass* pass)
{
  if (!pass || !this->ParticlePassChain->RemovePass(pass))
  {
    return;
  }
  // its GPU memory (an S-NDF of 513 MiB at 1280 x 720, an AO volume) goes when it is switched
  // off, not with the view: the renderer releases only the passes of its chain
  if (vtkRenderWindow* window = this->GetRenderWindow())
  {
    pass->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::SetScaleConsistentShading(int on)
{
  on = on ? 1 : 0;
  if (on == this->ScaleConsistentShading)
  {
    return;
  }
  this->ScaleConsistentShading = on;
  this->SetUseFXAA(this->RequestedFXAA);
  if (on)
  {
    // outermost: the AO passes added later (AddPass) stay inside, so that the samples see them
    this->ParticlePassChain->InsertPass(0, this->SNDFRenderPass);
  }
  else
  {
    this->TakeOutOfChain(this->SNDFRenderPass);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::SetUseFXAA(bool use)
{
  // The S-NDF picture is box-filtered over each pixel already; FXAA on top only blurs it (and
  // with ParaView's FXAA pass around the chain the S-NDF picture came out black: measured, the
  // cause not found). The view's property is kept and applies again when the shading is off.
  this->RequestedFXAA = use;
  this->Superclass::SetUseFXAA(use && !this->ScaleConsistentShading);
}

//------------------------------------------------------------------------------
int vtkParticleRenderView::GetScaleConsistentShading()
{
  return this->ScaleConsistentShading;
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::SetSNDFRenderPass(vtkSNDFRenderPass* pass)
{
  if (!pass || pass == this->SNDFRenderPass)
  {
    return;
  }
  if (this->ScaleConsistentShading)
  {
    this->TakeOutOfChain(this->SNDFRenderPass);
    this->ParticlePassChain->InsertPass(0, pass);
  }
  if (this->SNDFRenderPass)
  {
    this->SNDFRenderPass->RemoveObserver(this->SNDFProgressTag);
  }
  this->SNDFProgressTag =
    pass->AddObserver(vtkCommand::ProgressEvent, this, &vtkParticleRenderView::ForwardPassProgress);
  this->SNDFRenderPass = pass;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkSNDFRenderPass* vtkParticleRenderView::GetSNDFRenderPass()
{
  return this->SNDFRenderPass;
}

//------------------------------------------------------------------------------
vtkParticleOrderedCompositePass* vtkParticleRenderView::GetOrderedCompositePass()
{
  return this->OrderedComposite;
}

//------------------------------------------------------------------------------
int vtkParticleRenderView::GetImagesBlendedBeforeIceT()
{
  // (out of the chain its flag is the one of the last render it took part in)
  return this->ParticlePassChain->HasPass(this->OrderedComposite) &&
      this->OrderedComposite->GetLastBlended()
    ? 1
    : 0;
}

//------------------------------------------------------------------------------
vtkParticleViewPartition* vtkParticleRenderView::GetViewPartition()
{
  return this->ViewPartition;
}

//------------------------------------------------------------------------------
vtkParticleDistributedVolumes* vtkParticleRenderView::GetParticleVolumes()
{
  return this->ParticleVolumes;
}

//------------------------------------------------------------------------------
int vtkParticleRenderView::GetParticlesPartitionedTogether()
{
  return this->ViewPartition->GetShared() ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::Update()
{
  this->Superclass::Update();
  // the partition is collective over the data processes; whether to update again over all the
  // view's processes (a client too: the update exchanges messages with it)
  const vtkTypeUInt64 changed = this->ViewPartition->Update(this->NeedsOrderedCompositing) ? 1 : 0;
  vtkTypeUInt64 anyChanged = changed;
  this->AllReduce(changed, anyChanged, vtkCommunicator::MAX_OP);
  if (anyChanged)
  {
    this->ViewPartition->Redeliver();
    this->Superclass::Update();
    this->ViewPartition->FinishRedelivery();
  }
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
  // still renders converge when asked (screenshots, batch); interactive ones never do
  this->SNDFRenderPass->SetConvergeOnRender(this->SNDFConvergeStillRenders != 0 && !interactive);
  // the speed/accuracy trade: the frame time every particle technique chooses from, and the
  // passes' quality
  if (interactive && this->InteractiveFrameBudget > 0.0 && this->GetRenderWindow())
  {
    this->GetRenderWindow()->SetDesiredUpdateRate(1000.0 / this->InteractiveFrameBudget);
  }
  for (int method = DENSITY_VOLUME; method <= POINT_AO; ++method)
  {
    if (auto* pass =
          vtkParticleAmbientLightPass::SafeDownCast(this->GetAmbientOcclusionPass(method)))
    {
      pass->GetFrameBudget()->SetQuality(this->InteractiveQuality);
      // under MPI every process draws the same level (see vtkParticleFrameBudget)
      pass->GetFrameBudget()->SetChooseByTime(!vtkParticleProcessReduction::Distributed());
    }
  }
  this->UpdateDistributedCompositing(interactive);
  this->UpdateDistributedVolumes(interactive);
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::Render(bool interactive, bool skip_rendering)
{
  this->Superclass::Render(interactive, skip_rendering);
  this->CompositeBounds->VisibilityOff();
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::UpdateDistributedCompositing(bool interactive)
{
  // Every process renders this frame (distributed rendering, as ParaView decides it in Render)
  // and IceT composites one tile. IceT calls a process's draw callback only when its visible
  // props' bounds project into the view, so while a pass composites across the processes inside
  // that callback, CompositeBounds gives every process the view's geometry bounds over all
  // processes (reduced by ParaView in Update): the same bounds everywhere, the same decision
  // everywhere. Tile and CAVE displays draw several tiles per frame and keep each process's own
  // images.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool lod = interactive && this->GetUseLODForInteractiveRender();
  const bool distributed = controller && controller->GetNumberOfProcesses() > 1 &&
    (lod ? this->GetUseDistributedRenderingForLODRender()
         : this->GetUseDistributedRenderingForRender()) &&
    !this->InTileDisplayMode() && !this->InCaveDisplayMode() && this->GeometryBounds.IsValid();

  // PointAO reads the G-buffer of all processes
  const bool pointAO = distributed && this->AmbientOcclusion == POINT_AO;
  this->PointAOPass->SetController(pointAO ? controller : nullptr);

  // S-NDF composites each sample pass's G-buffer over the processes: every process shades the
  // whole picture's S-NDFs
  const bool sndf = distributed && this->ScaleConsistentShading;
  this->SNDFRenderPass->SetController(sndf ? controller : nullptr);

  // ordered compositing (set up by the superclass's Render before this): the processes' images
  // blended in floating point in the order of ParaView's partition boxes
  auto* delivery = vtkPVRenderViewDataDeliveryManager::SafeDownCast(this->GetDeliveryManager());
  const bool ordered = distributed && this->GetUseOrderedCompositing() && delivery &&
    static_cast<int>(delivery->GetCuts().size()) == controller->GetNumberOfProcesses();
  if (ordered)
  {
    this->OrderedComposite->SetController(controller);
    this->OrderedComposite->SetBoundingBoxes(delivery->GetCuts());
    // (before IceT swaps it for a transparent one, which ParaView fills in after compositing)
    vtkRenderer* renderer = this->GetRenderer();
    this->OrderedComposite->SetBackground(renderer->GetBackground(),
      !renderer->GetGradientBackground() && !renderer->GetTexturedBackground() &&
        renderer->GetBackgroundAlpha() >= 1.0);
    // PointAO and S-NDF work on the finished colour image, translucent particles included
    this->OrderedComposite->SetDeferTranslucentParticles(
      this->AmbientOcclusion != POINT_AO && !this->ScaleConsistentShading);
    this->OrderWithTransformedPartition(controller->GetNumberOfProcesses());
    if (this->ParticlePassChain->GetNumberOfPasses() == 0 ||
      this->ParticlePassChain->GetPass(0) != this->OrderedComposite.GetPointer())
    {
      this->ParticlePassChain->RemovePass(this->OrderedComposite);
      this->ParticlePassChain->InsertPass(0, this->OrderedComposite);
    }
  }
  else
  {
    this->OrderedComposite->SetController(nullptr);
    this->TakeOutOfChain(this->OrderedComposite);
  }

  if (pointAO || sndf || ordered)
  {
    double bounds[6];
    this->GeometryBounds.GetBounds(bounds);
    this->CompositeBounds->SetBounds(bounds);
  }
  this->CompositeBounds->SetVisibility(pointAO || sndf || ordered);
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::UpdateDistributedVolumes(bool interactive)
{
  // Every process renders this frame (after every representation's REQUEST_RENDER, on every
  // process): the AO volume of all processes' particles, of all the Particles representations
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool lod = interactive && this->GetUseLODForInteractiveRender();
  const bool distributed = controller && controller->GetNumberOfProcesses() > 1 &&
    (lod ? this->GetUseDistributedRenderingForLODRender()
         : this->GetUseDistributedRenderingForRender());
  this->ParticleVolumes->Update(distributed,
    this->AmbientOcclusion == DENSITY_VOLUME ? this->DensityVolumeAOPass.Get() : nullptr,
    this->AmbientOcclusion == VOXEL_CONE_TRACING ? this->VoxelConeAOPass.Get() : nullptr);
}

//------------------------------------------------------------------------------
void vtkParticleRenderView::OrderWithTransformedPartition(int processes)
{
  // ParaView's cuts are the world bounds of the processes' partition boxes. With the particles'
  // actor turned (or sheared) those bounds overlap and give no visibility order: when the
  // partitioned Particles representations share their boxes and their transform, the order then
  // comes from the boxes in data coordinates, seen by the camera taken into them.
  // (the representation puts its boxes on its actor, vtkParticleDistributedPartition::MarkProp;
  // an actor hidden on a process without particles counts all the same)
  std::vector<double> boxes;
  vtkNew<vtkMatrix4x4> matrix;
  vtkNew<vtkMatrix4x4> other;
  int partitioned = 0;
  bool same = true;
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = this->GetRenderer()->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    vtkInformation* keys = prop->GetPropertyKeys();
    auto* actor = vtkActor::SafeDownCast(prop);
    if (actor && keys && keys->Has(vtkParticleDistributedPartition::BOXES()))
    {
      const int n = keys->Length(vtkParticleDistributedPartition::BOXES());
      const double* values = keys->Get(vtkParticleDistributedPartition::BOXES());
      actor->GetMatrix(partitioned == 0 ? matrix.GetPointer() : other.GetPointer());
      if (partitioned > 0)
      {
        // (representations partitioned together carry the same boxes)
        same = same && std::equal(boxes.begin(), boxes.end(), values, values + n) &&
          std::equal(matrix->GetData(), matrix->GetData() + 16, other->GetData());
      }
      boxes.assign(values, values + n);
      ++partitioned;
    }
  }
  if (partitioned == 0 || !same || matrix->IsIdentity() ||
    boxes.size() != 6 * static_cast<size_t>(processes))
  {
    return;
  }
  std::vector<vtkBoundingBox> model;
  for (int p = 0; p < processes; ++p)
  {
    model.emplace_back(boxes.data() + 6 * p);
  }
  this->OrderedComposite->SetBoundingBoxes(model, matrix);
}

//------------------------------------------------------------------------------
const char* vtkParticleRenderView::GetAmbientOcclusionQualityText()
{
  auto* pass = vtkParticleAmbientLightPass::SafeDownCast(
    this->GetAmbientOcclusionPass(this->AmbientOcclusion));
  this->AmbientOcclusionQualityText = pass ? pass->GetQualityText() : std::string();
  return this->AmbientOcclusionQualityText.c_str();
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
  os << indent << "AmbientOcclusion: " << this->AmbientOcclusion << "\n";
  os << indent << "ScaleConsistentShading: " << this->ScaleConsistentShading << "\n";
  os << indent << "SNDFConvergeStillRenders: " << this->SNDFConvergeStillRenders << "\n";
  os << indent << "InteractiveQuality: " << this->InteractiveQuality << "\n";
  os << indent << "InteractiveFrameBudget: " << this->InteractiveFrameBudget << "\n";
  os << indent << "CompositeBounds visible: " << this->CompositeBounds->GetVisibility() << "\n";
  os << indent << "ParticlesPartitionedTogether: " << this->GetParticlesPartitionedTogether()
     << "\n";
  os << indent << "ParticlePassChain:\n";
  this->ParticlePassChain->PrintSelf(os, indent.GetNextIndent());
}
