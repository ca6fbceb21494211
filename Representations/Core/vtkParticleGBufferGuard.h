/**
 * @file   vtkParticleGBufferGuard.h
 * @brief  what must hold while a pass's delegate draws into a G-buffer with auxiliary targets
 *
 * vtkPointAOPass and vtkSNDFRenderPass draw their delegate into a framebuffer whose colour
 * attachment 0 is the picture and whose further attachments (1, 2, ...) receive per-fragment
 * data that the pass's shader hooks write (normals, radii, depths, colour coordinates). Two
 * things that VTK does by default would corrupt those targets:
 * - Blending. VTK keeps blending on for opaque geometry (SRC_ALPHA, ONE_MINUS_SRC_ALPHA). With
 *   alpha 1 that keeps the written value on paper, but an implementation may blend as
 *   dst + a (src - dst) (Mesa's llvmpipe does): the value comes back rounded, off by an ulp
 *   wherever a fragment overwrites another. The targets take each fragment as written instead.
 * - The renderer's FXAA (vtkRenderer::UseFXAA, on in ParaView by default) runs inside the
 *   delegate, after the translucent geometry, as a full-screen quad into the bound framebuffer.
 *   Its shader has one output: every further attachment receives undefined values (in practice
 *   whatever the shader core holds, different each frame). It is held back; the pass applies it
 *   to its final picture, if at all (GetHeldBackFXAA()).
 *
 * Construct the guard after binding the G-buffer and activating its draw buffers, destroy it
 * when the delegate is done. Anything else drawn into the G-buffer by the delegate without the
 * pass's hooks (depth peeling's and volumes' full-screen quads, overlays) still leaves undefined
 * values in the auxiliary targets, garbage or the old value by tile and thread: the passes draw
 * those targets only when no such geometry is in view (vtkPointAOPass; vtkSNDFRenderPass shows
 * the plain picture with translucent geometry in view) and tell their own writes apart
 * (vtkPointAOPass stores a stamp of the fragment's depth with its normal).
 */
#ifndef vtkParticleGBufferGuard_h
#define vtkParticleGBufferGuard_h

#include "vtkParticleRenderingCoreModule.h" // for export macro

class vtkRenderer;

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleGBufferGuard
{
public:
  /**
   * Blending off for colour attachments [1, attachments) of the bound framebuffer and the
   * renderer's FXAA off, until destruction.
   */
  vtkParticleGBufferGuard(vtkRenderer* renderer, unsigned int attachments);
  ~vtkParticleGBufferGuard();

  /** Whether the renderer asked for FXAA, which the guard held back from the delegate. */
  bool GetHeldBackFXAA() const { return this->FXAA; }

  vtkParticleGBufferGuard(const vtkParticleGBufferGuard&) = delete;
  vtkParticleGBufferGuard& operator=(const vtkParticleGBufferGuard&) = delete;

private:
  vtkRenderer* Renderer;
  unsigned int Attachments;
  bool FXAA;
};

#endif
