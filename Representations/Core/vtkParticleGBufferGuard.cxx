#include "vtkParticleGBufferGuard.h"

#include "vtkRenderer.h"

#include "vtkParticleCompat.h"

//------------------------------------------------------------------------------
vtkParticleGBufferGuard::vtkParticleGBufferGuard(vtkRenderer* renderer, unsigned int attachments)
  : Renderer(renderer)
  , Attachments(attachments)
  , FXAA(renderer && renderer->GetUseFXAA())
{
  for (unsigned int a = 1; a < this->Attachments; ++a)
  {
    glDisablei(GL_BLEND, a);
  }
  if (this->FXAA)
  {
    this->Renderer->SetUseFXAA(false);
  }
}

//------------------------------------------------------------------------------
vtkParticleGBufferGuard::~vtkParticleGBufferGuard()
{
  if (this->FXAA)
  {
    this->Renderer->SetUseFXAA(true);
  }
  // back to what draw buffer 0 has (GL's state: VTK's state cache can be out of step with it)
  if (glIsEnabledi(GL_BLEND, 0))
  {
    for (unsigned int a = 1; a < this->Attachments; ++a)
    {
      glEnablei(GL_BLEND, a);
    }
  }
}
