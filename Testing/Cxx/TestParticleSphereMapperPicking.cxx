// Picking with the hardware selector in a scene of particles and a polygonal plane:
// - a cell selection over a single sphere's pixels returns the particles' actor and the vertex
//   cell holding that particle (the cells list the particles in another order);
// - a point selection returns the particle index;
// - on data without cells (as ParaView delivers point data) both return the particle index, also
//   for ids that need more than one byte;
// - selecting over the plane returns the plane's actor, not the particles (other props unharmed).
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"

namespace
{
// Selects the square [x-h, x+h] x [y-h, y+h] and returns the ids selected on `prop` (empty when
// that prop is not in the selection).
std::vector<vtkIdType> Select(vtkRenderer* renderer, int association, vtkProp* prop, int x, int y,
  int h, bool& otherPropSelected)
{
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  selector->SetFieldAssociation(association);
  selector->SetArea(x - h, y - h, x + h, y + h);
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  std::vector<vtkIdType> ids;
  otherPropSelected = false;
  for (unsigned int n = 0; selection && n < selection->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = selection->GetNode(n);
    vtkProp* selected = vtkProp::SafeDownCast(node->GetProperties()->Get(vtkSelectionNode::PROP()));
    if (selected != prop)
    {
      otherPropSelected = true;
      continue;
    }
    vtkIdTypeArray* list = vtkArrayDownCast<vtkIdTypeArray>(node->GetSelectionList());
    for (vtkIdType i = 0; list && i < list->GetNumberOfTuples(); ++i)
    {
      ids.push_back(list->GetValue(i));
    }
  }
  return ids;
}
}

int TestParticleSphereMapperPicking(int argc, char* argv[])
{
  (void)argc;
  (void)argv;
  // three particles in a row at x = -3, 0, 3; the cells list them in another order, so a
  // cell-index-based id would be wrong
  vtkNew<vtkPolyData> particles;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-3, 0, 0);
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(3, 0, 0);
  particles->SetPoints(points);
  vtkNew<vtkCellArray> verts;
  for (vtkIdType id : { 2, 0, 1 })
  {
    verts->InsertNextCell(1, &id);
  }
  particles->SetVerts(verts);
  vtkNew<vtkParticleSphereMapper> mapper;
  mapper->SetInputData(particles);
  mapper->SetRadius(1.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  // a plane behind the particles, visible above them
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-6, -1, -3);
  plane->SetPoint1(6, -1, -3);
  plane->SetPoint2(-6, 5, -3);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> planeActor;
  planeActor->SetMapper(planeMapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AddActor(planeActor);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 200);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 20);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelProjection(true);
  camera->SetParallelScale(5); // 200 px = 10 units: 20 px per unit
  renderer->ResetCameraClippingRange();
  window->Render();

  bool ok = true;
  bool other = false;
  // the right particle (index 2) is centred at pixel (150 + 60, 100)
  std::vector<vtkIdType> cells =
    Select(renderer, vtkDataObject::FIELD_ASSOCIATION_CELLS, actor, 210, 100, 4, other);
  ok &= prTest::Check(cells.size() == 1 && cells[0] == 0,
    "cell selection over particle 2 (vertex cell 0) returned " + std::to_string(cells.size()) +
      " ids" + (cells.empty() ? "" : ", first " + std::to_string(cells[0])));
  ok &= prTest::Check(!other, "cell selection over particle 2 selected another prop");

  std::vector<vtkIdType> pointIds =
    Select(renderer, vtkDataObject::FIELD_ASSOCIATION_POINTS, actor, 90, 100, 4, other);
  ok &= prTest::Check(pointIds.size() == 1 && pointIds[0] == 0,
    "point selection over particle 0 returned " + std::to_string(pointIds.size()) + " ids" +
      (pointIds.empty() ? "" : ", first " + std::to_string(pointIds[0])));

  // above the particles only the plane is visible
  std::vector<vtkIdType> none =
    Select(renderer, vtkDataObject::FIELD_ASSOCIATION_CELLS, actor, 150, 170, 4, other);
  ok &= prTest::Check(none.empty(), "selection over the plane returned particles");
  ok &= prTest::Check(other, "selection over the plane did not select the plane");

  // 1000 particles without any cell (as ParaView delivers point data): a 40 x 25 grid filling the
  // view; cell and point selections over particle 837 (column 37, row 20) must both return 837
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> cloudPoints;
  for (int j = 0; j < 25; ++j)
  {
    for (int i = 0; i < 40; ++i)
    {
      cloudPoints->InsertNextPoint(-7.5 + 0.25 * i + 0.125, -5 + 0.4 * j + 0.2, 0);
    }
  }
  cloud->SetPoints(cloudPoints);
  mapper->SetInputData(cloud);
  mapper->SetRadius(0.12);
  renderer->RemoveActor(planeActor);
  camera->SetParallelScale(5);
  renderer->ResetCameraClippingRange();
  window->SetSize(300, 200); // 20 px per unit: particle (i, j) at pixel (5 i + 2.5, 8 j + 4)
  window->Render();
  const int px = 5 * 37 + 2, py = 8 * 20 + 4;
  cells = Select(renderer, vtkDataObject::FIELD_ASSOCIATION_CELLS, actor, px, py, 1, other);
  ok &= prTest::Check(cells.size() == 1 && cells[0] == 837,
    "cell-less data: cell selection returned " + std::to_string(cells.size()) + " ids" +
      (cells.empty() ? "" : ", first " + std::to_string(cells[0])) + ", expected 837");
  pointIds = Select(renderer, vtkDataObject::FIELD_ASSOCIATION_POINTS, actor, px, py, 1, other);
  ok &= prTest::Check(pointIds.size() == 1 && pointIds[0] == 837,
    "cell-less data: point selection returned " + std::to_string(pointIds.size()) + " ids" +
      (pointIds.empty() ? "" : ", first " + std::to_string(pointIds[0])) + ", expected 837");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
