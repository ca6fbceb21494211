#include "vtkParticleDepthSort.h"
#include "vtkParticleMemory.h"

#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleShaders.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include "vtkParticleCompat.h"

#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkParticleDepthSort);

namespace
{
constexpr std::uint64_t Tile = 1024;     // keys per work group (256 invocations x 4)
constexpr std::uint64_t BitsTile = 4096; // keys per work group of RadixSortBits
constexpr std::uint64_t Buckets = 16;

std::uint64_t DivUp(std::uint64_t a, std::uint64_t b)
{
  return (a + b - 1) / b;
}

// Lengths of the levels of the multi-level scan of `length` entries: level 0 is the array itself,
// every further level holds the sums of the 1024-entry tiles of the level below, up to a level
// that one work group scans.
std::vector<std::uint64_t> ScanLevels(std::uint64_t length)
{
  std::vector<std::uint64_t> levels{ length };
  while (levels.back() > Tile)
  {
    levels.push_back(DivUp(levels.back(), Tile));
  }
  return levels;
}

// Entries of the scratch key buffer after its keys: AND and OR of the keys, the digit counts of
// every tile and the upper scan levels. Grows with count, so the tail of the capacity holds the
// tail of any smaller count.
std::uint64_t TailSize(std::uint64_t count)
{
  std::uint64_t size = 2;
  for (std::uint64_t length : ScanLevels(Buckets * DivUp(count, Tile)))
  {
    size += length;
  }
  return size;
}
}

//------------------------------------------------------------------------------
class vtkParticleDepthSort::vtkInternals
{
public:
  vtkWeakPointer<vtkOpenGLRenderWindow> Context;
  // the same window, to recognise it in its own destructor (weak pointers are cleared first)
  vtkOpenGLRenderWindow* ContextAddress = nullptr;
  vtkNew<vtkParticleComputeProgram> Bits;
  vtkNew<vtkParticleComputeProgram> FlipCopy;
  vtkNew<vtkParticleComputeProgram> Iota;
  vtkNew<vtkParticleComputeProgram> Histogram;
  vtkNew<vtkParticleComputeProgram> Scan;
  vtkNew<vtkParticleComputeProgram> ScanAdd;
  vtkNew<vtkParticleComputeProgram> Scatter;
  vtkOpenGLRenderTimer Timer;
  bool Timed = false;
  // keys, indices (an element array), scratch keys (+ tail), scratch indices
  vtkSmartPointer<vtkOpenGLBufferObject> Buffers[4] = {
    vtkSmartPointer<vtkOpenGLBufferObject>::New(), vtkSmartPointer<vtkOpenGLBufferObject>::New(),
    vtkSmartPointer<vtkOpenGLBufferObject>::New(), vtkSmartPointer<vtkOpenGLBufferObject>::New()
  };
  bool BuiltCoalescedWrites = true;

  std::vector<std::pair<vtkParticleComputeProgram*, const char*>> Programs()
  {
    return { { this->Bits, "RadixSortBits" }, { this->FlipCopy, "RadixSortFlipCopy" },
      { this->Iota, "RadixSortIota" }, { this->Histogram, "RadixSortHistogram" },
      { this->Scan, "RadixSortScan" }, { this->ScanAdd, "RadixSortScanAdd" },
      { this->Scatter, "RadixSortScatter" } };
  }

  // Dispatch `groups` work groups of the bound program (prNumGroups tells the shader how many of
  // the possibly larger 2D grid have work).
  static bool Run(vtkParticleComputeProgram* program, std::uint64_t groups)
  {
    program->SetUniformui("prNumGroups", static_cast<unsigned int>(groups));
    const bool ok = program->Dispatch(static_cast<unsigned int>(groups));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    return ok;
  }
};

//------------------------------------------------------------------------------
vtkParticleDepthSort::vtkParticleDepthSort()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkParticleDepthSort::~vtkParticleDepthSort()
{
  // GL objects still alive here go with their context (no context may be current now); owners
  // call ReleaseGraphicsResources() first.
  delete this->Internals;
}

//------------------------------------------------------------------------------
bool vtkParticleDepthSort::BuildPrograms()
{
  vtkInternals& internals = *this->Internals;
  for (auto& program : internals.Programs())
  {
    const bool scatter = program.first == internals.Scatter.GetPointer();
    if (program.first->IsBuilt() &&
      !(scatter && internals.BuiltCoalescedWrites != this->CoalescedWrites))
    {
      continue;
    }
    std::string source = vtkParticleShaders::Get(program.second);
    if (scatter)
    {
      // after the #version line
      source.insert(source.find('\n') + 1,
        std::string("#define PR_LOCAL_REORDER ") + (this->CoalescedWrites ? "1\n" : "0\n"));
      internals.BuiltCoalescedWrites = this->CoalescedWrites;
    }
    program.first->SetSource(source);
    if (!program.first->Build(internals.Context))
    {
      vtkErrorMacro(<< "Could not build " << program.second << ".glsl.");
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleDepthSort::Reserve(vtkOpenGLRenderWindow* context, vtkIdType count)
{
  std::string reason;
  if (!vtkParticleComputeProgram::IsSupported(context, &reason))
  {
    vtkErrorMacro(<< "GPU depth sort unavailable: " << reason);
    return false;
  }
  if (count < 0)
  {
    vtkErrorMacro(<< "Negative key count " << count << ".");
    return false;
  }
  if (this->Internals->Context && this->Internals->Context != context && this->Capacity > 0)
  {
    vtkErrorMacro(<< "Reserve() in another context: call ReleaseGraphicsResources() in the old "
                     "one first.");
    return false;
  }
  this->Internals->Context = context;
  this->Internals->ContextAddress = context;
  if (!this->BuildPrograms())
  {
    return false;
  }
  if (count <= this->Capacity && this->Internals->Buffers[0]->GetHandle() != 0)
  {
    return true;
  }

  // limits: one shader storage block per buffer, 32-bit indices, the dispatch grid
  const std::uint64_t n = static_cast<std::uint64_t>(count);
  GLint64 blockLimit = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockLimit);
  const std::uint64_t limit = static_cast<std::uint64_t>(blockLimit > 0 ? blockLimit : 0);
  const std::uint64_t scratchBytes = 4 * (n + TailSize(n));
  if (scratchBytes > limit)
  {
    // the largest count whose scratch key buffer fits
    std::uint64_t low = 0;
    std::uint64_t high = limit / 4;
    while (low < high)
    {
      const std::uint64_t mid = (low + high + 1) / 2;
      if (4 * (mid + TailSize(mid)) <= limit)
      {
        low = mid;
      }
      else
      {
        high = mid - 1;
      }
    }
    vtkErrorMacro(<< count << " keys need a shader storage block of " << scratchBytes
                  << " bytes, above this context's GL_MAX_SHADER_STORAGE_BLOCK_SIZE of " << limit
                  << " bytes: at most " << low << " keys can be sorted.");
    return false;
  }
  const std::uint64_t indexLimit = (std::uint64_t(1) << 32) - 2 * Tile * Tile;
  if (n > indexLimit)
  {
    vtkErrorMacro(<< count << " keys exceed the 32-bit index limit of " << indexLimit << " keys.");
    return false;
  }
  const unsigned long long groupLimit =
    vtkParticleComputeProgram::GetMaxLinearWorkGroupCount(context);
  if (DivUp(n, Tile) > groupLimit)
  {
    vtkErrorMacro(<< count << " keys need " << DivUp(n, Tile)
                  << " work groups, above this context's GL_MAX_COMPUTE_WORK_GROUP_COUNT limit "
                     "of "
                  << groupLimit << " (x times y): at most " << groupLimit * Tile
                  << " keys can be sorted.");
    return false;
  }

  const std::uint64_t capacity = n < Tile ? Tile : n;
  const std::uint64_t bytes[4] = { 4 * capacity, 4 * capacity, 4 * (capacity + TailSize(capacity)),
    4 * capacity };
  // a software rasteriser's buffers are host memory: check that they fit before asking
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (renderer && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe")))
  {
    std::string why;
    if (!vtkParticleMemory::CanAllocate(
          static_cast<double>(bytes[0] + bytes[1] + bytes[2] + bytes[3]), why))
    {
      vtkErrorMacro(<< "The depth sort of " << count << " keys " << why << ".");
      this->Capacity = 0;
      return false;
    }
  }
  this->Internals->Buffers[1]->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
  bool allocated = true;
  for (int i = 0; i < 4; ++i)
  {
    allocated = vtkParticleComputeProgram::AllocateStorage(
                  this->Internals->Buffers[i], static_cast<std::size_t>(bytes[i])) &&
      allocated;
  }
  if (!allocated)
  {
    vtkErrorMacro(<< "Could not allocate " << (bytes[0] + bytes[1] + bytes[2] + bytes[3])
                  << " bytes of buffers for " << count << " keys (out of GPU memory?).");
    this->Capacity = 0;
    return false;
  }
  this->Capacity = static_cast<vtkIdType>(capacity);
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
vtkOpenGLBufferObject* vtkParticleDepthSort::GetKeyBuffer()
{
  return this->Internals->Buffers[0];
}

//------------------------------------------------------------------------------
vtkOpenGLBufferObject* vtkParticleDepthSort::GetIndexBuffer()
{
  return this->Internals->Buffers[1];
}

//------------------------------------------------------------------------------
bool vtkParticleDepthSort::Scan(unsigned int offset, unsigned int length)
{
  vtkInternals& internals = *this->Internals;
  const std::vector<std::uint64_t> lengths = ScanLevels(length);
  std::vector<std::uint64_t> offsets{ offset };
  for (std::size_t level = 1; level < lengths.size(); ++level)
  {
    offsets.push_back(offsets.back() + lengths[level - 1]);
  }
  const std::size_t top = lengths.size() - 1;
  bool ok = true;
  vtkParticleComputeProgram* scan = internals.Scan;
  scan->Use();
  for (std::size_t level = 0; level <= top; ++level)
  {
    scan->SetUniformui("prOffset", static_cast<unsigned int>(offsets[level]));
    scan->SetUniformui("prLength", static_cast<unsigned int>(lengths[level]));
    scan->SetUniformui(
      "prSumsOffset", static_cast<unsigned int>(level < top ? offsets[level + 1] : 0));
    scan->SetUniformui("prWriteSums", level < top ? 1u : 0u);
    ok = vtkInternals::Run(scan, DivUp(lengths[level], Tile)) && ok;
  }
  if (top > 0)
  {
    vtkParticleComputeProgram* add = internals.ScanAdd;
    add->Use();
    for (std::size_t level = top; level-- > 0;)
    {
      add->SetUniformui("prOffset", static_cast<unsigned int>(offsets[level]));
      add->SetUniformui("prLength", static_cast<unsigned int>(lengths[level]));
      add->SetUniformui("prSumsOffset", static_cast<unsigned int>(offsets[level + 1]));
      ok = vtkInternals::Run(add, DivUp(lengths[level], Tile)) && ok;
    }
  }
  return ok;
}

//------------------------------------------------------------------------------
bool vtkParticleDepthSort::Sort(vtkIdType count)
{
  vtkInternals& internals = *this->Internals;
  if (internals.Buffers[0]->GetHandle() == 0 || !internals.Context)
  {
    vtkErrorMacro(<< "Sort() before Reserve().");
    return false;
  }
  if (count < 0 || count > this->Capacity)
  {
    vtkErrorMacro(<< "Sort(" << count << ") outside the reserved capacity of " << this->Capacity
                  << " keys.");
    return false;
  }
  this->LastNumberOfPasses = 0;
  internals.Timed = false;
  if (count == 0)
  {
    return true;
  }
  if (!this->BuildPrograms()) // rebuilds the scatter stage when CoalescedWrites changed
  {
    return false;
  }

  if (this->CollectTimings)
  {
    internals.Timer.Reset();
    internals.Timer.Start();
    internals.Timed = true;
  }

  // the caller's shader writes of the keys become visible to ours
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  for (unsigned int binding = 0; binding < 4; ++binding)
  {
    vtkParticleComputeProgram::BindStorage(binding, internals.Buffers[binding]);
  }

  bool ok = true;
  const std::vector<unsigned int> shifts =
    this->FindDifferingDigits(static_cast<unsigned int>(count), ok);
  this->LastNumberOfPasses = static_cast<int>(shifts.size());
  ok = this->RunPasses(shifts, static_cast<unsigned int>(count)) && ok;

  // the results can be drawn (indices, attributes), read by shaders and read back
  glMemoryBarrier(GL_ELEMENT_ARRAY_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT |
    GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  if (internals.Timed)
  {
    internals.Timer.Stop();
  }
  // vtkParticleComputeProgram::Use() told VTK's shader cache that its program is unbound: the
  // caller's next VTK draw binds its own program again (ReadyShaderProgram)
  vtkParticleComputeProgram::UseNone();
  if (!ok)
  {
    vtkErrorMacro(<< "A sort dispatch failed; the index buffer is undefined.");
  }
  return ok;
}

//------------------------------------------------------------------------------
std::vector<unsigned int> vtkParticleDepthSort::FindDifferingDigits(unsigned int count, bool& ok)
{
  vtkInternals& internals = *this->Internals;
  const std::uint64_t n = count;
  const unsigned int bitsOffset = static_cast<unsigned int>(this->Capacity);
  unsigned int differing = 0xFFFFFFFFu;
  if (this->SkipUniformDigits)
  {
    const GLuint initial[2] = { 0xFFFFFFFFu, 0u };
    vtkParticleComputeProgram::UploadStorage(
      internals.Buffers[2], 4 * static_cast<std::size_t>(bitsOffset), sizeof(initial), initial);
    vtkParticleComputeProgram* bits = internals.Bits;
    bits->Use();
    bits->SetUniformui("prCount", static_cast<unsigned int>(n));
    bits->SetUniformui("prBitsOffset", bitsOffset);
    ok = vtkInternals::Run(bits, DivUp(n, BitsTile)) && ok;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint andOr[2] = { 0u, 0u };
    vtkParticleComputeProgram::DownloadStorage(
      internals.Buffers[2], 4 * static_cast<std::size_t>(bitsOffset), sizeof(andOr), andOr);
    differing = andOr[0] ^ andOr[1];
  }
  std::vector<unsigned int> shifts;
  for (unsigned int shift = 0; shift < 32; shift += 4)
  {
    if ((differing >> shift) & 0xFu)
    {
      shifts.push_back(shift);
    }
  }
  return shifts;
}

//------------------------------------------------------------------------------
bool vtkParticleDepthSort::RunPasses(const std::vector<unsigned int>& shifts, unsigned int count)
{
  vtkInternals& internals = *this->Internals;
  const std::uint64_t n = count;
  const std::uint64_t tiles = DivUp(n, Tile);
  const unsigned int countsOffset = static_cast<unsigned int>(this->Capacity) + 2;
  bool ok = true;
  const bool reportProgress = this->HasObserver(vtkCommand::ProgressEvent) != 0;
  auto progress = [&](double fraction)
  {
    if (reportProgress)
    {
      this->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
    }
  };
  progress(0.0);

  if (shifts.empty())
  {
    // every key is the same: the identity permutation, keys unchanged
    vtkParticleComputeProgram* iota = internals.Iota;
    iota->Use();
    iota->SetUniformui("prCount", static_cast<unsigned int>(n));
    ok = vtkInternals::Run(iota, tiles) && ok;
  }
  else
  {
    // Passes alternate A -> B -> A ...; the last must write side A. With an odd number of passes
    // the mapped keys are copied to side B first and the first pass reads them there.
    unsigned int readB = 0;
    if (shifts.size() % 2 == 1)
    {
      vtkParticleComputeProgram* copy = internals.FlipCopy;
      copy->Use();
      copy->SetUniformui("prCount", static_cast<unsigned int>(n));
      ok = vtkInternals::Run(copy, tiles) && ok;
      readB = 1;
    }
    const unsigned int flipFirst = readB ? 0u : 1u;
    for (std::size_t pass = 0; pass < shifts.size(); ++pass)
    {
      const unsigned int flip = pass == 0 ? flipFirst : 0u;

      vtkParticleComputeProgram* histogram = internals.Histogram;
      histogram->Use();
      histogram->SetUniformui("prCount", static_cast<unsigned int>(n));
      histogram->SetUniformui("prShift", shifts[pass]);
      histogram->SetUniformui("prReadB", readB);
      histogram->SetUniformui("prFlipInput", flip);
      histogram->SetUniformui("prCountsOffset", countsOffset);
      ok = vtkInternals::Run(histogram, tiles) && ok;

      ok = this->Scan(countsOffset, static_cast<unsigned int>(Buckets * tiles)) && ok;

      vtkParticleComputeProgram* scatter = internals.Scatter;
      scatter->Use();
      scatter->SetUniformui("prCount", static_cast<unsigned int>(n));
      scatter->SetUniformui("prShift", shifts[pass]);
      scatter->SetUniformui("prReadB", readB);
      scatter->SetUniformui("prFlipInput", flip);
      scatter->SetUniformui("prIotaValues", pass == 0 ? 1u : 0u);
      scatter->SetUniformui("prUnflipOutput", pass + 1 == shifts.size() ? 1u : 0u);
      scatter->SetUniformui("prCountsOffset", countsOffset);
      ok = vtkInternals::Run(scatter, tiles) && ok;
      readB ^= 1u;
      progress(static_cast<double>(pass + 1) / static_cast<double>(shifts.size()));
    }
  }
  if (shifts.empty())
  {
    progress(1.0);
  }

  return ok;
}

//------------------------------------------------------------------------------
double vtkParticleDepthSort::GetLastSortGPUSeconds()
{
  vtkOpenGLRenderTimer& timer = this->Internals->Timer;
  if (!this->Internals->Timed || !timer.Stopped())
  {
    return 0.0;
  }
  // after glFinish the query results are available (bounded, in case a driver never says so)
  for (int attempt = 0; attempt < 100 && !timer.Ready(); ++attempt)
  {
    glFinish();
  }
  return timer.GetElapsedSeconds(); // 0 when still not ready
}

//------------------------------------------------------------------------------
void vtkParticleDepthSort::ReleaseGraphicsResources(vtkWindow* window)
{

  for (auto& program : this->Internals->Programs())
  {
    program.first->ReleaseGraphicsResources(window);
  }
  this->Internals->Timed = false;
  if (this->Internals->Buffers[0]->GetHandle() != 0)
  {
    // our window, also in its own destructor (the weak pointer is cleared by then)
    vtkOpenGLRenderWindow* context = this->Internals->Context;
    if (!context && window && window == this->Internals->ContextAddress)
    {
      context = this->Internals->ContextAddress;
    }
    const bool current = vtkParticleComputeProgram::MakeCurrentForRelease(context);
    if (current)
    {
      this->Internals->Timer.ReleaseGraphicsResources();
    }
    for (auto& buffer : this->Internals->Buffers)
    {
      vtkParticleComputeProgram::ReleaseStorage(buffer, current);
    }
  }
  this->Capacity = 0;
  this->Internals->Context = nullptr;
  this->Internals->ContextAddress = nullptr;
}

//------------------------------------------------------------------------------
void vtkParticleDepthSort::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Capacity: " << this->Capacity << "\n";
  os << indent << "KeyBuffer: " << this->Internals->Buffers[0]->GetHandle() << "\n";
  os << indent << "IndexBuffer: " << this->Internals->Buffers[1]->GetHandle() << "\n";
  os << indent << "SkipUniformDigits: " << this->SkipUniformDigits << "\n";
  os << indent << "CoalescedWrites: " << this->CoalescedWrites << "\n";
  os << indent << "LastNumberOfPasses: " << this->LastNumberOfPasses << "\n";
  os << indent << "CollectTimings: " << this->CollectTimings << "\n";
}
