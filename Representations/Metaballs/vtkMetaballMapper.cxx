#include "vtkMetaballMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMetaballWalkingPlane.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkParticleCellList.h"
#include "vtkParticleCompat.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleFrameBudget.h"
#include "vtkParticleMemory.h"
#include "vtkParticleOcclusionCuller.h"
#include "vtkParticleShaderHooks.h"
#include "vtkParticleShaders.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMetaballMapper);

namespace
{
// storage binding points of the lists (the fragment lists of the transparent mapper use 4-7)
const unsigned int RangeBinding = 0;
const unsigned int EntryBinding = 1;
const unsigned int IdBinding = 2;
const unsigned int ColorBinding = 3;
const char* const ExtensionLine = "#extension GL_ARB_shader_storage_buffer_object : require\n"
                                  "#extension GL_ARB_conservative_depth : require\n";
// bytes of a list entry (centre offset and radius, neighbour index) and per particle (range)
const double EntryBytes = 20.0;
const double ParticleBytes = 8.0;
// the shader variants: the final draw (vicinity in one pass; the walking plane's shading), the
// walking plane's splat passes, the vicinity pre-pass's iso-spheres and the vicinity draw
// limited by the pre-pass's depth
enum ShaderVariant
{
  FinalDraw = 0,
  WalkingSplat = 1,
  VicinitySpheres = 2,
  VicinityLimited = 3
};
// window-depth margin of the pre-pass limit (as vtkParticleOcclusionCuller's DepthMargin): far
// above the float rounding of the depths the shaders write
const float PrePassDepthMargin = 1.0f / 1048576.0f;

// The neighbour-list build (vtkMetaballMapper::UpdateNeighborLists): what its stages share, the
// particles and the search's parameters.
struct NeighborSearch
{
  vtkIdType N = 0;
  const float* R = nullptr;      // radii (model units, before RadiusScaleFactor)
  std::vector<double> Positions; // 3 per particle
  double Scale = 1.0;            // |RadiusScaleFactor|
  double K = 2.0;                // InfluenceFactor
  int MaximumNeighbors = 64;
  double RMax = 0.0;         // the largest radius, scaled
  double RadiusFactor = 1.0; // below 1: the query radius shrunk (crowded)
  vtkParticleCellList Cells; // the candidates' cells
};
// The lists the search found for the particles from Begin on: per particle its length, the
// neighbours of all (nearest first), how many lists were cut.
struct NeighborChunk
{
  vtkIdType Begin = 0;
  std::vector<std::int32_t> Counts;
  std::vector<std::int32_t> Neighbors;
  vtkIdType Truncated = 0;
};
}

//------------------------------------------------------------------------------
class vtkMetaballMapper::vtkInternals
{
public:
  explicit vtkInternals(vtkObject* self)
    : Hooks(self)
  {
  }
  vtkParticleShaderHooks Hooks;

  // what the lists were built from
  struct Signature
  {
    vtkDataArray* Positions = nullptr;
    vtkMTimeType PositionsTime = 0;
    vtkFloatArray* Radii = nullptr;
    vtkMTimeType RadiiTime = 0;
    vtkIdType Count = -1;
    double Scale = 0.0;
    double Influence = 0.0;
    int MaximumNeighbors = 0;
    double MaximumMemory = 0.0;
    bool operator==(const Signature& o) const
    {
      return Positions == o.Positions && PositionsTime == o.PositionsTime && Radii == o.Radii &&
        RadiiTime == o.RadiiTime && Count == o.Count && Scale == o.Scale &&
        Influence == o.Influence && MaximumNeighbors == o.MaximumNeighbors &&
        MaximumMemory == o.MaximumMemory;
    }
  };
  Signature Built;
  bool HaveLists = false;

  // the lists on the CPU
  std::vector<std::int32_t> Ranges; // first, count per uploaded particle
  std::vector<float> Entries;       // offset (3), radius per entry
  std::vector<std::int32_t> Ids;    // neighbour per entry
  // the vertex attribute metaballMC: 0 isolated, n > 0 the length of a complete list, -1 a list
  // that was cut
  vtkNew<vtkFloatArray> Flags;
  vtkNew<vtkFloatArray> NoFlags; // all 0: without shader storage every particle is a sphere
  std::vector<float> CullingRadii;
  std::string LastListWarning;
  std::string LastSupportWarning;

  // the lists on the GPU
  vtkWeakPointer<vtkOpenGLRenderWindow> Context;
  vtkSmartPointer<vtkOpenGLBufferObject> RangeBuffer =
    vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> EntryBuffer =
    vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> IdBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> ColorBuffer =
    vtkSmartPointer<vtkOpenGLBufferObject>::New();
  bool ListsUploaded = false;
  bool Supported = true; // the context has shader storage buffers (OpenGL 4.3)

  // the method the vertex buffers and attributes were built for
  int BuiltMethod = -1;
  // the walking depth plane: its buffers, the pass being drawn (0: the final draw), whether the
  // shaders blend scalar colours, the smallest positive radius (model units, before scaling)
  vtkNew<vtkMetaballWalkingPlane> Plane;
  int Pass = 0;
  int Variant = FinalDraw;      // the shader variant wanted (ShaderVariant)
  int BuiltVariant = FinalDraw; // and built
  std::string OpacityWarning;   // the last warning about an opacity that is not applied
  std::string WalkWarning;      // the last warning about a still walk cut by MaximumPasses
  // the vicinity pre-pass: the depth of the iso-spheres, its viewport origin
  vtkNew<vtkTextureObject> PrePassDepth;
  int PrePassOrigin[2] = { 0, 0 };
  bool WalkingColors = false;
  double SmallestRadius = 0.0;
  double AnchorMC[3] = { 0.0, 0.0, 0.0 }; // lambda's origin: the centre of the positions' bounds
  // per frame: the anchor in vertex-buffer coordinates (as the shader sees it), lambda of the
  // near plane
  float WalkingAnchor[3] = { 0.0f, 0.0f, 0.0f };
  float WalkingNear = 0.0f;

  void ReleaseBuffers(bool current)
  {
    vtkParticleComputeProgram::ReleaseStorage(this->RangeBuffer, current);
    vtkParticleComputeProgram::ReleaseStorage(this->EntryBuffer, current);
    vtkParticleComputeProgram::ReleaseStorage(this->IdBuffer, current);
    vtkParticleComputeProgram::ReleaseStorage(this->ColorBuffer, current);
    this->ListsUploaded = false;
  }

  // what the lists of `self`'s uploaded particles are built from
  static Signature SignatureOf(vtkMetaballMapper* self)
  {
    vtkDataArray* positions = self->GetUploadedPositions();
    vtkFloatArray* radii = self->GetUploadedRadii();
    Signature signature;
    signature.Positions = positions;
    signature.PositionsTime = positions ? positions->GetMTime() : 0;
    signature.Radii = radii;
    signature.RadiiTime = radii ? radii->GetMTime() : 0;
    signature.Count = radii ? radii->GetNumberOfTuples() : 0;
    signature.Scale = std::abs(self->RadiusScaleFactor);
    signature.Influence = self->InfluenceFactor;
    signature.MaximumNeighbors = self->MaximumNumberOfNeighbors;
    signature.MaximumMemory = self->MaximumListMemory;
    return signature;
  }

  // the lists' arrays sized for n particles, with no entry
  void ResetLists(vtkIdType n)
  {
    this->Ranges.assign(2 * static_cast<size_t>(n), 0);
    this->Entries.clear();
    this->Ids.clear();
    this->Flags->SetNumberOfTuples(n);
    this->CullingRadii.assign(static_cast<size_t>(n), 0.0f);
  }

  // the lists the search found, each cut to `cap` entries: ranges, entries, ids, flags and
  // culling radii; returns the number of entries, adds the lists the cap cut to `cut`
  vtkIdType WriteLists(const NeighborSearch& search, const std::vector<NeighborChunk>& chunks,
    std::int32_t cap, vtkIdType& cut);
};

//------------------------------------------------------------------------------
vtkMetaballMapper::vtkMetaballMapper()
  : Internals(new vtkInternals(this))
{
  this->Internals->Flags->SetName("metaballMC");
}

//------------------------------------------------------------------------------
vtkMetaballMapper::~vtkMetaballMapper()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
double vtkMetaballMapper::KernelScale(double influenceFactor)
{
  const double f = 1.0 - 1.0 / (influenceFactor * influenceFactor);
  return 1.0 / (f * f);
}

//------------------------------------------------------------------------------
double vtkMetaballMapper::IsolatedRadiusFactor(double influenceFactor, double isoValue)
{
  const double ratio = isoValue / KernelScale(influenceFactor);
  if (!(ratio < 1.0))
  {
    return 0.0;
  }
  return influenceFactor * std::sqrt(1.0 - std::sqrt(ratio));
}

//------------------------------------------------------------------------------
double* vtkMetaballMapper::GetBounds()
{
  this->Superclass::GetBounds();
  if (!vtkMath::AreBoundsInitialized(this->Bounds))
  {
    return this->Bounds;
  }
  vtkFloatArray* radii = this->GetParticleRadii();
  double range[2] = { 0.0, 0.0 };
  if (radii && radii->GetNumberOfTuples() > 0)
  {
    radii->GetRange(range, 0);
  }
  // the superclass grew the centres by the largest radius; the surface reaches k R
  const double scale = std::abs(this->RadiusScaleFactor);
  const double extra = std::max(0.0, this->InfluenceFactor - 1.0) * range[1] * scale;
  for (int k = 0; k < 3; ++k)
  {
    this->Bounds[2 * k] -= extra;
    this->Bounds[2 * k + 1] += extra;
  }
  return this->Bounds;
}

//------------------------------------------------------------------------------
bool vtkMetaballMapper::GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  if (this->Superclass::GetNeedToRebuildBufferObjects(ren, act))
  {
    return true;
  }
  if (this->Method == WALKING_DEPTH_PLANE)
  {
    return this->Internals->BuiltMethod != this->Method;
  }
  // the lists (and the per-particle flags) also depend on these
  const vtkInternals::Signature& built = this->Internals->Built;
  return this->Internals->BuiltMethod != this->Method || !this->Internals->HaveLists ||
    built.Scale != std::abs(this->RadiusScaleFactor) || built.Influence != this->InfluenceFactor ||
    built.MaximumNeighbors != this->MaximumNumberOfNeighbors ||
    built.MaximumMemory != this->MaximumListMemory;
}

//------------------------------------------------------------------------------
namespace
{
// The largest of the n radii r.
float LargestRadius(const float* r, vtkIdType n)
{
  float largest = 0.0f;
  for (vtkIdType i = 0; i < n; ++i)
  {
    largest = std::max(largest, r[i]);
  }
  return largest;
}

// The positions in one double array (skipped particles sit on a valid one with radius 0 and
// are never neighbours, nor binned).
void CopyPositions(vtkDataArray* positions, NeighborSearch& search)
{
  search.Positions.resize(3 * static_cast<size_t>(search.N));
  double* xyz = search.Positions.data();
  vtkSMPTools::For(0, search.N,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        positions->GetTuple(i, xyz + 3 * i);
      }
    });
}

// The mean number of candidates a query finds (itself included), from a sample of the
// particles.
double MeanCandidates(const NeighborSearch& search)
{
  const vtkIdType n = search.N;
  const float* r = search.R;
  const double k = search.K;
  double sum = 0.0;
  vtkIdType sampled = 0;
  const vtkIdType step = std::max<vtkIdType>(1, n / 256);
  for (vtkIdType i = 0; i < n; i += step)
  {
    if (r[i] > 0.0f)
    {
      const double q = k * (r[i] * search.Scale + search.RMax);
      vtkIdType found = 1; // itself
      search.Cells.ForEachCandidate(i, [&](vtkIdType, double d2) { found += d2 < q * q ? 1 : 0; });
      sum += static_cast<double>(found);
      ++sampled;
    }
  }
  return sampled > 0 ? sum / sampled : 0.0;
}

// Candidates: the centres within k (R_i + R_max) of each particle (every particle whose
// influence sphere can overlap its own), from cells of edge 2 k R_max. A sample of the
// particles first measures how many that is; when crowded (a huge InfluenceFactor makes every
// particle a neighbour of every other), the query radius and the cells shrink so that a query
// finds about 2 (M + 1) centres: the cost stays O(N M) instead of O(N^2), and the lists,
// possibly incomplete, are counted as cut.
void BuildCandidateCells(NeighborSearch& search)
{
  if (!(search.RMax > 0.0))
  {
    return;
  }
  const double k = search.K;
  const double rMax = search.RMax;
  const int maxNeighbors = search.MaximumNeighbors;
  search.Cells.Build(search.Positions.data(), search.N, search.R, 2.0 * k * rMax);
  const double mean = MeanCandidates(search);
  if (mean > 4.0 * (maxNeighbors + 1))
  {
    search.RadiusFactor = std::cbrt(2.0 * (maxNeighbors + 1) / mean);
    search.Cells.Build(
      search.Positions.data(), search.N, search.R, search.RadiusFactor * 2.0 * k * rMax);
  }
}

// The list of particle i (radius > 0) appended to the chunk: the candidates whose influence
// spheres overlap its own, the nearest M of them; returns its length. `overlapping` is scratch.
std::int32_t FindNeighborsOf(const NeighborSearch& search, vtkIdType i,
  std::vector<std::pair<double, std::int32_t>>& overlapping, NeighborChunk& chunk)
{
  const float* r = search.R;
  const double scale = search.Scale;
  const double k = search.K;
  const double ri = r[i] * scale;
  const double q = search.RadiusFactor * k * (ri + search.RMax);
  overlapping.clear();
  search.Cells.ForEachCandidate(i,
    [&](vtkIdType j, double d2)
    {
      const double reach = k * (ri + r[j] * scale);
      if (d2 < reach * reach && d2 < q * q)
      {
        overlapping.emplace_back(d2, static_cast<std::int32_t>(j));
      }
    });
  // the nearest M (by centre distance), nearest first
  const size_t keep = std::min<size_t>(overlapping.size(), search.MaximumNeighbors);
  if (keep < overlapping.size())
  {
    std::nth_element(overlapping.begin(), overlapping.begin() + keep, overlapping.end());
  }
  std::sort(overlapping.begin(), overlapping.begin() + keep);
  for (size_t m = 0; m < keep; ++m)
  {
    chunk.Neighbors.push_back(overlapping[m].second);
  }
  if (overlapping.size() > keep || search.RadiusFactor < 1.0)
  {
    ++chunk.Truncated;
  }
  return static_cast<std::int32_t>(keep);
}

// The lists of all particles, in chunks (in parallel), ordered by their first particle.
std::vector<NeighborChunk> FindNeighbors(const NeighborSearch& search)
{
  vtkSMPThreadLocal<std::vector<NeighborChunk>> chunks;
  vtkSMPTools::For(0, search.N,
    [&](vtkIdType begin, vtkIdType end)
    {
      NeighborChunk chunk;
      chunk.Begin = begin;
      chunk.Counts.resize(static_cast<size_t>(end - begin));
      std::vector<std::pair<double, std::int32_t>> overlapping;
      for (vtkIdType i = begin; i < end; ++i)
      {
        std::int32_t count = 0;
        if (search.R[i] > 0.0f)
        {
          count = FindNeighborsOf(search, i, overlapping, chunk);
        }
        chunk.Counts[i - begin] = count;
      }
      chunks.Local().push_back(std::move(chunk));
    });

  std::vector<NeighborChunk> ordered;
  for (std::vector<NeighborChunk>& local : chunks)
  {
    for (NeighborChunk& chunk : local)
    {
      ordered.push_back(std::move(chunk));
    }
  }
  std::sort(ordered.begin(), ordered.end(),
    [](const NeighborChunk& a, const NeighborChunk& b) { return a.Begin < b.Begin; });
  return ordered;
}

// The memory bound: every list cut to the share that fits. Returns the entries a list keeps
// (0 when the lists cannot be allocated), says why into `warning`; `truncated` is the number of
// lists the search cut.
std::int32_t ListCap(const NeighborSearch& search, const std::vector<NeighborChunk>& chunks,
  double maximumListMemory, std::ostream& warning, vtkIdType& truncated)
{
  const vtkIdType n = search.N;
  double total = 0.0;
  vtkIdType listed = 0;
  truncated = 0;
  for (const NeighborChunk& chunk : chunks)
  {
    total += static_cast<double>(chunk.Neighbors.size());
    truncated += chunk.Truncated;
    for (std::int32_t c : chunk.Counts)
    {
      listed += c > 0 ? 1 : 0;
    }
  }
  const double budget = maximumListMemory * 1048576.0;
  std::int32_t cap = search.MaximumNeighbors;
  if (n * ParticleBytes + total * EntryBytes > budget || total > 2147483647.0)
  {
    const double entries =
      std::min(2147483647.0, std::max(0.0, (budget - n * ParticleBytes) / EntryBytes));
    cap = static_cast<std::int32_t>(
      std::max(0.0, std::floor(entries / std::max<vtkIdType>(1, listed))));
    warning << "The neighbour lists of " << n << " particles would take "
            << (n * ParticleBytes + total * EntryBytes) / 1048576.0
            << " MiB, more than MaximumListMemory (" << maximumListMemory
            << " MiB): every list keeps its " << cap
            << " nearest neighbours; the surface is approximate where particles have more. ";
  }
  std::string why;
  if (!vtkParticleMemory::CanAllocate(
        std::min(total, static_cast<double>(cap) * listed) * EntryBytes, why))
  {
    warning << "The neighbour lists cannot be allocated (" << why
            << "): the particles are drawn as spheres. ";
    cap = 0;
  }
  return cap;
}

// The first entry of each chunk's lists, each list cut to `cap` (one more: the total); adds the
// lists the cap cuts to `cut`.
std::vector<vtkIdType> ChunkOffsets(
  const std::vector<NeighborChunk>& chunks, std::int32_t cap, vtkIdType& cut)
{
  std::vector<vtkIdType> chunkOffsets(chunks.size() + 1, 0);
  for (size_t c = 0; c < chunks.size(); ++c)
  {
    vtkIdType sum = 0;
    for (std::int32_t count : chunks[c].Counts)
    {
      sum += std::min(count, cap);
      cut += count > cap ? 1 : 0;
    }
    chunkOffsets[c + 1] = chunkOffsets[c] + sum;
  }
  return chunkOffsets;
}

// The particles with a radius and an empty list (drawn as plain spheres).
vtkIdType CountIsolated(const NeighborSearch& search, const std::vector<std::int32_t>& ranges)
{
  vtkIdType isolated = 0;
  for (vtkIdType i = 0; i < search.N; ++i)
  {
    isolated += (search.R[i] > 0.0f && ranges[2 * i + 1] == 0) ? 1 : 0;
  }
  return isolated;
}

// The warning about the `truncated` lists the search cut.
void DescribeTruncation(std::ostream& warning, const NeighborSearch& search, vtkIdType truncated)
{
  const int maxNeighbors = search.MaximumNeighbors;
  warning << truncated << " of " << search.N
          << " particles have more than MaximumNumberOfNeighbors (" << maxNeighbors
          << ") particles within their influence radius (InfluenceFactor " << search.K
          << (search.RadiusFactor < 1.0 ? "; so crowded that only the nearest were searched" : "")
          << "): their " << maxNeighbors
          << " nearest are used; the surface there is approximate. Lower InfluenceFactor or "
             "raise MaximumNumberOfNeighbors (at most 255). ";
}
}

//------------------------------------------------------------------------------
// Offsets, then the entries (centre offsets formed in double: exact far from the origin).
vtkIdType vtkMetaballMapper::vtkInternals::WriteLists(const NeighborSearch& search,
  const std::vector<NeighborChunk>& chunks, std::int32_t cap, vtkIdType& cut)
{
  const std::vector<vtkIdType> chunkOffsets = ChunkOffsets(chunks, cap, cut);
  const vtkIdType entries = chunkOffsets.back();
  this->Entries.resize(4 * static_cast<size_t>(entries));
  this->Ids.resize(static_cast<size_t>(entries));
  float* flags = this->Flags->GetPointer(0);
  const float* r = search.R;
  const double* xyz = search.Positions.data();
  const double k = search.K;
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks.size()),
    [&](vtkIdType cb, vtkIdType ce)
    {
      for (vtkIdType c = cb; c < ce; ++c)
      {
        const NeighborChunk& chunk = chunks[c];
        vtkIdType out = chunkOffsets[c];
        size_t in = 0;
        for (size_t m = 0; m < chunk.Counts.size(); ++m)
        {
          const vtkIdType i = chunk.Begin + static_cast<vtkIdType>(m);
          const std::int32_t count = chunk.Counts[m];
          const std::int32_t kept = std::min(count, cap);
          this->Ranges[2 * i] = static_cast<std::int32_t>(out);
          this->Ranges[2 * i + 1] = kept;
          flags[i] = kept == 0 ? 0.0f : (kept == count ? static_cast<float>(kept) : -1.0f);
          // the culler tests a sphere containing the imposter: the influence sphere (the
          // iso-sphere of an isolated particle is inside it for every IsoValue)
          this->CullingRadii[i] = static_cast<float>(k * r[i]);
          const double* ci = xyz + 3 * i;
          for (std::int32_t e = 0; e < kept; ++e)
          {
            const std::int32_t j = chunk.Neighbors[in + e];
            const double* cj = xyz + 3 * static_cast<vtkIdType>(j);
            float* entry = &this->Entries[4 * static_cast<size_t>(out)];
            entry[0] = static_cast<float>(cj[0] - ci[0]);
            entry[1] = static_cast<float>(cj[1] - ci[1]);
            entry[2] = static_cast<float>(cj[2] - ci[2]);
            entry[3] = r[j];
            this->Ids[static_cast<size_t>(out)] = j;
            ++out;
          }
          in += static_cast<size_t>(count);
        }
      }
    });
  this->Flags->Modified();
  return entries;
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::UpdateNeighborLists()
{
  vtkInternals& internals = *this->Internals;
  const vtkInternals::Signature signature = vtkInternals::SignatureOf(this);
  if (internals.HaveLists && internals.Built == signature)
  {
    return;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  internals.Built = signature;
  internals.HaveLists = true;
  internals.ListsUploaded = false;
  ++this->NumberOfListBuilds;

  const vtkIdType n = signature.Count;
  internals.ResetLists(n);
  this->NumberOfListEntries = 0;
  this->NumberOfIsolatedParticles = 0;
  this->NumberOfTruncatedLists = 0;
  if (n == 0 || !signature.Positions)
  {
    this->LastListBuildSeconds = vtkTimerLog::GetUniversalTime() - start;
    return;
  }

  NeighborSearch search;
  search.N = n;
  search.R = signature.Radii->GetPointer(0);
  search.Scale = signature.Scale;
  search.K = this->InfluenceFactor;
  search.MaximumNeighbors = this->MaximumNumberOfNeighbors;
  search.RMax = LargestRadius(search.R, n) * search.Scale;
  CopyPositions(signature.Positions, search);
  BuildCandidateCells(search);
  const std::vector<NeighborChunk> chunks = FindNeighbors(search);

  std::ostringstream warning;
  vtkIdType truncated = 0;
  const std::int32_t cap = ListCap(search, chunks, this->MaximumListMemory, warning, truncated);
  vtkIdType cut = 0;
  const vtkIdType entries = internals.WriteLists(search, chunks, cap, cut);

  this->NumberOfListEntries = entries;
  this->NumberOfIsolatedParticles = CountIsolated(search, internals.Ranges);
  this->NumberOfTruncatedLists = std::max(truncated, cut);
  if (truncated > 0)
  {
    DescribeTruncation(warning, search, truncated);
  }
  this->WarnOnChange(warning.str(), internals.LastListWarning);
  this->LastListBuildSeconds = vtkTimerLog::GetUniversalTime() - start;
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::CacheParticleAttributes(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::CacheParticleAttributes(ren, act);
  vtkInternals& internals = *this->Internals;
  vtkOpenGLRenderWindow* context = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  internals.BuiltMethod = this->Method;
  if (this->Method == WALKING_DEPTH_PLANE)
  {
    // no lists; the largest step follows the smallest radius (Sec. 3.2.3)
    vtkFloatArray* radii = this->GetUploadedRadii();
    const vtkIdType n = radii ? radii->GetNumberOfTuples() : 0;
    float smallest = std::numeric_limits<float>::max();
    for (vtkIdType i = 0; i < n; ++i)
    {
      const float r = radii->GetValue(i);
      if (r > 0.0f && r < smallest)
      {
        smallest = r;
      }
    }
    internals.SmallestRadius = smallest < std::numeric_limits<float>::max() ? smallest : 0.0;
    vtkDataArray* positions = this->GetUploadedPositions();
    for (int k = 0; k < 3; ++k)
    {
      double range[2] = { 0.0, 0.0 };
      if (positions && n > 0)
      {
        positions->GetRange(range, k);
      }
      internals.AnchorMC[k] = 0.5 * (range[0] + range[1]);
    }
    internals.NoFlags->SetNumberOfTuples(n);
    internals.NoFlags->FillValue(0.0f);
    this->VBOs->CacheDataArray("metaballMC", internals.NoFlags, ren, VTK_FLOAT);
    return;
  }

  std::string reason;
  internals.Supported = context && vtkParticleComputeProgram::IsSupported(context, &reason);
  std::string supportWarning;
  if (!internals.Supported)
  {
    supportWarning = "Metaballs need shader storage buffers in the fragment stage: " + reason +
      ". Every particle is drawn as its sphere.";
    if (supportWarning != internals.LastSupportWarning)
    {
      vtkErrorMacro(<< supportWarning);
    }
  }
  internals.LastSupportWarning = supportWarning;

  this->UpdateNeighborLists();
  if (!internals.Supported)
  {
    // every particle through the sphere path
    internals.NoFlags->SetNumberOfTuples(internals.Flags->GetNumberOfTuples());
    internals.NoFlags->FillValue(0.0f);
    this->VBOs->CacheDataArray("metaballMC", internals.NoFlags, ren, VTK_FLOAT);
    return;
  }
  this->VBOs->CacheDataArray("metaballMC", internals.Flags, ren, VTK_FLOAT);

  // the lists and the colours into shader storage (the context is current while buffers build)
  if (internals.Context != context)
  {
    internals.ReleaseBuffers(false);
    internals.Context = context;
  }
  auto upload = [](vtkOpenGLBufferObject* buffer, const void* data, size_t bytes)
  {
    static const std::int32_t zeros[4] = { 0, 0, 0, 0 };
    const size_t size = std::max<size_t>(bytes, sizeof(zeros));
    return vtkParticleComputeProgram::AllocateStorage(buffer, size) &&
      vtkParticleComputeProgram::UploadStorage(
        buffer, 0, bytes > 0 ? bytes : sizeof(zeros), bytes > 0 ? data : zeros);
  };
  if (!internals.ListsUploaded)
  {
    const bool ok =
      upload(internals.RangeBuffer, internals.Ranges.data(), internals.Ranges.size() * 4) &&
      upload(internals.EntryBuffer, internals.Entries.data(), internals.Entries.size() * 4) &&
      upload(internals.IdBuffer, internals.Ids.data(), internals.Ids.size() * 4);
    if (!ok)
    {
      vtkErrorMacro(<< "The neighbour lists could not be uploaded (" << internals.Entries.size() / 4
                    << " entries).");
    }
    internals.ListsUploaded = true;
  }
  // colours of the drawn particles (RGBA8, r in the low byte), when scalars colour them
  vtkUnsignedCharArray* colors = this->Colors;
  const vtkIdType n = this->GetUploadedRadii() ? this->GetUploadedRadii()->GetNumberOfTuples() : 0;
  vtkUnsignedCharArray* strided = nullptr;
  vtkPolyData* input = this->GetInput();
  if (colors && input && colors->GetNumberOfTuples() == input->GetNumberOfPoints() &&
    colors->GetNumberOfComponents() == 4)
  {
    strided = vtkUnsignedCharArray::SafeDownCast(this->StrideForUpload(colors));
  }
  if (strided && strided->GetNumberOfTuples() == n)
  {
    upload(internals.ColorBuffer, strided->GetPointer(0), static_cast<size_t>(n) * 4);
  }
  else
  {
    upload(internals.ColorBuffer, nullptr, 0);
  }
}

//------------------------------------------------------------------------------
const float* vtkMetaballMapper::GetCullingRadii()
{
  vtkInternals& internals = *this->Internals;
  vtkFloatArray* radii = this->GetUploadedRadii();
  if (!radii || internals.CullingRadii.size() != static_cast<size_t>(radii->GetNumberOfTuples()))
  {
    return this->Superclass::GetCullingRadii();
  }
  return internals.CullingRadii.data();
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
  vtkInternals& internals = *this->Internals;

  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string gs = shaders[vtkShader::Geometry]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  internals.Hooks.Begin(vs, gs, fs);
  // The surface is opaque whatever the colours' alpha (translucent metaballs are not
  // implemented): a partial alpha would blend it with whatever was drawn before it, which
  // depends on the draw order and, under MPI, on the partition. prMetaballAlpha: 1, or the
  // actor's opacity where VTK draws the actor as translucent geometry.
  internals.Hooks.Insert(
    vtkParticleShaderHooks::Fragment, "//PR::Sphere::Dec", "uniform float prMetaballAlpha;");
  internals.Hooks.Insert(
    vtkParticleShaderHooks::Fragment, "//PR::Shading::Impl", "gl_FragData[0].a = prMetaballAlpha;");
  if (this->Method == WALKING_DEPTH_PLANE)
  {
    this->ReplaceWalkingShaderValues(vs, gs, fs);
  }
  else
  {
    this->ReplaceVicinityShaderValues(vs, gs, fs);
  }
  for (std::string* source : { &vs, &gs, &fs })
  {
    *source = vtkParticleShaders::ResolveIncludes(*source);
  }
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Geometry]->SetSource(gs);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

//------------------------------------------------------------------------------
namespace
{
// VTK's colour code in main() reads the blended colour prMetaballRGBA
void ReadBlendedColor(std::string& fs)
{
  const std::string::size_type main = fs.find("void main()");
  if (main != std::string::npos)
  {
    std::string body = fs.substr(main);
    vtkShaderProgram::Substitute(body, "vertexColorVSOutput.", "prMetaballRGBA.", true);
    fs = fs.substr(0, main) + body;
  }
}
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::ReplaceWalkingShaderValues(
  std::string& vs, std::string& gs, std::string& fs)
{
  vtkInternals& internals = *this->Internals;
  vtkParticleShaderHooks& hooks = internals.Hooks;
  using Hooks = vtkParticleShaderHooks;
  // every particle draws its influence sphere
  // and gives the view depth of its centre from the anchor, formed from the small difference
  // of the centre and the anchor (lambda's origin, near the data, see SetWalkingShaderParameters)
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Dec",
    "uniform float prInfluenceFactor;\n"
    "uniform vec3 prWalkingAnchor;");
  hooks.AddSphereVarying("float", "prWalkingCenterZ");
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Impl",
    "radiusVC *= prInfluenceFactor;\n"
    "  centerRadiusVCVSOutput.w = radiusVC;\n"
    "  prWalkingCenterZVSOutput = (mat3(MCVCMatrix) * (vertexMC.xyz - prWalkingAnchor)).z;");
  const bool colors = fs.find("vertexColorVSOutput") != std::string::npos;
  internals.WalkingColors = colors;
  internals.BuiltVariant = internals.Variant;
  hooks.Insert(Hooks::Fragment, "//PR::Sphere::Dec", "//PR::Include MetaballWalking");
  std::ostringstream surface;
  surface << "vec4 prMetaballRGBA = " << (colors ? "vertexColorVSOutput" : "vec4(1.0)") << ";\n";
  if (internals.Variant == WalkingSplat)
  {
    // The splat passes' variant returns early with its contribution. It writes no depth and
    // its triangles are at depth 0.5, so that the depth test rejects the finished pixels
    // (masked at depth 0 by vtkMetaballWalkingPlane) before the fragment stage runs.
    vtkParticleShaders::ReplaceHook(
      fs, "//VTK::System::Dec", "//VTK::System::Dec\n#define PR_NO_DEPTH_WRITE");
    vtkParticleShaders::ReplaceHook(
      gs, "//VTK::System::Dec", "//VTK::System::Dec\n#define PR_FLAT_DEPTH");
    surface << "  vec4 prSplat;\n"
               "  if (!prHit || !prWalkingSplat(prRayS, prRayD, prT0, prT1,\n"
               "    prWalkingCenterZVSOutput, radiusVC, prMetaballRGBA, prSplat))\n"
               "  {\n"
               "    discard;\n"
               "  }\n"
               "  gl_FragData[0] = prSplat;\n"
               "  return;";
  }
  else
  {
    // the final draw puts the point where the plane is
    surface
      << "  if (prHit)\n"
         "  {\n"
         "    float prTWalk;\n"
         "    prHit = prWalkingSurface(prRayS, prRayD, prT0, prT1, prWalkingCenterZVSOutput,\n"
         "      prTWalk);\n"
         "    prT0 = prTWalk;\n"
         "    prT1 = prTWalk;\n"
         "  }";
    if (colors)
    {
      surface << "\n  prMetaballRGBA = prWalkingColor(prMetaballRGBA);";
    }
  }
  hooks.Insert(Hooks::Fragment, "//PR::Surface::Impl", surface.str());
  hooks.Insert(Hooks::Fragment, "//PR::Surface::Normal",
    "normalVCVSOutput = prWalkingNormal(prRayD, normalVCVSOutput);");
  if (colors)
  {
    ReadBlendedColor(fs);
  }
}

//------------------------------------------------------------------------------
namespace
{
// The fragment code of the vicinity method's surface (//PR::Surface::Impl): the search of the
// ray's chord through the influence sphere for the first crossing of the iso-value
// (Metaballs.glsl), the chord ended at the pre-pass's iso-sphere depth where `limited`, the blended
// colour there where the particles have `colors`.
std::string VicinitySurfaceCode(bool colors, bool limited)
{
  std::ostringstream surface;
  surface
    << "bool prMetaballInside = false;\n"
       "  vec4 prMetaballRGBA = "
    << (colors ? "vertexColorVSOutput" : "vec4(1.0)")
    << ";\n"
       "  if (prHit && prMetaballVSOutput > 0.0)\n"
       "  {\n"
       "    float prRadius = radiusVC / prMetaballVSOutput;\n"
       "    // the search starts where the chord enters the influence sphere, or on the near\n"
       "    // plane when that cuts it (clip z + w = 0, affine along the ray)\n"
       "    vec2 prZW0 = prClipZWOfSplitPointVC(clipZWOfTranslation,\n"
       "      centerOffsetVCVSOutput + prRayS, VCDCMatrix);\n"
       "    vec2 prZW1 = prClipZWOfSplitPointVC(clipZWOfTranslation,\n"
       "      centerOffsetVCVSOutput + prRayS + prRayD, VCDCMatrix);\n"
       "    float prF0 = prZW0.x + prZW0.y;\n"
       "    float prF1 = (prZW1.x + prZW1.y) - prF0;\n"
       "    float prTLo = prT0;\n"
       "    bool prNearCut = false;\n"
       "    if (prF1 > 0.0 && -prF0 / prF1 > prT0)\n"
       "    {\n"
       "      prTLo = -prF0 / prF1;\n"
       "      prNearCut = true;\n"
       "    }\n"
       "    float prTHi = prT1;\n";
  if (limited)
  {
    // The pre-pass's iso-spheres lie inside the surface, so the surface is never behind
    // their depth: the chord ends there (clip z - ndc w is affine along the ray), and a
    // fragment whose chord starts behind it is dropped before it gathers its kernels.
    surface << "    float prLimitNDC = 2.0 * (texelFetch(prPrePassDepth,\n"
               "      ivec2(gl_FragCoord.xy) - prPrePassOrigin, 0).r + prPrePassMargin) - 1.0;\n"
               "    float prG0 = prZW0.x - prLimitNDC * prZW0.y;\n"
               "    float prG1 = (prZW1.x - prLimitNDC * prZW1.y) - prG0;\n"
               "    if (prG0 + prG1 * prTLo > 0.0)\n"
               "    {\n"
               "      prTHi = prTLo;\n"
               "    }\n"
               "    else if (prG1 > 0.0)\n"
               "    {\n"
               "      prTHi = min(prTHi, -prG0 / prG1);\n"
               "    }\n";
  }
  surface << "    prHit = prTLo < prTHi;\n"
             "    float prTHit;\n"
             "    if (prHit)\n"
             "    {\n"
             "      prGatherKernels(particleIdVSOutput, prRadius, prRayS, prRayD, prTLo, prTHi);\n"
             "      prHit = prMetaballSearch(prTLo, prTHi, prRadius, prTHit, prMetaballInside) &&\n"
             "        (prNearCut || !prMetaballInside);\n"
             "    }\n"
             "    if (prHit)\n"
             "    {\n"
             "      prT0 = prTHit;\n"
             "      prT1 = prTHit;\n";
  if (colors)
  {
    surface << "      prMetaballRGBA = prMetaballColor(prRayS + prTHit * prRayD, prRadius, "
               "vertexColorVSOutput);\n";
  }
  surface << "    }\n"
             "  }";
  return surface.str();
}
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::ReplaceVicinityShaderValues(
  std::string& vs, std::string& gs, std::string& fs)
{
  vtkInternals& internals = *this->Internals;
  vtkParticleShaderHooks& hooks = internals.Hooks;
  using Hooks = vtkParticleShaderHooks;
  (void)vs;
  internals.BuiltVariant = internals.Variant;
  if (internals.Variant == VicinitySpheres)
  {
    // the pre-pass: every particle's own iso-sphere, a plain sphere of the core
    hooks.Insert(Hooks::Vertex, "//PR::Sphere::Dec", "uniform float prIsolatedScale;");
    hooks.Insert(Hooks::Vertex, "//PR::Sphere::Impl",
      "radiusVC *= prIsolatedScale;\n"
      "  centerRadiusVCVSOutput.w = radiusVC;");
    return;
  }
  const bool limited = internals.Variant == VicinityLimited;
  // The imposter: an isolated particle's iso-sphere; else the part of the influence sphere
  // (k R) where the particle can hold the largest kernel of a surface point. There the field
  // is IsoValue, summed over at most 1 + n kernels (its n neighbours reach it, no other
  // particle), so the largest is at least IsoValue / (1 + n): c (1 - r^2/K^2)^2 >= IsoValue /
  // (1 + n), r <= K sqrt(1 - sqrt(IsoValue / (c (1 + n)))). Every surface point lies in the
  // sphere of the particle with its largest kernel, whose search finds it (the first crossing
  // on the whole ray is the first in that chord). The bound is reached where the largest kernel
  // is shared by all (coincident particles), so the sphere is 0.02 R larger: the search must
  // start outside the surface there. A cut list (-1) keeps the influence sphere.
  // prMetaballVSOutput: the drawn radius over R for these particles, 0 for isolated ones.
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Dec",
    "in float metaballMC;\n"
    "uniform float prInfluenceFactor;\n"
    "uniform float prIsolatedScale;\n"
    "uniform float prIsoOverKernelScale; // IsoValue / c");
  hooks.AddSphereVarying("float", "prMetaball");
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Impl",
    "float prScale = prIsolatedScale;\n"
    "  if (metaballMC != 0.0)\n"
    "  {\n"
    "    prScale = prInfluenceFactor;\n"
    "    if (metaballMC > 0.0)\n"
    "    {\n"
    "      prScale = min(prScale,\n"
    "        prScale * sqrt(max(1.0 - sqrt(prIsoOverKernelScale / (1.0 + metaballMC)), 0.0)) + "
    "0.02);\n"
    "    }\n"
    "  }\n"
    "  radiusVC *= prScale;\n"
    "  centerRadiusVCVSOutput.w = radiusVC;\n"
    "  prMetaballVSOutput = metaballMC != 0.0 ? prScale : 0.0;");
  if (limited)
  {
    // isolated particles are final in the pre-pass
    hooks.Insert(Hooks::Geometry, "//PR::Sphere::Cull",
      "if (!(prMetaballVSOutput[0] > 0.0))\n"
      "  {\n"
      "    return;\n"
      "  }");
  }

  if (internals.Supported)
  {
    const bool colors = fs.find("vertexColorVSOutput") != std::string::npos;
    std::ostringstream dec;
    dec << "#define PR_METABALL_KERNELS " << this->MaximumNumberOfNeighbors + 1 << "\n";
    if (colors)
    {
      dec << "#define PR_METABALL_COLORS\n";
    }
    if (limited)
    {
      dec << "uniform sampler2D prPrePassDepth; // window depth of the pre-pass's iso-spheres\n"
             "uniform ivec2 prPrePassOrigin;    // its viewport's lower left pixel\n"
             "uniform float prPrePassMargin;\n";
    }
    dec << "//PR::Include Metaballs\n"
           "layout(depth_greater) out float gl_FragDepth;";
    hooks.Insert(Hooks::Fragment, "//PR::Sphere::Dec", dec.str());
    vtkParticleShaders::ReplaceHook(
      fs, "//VTK::System::Dec", std::string("//VTK::System::Dec\n") + ExtensionLine);
    // the imposters at their nearest depth, written depths only greater (early depth tests)
    vtkParticleShaders::ReplaceHook(
      gs, "//VTK::System::Dec", "//VTK::System::Dec\n#define PR_CONSERVATIVE_DEPTH");

    hooks.Insert(Hooks::Fragment, "//PR::Surface::Impl", VicinitySurfaceCode(colors, limited));
    hooks.Insert(Hooks::Fragment, "//PR::Surface::Normal",
      "if (prMetaballVSOutput > 0.0)\n"
      "  {\n"
      "    normalVCVSOutput = prMetaballNormal(hitRel, radiusVC / prMetaballVSOutput);\n"
      "    if (dot(normalVCVSOutput, prRayD) > 0.0)\n"
      "    {\n"
      "      normalVCVSOutput = -normalVCVSOutput;\n"
      "    }\n"
      "    prInside = prInside || prMetaballInside;\n"
      "  }");
    if (colors)
    {
      ReadBlendedColor(fs);
    }
  }
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  if (!program)
  {
    return;
  }
  vtkInternals& internals = *this->Internals;
  program->SetUniformf("prMetaballAlpha",
    act->IsRenderingTranslucentPolygonalGeometry()
      ? static_cast<float>(act->GetProperty()->GetOpacity())
      : 1.0f);
  const double k = this->InfluenceFactor;
  program->SetUniformf("prInfluenceFactor", static_cast<float>(k));
  if (this->Method == WALKING_DEPTH_PLANE)
  {
    this->SetWalkingShaderParameters(program, ren, act);
    return;
  }
  program->SetUniformf(
    "prIsolatedScale", static_cast<float>(IsolatedRadiusFactor(k, this->IsoValue)));
  program->SetUniformf("prIsoOverKernelScale", static_cast<float>(this->IsoValue / KernelScale(k)));
  if (!internals.Supported || !program->IsUniformUsed("prKernelScale"))
  {
    return;
  }
  program->SetUniformf("prKernelScale", static_cast<float>(KernelScale(k)));
  program->SetUniformf("prIsoValue", static_cast<float>(this->IsoValue));
  program->SetUniformf("prTolerance", static_cast<float>(this->Tolerance));
  program->SetUniformi("prIterationLimit", this->IterationLimit);
  program->SetUniformi("prRefinementSteps", this->RefinementSteps);
  // view -> list coordinates (model coordinates relative to the drawn centre, radii times
  // RadiusScaleFactor): the inverse of the linear part of model -> view, over the core's
  // radius scale sigma (Shaders/Metaballs.glsl)
  vtkNew<vtkMatrix4x4> modelToView;
  vtkMatrix4x4* view = ren->GetActiveCamera()->GetModelViewTransformMatrix();
  if (act->GetIsIdentity())
  {
    modelToView->DeepCopy(view);
  }
  else
  {
    vtkMatrix4x4::Multiply4x4(view, act->GetMatrix(), modelToView);
  }
  double linear[3][3];
  double inverse[3][3];
  for (int row = 0; row < 3; ++row)
  {
    for (int col = 0; col < 3; ++col)
    {
      linear[row][col] = modelToView->GetElement(row, col);
    }
  }
  vtkMath::Invert3x3(linear, inverse);
  float viewToList[9]; // column-major
  for (int col = 0; col < 3; ++col)
  {
    for (int row = 0; row < 3; ++row)
    {
      viewToList[3 * col + row] = static_cast<float>(inverse[row][col]);
    }
  }
  // the actor's part of the core's radius scale (GetRadiusScaleVC)
  double sigma = act->GetIsIdentity() ? 1.0 : std::cbrt(std::abs(act->GetMatrix()->Determinant()));
  sigma = sigma > 0.0 && std::isfinite(sigma) ? sigma : 1.0; // a singular actor draws nothing
  program->SetUniformMatrix3x3("prViewToListLinear", viewToList);
  program->SetUniformf("prViewToListScale", static_cast<float>(1.0 / sigma));
  program->SetUniformf("prListRadiusScale", static_cast<float>(this->RadiusScaleFactor));
  if (internals.Variant == VicinityLimited)
  {
    program->SetUniformi("prPrePassDepth", internals.PrePassDepth->GetTextureUnit());
    program->SetUniform2i("prPrePassOrigin", internals.PrePassOrigin);
    program->SetUniformf("prPrePassMargin", PrePassDepthMargin);
  }

  // the storage blocks
  const unsigned int handle = static_cast<unsigned int>(program->GetHandle());
  using Program = vtkParticleComputeProgram;
  Program::BindStorageBlock(handle, "prMetaballRangeBlock", RangeBinding, internals.RangeBuffer);
  Program::BindStorageBlock(handle, "prMetaballEntryBlock", EntryBinding, internals.EntryBuffer);
  Program::BindStorageBlock(handle, "prMetaballIdBlock", IdBinding, internals.IdBuffer);
  Program::BindStorageBlock(handle, "prMetaballColorBlock", ColorBinding, internals.ColorBuffer);
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::SetWalkingShaderParameters(
  vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& internals = *this->Internals;
  vtkMetaballWalkingPlane* plane = internals.Plane;
  program->SetUniformi("prWalkingPass", internals.Pass);
  program->SetUniformf("prKernelScale", static_cast<float>(KernelScale(this->InfluenceFactor)));
  program->SetUniformf("prIsoValue", static_cast<float>(this->IsoValue));
  program->SetUniformf("prWalkingTolerance", static_cast<float>(this->WalkingTolerance));
  program->SetUniformf("prWalkingStepMax", static_cast<float>(plane->GetMaximumStep()));
  program->SetUniform3f("prWalkingAnchor", internals.WalkingAnchor);
  program->SetUniformf("prWalkingNear", internals.WalkingNear);
  int origin[2] = { 0, 0 };
  if (internals.Pass == 0)
  {
    origin[0] = plane->GetViewport()[0];
    origin[1] = plane->GetViewport()[1];
  }
  program->SetUniform2i("prWalkingOrigin", origin);
  const std::pair<const char*, vtkTextureObject*> samplers[] = {
    { "prWalkingPlaneTexture", plane->GetPlaneTexture() },
    { "prWalkingGradientTexture", plane->GetGradientTexture() },
    { "prWalkingColorTexture", plane->GetColorTexture() },
  };
  for (const auto& sampler : samplers)
  {
    if (sampler.second->GetTextureUnit() >= 0)
    {
      program->SetUniformi(sampler.first, sampler.second->GetTextureUnit());
    }
  }
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::RenderWalkingPlane(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& internals = *this->Internals;
  vtkMetaballWalkingPlane* plane = internals.Plane;
  if (!(internals.SmallestRadius > 0.0))
  {
    return; // nothing drawn
  }
  // lambda's origin, the anchor: the centre of the particles' bounds in vertex-buffer
  // coordinates, rounded to float as the shader sees it; lambda of the near plane
  // (z = -near in view coordinates) from its view depth in double
  vtkNew<vtkMatrix4x4> modelToBuffer;
  vtkMatrix4x4::Transpose(this->VBOShiftScale, modelToBuffer); // buffer -> model, stored transposed
  modelToBuffer->Invert();
  double anchor[4] = { internals.AnchorMC[0], internals.AnchorMC[1], internals.AnchorMC[2], 1.0 };
  modelToBuffer->MultiplyPoint(anchor, anchor);
  for (int i = 0; i < 3; ++i)
  {
    internals.WalkingAnchor[i] = static_cast<float>(anchor[i]);
    anchor[i] = internals.WalkingAnchor[i];
  }
  vtkNew<vtkMatrix4x4> bufferToView;
  this->GetBufferToViewMatrix(ren, act, bufferToView);
  double anchorVC[4];
  bufferToView->MultiplyPoint(anchor, anchorVC);
  const double nearDistance = ren->GetActiveCamera()->GetClippingRange()[0];
  internals.WalkingNear = static_cast<float>(nearDistance + anchorVC[2]);
  plane->SetIsoValue(this->IsoValue);
  const double smallest = internals.SmallestRadius * std::abs(this->GetRadiusScaleVC(act));
  plane->SetMaximumStep(smallest * this->MaximumStepFactor);
  plane->SetDepthTolerance(smallest * this->WalkingTolerance);
  plane->SetDensityTolerance(this->WalkingTolerance);
  plane->SetStepOracle(this->StepOracle);
  plane->SetMaximumPasses(this->MaximumPasses);
  plane->SetFinishedShare(this->FinishedShare);
  // the frame budget's levels: 0 the walk bounded by TimeBudget, 1 (exact: still frames) the walk
  // to convergence, bounded by MaximumPasses alone
  vtkParticleFrameBudget* budget = this->GetFrameBudget();
  const bool converge = budget->BeginFrame(ren, 2) == 1;
  plane->SetTimeBudget(converge ? std::numeric_limits<double>::max() : this->TimeBudget);

  // the splat passes need every particle: no occlusion culling (see GetOcclusionCullingCompiled)
  const bool culling = this->OcclusionCulling;
  this->OcclusionCulling = false;
  vtkTextureObject* planeTexture = plane->GetPlaneTexture();
  if (plane->Begin(ren))
  {
    internals.Variant = WalkingSplat;
    internals.Pass = 1;
    plane->StartInitialization();
    this->Superclass::RenderPieceDraw(ren, act);
    planeTexture->Activate();
    internals.Pass = 2;
    while (plane->StartDensity())
    {
      this->Superclass::RenderPieceDraw(ren, act);
      plane->Step();
    }
    internals.Pass = 3;
    plane->StartShading(false);
    this->Superclass::RenderPieceDraw(ren, act);
    if (internals.WalkingColors)
    {
      internals.Pass = 4;
      plane->StartShading(true);
      this->Superclass::RenderPieceDraw(ren, act);
    }
    plane->End();

    // the final draw
    internals.Variant = FinalDraw;
    internals.Pass = 0;
    plane->GetGradientTexture()->Activate();
    if (internals.WalkingColors)
    {
      plane->GetColorTexture()->Activate();
    }
    this->Superclass::RenderPieceDraw(ren, act);
    planeTexture->Deactivate();
    plane->GetGradientTexture()->Deactivate();
    if (internals.WalkingColors)
    {
      plane->GetColorTexture()->Deactivate();
    }
  }
  budget->EndFrame();
  this->OcclusionCulling = culling;

  std::string cut;
  if (converge && plane->GetTermination() == vtkMetaballWalkingPlane::PASS_LIMIT)
  {
    std::ostringstream text;
    text << "The walking depth plane stopped at Maximum Passes (" << this->MaximumPasses
         << ") with " << plane->GetActivePixels() << " of " << plane->GetCoveredPixels()
         << " pixels not finished: the surface is missing or misplaced there. Raise Maximum "
            "Passes or use the vicinity method.";
    cut = text.str();
  }
  this->WarnOnChange(cut, internals.WalkWarning);
}

//------------------------------------------------------------------------------
bool vtkMetaballMapper::RenderVicinityWithPrePass(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLRenderWindow* context = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!this->DepthPrePass || !internals.Supported || !context ||
    this->NumberOfIsolatedParticles >= this->Primitives[PrimitiveTris].IBO->IndexCount)
  {
    return false; // not wanted, no lists, or nothing but isolated particles (one pass is all)
  }
  // the depth must be a plain single-sampled [0, 1] depth buffer that the draws test and write
  vtkOpenGLState* ostate = context->GetState();
  GLboolean depthMask = GL_FALSE;
  ostate->vtkglGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
  GLint depthFunc = GL_LESS;
  ostate->vtkglGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  GLfloat range[2] = { 0.0f, 1.0f };
  glGetFloatv(GL_DEPTH_RANGE, range);
  if (!ostate->GetEnumState(GL_DEPTH_TEST) || !depthMask ||
    (depthFunc != GL_LESS && depthFunc != GL_LEQUAL) || samples > 0 || range[0] != 0.0f ||
    range[1] != 1.0f)
  {
    return false;
  }
  GLint viewport[4] = { 0, 0, 0, 0 };
  ostate->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  if (viewport[2] <= 0 || viewport[3] <= 0)
  {
    return false;
  }

  // the iso-spheres
  internals.Variant = VicinitySpheres;
  this->Superclass::RenderPieceDraw(ren, act);

  // their depth, copied from the bound framebuffer
  vtkTextureObject* depth = internals.PrePassDepth;
  if (depth->GetContext() != context)
  {
    depth->SetContext(context);
  }
  if (static_cast<int>(depth->GetWidth()) != viewport[2] ||
    static_cast<int>(depth->GetHeight()) != viewport[3] || !depth->GetHandle())
  {
    depth->SetMinificationFilter(vtkTextureObject::Nearest);
    depth->SetMagnificationFilter(vtkTextureObject::Nearest);
    depth->SetWrapS(vtkTextureObject::ClampToEdge);
    depth->SetWrapT(vtkTextureObject::ClampToEdge);
    if (!depth->AllocateDepth(static_cast<unsigned int>(viewport[2]),
          static_cast<unsigned int>(viewport[3]), vtkTextureObject::Float32))
    {
      vtkErrorMacro("Cannot allocate the depth pre-pass texture; the influence spheres are drawn"
                    " without it.");
      return false; // (drawn again by the one-pass variant, over the iso-spheres)
    }
  }
  GLint drawFramebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
  ostate->PushReadFramebufferBinding();
  ostate->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<unsigned int>(drawFramebuffer));
  depth->Bind();
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, viewport[0], viewport[1], viewport[2], viewport[3]);
  ostate->PopReadFramebufferBinding();
  internals.PrePassOrigin[0] = viewport[0];
  internals.PrePassOrigin[1] = viewport[1];

  // the influence spheres, searched in front of that depth
  internals.Variant = VicinityLimited;
  depth->Activate();
  vtkParticleOcclusionCuller* culler = this->GetOcclusionCuller();
  culler->DepthPrimedOn();
  this->Superclass::RenderPieceDraw(ren, act);
  culler->DepthPrimedOff();
  depth->Deactivate();
  internals.Variant = FinalDraw;
  return true;
}

//------------------------------------------------------------------------------
bool vtkMetaballMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  // the walking depth plane and the vicinity pre-pass switch between two variants twice per
  // frame (the shader cache keeps both programs compiled)
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act) ||
    this->Internals->Variant != this->Internals->BuiltVariant;
}

//------------------------------------------------------------------------------
bool vtkMetaballMapper::GetOcclusionCullingCompiled(vtkRenderer* ren)
{
  return this->Method != WALKING_DEPTH_PLANE && this->Superclass::GetOcclusionCullingCompiled(ren);
}

//------------------------------------------------------------------------------
bool vtkMetaballMapper::HasOpaqueGeometry()
{
  return true; // (colours with alpha below 1 included: the surface is opaque)
}

//------------------------------------------------------------------------------
bool vtkMetaballMapper::HasTranslucentPolygonalGeometry()
{
  return false;
}

//------------------------------------------------------------------------------
vtkMetaballWalkingPlane* vtkMetaballMapper::GetWalkingPlane()
{
  return this->Internals->Plane;
}

//------------------------------------------------------------------------------
std::string vtkMetaballMapper::GetQualityLevelNames()
{
  if (this->Method == WALKING_DEPTH_PLANE)
  {
    return "walk within the time budget|walk to convergence";
  }
  return this->Internals->Supported ? "iso-spheres|exact surface" : "exact surface";
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  std::string translucent;
  if (act->IsRenderingTranslucentPolygonalGeometry())
  {
    std::ostringstream text;
    text << "The metaball surface is an opaque surface (translucent metaballs are not "
            "implemented). With the actor's opacity "
         << act->GetProperty()->GetOpacity()
         << " VTK draws it as translucent geometry, blended by VTK's translucency method: set "
            "the opacity to 1 (or ForceOpaqueOn() the actor) for the opaque surface.";
    translucent = text.str();
  }
  this->WarnOnChange(translucent, this->Internals->OpacityWarning);
  if (this->Method == WALKING_DEPTH_PLANE)
  {
    this->RenderWalkingPlane(ren, act);
    return;
  }
  // the frame budget's levels (vicinity method with lists): 0 the iso-spheres alone, 1 exact
  vtkParticleFrameBudget* budget = this->GetFrameBudget();
  const int levels = this->Internals->Supported ? 2 : 1;
  if (budget->BeginFrame(ren, levels) < levels - 1)
  {
    this->LastDrawUsedDepthPrePass = false;
    this->Internals->Variant = VicinitySpheres;
    this->Superclass::RenderPieceDraw(ren, act);
    this->Internals->Variant = FinalDraw;
  }
  else
  {
    this->LastDrawUsedDepthPrePass = this->RenderVicinityWithPrePass(ren, act);
    if (!this->LastDrawUsedDepthPrePass)
    {
      this->Internals->Variant = FinalDraw;
      this->Superclass::RenderPieceDraw(ren, act);
    }
  }
  budget->EndFrame();
  if (this->Internals->Supported)
  {
    for (unsigned int binding : { RangeBinding, EntryBinding, IdBinding, ColorBinding })
    {
      vtkParticleComputeProgram::BindStorage(binding, nullptr);
    }
  }
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLRenderWindow* context = internals.Context;
  const bool current = context && vtkParticleComputeProgram::MakeCurrentForRelease(context);
  internals.ReleaseBuffers(current);
  internals.Plane->ReleaseGraphicsResources(window);
  internals.PrePassDepth->ReleaseGraphicsResources(window);
  internals.Context = nullptr;
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
bool vtkMetaballMapper::GetDrawsSphereGlyphs()
{
  return false;
}

//------------------------------------------------------------------------------
void vtkMetaballMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent
     << "Method: " << (this->Method == WALKING_DEPTH_PLANE ? "WalkingDepthPlane" : "Vicinity")
     << "\n";
  os << indent << "InfluenceFactor: " << this->InfluenceFactor << "\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "DepthPrePass: " << this->DepthPrePass << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "RefinementSteps: " << this->RefinementSteps << "\n";
  os << indent << "IterationLimit: " << this->IterationLimit << "\n";
  os << indent << "MaximumNumberOfNeighbors: " << this->MaximumNumberOfNeighbors << "\n";
  os << indent << "MaximumListMemory: " << this->MaximumListMemory << "\n";
  os << indent << "WalkingTolerance: " << this->WalkingTolerance << "\n";
  os << indent << "StepOracle: " << this->StepOracle << "\n";
  os << indent << "MaximumStepFactor: " << this->MaximumStepFactor << "\n";
  os << indent << "MaximumPasses: " << this->MaximumPasses << "\n";
  os << indent << "TimeBudget: " << this->TimeBudget << "\n";
  os << indent << "FinishedShare: " << this->FinishedShare << "\n";
  os << indent << "WalkingPlane:\n";
  this->Internals->Plane->PrintSelf(os, indent.GetNextIndent());
  os << indent << "NumberOfListBuilds: " << this->NumberOfListBuilds << "\n";
  os << indent << "LastListBuildSeconds: " << this->LastListBuildSeconds << "\n";
  os << indent << "NumberOfListEntries: " << this->NumberOfListEntries << "\n";
  os << indent << "NumberOfIsolatedParticles: " << this->NumberOfIsolatedParticles << "\n";
  os << indent << "NumberOfTruncatedLists: " << this->NumberOfTruncatedLists << "\n";
}
