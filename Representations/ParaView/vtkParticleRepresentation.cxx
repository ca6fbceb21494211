#include "vtkParticleRepresentation.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkCommunicator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMetaballMapper.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkParticleDistributedPartition.h"
#include "vtkParticleDistributedVolumes.h"
#include "vtkParticleFrameBudget.h"
#include "vtkParticleProcessReduction.h"
#include "vtkParticleRenderView.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkTransform.h"
#include "vtkTransparentSphereMapper.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkParticleRepresentation);

//------------------------------------------------------------------------------
vtkParticleRepresentation::vtkParticleRepresentation()
{
  this->Mapper = NewMapper(this->Technique);
  // the translucency defaults are the mapper's own
  if (auto* transparent = vtkTransparentSphereMapper::SafeDownCast(this->Mapper))
  {
    this->DensityModel = transparent->GetDensityModel();
    this->HollowFraction = transparent->GetHollowFraction();
    this->VolumeMix = transparent->GetVolumeMix();
    this->EarlyTermination = transparent->GetEarlyTermination();
    this->OverlapCompositing = transparent->GetOverlapCompositing();
    this->FragmentListMemory = transparent->GetFragmentListMemory();
    this->OverlapTolerance = transparent->GetOverlapTolerance();
    this->OpacityReference = transparent->GetOpacityReference();
  }
  this->Actor->SetMapper(this->Mapper);
  // (the partition's boxes travel on the actor to the view's compositing order)
  this->DistributedPartition->SetProp(this->Actor);
  this->DistributedPartition->SetPropShown(true);
  // Colours come from the lookup table's range (set by ParaView), as for every representation.
  this->Mapper->SetUseLookupTableScalarRange(1);
  this->Mapper->SetScalarVisibility(0);
  this->ProcessedData = MakeParticles(nullptr, false);
  // ParaView listens to the progress of the representation (an algorithm registered with the
  // session's progress handler), not to its mapper's: pass the mapper's long work on.
  this->Mapper->AddObserver(
    vtkCommand::ProgressEvent, this, &vtkParticleRepresentation::ForwardMapperProgress);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkParticleSphereMapper> vtkParticleRepresentation::NewMapper(int technique)
{
  switch (technique)
  {
    case METABALLS:
      return vtkSmartPointer<vtkMetaballMapper>::New();
    case SPHERES:
    default:
      return vtkSmartPointer<vtkTransparentSphereMapper>::New();
  }
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetTechnique(int technique)
{
  if (technique != SPHERES && technique != METABALLS)
  {
    vtkErrorMacro(<< "Unknown particle technique " << technique << ": keeping " << this->Technique
                  << ".");
    return;
  }
  if (technique == this->Technique)
  {
    return;
  }
  vtkSmartPointer<vtkParticleSphereMapper> previous = this->Mapper;
  this->Technique = technique;
  this->Mapper = NewMapper(technique);
  // what the representation does not hold itself lives on the previous mapper: carry it over
  this->Mapper->SetInputDataObject(previous->GetInputDataObject(0, 0));
  this->Mapper->SetRadius(previous->GetRadius());
  this->Mapper->SetRadiusScaleFactor(previous->GetRadiusScaleFactor());
  this->Mapper->SetLookupTable(previous->GetLookupTable());
  this->Mapper->SetColorMode(previous->GetColorMode());
  this->Mapper->SetUseLookupTableScalarRange(previous->GetUseLookupTableScalarRange());
  this->Mapper->SetScalarVisibility(previous->GetScalarVisibility());
  this->Mapper->SetScalarMode(previous->GetScalarMode());
  this->Mapper->SelectColorArray(previous->GetArrayName());
  this->Mapper->AddObserver(
    vtkCommand::ProgressEvent, this, &vtkParticleRepresentation::ForwardMapperProgress);
  this->ApplyMapperSettings();
  this->ApplyOpacity();
  this->Mapper->SetPositionBounds(this->PositionBounds);
  this->Actor->SetMapper(this->Mapper);
  this->MarkModified(); // bounds, and the partition of metaballs under MPI
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::ApplyMapperSettings()
{
  this->UpdateMapperRadiusArray();
  this->UpdateMapperOpacityArray();
  this->Mapper->GetFrameBudget()->SetQuality(this->InteractiveQuality);
  // under MPI every process must draw the same level: the cheapest while moving, not each
  // process's own choice by its own timings
  this->Mapper->GetFrameBudget()->SetChooseByTime(!vtkParticleProcessReduction::Distributed());
  if (auto* transparent = vtkTransparentSphereMapper::SafeDownCast(this->Mapper))
  {
    transparent->SetDensityModel(this->DensityModel);
    transparent->SetHollowFraction(this->HollowFraction);
    transparent->SetVolumeMix(this->VolumeMix);
    transparent->SetEarlyTermination(this->EarlyTermination);
    transparent->SetOverlapCompositing(this->OverlapCompositing);
    transparent->SetFragmentListMemory(this->FragmentListMemory);
    transparent->SetOverlapTolerance(this->OverlapTolerance);
    transparent->SetAutomaticErrorTolerance(this->AutomaticErrorTolerance);
    transparent->SetAutomaticPixelShare(this->AutomaticPixelShare);
    transparent->SetOpacityReference(this->OpacityReference);
    // 0: the mapper estimates from its own particles (one process)
    transparent->SetColumnLayers(this->DistributedPartition->GetColumnLayers());
  }
  if (auto* metaballs = vtkMetaballMapper::SafeDownCast(this->Mapper))
  {
    metaballs->SetInfluenceFactor(this->InfluenceFactor);
    metaballs->SetIsoValue(this->IsoValue);
    metaballs->SetTolerance(this->MetaballTolerance);
    metaballs->SetRefinementSteps(this->RefinementSteps);
    metaballs->SetIterationLimit(this->IterationLimit);
    metaballs->SetMaximumNumberOfNeighbors(this->MaximumNumberOfNeighbors);
    metaballs->SetMethod(this->MetaballMethod);
    metaballs->SetWalkingTolerance(this->WalkingTolerance);
    metaballs->SetMaximumPasses(this->MaximumPasses);
    metaballs->SetTimeBudget(this->TimeBudget);
  }
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetInfluenceFactor(double factor)
{
  this->InfluenceFactor = factor;
  this->ApplyMapperSettings();
  this->MarkModified(); // the bounds grow with it
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetIsoValue(double value)
{
  this->IsoValue = value;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetMetaballTolerance(double tolerance)
{
  this->MetaballTolerance = tolerance;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetRefinementSteps(int steps)
{
  this->RefinementSteps = steps;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetIterationLimit(int limit)
{
  this->IterationLimit = limit;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetMaximumNumberOfNeighbors(int count)
{
  this->MaximumNumberOfNeighbors = count;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetMetaballMethod(int method)
{
  this->MetaballMethod = method;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetWalkingTolerance(double tolerance)
{
  this->WalkingTolerance = tolerance;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetMaximumPasses(int passes)
{
  this->MaximumPasses = passes;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetTimeBudget(double seconds)
{
  this->TimeBudget = seconds;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::ForwardMapperProgress(vtkObject*, unsigned long, void* callData)
{
  const char* text = this->Mapper->GetProgressText();
  if (!text || !*text)
  {
    return; // the mapper's own pipeline update, not rendering work
  }
  this->SetProgressText(text);
  this->UpdateProgress(*static_cast<double*>(callData));
  this->SetProgressText(nullptr);
}

//------------------------------------------------------------------------------
vtkParticleRepresentation::~vtkParticleRepresentation() = default;

//------------------------------------------------------------------------------
int vtkParticleRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  // Representations have no input on the client in client-server mode.
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkParticleRepresentation::MakeParticles(
  vtkDataObject* input, bool vertexCells)
{
  std::vector<vtkDataSet*> leaves;
  if (auto dataSet = vtkDataSet::SafeDownCast(input))
  {
    leaves.push_back(dataSet);
  }
  else if (vtkCompositeDataSet::SafeDownCast(input))
  {
    leaves = vtkCompositeDataSet::GetDataSets<vtkDataSet>(input);
  }

  std::vector<vtkSmartPointer<vtkPolyData>> pieces;
  for (vtkDataSet* leaf : leaves)
  {
    const vtkIdType numPts = leaf ? leaf->GetNumberOfPoints() : 0;
    if (numPts == 0)
    {
      continue;
    }
    auto piece = vtkSmartPointer<vtkPolyData>::New();
    auto pointSet = vtkPointSet::SafeDownCast(leaf);
    if (pointSet && pointSet->GetPoints())
    {
      piece->SetPoints(pointSet->GetPoints()); // shared, not copied
    }
    else
    {
      // implicit points (image data, rectilinear grid, ...)
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      points->SetNumberOfPoints(numPts);
      double p[3];
      for (vtkIdType i = 0; i < numPts; ++i)
      {
        leaf->GetPoint(i, p);
        points->SetPoint(i, p);
      }
      piece->SetPoints(points);
    }
    piece->GetPointData()->ShallowCopy(leaf->GetPointData());
    pieces.push_back(piece);
  }

  vtkSmartPointer<vtkPolyData> particles;
  if (pieces.empty())
  {
    // Empty, but with a points object: ParaView's redistribution filters (ordered compositing
    // in parallel) crash on a polydata without one.
    particles = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints> points;
    particles->SetPoints(points);
  }
  else if (pieces.size() == 1)
  {
    particles = pieces.front();
  }
  else
  {
    // Keeps the point arrays common to all pieces.
    vtkNew<vtkAppendPolyData> append;
    for (auto& piece : pieces)
    {
      append->AddInputData(piece);
    }
    append->Update();
    particles = append->GetOutput();
  }

  const vtkIdType numPts = particles->GetNumberOfPoints();
  if (vertexCells && numPts > 0)
  {
    vtkNew<vtkCellArray> verts;
    if (numPts < VTK_TYPE_INT32_MAX)
    {
      vtkNew<vtkTypeInt32Array> connectivity;
      connectivity->SetNumberOfValues(numPts);
      std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + numPts, 0);
      verts->SetData(1, connectivity);
    }
    else
    {
      vtkNew<vtkTypeInt64Array> connectivity;
      connectivity->SetNumberOfValues(numPts);
      std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + numPts, 0);
      verts->SetData(1, connectivity);
    }
    particles->SetVerts(verts);
  }
  return particles;
}

//------------------------------------------------------------------------------
int vtkParticleRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // No vertex cells: ParaView never redistributes these particles (the representation
  // partitions them itself, see vtkParticleDistributedPartition), and the mapper ignores cells.
  if (this->DistributedPartition->TakeRedelivery())
  {
    // the view partitioned these particles with its other Particles representations after they
    // were delivered: deliver again, nothing else changed (vtkParticleViewPartition)
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  this->ProcessedData = MakeParticles(input, false);
  this->AddBoundingRadii(this->ProcessedData);
  // Distributed rendering: translucent spheres are partitioned here, in the pipeline, which
  // runs on every process together (a render pass may not: IceT runs it zero or more times)
  double bounds[6];
  this->ComputeSphereBounds(this->ProcessedData, bounds);
  this->UpdatePositionBounds();
  // Translucent spheres need the partition (ordered compositing of boxes); metaballs need every
  // particle whose influence reaches into the box (ghosts within k R) and a surface clipped to
  // it; opaque spheres composite by depth wherever they are.
  const bool needed =
    (this->IsTranslucent() && this->Technique == SPHERES) || this->Technique == METABALLS;
  const double reach = this->Technique == METABALLS ? this->InfluenceFactor : 1.0;
  // (ellipsoids count in the column-layer estimate with sqrt(a b c / a_max))
  this->DistributedPartition->SetColumnRadiusArray(this->EllipsoidsInEffect(this->ProcessedData) &&
        this->ProcessedData->GetPointData()->GetArray("ParticleColumnRadius")
      ? "ParticleColumnRadius"
      : "");
  this->DistributedPartition->Update(this->ProcessedData, input, needed,
    this->EffectiveRadiusArray(this->ProcessedData), this->Mapper->GetRadius(),
    this->Mapper->GetRadiusScaleFactor(), reach, bounds);
  this->ApplyMapperSettings(); // the column layers of all processes
  this->UpdateOpacityArrayDataRange();
  this->UpdateMapperOpacityArray();
  this->WarnOpaqueMetaballs();
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::UpdatePositionBounds()
{
  // The finite centres of all processes' particles (collective; one process: its own), so that
  // every process uploads a particle's position with the same float rounding as one process
  // (vtkParticleSphereMapper::SetPositionBounds).
  vtkParticleProcessReduction::Extent extent;
  const vtkIdType n = this->ProcessedData ? this->ProcessedData->GetNumberOfPoints() : 0;
  if (n > 0)
  {
    // (ComputeSphereBounds cached them for these points)
    const double lo[3] = { this->CenterBounds[0], this->CenterBounds[2], this->CenterBounds[4] };
    const double hi[3] = { this->CenterBounds[1], this->CenterBounds[3], this->CenterBounds[5] };
    extent.AddBox(lo, hi);
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    extent.Reduce(controller);
  }
  std::copy(extent.Bounds, extent.Bounds + 6, this->PositionBounds);
  if (!vtkMath::AreBoundsInitialized(this->PositionBounds))
  {
    vtkMath::UninitializeBounds(this->PositionBounds);
  }
  this->Mapper->SetPositionBounds(this->PositionBounds);
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::WarnOpaqueMetaballs()
{
  std::string warning;
  if (this->Technique == METABALLS && (this->Opacity < 1.0 || this->UseOpacityArray))
  {
    std::ostringstream text;
    text << "Metaballs are drawn opaque: "
         << (this->UseOpacityArray ? "the opacity array is" : "Opacity is")
         << " not applied (translucent metaballs are not implemented; Spheres draw translucency).";
    warning = text.str();
  }
  if (!warning.empty() && warning != this->OpacityWarning)
  {
    vtkWarningMacro(<< warning);
  }
  this->OpacityWarning = warning;
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::ComputeSphereBounds(vtkPolyData* particles, double bounds[6])
{
  vtkMath::UninitializeBounds(bounds);
  if (!particles || !particles->GetPoints() || particles->GetNumberOfPoints() == 0)
  {
    return;
  }
  // Bounds of the centres whose three coordinates are finite (the particles the mapper draws;
  // per-component finite ranges would let a point such as (1e30, 1e30, Inf) stretch them),
  // cached on the points' modification time.
  vtkDataArray* points = particles->GetPoints()->GetData();
  if (points != this->CenterBoundsArray || points->GetMTime() != this->CenterBoundsTime)
  {
    struct Partial
    {
      double B[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
        VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    };
    vtkSMPThreadLocal<Partial> partials;
    vtkSMPTools::For(0, points->GetNumberOfTuples(),
      [&](vtkIdType begin, vtkIdType end)
      {
        Partial& partial = partials.Local();
        double x[3];
        for (vtkIdType i = begin; i < end; ++i)
        {
          points->GetTuple(i, x);
          if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))
          {
            for (int k = 0; k < 3; ++k)
            {
              partial.B[2 * k] = std::min(partial.B[2 * k], x[k]);
              partial.B[2 * k + 1] = std::max(partial.B[2 * k + 1], x[k]);
            }
          }
        }
      });
    Partial all;
    for (const Partial& partial : partials)
    {
      for (int k = 0; k < 3; ++k)
      {
        all.B[2 * k] = std::min(all.B[2 * k], partial.B[2 * k]);
        all.B[2 * k + 1] = std::max(all.B[2 * k + 1], partial.B[2 * k + 1]);
      }
    }
    std::copy(all.B, all.B + 6, this->CenterBounds);
    this->CenterBoundsArray = points;
    this->CenterBoundsTime = points->GetMTime();
  }
  double centers[6];
  std::copy(this->CenterBounds, this->CenterBounds + 6, centers);
  for (int k = 0; k < 3; ++k)
  {
    if (!(centers[2 * k] <= centers[2 * k + 1]))
    {
      return;
    }
  }

  double maxRadius = this->Mapper->GetRadius();
  const std::string radiusArray = this->EffectiveRadiusArray(particles);
  if (!radiusArray.empty())
  {
    vtkDataArray* radii = particles->GetPointData()->GetArray(radiusArray.c_str());
    if (radii && radii->GetNumberOfComponents() == 1 && radii->GetNumberOfTuples() > 0)
    {
      double range[2];
      radii->GetFiniteRange(range, 0);
      maxRadius = range[0] <= range[1] ? std::max(0.0, range[1]) : 0.0;
    }
  }
  // (metaball surfaces reach the influence radius k R)
  const double reach = this->Technique == METABALLS ? this->InfluenceFactor : 1.0;
  const double grow = reach * maxRadius * std::abs(this->Mapper->GetRadiusScaleFactor());
  for (int k = 0; k < 3; ++k)
  {
    bounds[2 * k] = centers[2 * k] - grow;
    bounds[2 * k + 1] = centers[2 * k + 1] + grow;
  }
}

//------------------------------------------------------------------------------
int vtkParticleRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request_type, vtkInformation* inInfo, vtkInformation* outInfo)
{
  // The superclass returns 0 when the representation is not visible: nothing to do then.
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0;
  }

  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    const bool translucent = this->IsTranslucent();
    double bounds[6];
    this->ComputeSphereBounds(this->ProcessedData, bounds);
    vtkPVView::SetPiece(
      inInfo, this, this->DistributedPartition->PieceToDeliver(this->ProcessedData, bounds));
    vtkNew<vtkMatrix4x4> matrix;
    this->Actor->GetMatrix(matrix);
    vtkPVRenderView::SetGeometryBounds(inInfo, this, bounds, matrix);

    // Never DATA_IS_REDISTRIBUTABLE: ParaView 5.11 would move the data through appended XML,
    // which Debian's expat security updates break. The ranks' boxes come from the bounds.
    vtkPVRenderView::SetOrderedCompositingConfiguration(
      inInfo, this, vtkPVRenderView::USE_BOUNDS_FOR_REDISTRIBUTION);
    outInfo->Set(vtkPVRenderView::NEED_ORDERED_COMPOSITING(), translucent ? 1 : 0);
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    vtkDataObject* data = vtkPVView::GetDeliveredPiece(inInfo, this);
    vtkPolyData* particles = vtkPolyData::SafeDownCast(data);
    if (!particles)
    {
      // Nothing delivered to this process, or a composite dataset: flatten (cached).
      const vtkMTimeType time = data ? data->GetMTime() : 0;
      if (!this->RenderedData || data != this->LastDelivered || time != this->LastDeliveredTime)
      {
        this->RenderedData = MakeParticles(data, false);
        this->LastDelivered = data;
        this->LastDeliveredTime = time;
      }
      particles = this->RenderedData;
    }
    double clipBox[6];
    particles = this->DistributedPartition->PieceToDraw(particles, clipBox);
    this->Mapper->SetClipBox(clipBox);
    this->Mapper->SetInputDataObject(particles);
    if (auto particleView = vtkParticleRenderView::SafeDownCast(this->GetView()))
    {
      // (the view builds the AO volume of all its Particles representations before the frame)
      // (ellipsoids deposit their own volume: the radius of the sphere of that volume)
      const bool volumeRadii = this->EllipsoidsInEffect(this->ProcessedData) &&
        this->ProcessedData->GetPointData()->GetArray("ParticleVolumeRadius");
      particleView->GetParticleVolumes()->SetSource(this, this->Technique == SPHERES, this->Actor,
        this->Mapper, this->ProcessedData,
        volumeRadii ? std::string("ParticleVolumeRadius")
                    : this->EffectiveRadiusArray(this->ProcessedData));
    }
    this->UpdateMapperRadiusArray(); // the automatic radius array depends on the data
    // An empty local piece is normal (other ranks hold the data, nothing was delivered here,
    // an empty filter output): draw nothing, without the mapper's "no points" warning.
    this->HasLocalParticles = particles->GetNumberOfPoints() > 0;
    this->Actor->SetVisibility(this->GetVisibility() && this->HasLocalParticles);
    this->UpdateColoringParameters();
  }
  return 1;
}

//------------------------------------------------------------------------------
vtkDoubleArray* vtkParticleRepresentation::GetParticleDistribution()
{
  return this->DistributedPartition->GetDistribution();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::UpdateColoringParameters()
{
  vtkInformation* info = this->GetInputArrayInformation(0);
  const char* name = nullptr;
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  if (info && info->Has(vtkDataObject::FIELD_NAME()))
  {
    name = info->Get(vtkDataObject::FIELD_NAME());
    if (info->Has(vtkDataObject::FIELD_ASSOCIATION()))
    {
      association = info->Get(vtkDataObject::FIELD_ASSOCIATION());
    }
  }
  // Particles are points: only point arrays colour them.
  if (name && name[0] && association == vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    this->Mapper->SetScalarVisibility(1);
    this->Mapper->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
    this->Mapper->SelectColorArray(name);
    this->Mapper->SetUseLookupTableScalarRange(1);
  }
  else
  {
    this->Mapper->SetScalarVisibility(0);
    this->Mapper->SelectColorArray(static_cast<const char*>(nullptr));
  }
}

//------------------------------------------------------------------------------
bool vtkParticleRepresentation::AddToView(vtkView* view)
{
  if (auto rview = vtkPVRenderView::SafeDownCast(view))
  {
    rview->GetRenderer()->AddActor(this->Actor);
    rview->RegisterPropForHardwareSelection(this, this->Actor);
    if (auto particleView = vtkParticleRenderView::SafeDownCast(view))
    {
      particleView->GetViewPartition()->AddRepresentation(this, this->DistributedPartition);
    }
    return this->Superclass::AddToView(view);
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkParticleRepresentation::RemoveFromView(vtkView* view)
{
  if (auto rview = vtkPVRenderView::SafeDownCast(view))
  {
    rview->GetRenderer()->RemoveActor(this->Actor);
    rview->UnRegisterPropForHardwareSelection(this, this->Actor);
    if (auto particleView = vtkParticleRenderView::SafeDownCast(view))
    {
      particleView->GetViewPartition()->RemoveRepresentation(this);
      particleView->GetParticleVolumes()->RemoveSource(this);
    }
    return this->Superclass::RemoveFromView(view);
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetVisibility(bool val)
{
  // an empty local piece stays hidden (see ProcessViewRequest)
  this->Actor->SetVisibility(val && this->HasLocalParticles);
  this->DistributedPartition->SetPropShown(val);
  this->Superclass::SetVisibility(val);
}

//------------------------------------------------------------------------------
std::string vtkParticleRepresentation::EffectiveRadiusArray(vtkPolyData* particles) const
{
  if (particles && this->EllipsoidsInEffect(particles) &&
    particles->GetPointData()->GetArray("ParticleBoundingRadius"))
  {
    return "ParticleBoundingRadius"; // (AddBoundingRadii; the mapper itself uses the axes)
  }
  if (this->UseRadiusArray == RADIUS_ARRAY_ON)
  {
    return this->RadiusArray;
  }
  if (this->UseRadiusArray == RADIUS_ARRAY_AUTOMATIC && particles)
  {
    vtkDataArray* radius = particles->GetPointData()->GetArray("radius");
    if (radius && radius->GetNumberOfComponents() == 1)
    {
      return "radius";
    }
  }
  return std::string();
}

void vtkParticleRepresentation::UpdateMapperRadiusArray()
{
  const std::string name = this->EffectiveRadiusArray(this->Mapper->GetInput());
  this->Mapper->SetRadiusArrayName(name.empty() ? nullptr : name.c_str());
  this->UpdateMapperShape();
}

//------------------------------------------------------------------------------
bool vtkParticleRepresentation::EllipsoidsInEffect(vtkPolyData* particles) const
{
  if (this->Shape == SHAPE_ELLIPSOID || this->Shape == SHAPE_TENSOR_ELLIPSOID)
  {
    return true;
  }
  if (this->Shape != SHAPE_AUTOMATIC || !particles)
  {
    return false;
  }
  vtkDataArray* axes = particles->GetPointData()->GetArray("semi_axes");
  return axes && axes->GetNumberOfComponents() >= 3;
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::EffectiveEllipsoidArrays(vtkPolyData* particles, std::string& axes,
  int& axesComponent, bool& diameters, std::string& orientation, int& orientationComponent) const
{
  if (this->Shape == SHAPE_AUTOMATIC)
  {
    // what vtkLAMMPSDumpReader writes for LAMMPS's ellipsoids
    axes = "semi_axes";
    axesComponent = 0;
    diameters = false;
    vtkDataArray* quaternions =
      particles ? particles->GetPointData()->GetArray("orientation") : nullptr;
    orientation = quaternions && quaternions->GetNumberOfComponents() >= 4 ? "orientation" : "";
    orientationComponent = 0;
    return;
  }
  axes = this->AxesArray;
  axesComponent = this->AxesArrayComponent;
  diameters = this->AxesAreDiameters;
  orientation = this->OrientationArray;
  orientationComponent = this->OrientationArrayComponent;
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::UpdateMapperShape()
{
  vtkPolyData* particles = this->Mapper->GetInput();
  if (!this->EllipsoidsInEffect(particles))
  {
    this->Mapper->SetShapeToSphere();
    return;
  }
  std::string axes;
  std::string orientation;
  int axesComponent = 0;
  int orientationComponent = 0;
  bool diameters = false;
  this->EffectiveEllipsoidArrays(
    particles, axes, axesComponent, diameters, orientation, orientationComponent);
  this->Mapper->SetShapeToEllipsoid();
  this->Mapper->SetTensorArrayName(
    this->Shape == SHAPE_TENSOR_ELLIPSOID && !this->TensorArray.empty() ? this->TensorArray.c_str()
                                                                        : nullptr);
  this->Mapper->SetAxesArrayName(axes.empty() ? nullptr : axes.c_str());
  this->Mapper->SetAxesArrayComponent(axesComponent);
  this->Mapper->SetAxesAreDiameters(diameters);
  this->Mapper->SetOrientationArrayName(orientation.empty() ? nullptr : orientation.c_str());
  this->Mapper->SetOrientationArrayComponent(orientationComponent);
}

//------------------------------------------------------------------------------
namespace
{
// A new float point array `name` of particles, one value per point (to be filled).
vtkFloatArray* AddPointArray(vtkPolyData* particles, const char* name)
{
  vtkNew<vtkFloatArray> array;
  array->SetName(name);
  array->SetNumberOfTuples(particles->GetNumberOfPoints());
  particles->GetPointData()->AddArray(array);
  return array;
}
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::AddBoundingRadii(vtkPolyData* particles)
{
  if (!particles || !this->EllipsoidsInEffect(particles))
  {
    return;
  }
  if (this->Shape == SHAPE_TENSOR_ELLIPSOID)
  {
    this->AddTensorBoundingRadii(particles);
    return;
  }
  std::string axesName;
  std::string orientation;
  int component = 0;
  int orientationComponent = 0;
  bool diameters = false;
  this->EffectiveEllipsoidArrays(
    particles, axesName, component, diameters, orientation, orientationComponent);
  vtkDataArray* axes = particles->GetPointData()->GetArray(axesName.c_str());
  if (!axes || axes->GetNumberOfComponents() < component + 3)
  {
    return; // the mapper says what is wrong, and draws spheres
  }
  const vtkIdType n = particles->GetNumberOfPoints();
  vtkFloatArray* radii = AddPointArray(particles, "ParticleBoundingRadius");
  // and the radius of the sphere of each particle's volume, for the AO volumes, and the radius
  // that counts in the column-layer estimate, sqrt(a b c / a_max) (as the mapper's)
  vtkFloatArray* volumeRadii = AddPointArray(particles, "ParticleVolumeRadius");
  vtkFloatArray* columnRadii = AddPointArray(particles, "ParticleColumnRadius");
  const double factor = diameters ? 0.5 : 1.0;
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double largest = 0.0;
        double product = 1.0;
        for (int k = 0; k < 3; ++k)
        {
          const double a = factor * axes->GetComponent(i, component + k);
          // (a NaN makes the particle's bound NaN: skipped, as by the mapper)
          largest = std::isnan(a) ? a : std::max(largest, a);
          product *= a;
        }
        radii->SetValue(i, static_cast<float>(largest));
        volumeRadii->SetValue(i, static_cast<float>(product > 0.0 ? std::cbrt(product) : 0.0));
        // (from the float axes the mapper holds)
        double floats = 1.0;
        double floatLargest = 0.0;
        for (int k = 0; k < 3; ++k)
        {
          const double a = static_cast<float>(factor * axes->GetComponent(i, component + k));
          floats *= a;
          floatLargest = std::max(floatLargest, a);
        }
        columnRadii->SetValue(i,
          static_cast<float>(
            floats > 0.0 && floatLargest > 0.0 ? std::sqrt(floats / floatLargest) : 0.0));
      }
    });
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::AddTensorBoundingRadii(vtkPolyData* particles)
{
  vtkDataArray* tensors = particles->GetPointData()->GetArray(this->TensorArray.c_str());
  if (!tensors || tensors->GetNumberOfComponents() != 9)
  {
    return; // the mapper says what is wrong, and draws spheres
  }
  // the tensor's symmetric part S: its eigenvalues are the semi-axes (vtkTensorGlyph), so
  // max |lambda| <= |S|_F bounds the particle and |det S| = a b c gives its volume
  const vtkIdType n = particles->GetNumberOfPoints();
  vtkFloatArray* radii = AddPointArray(particles, "ParticleBoundingRadius");
  vtkFloatArray* volumeRadii = AddPointArray(particles, "ParticleVolumeRadius");
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      double t[9];
      for (vtkIdType i = begin; i < end; ++i)
      {
        tensors->GetTuple(i, t);
        double s[3][3];
        double frobenius = 0.0;
        for (int r = 0; r < 3; ++r)
        {
          for (int c = 0; c < 3; ++c)
          {
            s[r][c] = 0.5 * (t[r + 3 * c] + t[c + 3 * r]);
            frobenius += s[r][c] * s[r][c];
          }
        }
        radii->SetValue(i, static_cast<float>(std::sqrt(frobenius)));
        volumeRadii->SetValue(
          i, static_cast<float>(std::cbrt(std::abs(vtkMath::Determinant3x3(s)))));
      }
    });
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SelectTensorArray(int, int, int, int, const char* name)
{
  this->ChangeShapeSetting(this->TensorArray, std::string(name ? name : ""));
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetShape(int shape)
{
  this->ChangeShapeSetting(this->Shape,
    std::min(
      std::max(shape, static_cast<int>(SHAPE_SPHERE)), static_cast<int>(SHAPE_TENSOR_ELLIPSOID)));
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SelectAxesArray(int, int, int, int, const char* name)
{
  this->ChangeShapeSetting(this->AxesArray, std::string(name ? name : ""));
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetAxesArrayComponent(int component)
{
  this->ChangeShapeSetting(this->AxesArrayComponent, std::max(0, component));
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetAxesAreDiameters(bool diameters)
{
  this->ChangeShapeSetting(this->AxesAreDiameters, diameters);
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SelectOrientationArray(int, int, int, int, const char* name)
{
  // (the XML's none_string: no orientation array, axis-aligned ellipsoids)
  const std::string given = name ? name : "";
  this->ChangeShapeSetting(
    this->OrientationArray, given == "None (axis-aligned)" ? std::string() : given);
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetOrientationArrayComponent(int component)
{
  this->ChangeShapeSetting(this->OrientationArrayComponent, std::max(0, component));
}

//------------------------------------------------------------------------------
bool vtkParticleRepresentation::GetDrawsEllipsoids()
{
  return this->Mapper->GetInput() && this->Mapper->GetDrawsEllipsoids();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::UpdateMapperOpacityArray()
{
  auto* transparent = vtkTransparentSphereMapper::SafeDownCast(this->Mapper);
  if (!transparent)
  {
    return; // a technique without per-particle opacity
  }
  transparent->SetOpacityArrayName(
    (this->UseOpacityArray && !this->OpacityArray.empty()) ? this->OpacityArray.c_str() : nullptr);
  if (this->OpacityArrayRangeMode == OPACITY_RANGE_CUSTOM)
  {
    transparent->SetOpacityRange(this->OpacityArrayRange);
  }
  else
  {
    transparent->SetOpacityRange(this->OpacityArrayDataRange);
  }
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::UpdateOpacityArrayDataRange()
{
  double range[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  vtkDataArray* array = (this->ProcessedData && !this->OpacityArray.empty())
    ? this->ProcessedData->GetPointData()->GetArray(this->OpacityArray.c_str())
    : nullptr;
  if (array && array->GetNumberOfComponents() == 1 && array->GetNumberOfTuples() > 0)
  {
    array->GetFiniteRange(range, 0);
  }
  // the same range on every process (RequestData runs on all of them together)
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    double local[2] = { range[0], -range[1] };
    double global[2];
    controller->AllReduce(local, global, 2, vtkCommunicator::MIN_OP);
    range[0] = global[0];
    range[1] = -global[1];
  }
  if (range[0] <= range[1])
  {
    this->OpacityArrayDataRange[0] = range[0];
    this->OpacityArrayDataRange[1] = range[1];
  }
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetOpacityArrayRangeMode(int mode)
{
  mode = mode == OPACITY_RANGE_CUSTOM ? OPACITY_RANGE_CUSTOM : OPACITY_RANGE_DATA;
  if (this->OpacityArrayRangeMode != mode)
  {
    this->OpacityArrayRangeMode = mode;
    this->UpdateMapperOpacityArray();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetUseOpacityArray(bool use)
{
  if (this->UseOpacityArray != use)
  {
    this->UseOpacityArray = use;
    this->UpdateMapperOpacityArray();
    this->MarkModified(); // translucent or not: partitioned or not (RequestData)
  }
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetOpacityArray(const char* name)
{
  const std::string value = name ? name : "";
  if (this->OpacityArray != value)
  {
    this->OpacityArray = value;
    this->UpdateOpacityArrayDataRange();
    this->UpdateMapperOpacityArray();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SelectOpacityArray(int, int, int, int, const char* name)
{
  this->SetOpacityArray(name);
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetOpacityArrayRange(double lo, double hi)
{
  this->OpacityArrayRange[0] = lo;
  this->OpacityArrayRange[1] = hi;
  this->UpdateMapperOpacityArray();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetDensityModel(int model)
{
  this->DensityModel = model;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetHollowFraction(double fraction)
{
  this->HollowFraction = fraction;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetVolumeMix(double mix)
{
  this->VolumeMix = mix;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetEarlyTermination(int on)
{
  this->EarlyTermination = on != 0;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetOverlapCompositing(int mode)
{
  this->OverlapCompositing = mode;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetAutomaticErrorTolerance(double tolerance)
{
  this->AutomaticErrorTolerance = tolerance;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetAutomaticPixelShare(double share)
{
  this->AutomaticPixelShare = share;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetInteractiveQuality(int quality)
{
  this->InteractiveQuality = quality;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
const char* vtkParticleRepresentation::GetQualityText()
{
  this->QualityText = this->Mapper->GetQualityText();
  return this->QualityText.c_str();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetFragmentListMemory(double mebibytes)
{
  this->FragmentListMemory = mebibytes;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetOverlapTolerance(double tolerance)
{
  this->OverlapTolerance = tolerance;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetOpacityReference(int reference)
{
  this->OpacityReference = reference;
  this->ApplyMapperSettings();
}

//------------------------------------------------------------------------------
bool vtkParticleRepresentation::IsTranslucent()
{
  // (metaballs are opaque, see ApplyOpacity)
  return this->Technique == SPHERES && (this->Opacity < 1.0 || this->UseOpacityArray);
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::ApplyOpacity()
{
  // The metaball surface is opaque (translucent metaballs are not implemented): drawn in the
  // opaque pass and composited by depth, not blended with what lies behind it.
  this->Actor->GetProperty()->SetOpacity(this->Technique == METABALLS ? 1.0 : this->Opacity);
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetOpacity(double val)
{
  const bool wasTranslucent = this->IsTranslucent();
  this->Opacity = val;
  this->ApplyOpacity();
  if (this->IsTranslucent() != wasTranslucent)
  {
    this->MarkModified(); // partitioned for translucency or not (RequestData)
  }
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetUseRadiusArray(int mode)
{
  mode = std::min(
    std::max(mode, static_cast<int>(RADIUS_ARRAY_OFF)), static_cast<int>(RADIUS_ARRAY_AUTOMATIC));
  if (this->UseRadiusArray != mode)
  {
    this->UseRadiusArray = mode;
    this->UpdateMapperRadiusArray();
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetRadiusArray(const char* name)
{
  const std::string value = name ? name : "";
  if (this->RadiusArray != value)
  {
    this->RadiusArray = value;
    this->UpdateMapperRadiusArray();
    this->MarkModified();
  }
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SelectRadiusArray(int, int, int, int, const char* name)
{
  this->SetRadiusArray(name);
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetRadius(double radius)
{
  if (radius != this->Mapper->GetRadius())
  {
    this->Mapper->SetRadius(radius);
    this->MarkModified(); // the ghost copies of a partition reach one radius
  }
}

//------------------------------------------------------------------------------
double vtkParticleRepresentation::GetRadius()
{
  return this->Mapper->GetRadius();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetRadiusScaleFactor(double factor)
{
  if (factor != this->Mapper->GetRadiusScaleFactor())
  {
    this->Mapper->SetRadiusScaleFactor(factor);
    this->MarkModified(); // the ghost copies of a partition reach one radius
  }
}

//------------------------------------------------------------------------------
double vtkParticleRepresentation::GetRadiusScaleFactor()
{
  return this->Mapper->GetRadiusScaleFactor();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetLookupTable(vtkScalarsToColors* lut)
{
  this->Mapper->SetLookupTable(lut);
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetMapScalars(int val)
{
  this->Mapper->SetColorMode(val ? VTK_COLOR_MODE_MAP_SCALARS : VTK_COLOR_MODE_DIRECT_SCALARS);
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetUserTransform(const double matrix[16])
{
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(matrix);
  this->Actor->SetUserTransform(transform);
}

//------------------------------------------------------------------------------
vtkParticleSphereMapper* vtkParticleRepresentation::GetMapper()
{
  return this->Mapper;
}

//------------------------------------------------------------------------------
vtkActor* vtkParticleRepresentation::GetActor()
{
  return this->Actor;
}

//------------------------------------------------------------------------------
vtkIdType vtkParticleRepresentation::GetNumberOfParticles()
{
  return this->ProcessedData ? this->ProcessedData->GetNumberOfPoints() : 0;
}

//------------------------------------------------------------------------------
#define prForwardActor3(method)                                                                    \
  void vtkParticleRepresentation::method(double x, double y, double z)                             \
  {                                                                                                \
    this->Actor->method(x, y, z);                                                                  \
  }
#define prForwardProperty1(method)                                                                 \
  void vtkParticleRepresentation::method(double val)                                               \
  {                                                                                                \
    this->Actor->GetProperty()->method(val);                                                       \
  }
#define prForwardProperty3(method)                                                                 \
  void vtkParticleRepresentation::method(double r, double g, double b)                             \
  {                                                                                                \
    this->Actor->GetProperty()->method(r, g, b);                                                   \
  }

prForwardActor3(SetOrientation);
prForwardActor3(SetOrigin);
prForwardActor3(SetPosition);
prForwardActor3(SetScale);
prForwardProperty1(SetAmbient);
prForwardProperty1(SetDiffuse);
prForwardProperty1(SetSpecular);
prForwardProperty1(SetSpecularPower);
prForwardProperty3(SetAmbientColor);
prForwardProperty3(SetDiffuseColor);
prForwardProperty3(SetSpecularColor);

//------------------------------------------------------------------------------
void vtkParticleRepresentation::SetPickable(int val)
{
  this->Actor->SetPickable(val);
}

//------------------------------------------------------------------------------
const char* vtkParticleRepresentation::GetParticleInputWarning()
{
  return this->Mapper->GetLastInputWarning();
}

//------------------------------------------------------------------------------
void vtkParticleRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseRadiusArray: " << this->UseRadiusArray << "\n";
  os << indent << "Shape: " << this->Shape << "\n";
  os << indent << "AxesArray: " << this->AxesArray << " component " << this->AxesArrayComponent
     << (this->AxesAreDiameters ? " (diameters)" : "") << "\n";
  os << indent << "OrientationArray: " << this->OrientationArray << " component "
     << this->OrientationArrayComponent << "\n";
  os << indent << "RadiusArray: " << this->RadiusArray << "\n";
  os << indent << "Radius: " << this->Mapper->GetRadius() << "\n";
  os << indent << "RadiusScaleFactor: " << this->Mapper->GetRadiusScaleFactor() << "\n";
  os << indent << "NumberOfParticles: " << this->GetNumberOfParticles() << "\n";
  os << indent << "DistributedPartition:\n";
  this->DistributedPartition->PrintSelf(os, indent.GetNextIndent());
}
