// TestSNDFTargets: vtkSNDFTargets in a real OpenGL context:
//   a) Allocate makes the G-buffer (colour as drawn in 8 bits, two RGBA16F attachments, a float
//      depth), the shaded picture (RGBA32F), its depth (R32F) and the checkpoint (RGBA32F), all
//      width x height, with a complete framebuffer;
//   b) Allocate at another size makes them anew at that size;
//   c) AllocateDisplay makes the window's picture and depth, keeps them at the same size and
//      makes them anew at another;
//   d) Release frees them all (Width and Height 0).
#include "prTestUtilities.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSNDFTargets.h"
#include "vtkTextureObject.h"

#include "vtkParticleCompat.h"

#include <iostream>
#include <string>

namespace
{
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  Failures += prTest::Check(condition, what) ? 0 : 1;
}

bool Sized(vtkTextureObject* t, int width, int height)
{
  return t && t->GetHandle() != 0 && static_cast<int>(t->GetWidth()) == width &&
    static_cast<int>(t->GetHeight()) == height;
}

// a float picture: RGBA32F, or R32F for a depth
bool FloatImage(vtkTextureObject* t, bool depth)
{
  return t && t->GetVTKDataType() == VTK_FLOAT && t->GetComponents() == (depth ? 1 : 4) &&
    t->GetInternalFormat(VTK_FLOAT, depth ? 1 : 4, false) ==
    static_cast<unsigned int>(depth ? GL_R32F : GL_RGBA32F);
}

void CheckTargets(vtkSNDFTargets& targets, vtkOpenGLRenderWindow* context, int width, int height,
  const std::string& what)
{
  Check(targets.Width == width && targets.Height == height, what + ": Width x Height");
  for (unsigned int a = 0; a < vtkSNDFTargets::NumberOfAttachments; ++a)
  {
    Check(Sized(targets.Attachments[a], width, height), what + ": attachment sized");
  }
  vtkTextureObject* colour = targets.Attachments[0];
  Check(colour && colour->GetVTKDataType() == VTK_UNSIGNED_CHAR && colour->GetComponents() == 4,
    what + ": attachment 0 is 8-bit RGBA");
  for (unsigned int a = 1; a < vtkSNDFTargets::NumberOfAttachments; ++a)
  {
    vtkTextureObject* t = targets.Attachments[a];
    Check(t && t->GetInternalFormat(VTK_FLOAT, 4, false) == GL_RGBA16F,
      what + ": attachments 1 and 2 are RGBA16F");
  }
  Check(Sized(targets.Depth, width, height), what + ": depth sized");
  Check(Sized(targets.Image, width, height) && FloatImage(targets.Image, false),
    what + ": image RGBA32F");
  Check(Sized(targets.ImageDepth, width, height) && FloatImage(targets.ImageDepth, true),
    what + ": image depth R32F");
  Check(Sized(targets.Checkpoint, width, height) && FloatImage(targets.Checkpoint, false),
    what + ": checkpoint RGBA32F");
  Check(targets.Image != targets.Checkpoint, what + ": image and checkpoint differ");
  vtkOpenGLState* state = context->GetState();
  state->PushFramebufferBindings();
  targets.Framebuffer->Bind();
  const char* description = "";
  Check(vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_FRAMEBUFFER, description),
    what + ": framebuffer complete");
  state->PopFramebufferBindings();
}
}

int TestSNDFTargets(int, char*[])
{
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->SetSize(64, 64);
  window->Render();
  vtkOpenGLRenderWindow* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!context)
  {
    std::cerr << "FAILED: no OpenGL render window\n";
    return EXIT_FAILURE;
  }
  context->MakeCurrent();

  // a) and b)
  vtkSNDFTargets targets;
  Check(targets.Width == 0 && !targets.Framebuffer, "nothing before Allocate");
  targets.Allocate(context, 40, 30);
  CheckTargets(targets, context, 40, 30, "40 x 30");
  vtkTextureObject* first = targets.Image;
  vtkSmartPointer<vtkTextureObject> kept = first; // (not freed: Allocate makes a new one)
  targets.Allocate(context, 70, 20);
  CheckTargets(targets, context, 70, 20, "70 x 20");
  Check(targets.Image != first, "a new size makes new textures");
  Check(!targets.DisplayImage && !targets.DisplayDepth, "no display without AllocateDisplay");

  // c) the display
  targets.AllocateDisplay(context, 50, 25);
  Check(Sized(targets.DisplayImage, 50, 25) && FloatImage(targets.DisplayImage, false),
    "display image RGBA32F, the window's size");
  Check(Sized(targets.DisplayDepth, 50, 25) && FloatImage(targets.DisplayDepth, true),
    "display depth R32F, the window's size");
  vtkTextureObject* display = targets.DisplayImage;
  targets.AllocateDisplay(context, 50, 25);
  Check(targets.DisplayImage == display, "the same size keeps the display");
  targets.AllocateDisplay(context, 60, 25);
  Check(Sized(targets.DisplayImage, 60, 25) && Sized(targets.DisplayDepth, 60, 25),
    "another size makes the display anew");
  targets.AllocateDisplay(context, 60, 35);
  Check(Sized(targets.DisplayImage, 60, 35) && Sized(targets.DisplayDepth, 60, 35),
    "another height makes the display anew");

  // d) release
  targets.Release(context);
  bool released = targets.Width == 0 && targets.Height == 0 && !targets.Framebuffer &&
    !targets.Depth && !targets.Image && !targets.ImageDepth && !targets.Checkpoint &&
    !targets.DisplayImage && !targets.DisplayDepth;
  for (const auto& attachment : targets.Attachments)
  {
    released = released && !attachment;
  }
  Check(released, "Release frees every target");
  kept->ReleaseGraphicsResources(context);

  if (Failures > 0)
  {
    std::cerr << Failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
