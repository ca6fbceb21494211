// The OpenGL debug output of the suite's repeatability check (vtkParticleGLDebugLog, watched by
// vtkParticleImageComparison::TestRepeatable): a clean frame reports no error; a GL error made
// on purpose (binding a texture name that was never generated, GL_INVALID_OPERATION in a core
// profile) is counted and makes TestRepeatable fail although the two pictures are identical.
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkParticleGLDebugLog.h"
#include "vtkParticleImageComparison.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "vtkParticleCompat.h"

#include <cstdlib>
#include <iostream>

int TestGLDebugLog(int, char*[])
{
  vtkNew<vtkParticleSphereMapper> mapper;
  mapper->SetInputData(prTest::MakeLattice(6, 1.0, 3));
  mapper->SetRadius(0.3);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(120, 100);
  window->AddRenderer(renderer);
  window->Render();

  vtkParticleGLDebugLog* log = vtkParticleGLDebugLog::GetInstance();
  bool ok = prTest::Check(log->Watch(window), "the context has debug output (OpenGL 4.3)");
  ok &= prTest::Check(
    vtkParticleImageComparison::TestRepeatable(window, "clean frame"), "a clean frame passes");
  ok &= prTest::Check(log->GetNumberOfErrors() == 0, "a clean frame reports no error");

  // an error in every frame (an observer of the renderer's end): the check must fail
  vtkNew<vtkCallbackCommand> wrong;
  wrong->SetCallback(
    [](vtkObject*, unsigned long, void*, void*)
    {
      glBindTexture(GL_TEXTURE_2D, 987654321u);
      glGetError(); // VTK's own error checks must not see it first
    });
  renderer->AddObserver(vtkCommand::EndEvent, wrong);
  ok &= prTest::Check(!vtkParticleImageComparison::TestRepeatable(window, "frame with a GL error"),
    "a frame with a GL error fails the repeatability check");
  ok &= prTest::Check(log->GetNumberOfErrors() > 0, "the GL error is counted");
  std::cout << "errors reported: " << log->GetNumberOfErrors() << ", last: " << log->GetLastError()
            << "\n";
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
