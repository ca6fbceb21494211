// Baseline test of the sphere imposter core: radii from a point array, colours from scalars
// through a lookup table, spheres intersecting each other and a polygonal plane (depth writes),
// perspective projection with spheres far off-axis (silhouettes must not be clipped).
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestParticleSphereMapper(int argc, char* argv[])
{
  vtkSmartPointer<vtkPolyData> particles = prTest::MakeLattice(5, 1.0, 7);

  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();
  vtkNew<vtkParticleSphereMapper> mapper;
  mapper->SetInputData(particles);
  mapper->SetRadiusArrayName("radius");
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(0, 12);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.4);
  actor->GetProperty()->SetSpecularPower(30);

  // an opaque polygon cutting through the cloud
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1, -1, 2);
  plane->SetPoint1(5, -1, 2);
  plane->SetPoint2(-1, 5, 2.6);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> planeActor;
  planeActor->SetMapper(planeMapper);
  planeActor->GetProperty()->SetColor(0.85, 0.85, 0.8);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AddActor(planeActor);
  renderer->SetBackground(0.1, 0.1, 0.15);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 400);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(9, -6, 10);
  camera->SetFocalPoint(2, 2, 2);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(60); // wide angle: strong perspective at the image borders
  renderer->ResetCameraClippingRange();
  window->Render();

  return prTest::CompareWithBaseline(argc, argv, window) ? EXIT_SUCCESS : EXIT_FAILURE;
}
