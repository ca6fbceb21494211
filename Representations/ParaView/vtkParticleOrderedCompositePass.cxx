#include "vtkParticleOrderedCompositePass.h"

#include "vtkActor.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkCommunicator.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h" // the OpenGL loader of this VTK
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOrderedCompositingHelper.h"
#include "vtkParticleFrontToBackTarget.h"
#include "vtkParticleGBufferExchange.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTextureObject.h"
#include "vtkTransparentSphereMapper.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkParticleOrderedCompositePass);

namespace
{
// One step of the front-to-back blend of premultiplied RGBA: C += (1 - A) c, A += (1 - A) a.
void Under(double accumulated[4], const double pixel[4])
{
  const double remaining = 1.0 - accumulated[3];
  for (int c = 0; c < 4; ++c)
  {
    accumulated[c] += remaining * pixel[c];
  }
}
}

//------------------------------------------------------------------------------
vtkParticleOrderedCompositePass::vtkParticleOrderedCompositePass()
  : Helper(vtkSmartPointer<vtkOrderedCompositingHelper>::New())
  , Compositor(vtkSmartPointer<vtkParticleFrontToBackTarget>::New())
{
}

//------------------------------------------------------------------------------
vtkParticleOrderedCompositePass::~vtkParticleOrderedCompositePass() = default;

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::SetController(vtkMultiProcessController* controller)
{
  if (this->Controller != controller)
  {
    this->Controller = controller;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkParticleOrderedCompositePass::GetController()
{
  return this->Controller;
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::SetBoundingBoxes(const std::vector<vtkBoundingBox>& boxes)
{
  this->Helper->SetBoundingBoxes(boxes);
  this->WorldToModel = nullptr;
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::SetBoundingBoxes(
  const std::vector<vtkBoundingBox>& boxes, vtkMatrix4x4* modelToWorld)
{
  this->SetBoundingBoxes(boxes);
  if (modelToWorld && !modelToWorld->IsIdentity())
  {
    this->WorldToModel = vtkSmartPointer<vtkMatrix4x4>::New();
    vtkMatrix4x4::Invert(modelToWorld, this->WorldToModel);
  }
}

//------------------------------------------------------------------------------
std::vector<int> vtkParticleOrderedCompositePass::ComputeOrder(vtkCamera* camera)
{
  const int processes = this->Controller ? this->Controller->GetNumberOfProcesses() : 1;
  if (camera == nullptr || static_cast<int>(this->Helper->GetBoundingBoxes().size()) != processes)
  {
    return {};
  }
  if (!this->WorldToModel)
  {
    return this->Helper->ComputeSortOrder(camera);
  }
  // the camera in the boxes' model coordinates: the order of a partition by planes depends on
  // the side of each plane the eye (or, in parallel projection, the direction of projection)
  // lies on, which an affine map keeps
  auto toModel = [this](const double world[3], double model[3])
  {
    const double in[4] = { world[0], world[1], world[2], 1.0 };
    double out[4];
    this->WorldToModel->MultiplyPoint(in, out);
    for (int c = 0; c < 3; ++c)
    {
      model[c] = out[3] != 0.0 ? out[c] / out[3] : out[c];
    }
  };
  double position[3];
  double focal[3];
  toModel(camera->GetPosition(), position);
  toModel(camera->GetFocalPoint(), focal);
  vtkNew<vtkCamera> model;
  model->SetParallelProjection(camera->GetParallelProjection());
  model->SetPosition(position);
  model->SetFocalPoint(focal);
  return this->Helper->ComputeSortOrder(model);
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->LastBlended = false;
  if (this->DelegatePass == nullptr)
  {
    vtkWarningMacro(<< "No delegate pass: nothing is drawn.");
    return;
  }
  const std::vector<int> order = this->ComputeOrder(s->GetRenderer()->GetActiveCamera());
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  const int* size = context ? context->GetActualSize() : nullptr;
  const int width = size ? size[0] : 0;
  const int height = size ? size[1] : 0;
  const bool blend = order.size() >= 2 && context && this->SizesAgree(width, height);

  // 1. the process's own image, its translucent particles' composite deferred to the blend
  vtkParticleFrontToBackTarget* target =
    blend && this->DeferTranslucentParticles ? this->DeferredTarget(s, width, height) : nullptr;
  const double gatherBytes = 20.0 * width * height * this->Controller->GetNumberOfProcesses();
  if (target && gatherBytes > this->MaximumGatherBytes)
  {
    if (!this->WarnedGatherBytes)
    {
      vtkWarningMacro(<< "The translucent particles of " << this->Controller->GetNumberOfProcesses()
                      << " processes at " << width << " x " << height << " would gather "
                      << gatherBytes / 1048576.0 << " MiB on one process (MaximumGatherBytes "
                      << this->MaximumGatherBytes / 1048576.0
                      << " MiB): they are blended from 8-bit images, within about 1/255 per "
                         "process of the single-process picture.");
      this->WarnedGatherBytes = true;
    }
    target = nullptr;
  }
  if (target)
  {
    target->ClearRetainedAccumulation();
    target->SetDeferComposite(true);
  }
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  if (target)
  {
    target->SetDeferComposite(false);
  }
  if (!blend)
  {
    return;
  }

  // 2. every process's image (and deferred accumulation) on the first process in the order,
  // which blends them front to back; 3. the result there, transparent black elsewhere
  const int destination = order.front();
  const bool first = this->Controller->GetLocalProcessId() == destination;
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  this->ReadImage(width, height);
  const bool accumulations = this->GatherAccumulations(target, pixels, destination);
  if (!this->GatherImages(width, height, destination))
  {
    if (target && target->GetLastDeferred() && !this->LocalAccumulation.empty())
    {
      // (the gather failed: this process's own deferred particles, composited here)
      this->Compositor->CompositeOver(context, width, height, this->LocalAccumulation.data());
    }
    return;
  }
  if (first && accumulations)
  {
    // the 8-bit image under the translucent particles (the first opaque one, or the
    // background) and the particles' accumulation in front of it, blended as one process's
    // End() blends them
    this->Blended.resize(static_cast<size_t>(pixels) * 4);
    this->Over.resize(static_cast<size_t>(pixels) * 4);
    vtkParticleOrderedCompositePass::SplitInOrder(this->Gathered.data(),
      this->GatheredAccumulations.data(), this->Controller->GetNumberOfProcesses(), pixels, order,
      this->BackgroundValid ? this->Background : nullptr, this->Blended.data(), this->Over.data());
    this->WriteImage(s, width, height);
    this->Compositor->CompositeOver(context, width, height, this->Over.data());
  }
  else if (first)
  {
    this->Blended.assign(static_cast<size_t>(pixels) * 4, 0);
    vtkParticleOrderedCompositePass::BlendInOrder(this->Gathered.data(),
      this->Controller->GetNumberOfProcesses(), pixels, order, this->Blended.data());
    this->WriteImage(s, width, height);
  }
  else
  {
    this->ClearImage(s);
  }
  this->LastBlended = true;
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::SetBackground(const double rgb[3], bool valid)
{
  for (int c = 0; c < 3; ++c)
  {
    // the 8-bit value a single process clears its framebuffer to
    const double value = std::round(std::min(1.0, std::max(0.0, rgb[c])) * 255.0);
    this->Background[c] = static_cast<unsigned char>(std::isfinite(value) ? value : 0.0);
  }
  this->BackgroundValid = valid;
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::BlendInOrder(const unsigned char* images, int processes,
  vtkIdType pixels, const std::vector<int>& order, unsigned char* result)
{
  vtkSMPTools::For(0, pixels,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double accumulated[4] = { 0.0, 0.0, 0.0, 0.0 };
        for (int process : order)
        {
          if (process < 0 || process >= processes)
          {
            continue;
          }
          const unsigned char* image = images + (static_cast<vtkIdType>(process) * pixels + i) * 4;
          const double pixel[4] = { image[0] / 255.0, image[1] / 255.0, image[2] / 255.0,
            image[3] / 255.0 };
          Under(accumulated, pixel);
        }
        for (int c = 0; c < 4; ++c)
        {
          const double value = std::round(accumulated[c] * 255.0);
          result[i * 4 + c] = static_cast<unsigned char>(std::min(255.0, std::max(0.0, value)));
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::SplitInOrder(const unsigned char* images,
  const float* accumulations, int processes, vtkIdType pixels, const std::vector<int>& order,
  const unsigned char* background, unsigned char* under, float* over)
{
  vtkSMPTools::For(0, pixels,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        // front to back until the first opaque pixel (or the background, opaque; or none)
        double accumulated[4] = { 0.0, 0.0, 0.0, 0.0 };
        unsigned char backdrop[4] = { 0, 0, 0, 0 };
        if (background)
        {
          std::copy(background, background + 3, backdrop);
          backdrop[3] = 255;
        }
        const unsigned char* opaque = backdrop;
        for (int process : order)
        {
          if (process < 0 || process >= processes)
          {
            continue;
          }
          const vtkIdType offset = (static_cast<vtkIdType>(process) * pixels + i) * 4;
          double pixel[4];
          // the process's translucent particles (no NaN and nothing beyond opaque reaches the
          // picture), then its 8-bit image
          for (int c = 0; c < 4; ++c)
          {
            const double value = accumulations[offset + c];
            pixel[c] = std::isfinite(value) ? std::min(1.0, std::max(0.0, value)) : 0.0;
          }
          Under(accumulated, pixel);
          const unsigned char* image = images + offset;
          if (image[3] == 255)
          {
            opaque = image;
            break;
          }
          for (int c = 0; c < 4; ++c)
          {
            pixel[c] = image[c] / 255.0;
          }
          Under(accumulated, pixel);
        }
        for (int c = 0; c < 4; ++c)
        {
          under[i * 4 + c] = opaque[c];
          over[i * 4 + c] = static_cast<float>(accumulated[c]);
        }
      }
    });
}

//------------------------------------------------------------------------------
vtkParticleFrontToBackTarget* vtkParticleOrderedCompositePass::DeferredTarget(
  const vtkRenderState* s, int width, int height)
{
  // the accumulation must cover the whole image (IceT's tile: the window)
  int size[2];
  int origin[2];
  s->GetRenderer()->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  if (size[0] != width || size[1] != height || origin[0] != 0 || origin[1] != 0)
  {
    return nullptr;
  }
  // one translucent particle prop and no other translucent geometry (which the renderer
  // composites over the particles, after them)
  vtkParticleFrontToBackTarget* found = nullptr;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (!prop || !prop->GetVisibility() ||
      !(prop->HasTranslucentPolygonalGeometry() || prop->IsA("vtkVolume")))
    {
      continue;
    }
    auto* actor = vtkActor::SafeDownCast(prop);
    auto* mapper = actor ? vtkTransparentSphereMapper::SafeDownCast(actor->GetMapper()) : nullptr;
    if (!mapper || found)
    {
      return nullptr;
    }
    found = mapper->GetFrontToBackTarget();
  }
  return found;
}

//------------------------------------------------------------------------------
bool vtkParticleOrderedCompositePass::GatherAccumulations(
  vtkParticleFrontToBackTarget* target, vtkIdType pixels, int destination)
{
  // whether any process deferred its translucent particles (then every one sends its
  // accumulation, zero where it drew none)
  this->LocalAccumulation.clear();
  const bool deferred = target && target->GetLastDeferred() &&
    target->GetAccumulation(this->LocalAccumulation) &&
    static_cast<vtkIdType>(this->LocalAccumulation.size()) == 4 * pixels;
  int local = deferred ? 1 : 0;
  int any = 0;
  this->Controller->AllReduce(&local, &any, 1, vtkCommunicator::MAX_OP);
  if (!any)
  {
    this->LocalAccumulation.clear();
    this->GatheredAccumulations.clear();
    return false;
  }
  if (!deferred)
  {
    this->LocalAccumulation.assign(static_cast<size_t>(4 * pixels), 0.0f);
  }
  const bool receives = this->Controller->GetLocalProcessId() == destination;
  this->GatheredAccumulations.resize(
    receives ? static_cast<size_t>(4 * pixels) * this->Controller->GetNumberOfProcesses() : 0);
  return this->Controller->Gather(this->LocalAccumulation.data(),
           receives ? this->GatheredAccumulations.data() : nullptr, 4 * pixels, destination) != 0;
}

//------------------------------------------------------------------------------
bool vtkParticleOrderedCompositePass::SizesAgree(int width, int height)
{
  // the processes agree on the size first, or none blends (the gather needs equal lengths)
  const double sizes[2] = { static_cast<double>(width), static_cast<double>(height) };
  if (!vtkParticleGBufferExchange::AllEqual(this->Controller, sizes, 2) || width <= 0 ||
    height <= 0)
  {
    vtkWarningMacro(<< "The processes' windows differ in size (or are empty): their images are "
                       "composited by IceT alone.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::ReadImage(int width, int height)
{
  this->Local.resize(static_cast<size_t>(width) * height * 4);
  // the image IceT would read, from the same framebuffer
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, this->Local.data());
}

//------------------------------------------------------------------------------
bool vtkParticleOrderedCompositePass::GatherImages(int width, int height, int destination)
{
  const vtkIdType bytes = static_cast<vtkIdType>(width) * height * 4;
  const bool receives = this->Controller->GetLocalProcessId() == destination;
  this->Gathered.resize(
    receives ? static_cast<size_t>(bytes) * this->Controller->GetNumberOfProcesses() : 0);
  return this->Controller->Gather(
           this->Local.data(), receives ? this->Gathered.data() : nullptr, bytes, destination) != 0;
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::WriteImage(const vtkRenderState* s, int width, int height)
{
  // Blended (the blend, on the first process) over the colour
  // the delegate drew (the depth stays)
  auto* context = static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
  vtkOpenGLState* ostate = context->GetState();
  if (this->Texture == nullptr)
  {
    this->Texture = vtkSmartPointer<vtkTextureObject>::New();
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  }
  this->Texture->SetContext(context);
  if (static_cast<int>(this->Texture->GetWidth()) != width ||
    static_cast<int>(this->Texture->GetHeight()) != height || this->Texture->GetHandle() == 0)
  {
    // new storage under the same texture name: the framebuffer below keeps the texture it
    // attached first (AddColorAttachment ignores the same vtkTextureObject again), so a new
    // name would leave it blitting the previous size's last image (a screenshot at another
    // resolution than the view's, its tiles)
    this->Texture->SetInternalFormat(GL_RGBA8);
    this->Texture->SetFormat(GL_RGBA);
    this->Texture->SetDataType(GL_UNSIGNED_BYTE);
    this->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->Texture->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
  }
  this->Texture->Activate();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(
    GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, this->Blended.data());
  this->Texture->Deactivate();

  this->Framebuffer->SetContext(context);
  ostate->PushReadFramebufferBinding();
  this->Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  this->Framebuffer->AddColorAttachment(0, this->Texture);
  this->Framebuffer->ActivateReadBuffer(0);
  vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglColorMask mask(ostate);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  ostate->PopReadFramebufferBinding();
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::ClearImage(const vtkRenderState* s)
{
  // transparent black over the colour the delegate drew (the depth stays), as a cleared colour
  // buffer: nothing to upload
  auto* context = static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
  vtkOpenGLState* ostate = context->GetState();
  vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglColorMask mask(ostate);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const GLfloat transparent[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  glClearBufferfv(GL_COLOR, 0, transparent);
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(w);
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(w);
  }
  this->Compositor->ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkParticleOrderedCompositePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller.GetPointer() << "\n";
  os << indent << "Boxes: " << this->Helper->GetBoundingBoxes().size() << "\n";
  os << indent << "LastBlended: " << this->LastBlended << "\n";
  os << indent << "DeferTranslucentParticles: " << this->DeferTranslucentParticles << "\n";
  os << indent << "MaximumGatherBytes: " << this->MaximumGatherBytes << "\n";
  os << indent << "Background: " << static_cast<int>(this->Background[0]) << " "
     << static_cast<int>(this->Background[1]) << " " << static_cast<int>(this->Background[2])
     << (this->BackgroundValid ? "" : " (not used)") << "\n";
}
