/**
 * @class   vtkParticleFrontToBackTarget
 * @brief   off-screen front-to-back accumulation of translucent particles over the opaque image
 *
 * vtkParticleFrontToBackTarget is the render target of vtkTransparentSphereMapper's translucent
 * stage (Staib et al. 2015, Sec. 5.2). Begin() finds the framebuffer that holds the opaque image
 * (the one bound by the renderer, or the one a translucency pass -- VTK's dual depth peeling or
 * order-independent pass -- saved on the vtkOpenGLState binding stack before redirecting drawing
 * to its own buffers; VTK 9.2's passes offer no getter for it, so Begin() reads the top of that
 * stack by popping it and pushing it back, the one place in the project that does), copies its
 * depth into GetOpaqueDepthTexture(), and binds an RGBA32F
 * accumulation buffer cleared to 0 with front-to-back "under" blending of premultiplied colours
 * (C += (1 - A) c, A += (1 - A) a) and a depth buffer used only as the early-termination mask
 * (cleared to 1; fragments are drawn at depth 0.5 with GL_LESS and no depth writes).
 * MaskSaturatedPixels() sets the mask depth to 0 where the accumulated opacity exceeds a
 * threshold, so that later draws are rejected by the early depth test (paper Sec. 5.2).
 * End() blends the accumulation over the opaque image (C_out = C + (1 - A) C_opaque, float
 * precision until this single 8-bit write, over an opaque image that is itself 8-bit: at most
 * 1/255 in all) and restores the OpenGL state and bindings exactly.
 *
 * The accumulation is float so that hundreds of layers add up without 8-bit banding.
 *
 * Downsampling > 1 (the interactive level of vtkTransparentSphereMapper) accumulates at
 * ceil(width / d) x ceil(height / d) pixels over the same view: the opaque depth is reduced to
 * the farthest depth of each d x d block (so that no translucent fragment in front of any opaque
 * pixel of the block is cut away) and End() composites the accumulation with bilinear
 * upsampling. The picture differs from the full-resolution one only at the scale of d pixels
 * (silhouettes and opaque edges); with 1 (the default) nothing is resampled.
 */
#ifndef vtkParticleFrontToBackTarget_h
#define vtkParticleFrontToBackTarget_h

#include "vtkObject.h"
#include "vtkParticleRenderingTranslucencyModule.h" // for export macro

#include <vector> // for std::vector

class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

class VTKPARTICLERENDERINGTRANSLUCENCY_EXPORT vtkParticleFrontToBackTarget : public vtkObject
{
public:
  static vtkParticleFrontToBackTarget* New();
  vtkTypeMacro(vtkParticleFrontToBackTarget, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Bind the accumulation buffer for drawing. savedByPass: a translucency pass pushed the
   * framebuffer with the opaque image on the vtkOpenGLState draw-binding stack and bound its own
   * (dual depth peeling, order-independent translucency); false: the opaque image is the bound
   * framebuffer. Returns false (with an error) when the buffers cannot be created.
   */
  bool Begin(vtkRenderer* ren, bool savedByPass);

  /**
   * Depth of the opaque image (window depth, same size as the accumulation: the farthest of
   * each block when downsampled), valid between
   * Begin() and End(). Sample it with texelFetch at gl_FragCoord.xy.
   */
  vtkTextureObject* GetOpaqueDepthTexture();

  /**
   * The RGBA32F accumulation itself (premultiplied, cleared to 0 by Begin()), valid between
   * Begin() and End(), for a pass that writes it as an image (vtkParticleFragmentLists).
   */
  vtkTextureObject* GetAccumulationTexture();

  /**
   * Mask the pixels whose accumulated opacity exceeds threshold (see the class description).
   * Rebinds the accumulation buffer and the drawing state afterwards.
   */
  void MaskSaturatedPixels(double threshold);

  /**
   * Blend the accumulation over the opaque image and restore the state saved by Begin().
   */
  void End();

  /**
   * Restore the drawing state of Begin() (blending, mask depth test) after a caller changed it.
   */
  void ActivateDrawingState();

  ///@{
  /**
   * Accumulate at 1 / Downsampling of the viewport's resolution in each direction (1 to 4;
   * default 1, full resolution). Read at Begin().
   */
  vtkSetClampMacro(Downsampling, int, 1, 4);
  vtkGetMacro(Downsampling, int);
  ///@}

  ///@{
  /**
   * Size of the accumulation buffer (the renderer's viewport, divided by Downsampling) and the
   * number of masked pixels of the last MaskSaturatedPixels() (only counted with CountMaskedPixels,
   * a read-back).
   */
  vtkGetVector2Macro(Size, int);
  vtkSetMacro(CountMaskedPixels, bool);
  vtkGetMacro(NumberOfMaskedPixels, long long);
  ///@}

  /**
   * The accumulated RGBA (premultiplied, float) of the last frame, read back for tests:
   * 4 * width * height floats, bottom-up. Valid between the last draw and End() only if
   * KeepAccumulation is set; otherwise read right after End() from the retained copy.
   */
  bool GetAccumulation(std::vector<float>& rgba);

  /**
   * Forget the retained accumulation (for tests: after this, a frame that composites nothing
   * leaves GetAccumulation() empty instead of returning an older frame's).
   */
  void ClearRetainedAccumulation();
  vtkSetMacro(KeepAccumulation, bool);
  vtkGetMacro(KeepAccumulation, bool);

  ///@{
  /**
   * DeferComposite: End() of a full-resolution frame leaves the image as it is and keeps the
   * accumulation (GetAccumulation) for the caller to composite: distributed rendering, whose
   * ordered compositing (vtkParticleOrderedCompositePass) blends every process's float
   * accumulation with one rounding, as one process's End() does. A downsampled frame is
   * composited as usual. GetLastDeferred: whether the last End() deferred (false after
   * ClearRetainedAccumulation()).
   */
  vtkSetMacro(DeferComposite, bool);
  vtkGetMacro(DeferComposite, bool);
  vtkGetMacro(LastDeferred, bool);
  ///@}

  /**
   * Blend `rgba` (width x height premultiplied RGBA floats, bottom-up) over the bound draw
   * framebuffer at (0, 0) exactly as End() blends the accumulation over the opaque image (the
   * same shader and blending: the same rounding on any GPU). For a deferred composite
   * (DeferComposite) made elsewhere; not between Begin() and End().
   */
  void CompositeOver(vtkOpenGLRenderWindow* context, int width, int height, const float* rgba);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkParticleFrontToBackTarget();
  ~vtkParticleFrontToBackTarget() override;

  int Size[2] = { 0, 0 };
  int Downsampling = 1;
  bool CountMaskedPixels = false;
  long long NumberOfMaskedPixels = 0;
  bool KeepAccumulation = false;
  bool DeferComposite = false;
  bool LastDeferred = false;

private:
  // reduce the full-resolution opaque depth into the accumulation-sized one (Downsampling > 1)
  void ReduceOpaqueDepth(int width, int height);

  vtkParticleFrontToBackTarget(const vtkParticleFrontToBackTarget&) = delete;
  void operator=(const vtkParticleFrontToBackTarget&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
