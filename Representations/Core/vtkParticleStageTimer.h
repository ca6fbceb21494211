/**
 * @class   vtkParticleStageTimer
 * @brief   GPU times of a pass's stages with OpenGL timer queries (GL_TIME_ELAPSED)
 *
 * A pass with N stages calls Begin(stage) / End() around each stage's GL work in a frame (a
 * stage may run several times per frame: its times add up) and StartFrame() before the first
 * one. The results are read lazily -- Seconds(stage) waits for the queries of the last frame --
 * so timing costs no stall unless asked. With `on` false every call does nothing. Needs a
 * current context for every call but the constructor; Release() deletes unread queries.
 * Used by vtkSNDFRenderPass and vtkPointAOPass.
 */
#ifndef vtkParticleStageTimer_h
#define vtkParticleStageTimer_h

#include "vtkParticleRenderingCoreModule.h" // for export macro

#include <vector> // for std::vector

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleStageTimer
{
public:
  explicit vtkParticleStageTimer(int stages);

  /**
   * A new frame: the last frame's queries are read first (so Seconds() keeps them) when asked
   * for; otherwise deleted.
   */
  void StartFrame(bool on);
  void Begin(int stage);
  void End();

  /**
   * GPU seconds of the stage in the last timed frame (0 when it did not run).
   */
  double Seconds(int stage);

  /**
   * Delete the queries not read yet (the context must be current, or gone with them: then
   * nothing is deleted).
   */
  void Release(bool contextCurrent);

private:
  void Read();
  bool On = false;
  bool Running = false;
  bool Read_ = true;
  std::vector<std::vector<unsigned int>> Queries;
  std::vector<double> Times;
};

#endif
