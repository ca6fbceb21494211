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

#include "vtkObject.h"
#include "vtkParticleRenderingCoreModule.h" // for export macro
#include "vtkSmartPointer.h"                // for vtkSmartPointer

class vtkFloatArray;
class vtkMultiProcessController;

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

  /**
   * depth: the window depth per pixel (one component; values outside [0, 1] are clamped, NaN is
   * taken as 1, the background); payload: as many tuples, written by the process's nearest
   * fragment. Afterwards every process holds the nearest depth over all processes and, in
   * payload, the values of its process (at equal depth the lowest process id). Returns false,
   * changing nothing, for arrays that do not match. Collective (all processes must pass arrays
   * of the same size).
   */
  bool CompositeNearest(vtkFloatArray* depth, vtkFloatArray* payload);

protected:
  vtkParticleGBufferExchange();
  ~vtkParticleGBufferExchange() override;

  vtkSmartPointer<vtkMultiProcessController> Controller;

private:
  vtkParticleGBufferExchange(const vtkParticleGBufferExchange&) = delete;
  void operator=(const vtkParticleGBufferExchange&) = delete;
};

#endif
