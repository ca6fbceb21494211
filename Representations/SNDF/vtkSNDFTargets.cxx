#include "vtkSNDFTargets.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"

#include "vtkParticleCompat.h"

//------------------------------------------------------------------------------
void vtkSNDFTargets::Release(vtkWindow* w)
{
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(w);
  }
  for (auto& attachment : this->Attachments)
  {
    if (attachment)
    {
      attachment->ReleaseGraphicsResources(w);
    }
    attachment = nullptr;
  }
  for (auto* texture : { &this->Depth, &this->Image, &this->ImageDepth, &this->Checkpoint,
         &this->DisplayImage, &this->DisplayDepth })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(w);
    }
    *texture = nullptr;
  }
  this->Framebuffer = nullptr;
  this->Width = 0;
  this->Height = 0;
}

//------------------------------------------------------------------------------
void vtkSNDFTargets::Allocate(vtkOpenGLRenderWindow* context, int width, int height)
{
  this->Release(context);
  this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  for (auto& attachment : this->Attachments)
  {
    attachment = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->Depth = vtkSmartPointer<vtkTextureObject>::New();
  this->Image = vtkSmartPointer<vtkTextureObject>::New();
  this->ImageDepth = vtkSmartPointer<vtkTextureObject>::New();
  this->Checkpoint = vtkSmartPointer<vtkTextureObject>::New();
  this->Framebuffer->SetContext(context);
  for (unsigned int a = 0; a < NumberOfAttachments; ++a)
  {
    vtkTextureObject* t = this->Attachments[a];
    t->SetContext(context);
    if (a > 0)
    {
      t->SetInternalFormat(GL_RGBA16F);
      t->SetFormat(GL_RGBA);
      t->SetDataType(GL_FLOAT);
      t->Allocate2D(width, height, 4, VTK_FLOAT);
    }
    else
    {
      // 8 bits, as the window: the background and other geometry come out exactly as drawn
      // without the pass (a particle's ambient term is quantised per sample, < 0.5/255)
      t->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
    }
  }
  this->Depth->SetContext(context);
  this->Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
  AllocateImage(this->Image, context, width, height, false);
  AllocateImage(this->Checkpoint, context, width, height, false);
  AllocateImage(this->ImageDepth, context, width, height, true);
  vtkOpenGLState* ostate = context->GetState();
  ostate->PushFramebufferBindings();
  this->Framebuffer->Bind();
  for (unsigned int a = 0; a < NumberOfAttachments; ++a)
  {
    this->Framebuffer->AddColorAttachment(a, this->Attachments[a]);
  }
  this->Framebuffer->AddDepthAttachment(this->Depth);
  ostate->PopFramebufferBindings();
  this->Width = width;
  this->Height = height;
}

//------------------------------------------------------------------------------
void vtkSNDFTargets::AllocateDisplay(vtkOpenGLRenderWindow* context, int width, int height)
{
  for (auto* image : { &this->DisplayImage, &this->DisplayDepth })
  {
    if (*image && (*image)->GetHandle() && static_cast<int>((*image)->GetWidth()) == width &&
      static_cast<int>((*image)->GetHeight()) == height)
    {
      continue;
    }
    if (*image)
    {
      (*image)->ReleaseGraphicsResources(context);
    }
    *image = vtkSmartPointer<vtkTextureObject>::New();
    AllocateImage(*image, context, width, height, image == &this->DisplayDepth);
  }
}

//------------------------------------------------------------------------------
void vtkSNDFTargets::AllocateImage(
  vtkTextureObject* image, vtkOpenGLRenderWindow* context, int width, int height, bool depth)
{
  image->SetContext(context);
  image->SetInternalFormat(depth ? GL_R32F : GL_RGBA32F);
  image->SetFormat(depth ? GL_RED : GL_RGBA);
  image->SetDataType(GL_FLOAT);
  image->Allocate2D(width, height, depth ? 1 : 4, VTK_FLOAT);
}
