#include "vtkParticleViewport.h"

#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <sstream>

//------------------------------------------------------------------------------
bool vtkParticleViewport::FillsTarget(const vtkRenderState* s, std::string& what)
{
  vtkRenderer* ren = s ? s->GetRenderer() : nullptr;
  vtkRenderWindow* window = ren ? ren->GetRenderWindow() : nullptr;
  if (!window || s->GetFrameBuffer())
  {
    return true;
  }
  int width = 0;
  int height = 0;
  int x0 = 0;
  int y0 = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  const int* windowSize = window->GetSize();
  if (x0 == 0 && y0 == 0 && width == windowSize[0] && height == windowSize[1])
  {
    return true;
  }
  std::ostringstream text;
  text << width << " x " << height << " pixels at (" << x0 << ", " << y0 << ") of " << windowSize[0]
       << " x " << windowSize[1];
  what = text.str();
  return false;
}
