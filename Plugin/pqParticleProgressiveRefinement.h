/**
 * @class   pqParticleProgressiveRefinement
 * @brief   keeps rendering a Particle Render View while its S-NDF shading refines (GUI only)
 *
 * vtkSNDFRenderPass adds SamplesPerFrame jittered samples per pixel with each still render of a
 * view that holds still. ParaView 5.11 renders a view only when something changed (its own
 * progressive loop, pqViewStreamingBehavior, serves OSPRay and streaming and cannot be asked by a
 * plugin), so this auto-start object of the plugin renders a Particle Render View again after
 * each still render, through pqView::render() (deferred to the event loop: the GUI stays
 * responsive and any user action comes first). In a builtin session (the GUI's process renders)
 * it goes on while the view's sample count (information property SNDFNumberOfSamples) grows and
 * stays below TargetSamples; a render that added no sample (the pass shows the plain image, e.g.
 * translucent particles) ends the loop. With a remote server, whose pass the client cannot see,
 * it renders ceil(TargetSamples / SamplesPerFrame) times after the render of a change. Interactive
 * renders, "S-NDF Converge Still Renders" (every still render converges by itself) and views with
 * S-NDF shading off are left alone. Every still render it did not ask for (a camera, data or
 * setting change) starts the count again.
 *
 * In pvpython and pvbatch there is no such loop: Render() adds one step, or converges at once
 * with "S-NDF Converge Still Renders".
 */
#ifndef pqParticleProgressiveRefinement_h
#define pqParticleProgressiveRefinement_h

#include <QMap>
#include <QObject>
#include <QPointer>

class pqView;
class vtkObject;

class pqParticleProgressiveRefinement : public QObject
{
  Q_OBJECT
  typedef QObject Superclass;

public:
  pqParticleProgressiveRefinement(QObject* parent = nullptr);
  ~pqParticleProgressiveRefinement() override;

  void onStartup();
  void onShutdown();

private Q_SLOTS:
  void onViewAdded(pqView* view);
  void onViewRemoved(pqView* view);

private:
  Q_DISABLE_COPY(pqParticleProgressiveRefinement)

  // the view proxy's vtkCommand::EndEvent (call data: int interactive)
  void onRenderEnded(vtkObject* caller, unsigned long, void* callData);

  struct ViewState
  {
    QPointer<pqView> View;
    unsigned long Observer = 0;
    int Renders = 0;    // remote: renders asked for since the last render that was not
    int Samples = 0;    // builtin: the samples after the last render
    bool Asked = false; // a render asked for is pending
  };
  QMap<vtkObject*, ViewState> Views;
};

#endif
