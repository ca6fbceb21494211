/**
 * @class   vtkParticleFrameBudget
 * @brief   picks a technique's quality level for a frame from the time the frame may take
 *
 * Every technique of the plugin has an exact setting (the one its accuracy tests check) and
 * cheaper ones for frames drawn while the camera moves: a ladder of levels 0 (cheapest) ..
 * n - 1 (exact). Before its work in a frame the technique asks this object which level to draw
 * (BeginFrame) and brackets its GL work with BeginFrame / EndFrame, so the GPU time of every level
 * it draws is measured here with timer queries (GL_TIMESTAMP, read without a stall one or more
 * frames later) on this machine, for this data and view.
 *
 * The time a frame may take is VTK's own: 1 / vtkRenderWindow::GetDesiredUpdateRate(). VTK's
 * interactor styles set the interactor's DesiredUpdateRate (15 frames/s) while the mouse moves
 * and its StillUpdateRate (0.0001) when it stops; ParaView's vtkPVRenderView sets 5 for its
 * interactive renders and 0.002 for its still renders, on every rank; a window nobody changed
 * has 0.0001. The same rate drives vtkGPUVolumeRayCastMapper::AutoAdjustSampleDistances.
 *
 * The choice (ChooseLevel), with Quality ADAPTIVE (default):
 * - a frame allowed at least StillFrameTime seconds (default 1) is a still frame: the exact
 *   level, whatever it costs, so the still frame after an interactive sequence is the frame a
 *   still render gives directly;
 * - otherwise the most accurate level whose measured time fits the frame time (a level not
 *   measured yet is not assumed to fit); when none fits, the fastest level measured, the more
 *   accurate of equal times (a level meant to be cheap need not be cheaper on every scene: the
 *   per-sphere AO retrieval costs more than per fragment where spheres cover few pixels); the
 *   cheapest level is drawn once to measure it, and a level between the cheapest and the exact
 *   one once when the level below it fits. The exact level is measured by the still frames,
 *   so a scene that is cheap enough stays exact while moving.
 * With ChooseByTime off, an interactive ADAPTIVE frame draws the cheapest level without looking
 * at measured times: the processes of a distributed render, each with its own timings, then draw
 * the same level (ParaView's Particles representation and Particle Render View turn it off under
 * MPI; still frames stay exact).
 * EXACT always draws the exact level; INTERACTIVE always the cheapest (tests, benchmarks, or a
 * user who wants the fast picture). The technique's measured time is compared with the whole
 * frame's time: the opaque scene around it is not subtracted.
 */
#ifndef vtkParticleFrameBudget_h
#define vtkParticleFrameBudget_h

#include "vtkObject.h"
#include "vtkParticleRenderingCoreModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkRenderer;
class vtkWindow;

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleFrameBudget : public vtkObject
{
public:
  static vtkParticleFrameBudget* New();
  vtkTypeMacro(vtkParticleFrameBudget, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Qualities
  {
    ADAPTIVE = 0,   // exact on still frames, the most accurate level that fits while moving
    EXACT = 1,      // always the exact level
    INTERACTIVE = 2 // always the cheapest level
  };

  ///@{
  /**
   * ADAPTIVE (default), EXACT or INTERACTIVE (see the class description).
   */
  vtkSetClampMacro(Quality, int, ADAPTIVE, INTERACTIVE);
  vtkGetMacro(Quality, int);
  ///@}

  ///@{
  /**
   * Whether an interactive ADAPTIVE frame chooses its level by the measured times (default on)
   * or always draws the cheapest level (off: the same level on every process of a distributed
   * render).
   */
  vtkSetMacro(ChooseByTime, bool);
  vtkGetMacro(ChooseByTime, bool);
  vtkBooleanMacro(ChooseByTime, bool);
  ///@}

  ///@{
  /**
   * A frame allowed at least this many seconds is a still frame (default 1).
   */
  vtkSetClampMacro(StillFrameTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(StillFrameTime, double);
  ///@}

  /**
   * The seconds a frame of this renderer's window may take: 1 / DesiredUpdateRate (infinite when
   * the rate is 0 or there is no window).
   */
  static double GetFrameTime(vtkRenderer* ren);

  /**
   * The level (0 .. numberOfLevels - 1, the last exact) to draw in a frame that may take
   * `frameTime` seconds. Remembered as the last choice.
   */
  int ChooseLevel(double frameTime, int numberOfLevels);

  /**
   * A measured GPU time of a level (seconds). A time below the level's estimate replaces it; a
   * time above moves it half way (the slow outliers are frames that compile shaders or build
   * volumes: one of them does not make a level look unaffordable for long). Negative and
   * non-finite times are ignored.
   */
  void ReportTime(int level, double seconds);

  /**
   * The current estimate of a level's time in seconds, or -1 when it was never measured.
   */
  double GetMeasuredTime(int level);

  /**
   * Forget the measured times (the technique's cost changed by orders: a new data set, another
   * method).
   */
  void ForgetTimes();

  /**
   * ChooseLevel(GetFrameTime(ren), numberOfLevels) after reading the finished timer queries of
   * earlier frames (a current context is needed).
   */
  int ChooseFrameLevel(vtkRenderer* ren, int numberOfLevels);

  /**
   * ChooseFrameLevel, then start timing this frame's GL work.
   */
  int BeginFrame(vtkRenderer* ren, int numberOfLevels);

  /**
   * Start timing the GL work of the last chosen level (BeginFrame does it; for a technique that
   * chooses before work it does not want timed). The finished queries of earlier frames are read
   * first.
   */
  void StartTiming();

  /**
   * End the timing started by BeginFrame or StartTiming (nothing when none is running).
   */
  void EndFrame();

  ///@{
  /**
   * The last choice: the level, the number of levels, the frame time it was made for, and
   * whether that frame was interactive (shorter than StillFrameTime).
   */
  vtkGetMacro(LastLevel, int);
  vtkGetMacro(LastNumberOfLevels, int);
  vtkGetMacro(LastFrameTime, double);
  bool GetLastFrameInteractive() { return this->LastFrameTime < this->StillFrameTime; }
  ///@}

  /**
   * One line for users: the level drawn in the last frame (named by `levelNames`, one name per
   * level separated by '|'), why, and the measured times.
   */
  std::string GetLastChoiceText(const std::string& levelNames);

  /**
   * Delete the timer queries (the window's context must be current, or gone).
   */
  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkParticleFrameBudget();
  ~vtkParticleFrameBudget() override;

  int Quality = ADAPTIVE;
  bool ChooseByTime = true;
  double StillFrameTime = 1.0;
  int LastLevel = 0;
  int LastNumberOfLevels = 1;
  double LastFrameTime = 0.0;

private:
  vtkParticleFrameBudget(const vtkParticleFrameBudget&) = delete;
  void operator=(const vtkParticleFrameBudget&) = delete;

  void ReadFinishedTimers();

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
