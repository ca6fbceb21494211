/**
 * @class   vtkParticleOrderedCompositePass
 * @brief   blends the processes' images in floating point, in visibility order, before IceT
 *
 * With translucent geometry ParaView composites the processes' images in the visibility order of
 * their partition boxes (ordered compositing). IceT blends those 8-bit images pairwise in
 * integers, back * (255 - alpha) / 255 + front, truncating at every blend: with three processes a
 * pixel can end 3/255 darker than the single-process picture, more with more processes.
 *
 * This pass runs inside IceT's draw callback, outermost in the particle pass chain
 * (vtkParticleRenderView inserts it while ordered compositing is on). It lets its delegate draw
 * the process's image, reads it back (premultiplied RGBA, 8 bits), gathers every process's image
 * on the process that comes first in the visibility order (vtkMultiProcessController::Gather, 4
 * bytes per pixel and process), which blends them front to back
 * in double precision in the order of the partition boxes seen from the camera
 * (vtkOrderedCompositingHelper::ComputeSortOrder, the order ParaView gives IceT), rounds once, and
 * leaves the result on the process that comes first in that order and transparent black on all
 * the others. IceT then blends one image with empty ones, which its integer blend does without
 * loss (x + 0 = x and x * 255 / 255 = x), so the picture carries one rounding per process image
 * and one for the blend instead of one truncation per blend.
 *
 * Translucent particles are composited as one process composites them: when a process draws
 * one translucent particle prop (vtkTransparentSphereMapper) and no other translucent geometry,
 * the pass has the mapper's front-to-back target defer its composite
 * (vtkParticleFrontToBackTarget::SetDeferComposite), so that the process's image holds its
 * opaque geometry only, and gathers the float accumulation too (16 more bytes per pixel). The
 * first process takes, per pixel, the accumulations in front of the first opaque pixel
 * (composited front to back in double) and that 8-bit pixel, or the view's plain background
 * (SetBackground), and blends the one over the other on the GPU with the target's own blend
 * (vtkParticleFrontToBackTarget::CompositeOver): the single 8-bit write one process makes, with
 * the same rounding on any GPU. The picture then equals the single-process one up to float
 * associativity, where 8-bit images blended per process differed by their rounding, and an
 * image filter after compositing (ParaView's FXAA, on by default) amplified that rounding into
 * single pixels far off (measured: Documentation/Using.md, Distributed rendering).
 *
 * Every process must draw whenever one does (the gather is collective): the view shows its
 * vtkParticleBoundsProp while this pass is on, as for distributed PointAO. Processes whose windows
 * differ in size skip the blend together, with a warning. Without a controller, with one process
 * or without one box per process the pass only renders its delegate.
 *
 * @sa vtkParticleRenderView vtkParticleBoundsProp vtkOrderedCompositingHelper
 */
#ifndef vtkParticleOrderedCompositePass_h
#define vtkParticleOrderedCompositePass_h

#include "vtkImageProcessingPass.h"
#include "vtkParticleRenderingParaViewModule.h" // for export macro
#include "vtkSmartPointer.h"                    // for vtkSmartPointer

#include <vector> // for std::vector

class vtkBoundingBox;
class vtkCamera;
class vtkMatrix4x4;
class vtkMultiProcessController;
class vtkOpenGLFramebufferObject;
class vtkOrderedCompositingHelper;
class vtkParticleFrontToBackTarget;
class vtkTextureObject;

class VTKPARTICLERENDERINGPARAVIEW_EXPORT vtkParticleOrderedCompositePass
  : public vtkImageProcessingPass
{
public:
  static vtkParticleOrderedCompositePass* New();
  vtkTypeMacro(vtkParticleOrderedCompositePass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Draw the delegate, then blend the processes' images (see the class documentation).
   */
  void Render(const vtkRenderState* s) override;

  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * The processes that composite (ParaView's global controller on the render servers). Default
   * none: the pass only renders its delegate.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController();
  ///@}

  /**
   * The partition box of every process, indexed by process (ParaView's cuts for ordered
   * compositing), in world coordinates; or in the model coordinates of `modelToWorld` (the
   * partition of particles whose actor is transformed: a turned box's world bounds overlap its
   * neighbours', so they would give no order; the camera is taken into model coordinates instead,
   * where the boxes still partition space).
   */
  void SetBoundingBoxes(const std::vector<vtkBoundingBox>& boxes);
  void SetBoundingBoxes(const std::vector<vtkBoundingBox>& boxes, vtkMatrix4x4* modelToWorld);

  /**
   * The processes front to back for this camera (from the boxes; empty without them).
   */
  std::vector<int> ComputeOrder(vtkCamera* camera);

  /**
   * Blend the gathered images front to back: `images` holds `processes` images of `pixels` RGBA
   * pixels each, `order` the processes front to back; the result (rounded once) goes to `result`.
   * Public for the tests.
   */
  static void BlendInOrder(const unsigned char* images, int processes, vtkIdType pixels,
    const std::vector<int>& order, unsigned char* result);

  /**
   * Split the gathered images for the one blend of the translucent particles: front to back,
   * each process's deferred accumulation (`accumulations`, RGBA float premultiplied, `processes`
   * images of `pixels` each; zero where it drew none) and then its 8-bit image, up to the first
   * opaque pixel. `under` gets that pixel (or the 8-bit `background`, RGB 0-255, opaque; nullptr:
   * transparent black), `over` everything in front of it (RGBA float premultiplied). Public for
   * the tests.
   */
  static void SplitInOrder(const unsigned char* images, const float* accumulations, int processes,
    vtkIdType pixels, const std::vector<int>& order, const unsigned char* background,
    unsigned char* under, float* over);

  /**
   * The view's background, composited by the first process when the translucent particles are
   * blended at float precision (see the class documentation): a plain colour (valid; RGB in
   * [0, 1]); not valid (the default) for a gradient, textured or transparent background, which
   * ParaView adds after compositing.
   */
  void SetBackground(const double rgb[3], bool valid);

  ///@{
  /**
   * Whether the translucent particles' composite may be deferred to the blend (see the class
   * documentation). Default on. Off when a pass between this one and the particles works on the
   * finished colour image (PointAO darkens it, S-NDF re-shades it): it must see the translucent
   * particles in it, as in one process.
   */
  vtkSetMacro(DeferTranslucentParticles, bool);
  vtkGetMacro(DeferTranslucentParticles, bool);
  ///@}

  ///@{
  /**
   * The most bytes the first process may gather for the deferred composite (20 per pixel and
   * process: the 8-bit image and the float accumulation). Above it the processes blend 8-bit
   * images only (4 bytes per pixel and process), with a warning. Default 1 GiB (e.g. 16
   * processes at 1920 x 1080 need 663 MB).
   */
  vtkSetMacro(MaximumGatherBytes, double);
  vtkGetMacro(MaximumGatherBytes, double);
  ///@}

  /**
   * Whether the last render blended the processes' images.
   */
  vtkGetMacro(LastBlended, bool);

protected:
  vtkParticleOrderedCompositePass();
  ~vtkParticleOrderedCompositePass() override;

  // the stages of Render()
  bool SizesAgree(int width, int height);
  void ReadImage(int width, int height);
  bool GatherImages(int width, int height, int destination);
  void WriteImage(const vtkRenderState* s, int width, int height);
  void ClearImage(const vtkRenderState* s);
  // the one translucent particle prop whose composite this process defers (nullptr: none)
  vtkParticleFrontToBackTarget* DeferredTarget(const vtkRenderState* s, int width, int height);
  // the deferred accumulation of every process on the destination (empty: none deferred)
  bool GatherAccumulations(vtkParticleFrontToBackTarget* target, vtkIdType pixels, int destination);

  vtkSmartPointer<vtkMultiProcessController> Controller;
  vtkSmartPointer<vtkOrderedCompositingHelper> Helper;
  vtkSmartPointer<vtkMatrix4x4> WorldToModel; // (null: the boxes are in world coordinates)
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  std::vector<unsigned char> Local;
  std::vector<unsigned char> Gathered;
  std::vector<unsigned char> Blended;
  std::vector<float> LocalAccumulation;
  std::vector<float> GatheredAccumulations;
  std::vector<float> Over;
  // blends the translucent particles' accumulation over the first process's image
  vtkSmartPointer<vtkParticleFrontToBackTarget> Compositor;
  unsigned char Background[3] = { 0, 0, 0 };
  bool BackgroundValid = false;
  bool DeferTranslucentParticles = true;
  double MaximumGatherBytes = 1073741824.0;
  bool WarnedGatherBytes = false;
  bool LastBlended = false;

private:
  vtkParticleOrderedCompositePass(const vtkParticleOrderedCompositePass&) = delete;
  void operator=(const vtkParticleOrderedCompositePass&) = delete;
};

#endif
