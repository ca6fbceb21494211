#include "pqParticleProgressiveRefinement.h"

#include "pqApplicationCore.h"
#include "pqServer.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkCommand.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMViewProxy.h"

#include <QTimer>

#include <algorithm>
#include <string>

namespace
{
int IntProperty(vtkSMProxy* proxy, const char* name, int fallback)
{
  return proxy && proxy->GetProperty(name) ? vtkSMPropertyHelper(proxy, name).GetAsInt() : fallback;
}
}

//------------------------------------------------------------------------------
pqParticleProgressiveRefinement::pqParticleProgressiveRefinement(QObject* parent)
  : Superclass(parent)
{
}

//------------------------------------------------------------------------------
pqParticleProgressiveRefinement::~pqParticleProgressiveRefinement()
{
  this->onShutdown();
}

//------------------------------------------------------------------------------
void pqParticleProgressiveRefinement::onStartup()
{
  pqApplicationCore* core = pqApplicationCore::instance();
  pqServerManagerModel* model = core ? core->getServerManagerModel() : nullptr;
  if (!model)
  {
    return;
  }
  QObject::connect(model, &pqServerManagerModel::viewAdded, this,
    &pqParticleProgressiveRefinement::onViewAdded, Qt::UniqueConnection);
  QObject::connect(model, &pqServerManagerModel::viewRemoved, this,
    &pqParticleProgressiveRefinement::onViewRemoved, Qt::UniqueConnection);
  for (pqView* view : model->findItems<pqView*>())
  {
    this->onViewAdded(view);
  }
}

//------------------------------------------------------------------------------
void pqParticleProgressiveRefinement::onShutdown()
{
  for (auto it = this->Views.begin(); it != this->Views.end(); ++it)
  {
    if (it.value().View)
    {
      it.key()->RemoveObserver(it.value().Observer);
    }
  }
  this->Views.clear();
}

//------------------------------------------------------------------------------
void pqParticleProgressiveRefinement::onViewAdded(pqView* view)
{
  vtkSMViewProxy* proxy = view ? view->getViewProxy() : nullptr;
  // (pqView::getViewType() is "RenderView": ParaView wraps every render view proxy alike)
  if (!proxy || !proxy->GetXMLName() || std::string(proxy->GetXMLName()) != "ParticleRenderView" ||
    this->Views.contains(proxy))
  {
    return;
  }
  ViewState state;
  state.View = view;
  state.Observer =
    proxy->AddObserver(vtkCommand::EndEvent, this, &pqParticleProgressiveRefinement::onRenderEnded);
  this->Views.insert(proxy, state);
}

//------------------------------------------------------------------------------
void pqParticleProgressiveRefinement::onViewRemoved(pqView* view)
{
  vtkSMViewProxy* proxy = view ? view->getViewProxy() : nullptr;
  auto it = this->Views.find(proxy);
  if (it != this->Views.end())
  {
    proxy->RemoveObserver(it.value().Observer);
    this->Views.erase(it);
  }
}

//------------------------------------------------------------------------------
void pqParticleProgressiveRefinement::onRenderEnded(
  vtkObject* caller, unsigned long, void* callData)
{
  auto it = this->Views.find(caller);
  if (it == this->Views.end() || !it.value().View)
  {
    return;
  }
  ViewState& state = it.value();
  vtkSMProxy* proxy = state.View->getProxy();
  const bool interactive = callData && *static_cast<int*>(callData) != 0;
  const bool asked = state.Asked;
  state.Asked = false;
  if (interactive)
  {
    return; // the plain image; the still render at the end of the interaction starts again
  }
  if (!IntProperty(proxy, "ScaleConsistentShading", 0) ||
    IntProperty(proxy, "SNDFConvergeStillRenders", 0))
  {
    state.Renders = 0;
    return;
  }
  const int target = std::max(1, IntProperty(proxy, "SNDFTargetSamples", 1));
  pqServer* server = state.View->getServer();
  if (server && !server->isRemote())
  {
    // builtin session: this process renders, and the view reports its samples. Go on until the
    // target; a render asked for that left the count where it was (the pass shows the plain
    // image: an unsupported scene) ends the loop. Fewer samples than before: a change restarted
    // the S-NDFs (its render may have merged with the one asked for): go on.
    proxy->UpdatePropertyInformation();
    const int samples = IntProperty(proxy, "SNDFNumberOfSamples", 0);
    const bool stalled = asked && samples == state.Samples;
    if (samples >= target || stalled)
    {
      return;
    }
    state.Samples = samples;
  }
  else
  {
    // remote rendering: the pass on the server is not seen from here (the client's renders
    // nothing); render as often as the samples need after the render of a change
    state.Renders = asked ? state.Renders + 1 : 0;
    const int perFrame = std::max(1, IntProperty(proxy, "SNDFSamplesPerFrame", 1));
    if (state.Renders >= (target + perFrame - 1) / perFrame)
    {
      return;
    }
  }
  state.Asked = true;
  QPointer<pqView> view = state.View;
  QTimer::singleShot(0, view,
    [view]()
    {
      if (view)
      {
        view->render();
      }
    });
}
