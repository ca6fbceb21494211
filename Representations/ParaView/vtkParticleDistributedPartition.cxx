#include "vtkParticleDistributedPartition.h"

#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkParticlePartition.h"
#include "vtkParticleProcessReduction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkTransparentSphereMapper.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkParticleDistributedPartition);

//------------------------------------------------------------------------------
vtkParticleDistributedPartition::vtkParticleDistributedPartition() = default;

//------------------------------------------------------------------------------
vtkParticleDistributedPartition::~vtkParticleDistributedPartition() = default;

//------------------------------------------------------------------------------
void vtkParticleDistributedPartition::Update(vtkPolyData* particles, vtkDataObject* input,
  bool needed, const std::string& radiusArray, double radius, double radiusScale, double reach,
  const double sphereBounds[6])
{
  this->Particles = particles;
  this->Needed = needed;
  this->RadiusArray = radiusArray;
  this->Radius = radius;
  this->RadiusScale = radiusScale;
  this->Reach = reach;
  std::copy(sphereBounds, sphereBounds + 6, this->SphereBounds);
  std::ostringstream key;
  key.precision(17);
  key << needed << ";" << input << ";" << (input ? input->GetMTime() : 0) << ";" << radiusArray
      << ";" << radius << ";" << radiusScale << ";" << reach;
  this->InputKey = key.str();
  if (!this->PartitionedByView)
  {
    this->PartitionAlone();
  }
  this->UpdateColumnLayers();
}

//------------------------------------------------------------------------------
void vtkParticleDistributedPartition::PartitionAlone()
{
  this->Partitioned = this->PartitionParticles();
  this->MarkProp();
}

//------------------------------------------------------------------------------
void vtkParticleDistributedPartition::PartitionTogether(
  const std::vector<vtkParticleDistributedPartition*>& partitions)
{
  std::vector<vtkParticlePartition*> parts;
  std::vector<vtkParticlePartition::vtkParticleSet> sets;
  for (vtkParticleDistributedPartition* p : partitions)
  {
    parts.push_back(p->Partition);
    sets.push_back({ p->Particles, p->RadiusArray.empty() ? nullptr : p->RadiusArray.c_str(),
      p->Radius, p->RadiusScale, p->Reach, p->SphereBounds });
  }
  const bool partitioned = vtkParticlePartition::PartitionTogether(parts, sets);
  for (vtkParticleDistributedPartition* p : partitions)
  {
    p->Partitioned = partitioned;
    // (on its own again, it partitions anew)
    p->PartitionKey.clear();
    p->CopyDistribution();
    p->MarkProp();
  }
}

//------------------------------------------------------------------------------
void vtkParticleDistributedPartition::CopyDistribution()
{
  const std::vector<double>& distribution = this->Partition->GetDistribution();
  this->Distribution->SetNumberOfValues(static_cast<vtkIdType>(distribution.size()));
  std::copy(distribution.begin(), distribution.end(), this->Distribution->GetPointer(0));
}

//------------------------------------------------------------------------------
bool vtkParticleDistributedPartition::TakeRedelivery()
{
  const bool redelivery = this->Redelivery;
  this->Redelivery = false;
  return redelivery;
}

//------------------------------------------------------------------------------
bool vtkParticleDistributedPartition::PartitionParticles()
{
  vtkPolyData* particles = this->Particles;
  const bool needed = this->Needed;
  auto controller = vtkMultiProcessController::GetGlobalController();
  const int size = controller ? controller->GetNumberOfProcesses() : 1;
  const vtkIdType localCount = particles ? particles->GetNumberOfPoints() : 0;
  if (size <= 1)
  {
    this->Distribution->SetNumberOfValues(5);
    const double values[5] = { double(localCount), double(localCount), 0.0, 0.0, 0.0 };
    std::copy(values, values + 5, this->Distribution->GetPointer(0));
    return false;
  }
  if (!vtkParticleProcessReduction::StaleOnAnyProcess(this->InputKey, this->PartitionKey))
  {
    return needed && this->Partitioned;
  }
  if (!needed)
  {
    // the data stays where it is
    double local[5] = { double(localCount), double(localCount), 0.0, 0.0, 0.0 };
    this->Distribution->SetNumberOfValues(5 * size);
    controller->AllGather(local, this->Distribution->GetPointer(0), 5);
    return false;
  }
  const bool partitioned = this->Partition->Partition(particles,
    this->RadiusArray.empty() ? nullptr : this->RadiusArray.c_str(), this->Radius,
    this->RadiusScale, this->Reach, this->SphereBounds);
  this->CopyDistribution();
  return partitioned;
}

//------------------------------------------------------------------------------
void vtkParticleDistributedPartition::UpdateColumnLayers()
{
  vtkPolyData* particles = this->Particles;
  const std::string& radiusArray = this->RadiusArray;
  const double radius = this->Radius;
  const double* sphereBounds = this->SphereBounds;
  auto controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    this->ColumnLayers = 0.0;
    return;
  }
  // what vtkTransparentSphereMapper::GetEffectiveColumnLayers counts, over all processes: drawn
  // particles (finite centre, radius > 0 before the scale factor) and the union of the sphere
  // bounds
  vtkParticleProcessReduction::Extent extent;
  const vtkIdType n = particles && particles->GetPoints() ? particles->GetNumberOfPoints() : 0;
  vtkDataArray* radii = n > 0
    ? GetRadiusValues(
        particles, this->ColumnRadiusArray.empty() ? radiusArray : this->ColumnRadiusArray)
    : nullptr;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    particles->GetPoint(i, x);
    const double r = radii ? radii->GetComponent(i, 0) : radius;
    if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]) && std::isfinite(r) &&
      r > 0.0)
    {
      extent.Count += 1.0;
      extent.RadiusSum += r;
    }
  }
  if (vtkMath::AreBoundsInitialized(sphereBounds))
  {
    const double lo[3] = { sphereBounds[0], sphereBounds[2], sphereBounds[4] };
    const double hi[3] = { sphereBounds[1], sphereBounds[3], sphereBounds[5] };
    extent.AddBox(lo, hi);
  }
  extent.Reduce(controller);
  this->ColumnLayers =
    vtkTransparentSphereMapper::EstimateColumnLayers(extent.Count, extent.RadiusSum, extent.Bounds);
}

//------------------------------------------------------------------------------
vtkDoubleArray* vtkParticleDistributedPartition::GetDistribution()
{
  return this->Distribution;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkParticleDistributedPartition::PieceToDeliver(
  vtkPolyData* particles, double bounds[6])
{
  if (!this->Partitioned)
  {
    return particles;
  }
  // this process's box: IceT orders the processes' images by these boxes
  this->Partition->GetBox(bounds);
  return this->Partition->GetOutput();
}

//------------------------------------------------------------------------------
vtkInformationKeyMacro(vtkParticleDistributedPartition, BOXES, DoubleVector);

//------------------------------------------------------------------------------
void vtkParticleDistributedPartition::SetProp(vtkProp* prop)
{
  this->Prop = prop;
  this->MarkProp();
}

//------------------------------------------------------------------------------
void vtkParticleDistributedPartition::SetPropShown(bool shown)
{
  if (shown != this->PropShown)
  {
    this->PropShown = shown;
    this->MarkProp();
  }
}

//------------------------------------------------------------------------------
void vtkParticleDistributedPartition::MarkProp()
{
  if (!this->Prop)
  {
    return;
  }
  const std::vector<double> boxes = this->PropShown ? this->GetBoxes() : std::vector<double>();
  vtkInformation* keys = this->Prop->GetPropertyKeys();
  if (boxes.empty())
  {
    if (keys && keys->Has(BOXES()))
    {
      keys->Remove(BOXES());
    }
    return;
  }
  if (!keys)
  {
    vtkNew<vtkInformation> created;
    this->Prop->SetPropertyKeys(created);
    keys = created;
  }
  keys->Set(BOXES(), boxes.data(), static_cast<int>(boxes.size()));
}

//------------------------------------------------------------------------------
std::vector<double> vtkParticleDistributedPartition::GetBoxes()
{
  return this->Partitioned ? this->Partition->GetBoxes() : std::vector<double>();
}

//------------------------------------------------------------------------------
vtkPolyData* vtkParticleDistributedPartition::PieceToDraw(vtkPolyData* delivered, double clipBox[6])
{
  vtkMath::UninitializeBounds(clipBox);
  if (this->Partitioned)
  {
    // each process draws its box; the ghost copies draw the parts of the spheres in it
    this->Partition->GetBox(clipBox);
    return delivered;
  }
  auto ghosts = vtkUnsignedCharArray::SafeDownCast(
    delivered->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  if (!ghosts)
  {
    return delivered;
  }
  // partitioned particles gathered elsewhere (a client rendering locally): without the boxes
  // the ghost copies would draw their spheres twice
  if (this->OwnedData && this->OwnedDataSource == delivered &&
    this->OwnedDataTime == delivered->GetMTime())
  {
    return this->OwnedData;
  }
  vtkNew<vtkIdList> owned;
  for (vtkIdType i = 0; i < ghosts->GetNumberOfTuples(); ++i)
  {
    if (!(ghosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT))
    {
      owned->InsertNextId(i);
    }
  }
  this->OwnedData = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(delivered->GetPoints() ? delivered->GetPoints()->GetDataType() : VTK_FLOAT);
  if (delivered->GetPoints())
  {
    delivered->GetPoints()->GetPoints(owned, points);
  }
  this->OwnedData->SetPoints(points);
  vtkNew<vtkIdList> destination;
  destination->SetNumberOfIds(owned->GetNumberOfIds());
  std::iota(destination->GetPointer(0), destination->GetPointer(0) + owned->GetNumberOfIds(), 0);
  this->OwnedData->GetPointData()->CopyAllocate(delivered->GetPointData(), owned->GetNumberOfIds());
  this->OwnedData->GetPointData()->CopyData(delivered->GetPointData(), owned, destination);
  this->OwnedData->GetPointData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  this->OwnedDataSource = delivered;
  this->OwnedDataTime = delivered->GetMTime();
  return this->OwnedData;
}

//------------------------------------------------------------------------------
void vtkParticleDistributedPartition::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Partitioned: " << this->Partitioned << "\n";
  os << indent << "PartitionedByView: " << this->PartitionedByView << "\n";
  os << indent << "ColumnLayers: " << this->ColumnLayers << "\n";
  os << indent << "Partition:\n";
  this->Partition->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
vtkDataArray* vtkParticleDistributedPartition::GetRadiusValues(
  vtkPolyData* particles, const std::string& name)
{
  vtkDataArray* radii =
    (particles && particles->GetPoints() && particles->GetNumberOfPoints() > 0 && !name.empty())
    ? particles->GetPointData()->GetArray(name.c_str())
    : nullptr;
  return radii && radii->GetNumberOfComponents() == 1 ? radii : nullptr;
}
