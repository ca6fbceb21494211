/**
 * @file   vtkParticleViewport.h
 * @brief  whether a pass that renders its delegate into its own full-size target can do so for
 *         a render state
 *
 * A pass that draws its delegate into a target of the renderer's size (the G-buffers of
 * vtkPointAOPass and vtkSNDFRenderPass) relies on the delegate's camera pass setting up that
 * target's viewport. When the render state draws into the window and the renderer's viewport
 * does not fill it (several renderers side by side in plain VTK), the camera pass sets up the
 * window's viewport instead and the picture comes out distorted. Such passes render plainly
 * then, saying why.
 */
#ifndef vtkParticleViewport_h
#define vtkParticleViewport_h

#include "vtkParticleRenderingCoreModule.h" // for export macro

#include <string> // for std::string

class vtkRenderState;

namespace vtkParticleViewport
{
/**
 * True when the state draws into a framebuffer of its own or the renderer fills its window;
 * otherwise false, with `what` describing the renderer's part of the window ("120 x 120 pixels
 * at (0, 0) of 240 x 120").
 */
VTKPARTICLERENDERINGCORE_EXPORT bool FillsTarget(const vtkRenderState* s, std::string& what);
}

#endif
