#include "vtkSNDFTileCache.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleShaders.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
// bytes per texel besides the bin words: four vec4 sums
const double SumBytesPerTexel = 64.0;
const std::size_t TileTexels = static_cast<std::size_t>(vtkSNDFTileCache::TileSize) *
  static_cast<std::size_t>(vtkSNDFTileCache::TileSize);
// the most samples a texel averaged from finer ones claims (bin counts are 16 bits)
const float MaxDownsampledSamples = 32768.0f;

// storage bindings: the page table (or a list of slots) 0, the minimum 1, the sums from 2, the
// bins from 4 (SNDFTiles.glsl)
const unsigned int PageBinding = 0;
const unsigned int MinimumBinding = 1;
const unsigned int TileListBinding = 3;
const unsigned int SumBinding = 2;
const int MaximumSumBuffers = 16;
const unsigned int BinBinding = 4;
const int MaximumBinBuffers = 64;

// a tile: level, phase of the level's grid (x, y), tile position (x, y)
using Key = std::array<long long, 5>;

long long FloorDiv(long long a, long long b)
{
  long long q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

// the finer tiles under a tile: their slots (-1 where not in the cache) over a rectangle
// TilesX wide, and the texel of that rectangle under the tile's first texel
struct Children
{
  std::vector<int> Slots;
  int TilesX = 0;
  int TexelOffset[2] = { 0, 0 };
};

struct Slot
{
  Key Tile{};
  bool Used = false;
  long long LastUsed = 0; // the MapView() that last touched it
  long long Shown = -1;   // the MapView() that shows it (not to be evicted)
  long long Version = 0;  // the lighting table its shaded sums were formed with
};
}

//------------------------------------------------------------------------------
class vtkSNDFTileCache::vtkInternals
{
public:
  vtkWeakPointer<vtkOpenGLRenderWindow> Context;
  // the pool: the bins and the sums, each split over buffers of whole tiles within the
  // context's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (SlotsPer* tiles each)
  std::vector<vtkSmartPointer<vtkOpenGLBufferObject>> BinBuffers;
  std::vector<vtkSmartPointer<vtkOpenGLBufferObject>> SumBuffers;
  int SlotsPerBinBuffer = 1;
  int SlotsPerSumBuffer = 1;
  // the context's block size limit (0: not queried)
  double BlockBytes = 0.0;
  // the page table of the view (binding 2); a scratch table for downsampling and rebaking
  vtkSmartPointer<vtkOpenGLBufferObject> Page = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> Scratch = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> Minimum = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  std::size_t PageBytes = 0;
  std::size_t ScratchBytes = 0;
  vtkNew<vtkParticleComputeProgram> Downsample;
  vtkNew<vtkParticleComputeProgram> Rebake;
  vtkNew<vtkParticleComputeProgram> Recolour;
  vtkNew<vtkParticleComputeProgram> MinSamples;

  std::vector<Slot> Slots;
  std::map<Key, int> Table;
  long long Stamp = 0;
  int WordsPerTexel = 0;
  // the last MapView() (Mapped: its page table stands)
  bool Mapped = false;
  vtkSNDFTileCache::Placement MappedView;
  int MappedSize[2] = { 0, 0 };
  long long MappedVersion = 0;
  // the last mapped view: its tile rectangle, the window's offset into it, the pool's parts
  // (bin buffer, sum buffer) its tiles lie in
  int TilesX = 0;
  int TexelOffset[2] = { 0, 0 };
  std::vector<std::pair<int, int>> ViewParts;
  // per part, where its tiles start in the tile list and how many there are
  std::vector<std::pair<int, int>> ViewPartTiles;
  vtkSmartPointer<vtkOpenGLBufferObject> TileList = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  std::size_t TileListBytes = 0;
  // the zoom's per-texel records (SNDFDownsample.glsl)
  vtkSmartPointer<vtkOpenGLBufferObject> Partial = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  std::size_t PartialBytes = 0;

  // uploads `values` into `buffer` (grown as needed) for binding 2
  static void Upload(
    vtkOpenGLBufferObject* buffer, std::size_t& capacity, const std::vector<int>& values)
  {
    const std::size_t bytes = std::max<std::size_t>(1, values.size()) * sizeof(int);
    if (bytes > capacity)
    {
      vtkParticleComputeProgram::AllocateStorage(buffer, std::max(bytes, 2 * capacity));
      capacity = std::max(bytes, 2 * capacity);
    }
    if (!values.empty())
    {
      vtkParticleComputeProgram::UploadStorage(
        buffer, 0, values.size() * sizeof(int), values.data());
    }
  }

  // The tiles `down` levels finer (their texels 2^down times smaller) under tile (tx, ty) of the
  // view's level and grid; false when none of them is in the cache.
  bool FindChildren(const vtkSNDFTileCache::Placement& view, long long tx, long long ty, int down,
    Children& children) const
  {
    const int level = view.Level - down;
    if (level < vtkSNDFTileCache::MinimumLevel)
    {
      return false;
    }
    const long long texel = 1LL << (level + 8); // a texel of that level, in 1/256 level-0 texels
    const long long size = vtkSNDFTileCache::TileSize;
    const long long span = size << down; // its texels under one tile
    long long phase[2];
    long long first[2];
    long long tile0[2];
    int tiles[2];
    for (int a = 0; a < 2; ++a)
    {
      // the finer grid shares the phase modulo its texel; texel i of the view's level covers
      // its texels offset + i * 2^down ...
      phase[a] = view.Phase[a] % texel;
      const long long offset = (view.Phase[a] - phase[a]) / texel;
      first[a] = offset + span * (a == 0 ? tx : ty);
      tile0[a] = FloorDiv(first[a], size);
      tiles[a] = static_cast<int>(FloorDiv(first[a] + span - 1, size) - tile0[a] + 1);
      children.TexelOffset[a] = static_cast<int>(first[a] - size * tile0[a]);
    }
    children.TilesX = tiles[0];
    children.Slots.assign(static_cast<std::size_t>(tiles[0]) * tiles[1], -1);
    bool any = false;
    for (int j = 0; j < tiles[1]; ++j)
    {
      for (int i = 0; i < tiles[0]; ++i)
      {
        auto it = this->Table.find(Key{ level, phase[0], phase[1], tile0[0] + i, tile0[1] + j });
        if (it != this->Table.end())
        {
          children.Slots[static_cast<std::size_t>(j) * tiles[0] + i] = it->second;
          any = true;
        }
      }
    }
    return any;
  }

  void ClearSlot(int slot)
  {
    const GLuint zero = 0;
    const std::size_t binBytes = TileTexels * this->WordsPerTexel * 4;
    const std::size_t sumBytes = TileTexels * static_cast<std::size_t>(SumBytesPerTexel);
    auto clear = [&](vtkOpenGLBufferObject* buffer, std::size_t bytes, int index)
    {
      glBindBuffer(GL_COPY_WRITE_BUFFER, static_cast<GLuint>(buffer->GetHandle()));
      glClearBufferSubData(GL_COPY_WRITE_BUFFER, GL_R32UI, static_cast<GLintptr>(bytes * index),
        static_cast<GLsizeiptr>(bytes), GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    };
    clear(
      this->BinBuffers[slot / this->SlotsPerBinBuffer], binBytes, slot % this->SlotsPerBinBuffer);
    clear(
      this->SumBuffers[slot / this->SlotsPerSumBuffer], sumBytes, slot % this->SlotsPerSumBuffer);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  }

  // The buffers of part (bin buffer, sum buffer) for a one-part shader (in use).
  void BindPart(vtkParticleComputeProgram* program, const std::pair<int, int>& part)
  {
    program->SetUniformi("prWordsPerPixel", this->WordsPerTexel);
    program->SetUniformui(
      "prSlotsPerBinBuffer", static_cast<unsigned int>(this->SlotsPerBinBuffer));
    program->SetUniformui(
      "prSlotsPerSumBuffer", static_cast<unsigned int>(this->SlotsPerSumBuffer));
    program->SetUniformui("prBinPart", static_cast<unsigned int>(part.first));
    program->SetUniformui("prSumPart", static_cast<unsigned int>(part.second));
    vtkParticleComputeProgram::BindStorage(BinBinding, this->BinBuffers[part.first]);
    vtkParticleComputeProgram::BindStorage(SumBinding, this->SumBuffers[part.second]);
  }

  // the parts (bin buffer, sum buffer) that hold the given slots
  std::vector<std::pair<int, int>> PartsOf(const std::vector<int>& slots) const
  {
    std::vector<std::pair<int, int>> parts;
    for (int slot : slots)
    {
      if (slot >= 0)
      {
        parts.emplace_back(slot / this->SlotsPerBinBuffer, slot / this->SlotsPerSumBuffer);
      }
    }
    std::sort(parts.begin(), parts.end());
    parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
    return parts;
  }

  // One dispatch of `program` (in use; SNDFRebake.glsl's layout: group z works on the tile in
  // slot prPageTable[z]) per part of the pool over the given slots.
  void DispatchOverSlots(vtkParticleComputeProgram* program, const std::vector<int>& slots)
  {
    for (const auto& part : this->PartsOf(slots))
    {
      std::vector<int> inPart;
      for (int slot : slots)
      {
        if (slot / this->SlotsPerBinBuffer == part.first &&
          slot / this->SlotsPerSumBuffer == part.second)
        {
          inPart.push_back(slot);
        }
      }
      Upload(this->Scratch, this->ScratchBytes, inPart);
      vtkParticleComputeProgram::BindStorage(PageBinding, this->Scratch);
      this->BindPart(program, part);
      program->Dispatch(TileSize / 16, TileSize / 16, static_cast<unsigned int>(inPart.size()));
    }
  }

  // The storage declarations and accessors of SNDFTiles.glsl: one part of the pool bound (one
  // bin buffer and one sum buffer), prBinPart and prSumPart say which; prSNDFInPart() tells a
  // texel of the part.
  std::string StorageCode() const
  {
    std::string code = "layout(std430, binding = " + std::to_string(PageBinding) +
      ") readonly buffer prPageBuffer\n{\n  int prPageTable[];\n};\n"
      "uniform int prWordsPerPixel;\nuniform uint prSlotsPerBinBuffer;\n"
      "uniform uint prSlotsPerSumBuffer;\n";
    code += "uniform uint prBinPart;\nuniform uint prSumPart;\n"
            "layout(std430, binding = " +
      std::to_string(SumBinding) +
      ") buffer prSumBuffer0\n{\n  vec4 prSums0[];\n};\n"
      "layout(std430, binding = " +
      std::to_string(BinBinding) +
      ") buffer prBinBuffer0\n{\n  uint prBins0[];\n};\n"
      "bool prSNDFInPart(uint texel)\n{\n  uint slot = texel >> 12u;\n"
      "  return slot / prSlotsPerBinBuffer == prBinPart && slot / prSlotsPerSumBuffer == "
      "prSumPart;\n}\n"
      "uint prBinWordAddress(uint texel)\n{\n"
      "  return (texel - prBinPart * prSlotsPerBinBuffer * 4096u) * uint(prWordsPerPixel);\n}\n"
      "uint prSumAddress(uint texel)\n{\n"
      "  return (texel - prSumPart * prSlotsPerSumBuffer * 4096u) * 4u;\n}\n"
      "uint prBinWordAt(uint a, uint k)\n{\n  return prBins0[a + k];\n}\n"
      "void prSetBinWordAt(uint a, uint k, uint value)\n{\n  prBins0[a + k] = value;\n}\n"
      "vec4 prSumAt(uint a, uint k)\n{\n  return prSums0[a + k];\n}\n"
      "void prSetSumAt(uint a, uint k, vec4 value)\n{\n  prSums0[a + k] = value;\n}\n"
      "vec4 prSum(uint texel, uint k)\n{\n  return prSumAt(prSumAddress(texel), k);\n}\n";
    return code;
  }

  // prColourMatrix of the recolour program (in use) from a row-major matrix
  static void SetColourMatrix(vtkParticleComputeProgram* program, const double m[3][3])
  {
    // (GLSL's mat3 is column-major)
    float columns[9];
    for (int row = 0; row < 3; ++row)
    {
      for (int column = 0; column < 3; ++column)
      {
        columns[3 * column + row] = static_cast<float>(m[row][column]);
      }
    }
    program->SetUniformMatrix3x3("prColourMatrix", columns);
  }

  // The recolour dispatch (its mode's uniforms set, the program in use) over `slots`; marks them
  // for rebaking and counts them.
  int RecolourSlots(vtkSNDFTileCache* self, const std::vector<int>& slots)
  {
    vtkParticleComputeProgram* program = this->Recolour;
    program->SetUniformi("prBins", self->Bins);
    this->DispatchOverSlots(program, slots);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    vtkParticleComputeProgram::UseNone();
    // their shaded sums are formed again before they are shown or averaged
    for (int slot : slots)
    {
      this->Slots[slot].Version = -1;
    }
    this->Mapped = false;
    self->NumberOfRecolouredTiles += static_cast<long long>(slots.size());
    return static_cast<int>(slots.size());
  }

  // a slot for a new tile: a free one, else the least recently used one the view does not show;
  // -1 when every slot is shown
  int TakeSlot(long long& evictions)
  {
    int best = -1;
    for (int i = 0; i < static_cast<int>(this->Slots.size()); ++i)
    {
      const Slot& slot = this->Slots[i];
      if (!slot.Used)
      {
        return i;
      }
      if (slot.Shown != this->Stamp && (best < 0 || slot.LastUsed < this->Slots[best].LastUsed))
      {
        best = i;
      }
    }
    if (best >= 0)
    {
      this->Table.erase(this->Slots[best].Tile);
      this->Slots[best].Used = false;
      ++evictions;
    }
    return best;
  }

  // Tile `slot` as the average of its children `down` levels finer (SNDFDownsample.glsl): phase
  // 0 once per part that holds children (into per-texel records), phase 1 into the destination.
  void DownsampleInto(int slot, const Children& children, int down, int bins, bool moments)
  {
    const int maskVec4s = (std::max(1, bins * bins / 32) + 3) / 4;
    const std::size_t partialBytes =
      TileTexels * (4 + maskVec4s + (moments ? 2 : 1) * bins * bins) * 16;
    if (this->PartialBytes < partialBytes)
    {
      vtkParticleComputeProgram::AllocateStorage(this->Partial, partialBytes);
      this->PartialBytes = partialBytes;
    }
    vtkParticleComputeProgram* program = this->Downsample;
    program->Use();
    program->SetUniformi("prDestSlot", slot);
    program->SetUniformi("prFactor", 1 << down);
    program->SetUniformi("prBins", bins);
    program->SetUniformi("prMoments", moments ? 1 : 0);
    program->SetUniformf("prMaxSamples", MaxDownsampledSamples);
    program->SetUniform2i("prTexelOffset", children.TexelOffset[0], children.TexelOffset[1]);
    program->SetUniformi("prTilesX", children.TilesX);
    vtkInternals::Upload(this->Scratch, this->ScratchBytes, children.Slots);
    vtkParticleComputeProgram::BindStorage(PageBinding, this->Scratch);
    vtkParticleComputeProgram::BindStorage(MinimumBinding, this->Partial);
    program->SetUniformi("prPhase", 0);
    int first = 1;
    for (const auto& part : this->PartsOf(children.Slots))
    {
      this->BindPart(program, part);
      program->SetUniformi("prFirst", first);
      program->Dispatch(TileSize / 16, TileSize / 16);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
      first = 0;
    }
    program->SetUniformi("prPhase", 1);
    this->BindPart(
      program, std::make_pair(slot / this->SlotsPerBinBuffer, slot / this->SlotsPerSumBuffer));
    program->Dispatch(TileSize / 16, TileSize / 16);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    vtkParticleComputeProgram::UseNone();
  }

  // The view's tiles (indices into `page`) grouped part by part for the tile-list dispatches.
  void UploadViewTileList(const std::vector<int>& page)
  {
    std::vector<int> list;
    this->ViewPartTiles.clear();
    for (const auto& part : this->ViewParts)
    {
      const int first = static_cast<int>(list.size());
      for (std::size_t t = 0; t < page.size(); ++t)
      {
        if (page[t] / this->SlotsPerBinBuffer == part.first &&
          page[t] / this->SlotsPerSumBuffer == part.second)
        {
          list.push_back(static_cast<int>(t));
        }
      }
      this->ViewPartTiles.emplace_back(first, static_cast<int>(list.size()) - first);
    }
    Upload(this->TileList, this->TileListBytes, list);
  }
};

vtkStandardNewMacro(vtkSNDFTileCache);

//------------------------------------------------------------------------------
vtkSNDFTileCache::vtkSNDFTileCache()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkSNDFTileCache::~vtkSNDFTileCache()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
int vtkSNDFTileCache::GetWordsPerTexel(int bins, bool moments)
{
  // (three words per bin, SNDFBins.glsl, then the occupancy bits, then two words of moments per
  // bin)
  return (moments ? 5 : 3) * bins * bins + std::max(1, bins * bins / 32);
}

//------------------------------------------------------------------------------
double vtkSNDFTileCache::GetTileBytes(int bins, bool moments)
{
  return static_cast<double>(TileTexels) *
    (4.0 * GetWordsPerTexel(bins, moments) + SumBytesPerTexel);
}

//------------------------------------------------------------------------------
int vtkSNDFTileCache::GetTilesForView(int width, int height)
{
  return ((width + TileSize - 1) / TileSize + 1) * ((height + TileSize - 1) / TileSize + 1);
}

//------------------------------------------------------------------------------
double vtkSNDFTileCache::GetBytes() const
{
  return this->NumberOfSlots * GetTileBytes(this->Bins, this->Moments);
}

//------------------------------------------------------------------------------
int vtkSNDFTileCache::GetNumberOfTiles() const
{
  return static_cast<int>(this->Internals->Table.size());
}

//------------------------------------------------------------------------------
void vtkSNDFTileCache::QueryLimits(vtkOpenGLRenderWindow* context)
{
  vtkInternals& internals = *this->Internals;
  if (internals.Context == context && internals.BlockBytes > 0.0)
  {
    return;
  }
  if (internals.Context && internals.Context != context)
  {
    this->ReleaseGraphicsResources(internals.Context);
  }
  internals.Context = context;
  GLint64 blockSize = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockSize);
  // (at least the GL 4.3 minimum, 2^27 bytes, and int-addressable). A dispatch binds one bin
  // buffer and one sum buffer, 5 storage blocks in all (GL 4.3 guarantees 8).
  internals.BlockBytes = static_cast<double>(
    std::min<GLint64>(std::max<GLint64>(blockSize, GLint64(1) << 27), (GLint64(1) << 31) - 1));
}

//------------------------------------------------------------------------------
int vtkSNDFTileCache::GetMaximumSlots(vtkOpenGLRenderWindow* context, int bins, bool moments)
{
  this->QueryLimits(context);
  const vtkInternals& internals = *this->Internals;
  const double binTile = static_cast<double>(TileTexels) * 4.0 * GetWordsPerTexel(bins, moments);
  const double sumTile = static_cast<double>(TileTexels) * SumBytesPerTexel;
  return static_cast<int>(std::min(MaximumBinBuffers * std::floor(internals.BlockBytes / binTile),
    MaximumSumBuffers * std::floor(internals.BlockBytes / sumTile)));
}

//------------------------------------------------------------------------------
double vtkSNDFTileCache::GetBlockBytes() const
{
  return this->Internals->BlockBytes;
}

//------------------------------------------------------------------------------
std::string vtkSNDFTileCache::GetShaderSource(const std::string& name)
{
  std::string source = vtkParticleShaders::Get(name);
  const std::string tag = "//PR::SNDFStorage";
  const std::size_t at = source.find(tag);
  if (at != std::string::npos)
  {
    source.replace(at, tag.size(), this->Internals->StorageCode());
  }
  return source;
}

//------------------------------------------------------------------------------
bool vtkSNDFTileCache::Allocate(vtkOpenGLRenderWindow* context, int bins, int slots, bool moments)
{
  vtkInternals& internals = *this->Internals;
  this->QueryLimits(context);
  internals.WordsPerTexel = GetWordsPerTexel(bins, moments);
  this->Clear();
  const std::size_t binTile = TileTexels * internals.WordsPerTexel * 4;
  const std::size_t sumTile = TileTexels * static_cast<std::size_t>(SumBytesPerTexel);
  internals.SlotsPerBinBuffer = std::max(1, static_cast<int>(internals.BlockBytes / binTile));
  internals.SlotsPerSumBuffer = std::max(1, static_cast<int>(internals.BlockBytes / sumTile));
  const int binBuffers = (slots + internals.SlotsPerBinBuffer - 1) / internals.SlotsPerBinBuffer;
  const int sumBuffers = (slots + internals.SlotsPerSumBuffer - 1) / internals.SlotsPerSumBuffer;
  bool ok = slots > 0 && binBuffers <= MaximumBinBuffers && sumBuffers <= MaximumSumBuffers &&
    vtkParticleComputeProgram::AllocateStorage(internals.Minimum, 4);
  auto allocate = [&](std::vector<vtkSmartPointer<vtkOpenGLBufferObject>>& buffers, int count,
                    int per, std::size_t tileBytes)
  {
    for (int b = 0; b < count && ok; ++b)
    {
      if (static_cast<int>(buffers.size()) <= b)
      {
        buffers.push_back(vtkSmartPointer<vtkOpenGLBufferObject>::New());
      }
      ok = vtkParticleComputeProgram::AllocateStorage(
        buffers[b], tileBytes * static_cast<std::size_t>(std::min(per, slots - b * per)));
    }
  };
  allocate(internals.BinBuffers, binBuffers, internals.SlotsPerBinBuffer, binTile);
  allocate(internals.SumBuffers, sumBuffers, internals.SlotsPerSumBuffer, sumTile);
  if (!ok)
  {
    for (auto* family : { &internals.BinBuffers, &internals.SumBuffers })
    {
      for (auto& buffer : *family)
      {
        vtkParticleComputeProgram::ReleaseStorage(buffer, true);
      }
      family->clear();
    }
    this->NumberOfSlots = 0;
    this->Bins = 0;
    return false;
  }
  // (buffers beyond the ones needed now are released)
  for (auto* family : { &internals.BinBuffers, &internals.SumBuffers })
  {
    const std::size_t used =
      static_cast<std::size_t>(family == &internals.BinBuffers ? binBuffers : sumBuffers);
    for (std::size_t b = used; b < family->size(); ++b)
    {
      vtkParticleComputeProgram::ReleaseStorage((*family)[b], true);
    }
    family->resize(used);
  }
  if (!internals.Downsample->IsBuilt())
  {
    internals.Downsample->SetSource(this->GetShaderSource("SNDFDownsample"));
    internals.Rebake->SetSource(this->GetShaderSource("SNDFRebake"));
    internals.Recolour->SetSource(this->GetShaderSource("SNDFRecolour"));
    internals.MinSamples->SetSource(this->GetShaderSource("SNDFMinSamples"));
    if (!internals.Downsample->Build(context) || !internals.Rebake->Build(context) ||
      !internals.Recolour->Build(context) || !internals.MinSamples->Build(context))
    {
      vtkErrorMacro(<< "The S-MIP shaders did not build.");
      this->NumberOfSlots = 0;
      return false;
    }
  }
  internals.Slots.assign(static_cast<std::size_t>(slots), Slot());
  this->NumberOfSlots = slots;
  this->Bins = bins;
  this->Moments = moments;
  this->NumberOfDownsampledTiles = 0;
  this->NumberOfClearedTiles = 0;
  this->NumberOfEvictedTiles = 0;
  this->NumberOfRebakedTiles = 0;
  this->NumberOfRecolouredTiles = 0;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkSNDFTileCache::Clear()
{
  vtkInternals& internals = *this->Internals;
  internals.Mapped = false;
  internals.Table.clear();
  for (Slot& slot : internals.Slots)
  {
    slot = Slot();
  }
}

//------------------------------------------------------------------------------
int vtkSNDFTileCache::Recolour(const double m[3][3])
{
  vtkInternals& internals = *this->Internals;
  std::vector<int> slots;
  for (const auto& entry : internals.Table)
  {
    slots.push_back(entry.second);
  }
  if (slots.empty() || !internals.Recolour->IsBuilt())
  {
    return 0;
  }
  vtkParticleComputeProgram* program = internals.Recolour;
  program->Use();
  internals.SetColourMatrix(program, m);
  program->SetUniformi("prMode", 0);
  return internals.RecolourSlots(this, slots);
}

//------------------------------------------------------------------------------
int vtkSNDFTileCache::RecolourMap(vtkTextureObject* ramps, int size, const double residual[3][3])
{
  vtkInternals& internals = *this->Internals;
  std::vector<int> slots;
  for (const auto& entry : internals.Table)
  {
    slots.push_back(entry.second);
  }
  if (slots.empty() || !this->Moments || !ramps || size < 2 || !internals.Recolour->IsBuilt())
  {
    return 0;
  }
  vtkParticleComputeProgram* program = internals.Recolour;
  program->Use();
  program->SetUniformi("prMode", 1);
  internals.SetColourMatrix(program, residual);
  ramps->Activate();
  program->SetUniformi("prRamps", ramps->GetTextureUnit());
  program->SetUniformi("prRampSize", size);
  const int count = internals.RecolourSlots(this, slots);
  ramps->Deactivate();
  return count;
}

//------------------------------------------------------------------------------
bool vtkSNDFTileCache::MapView(
  const Placement& view, int width, int height, vtkTextureObject* table, long long tableVersion)
{
  vtkInternals& internals = *this->Internals;
  if (this->NumberOfSlots < 1 || width < 1 || height < 1)
  {
    return false;
  }
  if (internals.Mapped && internals.MappedView == view && internals.MappedSize[0] == width &&
    internals.MappedSize[1] == height && internals.MappedVersion == tableVersion)
  {
    return true; // the page table, the tile lists and the tiles' shading stand
  }
  const long long tx0 = FloorDiv(view.Origin[0], TileSize);
  const long long ty0 = FloorDiv(view.Origin[1], TileSize);
  const int tilesX = static_cast<int>(FloorDiv(view.Origin[0] + width - 1, TileSize) - tx0 + 1);
  const int tilesY = static_cast<int>(FloorDiv(view.Origin[1] + height - 1, TileSize) - ty0 + 1);
  if (tilesX * tilesY > this->NumberOfSlots)
  {
    return false;
  }
  ++internals.Stamp;
  std::vector<int> page(static_cast<std::size_t>(tilesX) * tilesY, -1);
  std::vector<int> stale;
  auto keyOf = [&](int level, long long px, long long py, long long tx, long long ty) {
    return Key{ level, px, py, tx, ty };
  };
  auto touch = [&](int slot)
  {
    Slot& s = internals.Slots[slot];
    s.LastUsed = internals.Stamp;
    if (s.Version != tableVersion)
    {
      stale.push_back(slot);
      s.Version = tableVersion;
    }
  };
  // rebake the stale tiles gathered so far (before they are shown or averaged)
  auto rebake = [&]()
  {
    if (stale.empty())
    {
      return;
    }
    vtkParticleComputeProgram* program = internals.Rebake;
    program->Use();
    table->Activate();
    program->SetUniformi("prTable", table->GetTextureUnit());
    program->SetUniformi("prBins", this->Bins);
    internals.DispatchOverSlots(program, stale);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    table->Deactivate();
    vtkParticleComputeProgram::UseNone();
    this->NumberOfRebakedTiles += static_cast<long long>(stale.size());
    stale.clear();
  };

  // the tiles in the cache: shown as they are
  for (int j = 0; j < tilesY; ++j)
  {
    for (int i = 0; i < tilesX; ++i)
    {
      auto it =
        internals.Table.find(keyOf(view.Level, view.Phase[0], view.Phase[1], tx0 + i, ty0 + j));
      if (it != internals.Table.end())
      {
        page[static_cast<std::size_t>(j) * tilesX + i] = it->second;
        internals.Slots[it->second].Shown = internals.Stamp;
        touch(it->second);
      }
    }
  }
  // the others: a slot each, averaged from a finer level where it has tiles, else empty
  for (int j = 0; j < tilesY; ++j)
  {
    for (int i = 0; i < tilesX; ++i)
    {
      int& entry = page[static_cast<std::size_t>(j) * tilesX + i];
      if (entry >= 0)
      {
        continue;
      }
      const int slot = internals.TakeSlot(this->NumberOfEvictedTiles);
      if (slot < 0)
      {
        return false; // (cannot happen: the view's tiles fit)
      }
      entry = slot;
      Slot& s = internals.Slots[slot];
      s.Tile = keyOf(view.Level, view.Phase[0], view.Phase[1], tx0 + i, ty0 + j);
      s.Used = true;
      s.Shown = internals.Stamp;
      s.LastUsed = internals.Stamp;
      s.Version = tableVersion;
      internals.Table[s.Tile] = slot;
      internals.ClearSlot(slot);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

      bool averaged = false;
      for (int down = 1; down <= 2 && !averaged; ++down)
      {
        Children children;
        if (!internals.FindChildren(view, tx0 + i, ty0 + j, down, children))
        {
          continue;
        }
        for (int child : children.Slots)
        {
          if (child >= 0)
          {
            touch(child);
          }
        }
        rebake();
        internals.DownsampleInto(slot, children, down, this->Bins, this->Moments);
        ++this->NumberOfDownsampledTiles;
        averaged = true;
      }
      if (!averaged)
      {
        ++this->NumberOfClearedTiles;
      }
    }
  }
  rebake();
  vtkInternals::Upload(internals.Page, internals.PageBytes, page);
  internals.Mapped = true;
  internals.MappedView = view;
  internals.MappedSize[0] = width;
  internals.MappedSize[1] = height;
  internals.MappedVersion = tableVersion;
  internals.TilesX = tilesX;
  internals.ViewParts = internals.PartsOf(page);
  internals.UploadViewTileList(page);
  internals.TexelOffset[0] = static_cast<int>(view.Origin[0] - TileSize * tx0);
  internals.TexelOffset[1] = static_cast<int>(view.Origin[1] - TileSize * ty0);
  return true;
}

//------------------------------------------------------------------------------
int vtkSNDFTileCache::CountAvailable(const Placement& view, int width, int height)
{
  vtkInternals& internals = *this->Internals;
  const long long tx0 = FloorDiv(view.Origin[0], TileSize);
  const long long ty0 = FloorDiv(view.Origin[1], TileSize);
  const long long tx1 = FloorDiv(view.Origin[0] + width - 1, TileSize);
  const long long ty1 = FloorDiv(view.Origin[1] + height - 1, TileSize);
  int available = 0;
  Children children;
  for (long long ty = ty0; ty <= ty1; ++ty)
  {
    for (long long tx = tx0; tx <= tx1; ++tx)
    {
      if (internals.Table.count(Key{ view.Level, view.Phase[0], view.Phase[1], tx, ty }) ||
        internals.FindChildren(view, tx, ty, 1, children) ||
        internals.FindChildren(view, tx, ty, 2, children))
      {
        ++available;
      }
    }
  }
  return available;
}

//------------------------------------------------------------------------------
void vtkSNDFTileCache::BindView(vtkParticleComputeProgram* program)
{
  vtkInternals& internals = *this->Internals;
  program->SetUniform2i("prTexelOffset", internals.TexelOffset[0], internals.TexelOffset[1]);
  program->SetUniformi("prTilesX", internals.TilesX);
  vtkParticleComputeProgram::BindStorage(PageBinding, internals.Page);
}

//------------------------------------------------------------------------------
int vtkSNDFTileCache::GetNumberOfViewParts() const
{
  return static_cast<int>(this->Internals->ViewParts.size());
}

//------------------------------------------------------------------------------
unsigned int vtkSNDFTileCache::BindViewPart(vtkParticleComputeProgram* program, int part)
{
  vtkInternals& internals = *this->Internals;
  const std::size_t k = static_cast<std::size_t>(part);
  internals.BindPart(program, internals.ViewParts[k]);
  program->SetUniformi("prTileListOffset", internals.ViewPartTiles[k].first);
  vtkParticleComputeProgram::BindStorage(TileListBinding, internals.TileList);
  return static_cast<unsigned int>(internals.ViewPartTiles[k].second);
}

//------------------------------------------------------------------------------
unsigned int vtkSNDFTileCache::CountMinimumSamples(int width, int height)
{
  vtkInternals& internals = *this->Internals;
  const unsigned int none = 0xFFFFFFFFu;
  vtkParticleComputeProgram::UploadStorage(internals.Minimum, 0, 4, &none);
  vtkParticleComputeProgram* program = internals.MinSamples;
  program->Use();
  program->SetUniform2i("prSize", width, height);
  this->BindView(program);
  vtkParticleComputeProgram::BindStorage(MinimumBinding, internals.Minimum);
  for (int part = 0; part < this->GetNumberOfViewParts(); ++part)
  {
    const unsigned int tiles = this->BindViewPart(program, part);
    program->Dispatch(TileSize / 16, TileSize / 16, tiles);
  }
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  vtkParticleComputeProgram::UseNone();
  unsigned int minimum = 0;
  vtkParticleComputeProgram::DownloadStorage(internals.Minimum, 0, 4, &minimum);
  return minimum == none ? 0u : minimum;
}

//------------------------------------------------------------------------------
void vtkSNDFTileCache::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& internals = *this->Internals;
  internals.Downsample->ReleaseGraphicsResources(w);
  internals.Rebake->ReleaseGraphicsResources(w);
  internals.Recolour->ReleaseGraphicsResources(w);
  internals.MinSamples->ReleaseGraphicsResources(w);
  const bool current = vtkParticleComputeProgram::MakeCurrentForRelease(internals.Context);
  for (auto* buffer : { &internals.Page, &internals.Scratch, &internals.Minimum,
         &internals.TileList, &internals.Partial })
  {
    vtkParticleComputeProgram::ReleaseStorage(*buffer, current);
  }
  for (auto* family : { &internals.BinBuffers, &internals.SumBuffers })
  {
    for (auto& buffer : *family)
    {
      vtkParticleComputeProgram::ReleaseStorage(buffer, current);
    }
    family->clear();
  }
  internals.BlockBytes = 0.0;
  internals.PageBytes = 0;
  internals.TileListBytes = 0;
  internals.PartialBytes = 0;
  internals.ScratchBytes = 0;
  internals.Mapped = false;
  internals.Slots.clear();
  internals.Table.clear();
  this->NumberOfSlots = 0;
  this->Bins = 0;
}

//------------------------------------------------------------------------------
void vtkSNDFTileCache::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSlots: " << this->NumberOfSlots << "\n";
  os << indent << "Bins: " << this->Bins << "\n";
  os << indent << "NumberOfTiles: " << this->GetNumberOfTiles() << "\n";
  os << indent << "NumberOfDownsampledTiles: " << this->NumberOfDownsampledTiles << "\n";
  os << indent << "NumberOfClearedTiles: " << this->NumberOfClearedTiles << "\n";
  os << indent << "NumberOfEvictedTiles: " << this->NumberOfEvictedTiles << "\n";
  os << indent << "NumberOfRebakedTiles: " << this->NumberOfRebakedTiles << "\n";
  os << indent << "NumberOfRecolouredTiles: " << this->NumberOfRecolouredTiles << "\n";
  os << indent << "Moments: " << this->Moments << "\n";
}
