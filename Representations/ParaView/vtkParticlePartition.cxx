#include "vtkParticlePartition.h"

#include "vtkBoundingBox.h"
#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkMultiProcessStream.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

vtkStandardNewMacro(vtkParticlePartition);

namespace
{
// tags of the exchange (one message per array and destination)
constexpr int PARTITION_TAG = 48270;

// a node of the k-d tree: a leaf holds a process, an inner node a split plane
struct KdNode
{
  int Rank = -1; // >= 0: leaf
  int Axis = 0;
  double Value = 0.0;
  int Lower = -1; // child with coordinate < Value
  int Upper = -1; // child with coordinate >= Value
};

// samples: x, y, z, weight
int BuildTree(std::vector<KdNode>& nodes, std::vector<double>& boxes, const double* samples,
  std::vector<vtkIdType>& indices, vtkIdType begin, vtkIdType end, const double box[6], int r0,
  int r1)
{
  const int index = static_cast<int>(nodes.size());
  nodes.emplace_back();
  if (r1 - r0 == 1)
  {
    nodes[index].Rank = r0;
    std::copy(box, box + 6, boxes.begin() + 6 * r0);
    return index;
  }
  const int lowerRanks = (r1 - r0) / 2;
  int axis = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (box[2 * k + 1] - box[2 * k] > box[2 * axis + 1] - box[2 * axis])
    {
      axis = k;
    }
  }
  const double fraction = static_cast<double>(lowerRanks) / (r1 - r0);
  double value = box[2 * axis] + fraction * (box[2 * axis + 1] - box[2 * axis]);
  vtkIdType cut = begin;
  if (end > begin)
  {
    std::sort(indices.begin() + begin, indices.begin() + end,
      [&](vtkIdType a, vtkIdType b) { return samples[4 * a + axis] < samples[4 * b + axis]; });
    double total = 0.0;
    for (vtkIdType i = begin; i < end; ++i)
    {
      total += samples[4 * indices[i] + 3];
    }
    // the cut k whose weight below is closest to the lower side's share
    const double target = fraction * total;
    double below = 0.0;
    double bestError = target;
    cut = begin;
    for (vtkIdType i = begin; i < end; ++i)
    {
      below += samples[4 * indices[i] + 3];
      const double error = std::abs(below - target);
      if (error < bestError)
      {
        bestError = error;
        cut = i + 1;
      }
    }
    if (cut == begin)
    {
      value = box[2 * axis];
    }
    else if (cut == end)
    {
      value = box[2 * axis + 1];
    }
    else
    {
      value = 0.5 * (samples[4 * indices[cut - 1] + axis] + samples[4 * indices[cut] + axis]);
    }
    value = std::min(std::max(value, box[2 * axis]), box[2 * axis + 1]);
    // samples on the plane belong to the upper side, as particles do
    while (cut > begin && samples[4 * indices[cut - 1] + axis] >= value)
    {
      --cut;
    }
  }
  nodes[index].Axis = axis;
  nodes[index].Value = value;
  double lowerBox[6];
  double upperBox[6];
  std::copy(box, box + 6, lowerBox);
  std::copy(box, box + 6, upperBox);
  lowerBox[2 * axis + 1] = value;
  upperBox[2 * axis] = value;
  const int lower =
    BuildTree(nodes, boxes, samples, indices, begin, cut, lowerBox, r0, r0 + lowerRanks);
  const int upper =
    BuildTree(nodes, boxes, samples, indices, cut, end, upperBox, r0 + lowerRanks, r1);
  nodes[index].Lower = lower;
  nodes[index].Upper = upper;
  return index;
}

int Owner(const std::vector<KdNode>& nodes, const double x[3])
{
  int node = 0;
  while (nodes[node].Rank < 0)
  {
    node = x[nodes[node].Axis] < nodes[node].Value ? nodes[node].Lower : nodes[node].Upper;
  }
  return nodes[node].Rank;
}

// every process whose box the cube [x - r, x + r] overlaps
void Overlapping(
  const std::vector<KdNode>& nodes, int node, const double x[3], double r, std::vector<int>& ranks)
{
  if (nodes[node].Rank >= 0)
  {
    ranks.push_back(nodes[node].Rank);
    return;
  }
  const KdNode& n = nodes[node];
  if (x[n.Axis] - r < n.Value)
  {
    Overlapping(nodes, n.Lower, x, r, ranks);
  }
  if (x[n.Axis] + r >= n.Value)
  {
    Overlapping(nodes, n.Upper, x, r, ranks);
  }
}

// the arrays that travel: the points' array first, then the point arrays
struct ArraySpec
{
  std::string Name;
  int Type = VTK_FLOAT;
  int Components = 1;
};
}

//------------------------------------------------------------------------------
vtkParticlePartition::vtkParticlePartition()
{
  this->Controller = vtkMultiProcessController::GetGlobalController();
  this->Output = vtkSmartPointer<vtkPolyData>::New();
}

//------------------------------------------------------------------------------
vtkParticlePartition::~vtkParticlePartition() = default;

//------------------------------------------------------------------------------
void vtkParticlePartition::SetController(vtkMultiProcessController* controller)
{
  if (this->Controller != controller)
  {
    this->Controller = controller;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkParticlePartition::GetController()
{
  return this->Controller;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkParticlePartition::GetOutput()
{
  return this->Output;
}

//------------------------------------------------------------------------------
void vtkParticlePartition::GetBox(double box[6]) const
{
  const int rank = this->Controller ? this->Controller->GetLocalProcessId() : 0;
  if (static_cast<int>(this->Boxes.size()) >= 6 * (rank + 1))
  {
    std::copy(this->Boxes.begin() + 6 * rank, this->Boxes.begin() + 6 * rank + 6, box);
  }
  else
  {
    vtkMath::UninitializeBounds(box);
  }
}

//------------------------------------------------------------------------------
// What one Partition() shares between its stages: this process, its particles, the k-d tree
// of the boxes, the arrays every process keeps, where each particle goes and what came in.
struct vtkParticlePartition::vtkRun
{
  vtkMultiProcessController* Controller = nullptr;
  int Size = 1;
  int Rank = 0;
  vtkPolyData* Particles = nullptr;
  vtkIdType LocalCount = 0;
  vtkDataArray* Points = nullptr;
  vtkDataArray* Radii = nullptr;
  vtkUnsignedCharArray* UpstreamGhosts = nullptr;
  double Root[6];
  std::vector<vtkIdType> Finite; // the taken particles with a finite centre
  std::vector<KdNode> Nodes;
  int SchemaRank = 0;
  std::vector<ArraySpec> Kept; // the arrays every process with particles has (0: the points)
  std::vector<vtkDataArray*> LocalArrays;
  std::vector<vtkSmartPointer<vtkIdList>> SendIds; // per destination
  std::vector<std::vector<unsigned char>> SendGhost;
  std::vector<vtkIdType> Matrix; // counts[source * size + destination]
  vtkIdType Total = 0;           // the particles this process receives
  std::vector<vtkSmartPointer<vtkDataArray>> OutArrays;
  vtkNew<vtkUnsignedCharArray> Ghosts;
  double BytesSent = 0.0;
};

//------------------------------------------------------------------------------
bool vtkParticlePartition::Partition(vtkPolyData* particles, const char* radiusArray, double radius,
  double radiusScale, double reach, const double sphereBounds[6])
{
  const vtkParticleSet set = { particles, radiusArray, radius, radiusScale, reach, sphereBounds };
  return vtkParticlePartition::PartitionTogether({ this }, { set });
}

//------------------------------------------------------------------------------
bool vtkParticlePartition::PartitionTogether(
  const std::vector<vtkParticlePartition*>& partitions, const std::vector<vtkParticleSet>& sets)
{
  if (partitions.empty() || partitions.size() != sets.size())
  {
    return false;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  // one tree for all sets: the root box over all their spheres, the splits over all their centres
  std::vector<vtkRun> runs(partitions.size());
  vtkBoundingBox bounds;
  for (size_t i = 0; i < partitions.size(); ++i)
  {
    partitions[i]->BeginRun(runs[i], sets[i].Particles, sets[i].RadiusArray);
    if (sets[i].SphereBounds && vtkMath::AreBoundsInitialized(sets[i].SphereBounds))
    {
      bounds.AddBounds(sets[i].SphereBounds);
    }
  }
  double sphereBounds[6];
  vtkMath::UninitializeBounds(sphereBounds);
  if (bounds.IsValid())
  {
    bounds.GetBounds(sphereBounds);
  }
  vtkParticlePartition* first = partitions[0];
  first->FindRootBox(runs[0], sphereBounds);
  const bool split = first->SplitIntoBoxes(runs);
  for (size_t i = 1; i < partitions.size(); ++i)
  {
    std::copy(runs[0].Root, runs[0].Root + 6, runs[i].Root);
    runs[i].Nodes = runs[0].Nodes;
    partitions[i]->Boxes = first->Boxes;
  }
  if (!split)
  {
    return false; // no process has a particle
  }
  for (size_t i = 0; i < partitions.size(); ++i)
  {
    vtkParticlePartition* partition = partitions[i];
    partition->AgreeOnArrays(runs[i]);
    partition->AssignParticles(runs[i], sets[i].Radius, sets[i].RadiusScale, sets[i].Reach);
    partition->ExchangeParticles(runs[i]);
    partition->AssembleOutput(runs[i]);
    partition->GatherDistribution(runs[i], start);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkParticlePartition::BeginRun(vtkRun& run, vtkPolyData* particles, const char* radiusArray)
{
  vtkMultiProcessController* controller = this->Controller;
  run.Controller = controller;
  run.Size = controller ? controller->GetNumberOfProcesses() : 1;
  run.Rank = controller ? controller->GetLocalProcessId() : 0;
  const int size = run.Size;
  this->Output = vtkSmartPointer<vtkPolyData>::New();
  this->Output->SetPoints(vtkSmartPointer<vtkPoints>::New());
  this->Boxes.assign(6 * size, 0.0);
  this->Distribution.assign(5 * size, 0.0);

  const vtkIdType localCount = run.LocalCount =
    (particles && particles->GetPoints()) ? particles->GetNumberOfPoints() : 0;
  run.Particles = particles;
  run.Points = localCount > 0 ? particles->GetPoints()->GetData() : nullptr;
  vtkDataArray* radii = (localCount > 0 && radiusArray && *radiusArray)
    ? particles->GetPointData()->GetArray(radiusArray)
    : nullptr;
  if (radii && radii->GetNumberOfComponents() != 1)
  {
    radii = nullptr;
  }
  run.Radii = radii;
  // particles that are ghosts upstream are another process's: not taken
  run.UpstreamGhosts = localCount > 0
    ? vtkUnsignedCharArray::SafeDownCast(
        particles->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName()))
    : nullptr;
}

//------------------------------------------------------------------------------
void vtkParticlePartition::FindRootBox(vtkRun& run, const double sphereBounds[6])
{
  vtkMultiProcessController* controller = run.Controller;
  const int size = run.Size;
  double(&root)[6] = run.Root;
  // the root box: the union of every process's sphere bounds
  {
    vtkBoundingBox local;
    if (sphereBounds && vtkMath::AreBoundsInitialized(sphereBounds))
    {
      local.SetBounds(sphereBounds);
    }
    double mins[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
    double maxs[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    if (local.IsValid())
    {
      local.GetMinPoint(mins);
      local.GetMaxPoint(maxs);
    }
    double globalMins[3] = { mins[0], mins[1], mins[2] };
    double globalMaxs[3] = { maxs[0], maxs[1], maxs[2] };
    if (size > 1)
    {
      controller->AllReduce(mins, globalMins, 3, vtkCommunicator::MIN_OP);
      controller->AllReduce(maxs, globalMaxs, 3, vtkCommunicator::MAX_OP);
    }
    for (int k = 0; k < 3; ++k)
    {
      root[2 * k] = globalMins[k];
      root[2 * k + 1] = globalMaxs[k];
    }
  }
}

//------------------------------------------------------------------------------
bool vtkParticlePartition::SplitIntoBoxes(std::vector<vtkRun>& runs)
{
  vtkRun& run = runs[0];
  vtkMultiProcessController* controller = run.Controller;
  const int size = run.Size;
  double(&root)[6] = run.Root;
  std::vector<KdNode>& nodes = run.Nodes;
  // the samples of the splits: finite centres of all sets, strided over their concatenation,
  // weighted by the local count
  vtkIdType finiteTotal = 0;
  for (vtkRun& r : runs)
  {
    r.Finite.reserve(r.LocalCount);
    for (vtkIdType i = 0; i < r.LocalCount; ++i)
    {
      if (r.UpstreamGhosts &&
        (r.UpstreamGhosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT))
      {
        continue;
      }
      double x[3];
      r.Points->GetTuple(i, x);
      if (std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]))
      {
        r.Finite.push_back(i);
      }
    }
    finiteTotal += static_cast<vtkIdType>(r.Finite.size());
  }
  const vtkIdType perProcess = std::max<vtkIdType>(1, this->MaximumSamples / size);
  const vtkIdType sampleCount = std::min<vtkIdType>(perProcess, finiteTotal);
  std::vector<double> localSamples(4 * sampleCount);
  size_t set = 0;
  vtkIdType setStart = 0; // the index of runs[set].Finite[0] in the concatenation
  for (vtkIdType s = 0; s < sampleCount; ++s)
  {
    const vtkIdType k = s * finiteTotal / sampleCount;
    while (k >= setStart + static_cast<vtkIdType>(runs[set].Finite.size()))
    {
      setStart += static_cast<vtkIdType>(runs[set].Finite.size());
      ++set;
    }
    runs[set].Points->GetTuple(runs[set].Finite[k - setStart], localSamples.data() + 4 * s);
    localSamples[4 * s + 3] = static_cast<double>(finiteTotal) / sampleCount;
  }
  std::vector<vtkIdType> lengths(size, 4 * sampleCount);
  std::vector<double> samples = localSamples;
  if (size > 1)
  {
    vtkIdType length = 4 * sampleCount;
    controller->AllGather(&length, lengths.data(), 1);
    std::vector<vtkIdType> offsets(size, 0);
    for (int r = 1; r < size; ++r)
    {
      offsets[r] = offsets[r - 1] + lengths[r - 1];
    }
    samples.assign(offsets[size - 1] + lengths[size - 1], 0.0);
    controller->AllGatherV(
      localSamples.data(), samples.data(), length, lengths.data(), offsets.data());
  }
  if (!(root[0] <= root[1] && root[2] <= root[3] && root[4] <= root[5]))
  {
    // no process has a particle
    vtkMath::UninitializeBounds(root);
    for (int r = 0; r < size; ++r)
    {
      std::copy(root, root + 6, this->Boxes.begin() + 6 * r);
    }
    return false;
  }
  std::vector<vtkIdType> indices(samples.size() / 4);
  std::iota(indices.begin(), indices.end(), 0);
  BuildTree(nodes, this->Boxes, samples.data(), indices, 0, indices.size(), root, 0, size);
  return true;
}

//------------------------------------------------------------------------------
void vtkParticlePartition::AgreeOnArrays(vtkRun& run)
{
  vtkMultiProcessController* controller = run.Controller;
  const int size = run.Size;
  const int rank = run.Rank;
  vtkPolyData* particles = run.Particles;
  const vtkIdType localCount = run.LocalCount;
  vtkDataArray* points = run.Points;
  std::vector<ArraySpec>& kept = run.Kept;
  std::vector<vtkDataArray*>& localArrays = run.LocalArrays;
  // the arrays: the schema of the lowest process with particles, kept where every process
  // with particles has it
  std::vector<vtkIdType> counts(size, localCount);
  if (size > 1)
  {
    controller->AllGather(&localCount, counts.data(), 1);
  }
  run.SchemaRank = static_cast<int>(
    std::find_if(counts.begin(), counts.end(), [](vtkIdType c) { return c > 0; }) - counts.begin());
  const int schemaRank = run.SchemaRank;
  std::vector<ArraySpec> specs;
  {
    vtkMultiProcessStream stream;
    if (rank == schemaRank)
    {
      vtkPointData* pd = particles->GetPointData();
      int n = 1;
      for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
      {
        vtkDataArray* array = pd->GetArray(a);
        n += (array && array->GetName() &&
               std::string(array->GetName()) != vtkDataSetAttributes::GhostArrayName())
          ? 1
          : 0;
      }
      stream << n << std::string() << points->GetDataType() << points->GetNumberOfComponents();
      for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
      {
        vtkDataArray* array = pd->GetArray(a);
        if (array && array->GetName() &&
          std::string(array->GetName()) != vtkDataSetAttributes::GhostArrayName())
        {
          stream << std::string(array->GetName()) << array->GetDataType()
                 << array->GetNumberOfComponents();
        }
      }
    }
    if (size > 1)
    {
      controller->Broadcast(stream, schemaRank);
    }
    int n = 0;
    stream >> n;
    specs.resize(n);
    for (auto& spec : specs)
    {
      stream >> spec.Name >> spec.Type >> spec.Components;
    }
  }
  std::vector<int> present(specs.size(), 1);
  for (size_t a = 1; a < specs.size() && localCount > 0; ++a)
  {
    vtkDataArray* array = particles->GetPointData()->GetArray(specs[a].Name.c_str());
    present[a] = array && array->GetDataType() == specs[a].Type &&
      array->GetNumberOfComponents() == specs[a].Components;
  }
  std::vector<int> everywhere = present;
  if (size > 1 && !present.empty())
  {
    controller->AllReduce(
      present.data(), everywhere.data(), present.size(), vtkCommunicator::MIN_OP);
  }
  for (size_t a = 0; a < specs.size(); ++a)
  {
    if (!everywhere[a])
    {
      if (rank == schemaRank)
      {
        vtkWarningMacro(<< "Point array '" << specs[a].Name
                        << "' is not on every process with particles (or not with the same type "
                           "and components): it is dropped by the partition.");
      }
      continue;
    }
    kept.push_back(specs[a]);
    localArrays.push_back(localCount == 0 ? nullptr
        : a == 0                          ? points
                 : particles->GetPointData()->GetArray(specs[a].Name.c_str()));
  }
}

//------------------------------------------------------------------------------
void vtkParticlePartition::AssignParticles(
  vtkRun& run, double radius, double radiusScale, double reach)
{
  const int size = run.Size;
  const int rank = run.Rank;
  const vtkIdType localCount = run.LocalCount;
  vtkDataArray* points = run.Points;
  vtkDataArray* radii = run.Radii;
  vtkUnsignedCharArray* upstreamGhosts = run.UpstreamGhosts;
  std::vector<vtkIdType>& finite = run.Finite;
  std::vector<KdNode>& nodes = run.Nodes;
  std::vector<vtkSmartPointer<vtkIdList>>& sendIds = run.SendIds;
  std::vector<std::vector<unsigned char>>& sendGhost = run.SendGhost;
  // where each particle goes: its owner, and as a ghost every other process its cube reaches
  sendIds.resize(size);
  sendGhost.resize(size);
  for (auto& ids : sendIds)
  {
    ids = vtkSmartPointer<vtkIdList>::New();
  }
  const double scale = std::abs(radiusScale) * std::max(0.0, reach);
  std::vector<int> overlapping;
  std::vector<char> isFinite(localCount, 0);
  for (vtkIdType i : finite)
  {
    isFinite[i] = 1;
  }
  for (vtkIdType i = 0; i < localCount; ++i)
  {
    if (upstreamGhosts && (upstreamGhosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT))
    {
      continue;
    }
    if (!isFinite[i])
    {
      sendIds[rank]->InsertNextId(i); // not drawn; stays here so that every particle is owned
      sendGhost[rank].push_back(0);
      continue;
    }
    double x[3];
    points->GetTuple(i, x);
    const int owner = Owner(nodes, x);
    sendIds[owner]->InsertNextId(i);
    sendGhost[owner].push_back(0);
    double r = radii ? radii->GetComponent(i, 0) : radius;
    r = std::isfinite(r) && r > 0.0 ? r * scale : 0.0;
    if (r > 0.0 && size > 1)
    {
      overlapping.clear();
      Overlapping(nodes, 0, x, r, overlapping);
      for (int other : overlapping)
      {
        if (other != owner)
        {
          sendIds[other]->InsertNextId(i);
          sendGhost[other].push_back(vtkDataSetAttributes::DUPLICATEPOINT);
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkParticlePartition::ExchangeParticles(vtkRun& run)
{
  vtkMultiProcessController* controller = run.Controller;
  const int size = run.Size;
  const int rank = run.Rank;
  std::vector<ArraySpec>& kept = run.Kept;
  std::vector<vtkDataArray*>& localArrays = run.LocalArrays;
  std::vector<vtkSmartPointer<vtkIdList>>& sendIds = run.SendIds;
  std::vector<std::vector<unsigned char>>& sendGhost = run.SendGhost;
  std::vector<vtkIdType>& matrix = run.Matrix;
  vtkIdType& total = run.Total;
  std::vector<vtkSmartPointer<vtkDataArray>>& outArrays = run.OutArrays;
  vtkUnsignedCharArray* ghosts = run.Ghosts;
  double& bytesSent = run.BytesSent;
  // counts[source * size + destination]
  std::vector<vtkIdType> sendCounts(size);
  for (int r = 0; r < size; ++r)
  {
    sendCounts[r] = sendIds[r]->GetNumberOfIds();
  }
  matrix.assign(size * size, 0);
  if (size > 1)
  {
    controller->AllGather(sendCounts.data(), matrix.data(), size);
  }
  else
  {
    matrix = sendCounts;
  }
  total = 0;
  for (int s = 0; s < size; ++s)
  {
    total += matrix[s * size + rank];
  }

  // the output arrays, filled by source process in order
  for (const auto& spec : kept)
  {
    auto array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(spec.Type));
    array->SetNumberOfComponents(spec.Components);
    array->SetNumberOfTuples(total);
    if (!spec.Name.empty())
    {
      array->SetName(spec.Name.c_str());
    }
    outArrays.push_back(array);
  }
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfTuples(total);

  bytesSent = 0.0;
  vtkIdType offset = 0;
  for (int source = 0; source < size; ++source)
  {
    const vtkIdType incoming = matrix[source * size + rank];
    if (source == rank)
    {
      // this process's own part, and (its round) what it sends to every other process
      for (size_t a = 0; a < kept.size(); ++a)
      {
        if (incoming > 0)
        {
          vtkNew<vtkIdList> destination;
          destination->SetNumberOfIds(incoming);
          std::iota(destination->GetPointer(0), destination->GetPointer(0) + incoming, offset);
          outArrays[a]->InsertTuples(destination, sendIds[rank], localArrays[a]);
        }
      }
      std::copy(sendGhost[rank].begin(), sendGhost[rank].end(), ghosts->GetPointer(offset));
      for (int destination = 0; destination < size; ++destination)
      {
        const vtkIdType n = sendIds[destination]->GetNumberOfIds();
        if (destination == rank || n == 0)
        {
          continue;
        }
        for (size_t a = 0; a < kept.size(); ++a)
        {
          auto part = vtkSmartPointer<vtkDataArray>::Take(localArrays[a]->NewInstance());
          part->SetNumberOfComponents(kept[a].Components);
          part->SetNumberOfTuples(n);
          localArrays[a]->GetTuples(sendIds[destination], part);
          controller->Send(part, destination, PARTITION_TAG);
          bytesSent += static_cast<double>(part->GetDataSize()) * part->GetDataTypeSize();
        }
        controller->Send(sendGhost[destination].data(), n, destination, PARTITION_TAG);
        bytesSent += static_cast<double>(n);
      }
    }
    else if (incoming > 0)
    {
      for (size_t a = 0; a < kept.size(); ++a)
      {
        auto part = vtkSmartPointer<vtkDataArray>::Take(outArrays[a]->NewInstance());
        controller->Receive(part, source, PARTITION_TAG);
        if (part->GetNumberOfTuples() != incoming ||
          part->GetNumberOfComponents() != kept[a].Components)
        {
          vtkErrorMacro(<< "Partition: process " << source << " sent " << part->GetNumberOfTuples()
                        << " values of '" << kept[a].Name << "', not " << incoming << ".");
          continue;
        }
        outArrays[a]->InsertTuples(offset, incoming, 0, part);
      }
      controller->Receive(ghosts->GetPointer(offset), incoming, source, PARTITION_TAG);
    }
    offset += incoming;
  }
}

//------------------------------------------------------------------------------
void vtkParticlePartition::AssembleOutput(vtkRun& run)
{
  std::vector<vtkSmartPointer<vtkDataArray>>& outArrays = run.OutArrays;
  vtkUnsignedCharArray* ghosts = run.Ghosts;
  vtkNew<vtkPoints> outPoints;
  if (!outArrays.empty())
  {
    outPoints->SetData(outArrays[0]);
  }
  this->Output->SetPoints(outPoints);
  for (size_t a = 1; a < outArrays.size(); ++a)
  {
    this->Output->GetPointData()->AddArray(outArrays[a]);
  }
  this->Output->GetPointData()->AddArray(ghosts);
}

//------------------------------------------------------------------------------
void vtkParticlePartition::GatherDistribution(vtkRun& run, double start)
{
  vtkMultiProcessController* controller = run.Controller;
  const int size = run.Size;
  const vtkIdType localCount = run.LocalCount;
  vtkIdType& total = run.Total;
  vtkUnsignedCharArray* ghosts = run.Ghosts;
  double& bytesSent = run.BytesSent;
  vtkIdType owned = 0;
  for (vtkIdType i = 0; i < total; ++i)
  {
    owned += ghosts->GetValue(i) == 0 ? 1 : 0;
  }
  double stats[5] = { static_cast<double>(localCount), static_cast<double>(owned),
    static_cast<double>(total - owned), bytesSent, vtkTimerLog::GetUniversalTime() - start };
  if (size > 1)
  {
    controller->AllGather(stats, this->Distribution.data(), 5);
  }
  else
  {
    std::copy(stats, stats + 5, this->Distribution.begin());
  }
}

//------------------------------------------------------------------------------
void vtkParticlePartition::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent << "Controller: " << this->Controller.GetPointer() << "\n";
  double box[6];
  this->GetBox(box);
  os << indent << "Box: " << box[0] << " " << box[1] << " " << box[2] << " " << box[3] << " "
     << box[4] << " " << box[5] << "\n";
}
