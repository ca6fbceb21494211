/**
 * @class   vtkParticleGBufferExchange
 * @brief   composites a screen-space pass's G-buffer over the processes that draw one picture
 *
 * Under distributed rendering (ParaView's pvbatch and pvserver with MPI, or a plain VTK program
 * that composites its processes' images by depth) each process draws only the particles it
 * holds, and a screen-space pass (vtkPointAOPass) that read only its own G-buffer would miss the
 * occluders the other processes draw. vtkParticleGBufferExchange gives every process the G-buffer
 * of the whole picture before the pass reads it: per pixel the depth of the nearest fragment over
 * all processes, and the values (normal, stamp) that this fragment's process wrote with it.
 *
 * How: two all-reduces over the controller. First the minimum of a 64-bit key per pixel, the
 * depth's bits (non-negative floats order as their bit patterns) above the process id: it gives
 * the nearest depth and its process (at equal depth the lowest id, so every process agrees).
 * CompositeFramebuffer does the whole round trip for a framebuffer's depth and colour targets
 * (vtkPointAOPass: normal and stamp; vtkSNDFRenderPass: each sample pass's four targets).
 * Then the sum of the payloads, each process contributing zeros where it is not the owner: the
 * owner's values arrive unchanged (x + 0 = x exactly). No user-defined MPI operation is needed,
 * so MPI may split the buffers wherever it likes. The picture each process composites afterwards
 * stays its own; only what the pass reads is the whole one, so the composited image is the
 * single process's.
 *
 * Collective: every process of the controller must call the same methods in the same order each
 * frame (the view makes sure every process draws; see vtkParticleRenderView).
 *
 * @sa vtkPointAOPass vtkMultiProcessController
 */
#ifndef vtkParticleGBufferExchange_h
#define vtkParticleGBufferExchange_h

#include "vtkNew.h" // for vtkNew
#include "vtkObject.h"
#include "vtkParticleRenderingCoreModule.h" // for export macro
#include "vtkSmartPointer.h"                // for vtkSmartPointer

#include <vector> // for std::vector

class vtkFloatArray;
class vtkMultiProcessController;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleGBufferExchange : public vtkObject
{
public:
  static vtkParticleGBufferExchange* New();
  vtkTypeMacro(vtkParticleGBufferExchange, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes whose pictures are composited by depth. nullptr (default) or one process:
   * nothing is exchanged.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController();
  ///@}

  /**
   * Whether there is more than one process to exchange with.
   */
  bool IsDistributed();

  /**
   * Replace values[0..n) by their sum over the processes. Collective.
   */
  void Sum(double* values, int n);

  /**
   * Replace values[0..n) by their minimum over the processes. Collective.
   */
  void Minimum(double* values, int n);

  ///@{
  /**
   * True when every process holds the same values[0..n) (collective; true with one process): the
   * minima of the values and of their negatives are opposite only when all are equal. The
   * static form takes any controller (nullptr: true).
   */
  bool AllEqual(const double* values, int n);
  static bool AllEqual(vtkMultiProcessController* controller, const double* values, int n);
  ///@}

  /**
   * depth: the window depth per pixel (one component; values outside [0, 1] are clamped, NaN is
   * taken as 1, the background); payload: as many tuples, written by the process's nearest
   * fragment. Afterwards every process holds the nearest depth over all processes and, in
   * payload, the values of its process (at equal depth the lowest process id). Returns false,
   * changing nothing, for arrays that do not match. Collective (all processes must pass arrays
   * of the same size).
   */
  bool CompositeNearest(vtkFloatArray* depth, vtkFloatArray* payload);

#if !defined(__VTK_WRAP__)
  /**
   * One target of CompositeFramebuffer: the colour attachment read back (Attachment; -1: not
   * drawn, every value Fill), its Components per pixel (4: RGBA, 1: RED), Bytes for an 8-bit
   * target (sent as whole numbers 0-255 in floats, exact), and the texture that receives the
   * whole picture's values (Result, Components and Bytes as read).
   */
  struct vtkTarget
  {
    int Attachment;
    int Components;
    bool Bytes;
    float Fill;
    vtkTextureObject* Result;
  };

  /**
   * A screen-space pass's G-buffer over the processes: reads back the depth and the targets of
   * `framebuffer` (width x height, after glFinish: every draw into it finished), composites them
   * by nearest depth (CompositeNearest) and uploads the whole picture's values, the depth to
   * `depthResult` (a depth texture, or with depthTexture false a one-component float texture)
   * and each target to its Result. Collective; false, changing nothing, for a bad size.
   */
  bool CompositeFramebuffer(vtkOpenGLRenderWindow* context, vtkOpenGLFramebufferObject* framebuffer,
    int width, int height, const std::vector<vtkTarget>& targets, vtkTextureObject* depthResult,
    bool depthTexture);
#endif

protected:
  vtkParticleGBufferExchange();
  ~vtkParticleGBufferExchange() override;

  vtkSmartPointer<vtkMultiProcessController> Controller;
  vtkNew<vtkFloatArray> Depths;  // CompositeFramebuffer's depth per pixel
  vtkNew<vtkFloatArray> Payload; // and its targets' values

private:
  vtkParticleGBufferExchange(const vtkParticleGBufferExchange&) = delete;
  void operator=(const vtkParticleGBufferExchange&) = delete;
};

#endif
