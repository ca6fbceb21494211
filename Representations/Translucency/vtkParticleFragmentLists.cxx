#include "vtkParticleFragmentLists.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleMemory.h"
#include "vtkParticleShaders.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkParticleFragmentLists);

namespace
{
// bytes per node (PR_LIST_NODE_UINTS words of Shaders/Translucency/FragmentListBuffers.glsl)
const double NodeBytes = 40.0;
// the storage binding points of the lists (the sort uses 0-3 and rebinds them anyway; OpenGL
// guarantees 8)
const unsigned int HeadBinding = 4;
const unsigned int NodeBinding = 5;
const unsigned int CounterBinding = 6;
const unsigned int DeferredBinding = 7;
// shader storage and float bit casts for VTK's GLSL 1.50 (both core in OpenGL 4.3)
const char* const ExtensionLine = "#extension GL_ARB_shader_storage_buffer_object : require\n"
                                  "#extension GL_ARB_shader_bit_encoding : require\n";
// initial pool: this many nodes per pixel (grown from the counts of overflowing frames)
const double InitialNodesPerPixel = 2.0;
// segments the resolve holds per pixel at a time (PR_LIST_LOCAL) in both passes: the first
// composites lists of up to that many, the second (rounds) the longer ones
const int SegmentsHeldFirst = 16;
const int SegmentsHeld = 16;
// a band with pixels where more than SegmentsHeld - 1 segments overlap at one point resolves its
// deferred pixels again holding this many (a program built when first needed). (64 gave wrong
// colours with the squared-distance density on llvmpipe, up to 109/255 against the reference,
// measured while the resolve's colour weights were a loop over the segments per quadrature node,
// the form that also gave the long lists wrong opacities; not measured again since.)
const int SegmentsHeldDeep = 32;
}

//------------------------------------------------------------------------------
class vtkParticleFragmentLists::vtkInternals
{
public:
  vtkWeakPointer<vtkOpenGLRenderWindow> Context;
  // the same window, to recognise it in its own destructor (weak pointers are cleared first)
  vtkOpenGLRenderWindow* ContextAddress = nullptr;
  vtkSmartPointer<vtkOpenGLBufferObject> Heads = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> Nodes = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> Counters = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> Deferred = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  std::size_t HeadBytes = 0;
  long long Capacity = 0; // nodes
  int Width = 0;
  vtkNew<vtkParticleComputeProgram> Resolve;
  vtkNew<vtkParticleComputeProgram> ResolveDeferred;
  vtkNew<vtkParticleComputeProgram> ResolveDeep;
  vtkOpenGLRenderWindow* ResolveContext = nullptr;
  int ResolveModel = -1;
  bool DroppedWarned = false;
  bool IncompleteWarned = false;
  std::pair<std::size_t, double> BudgetErrorSaid{ 0, 0.0 };

  // Delete the buffers in their context: `window` is the window being released (it may be ours
  // in its destructor, when the weak pointer is already cleared); without the context nothing is
  // deleted (vtkParticleComputeProgram::ReleaseStorage).
  void Release(vtkWindow* window)
  {
    vtkOpenGLRenderWindow* context = this->Context;
    if (!context && window && window == this->ContextAddress)
    {
      context = this->ContextAddress;
    }
    const bool current = vtkParticleComputeProgram::MakeCurrentForRelease(context);
    this->Resolve->ReleaseGraphicsResources(context);
    this->ResolveDeferred->ReleaseGraphicsResources(context);
    this->ResolveDeep->ReleaseGraphicsResources(context);
    this->ResolveModel = -1;
    for (vtkSmartPointer<vtkOpenGLBufferObject>* buffer :
      { &this->Heads, &this->Nodes, &this->Counters, &this->Deferred })
    {
      vtkParticleComputeProgram::ReleaseStorage(*buffer, current);
    }
    this->HeadBytes = 0;
    this->Capacity = 0;
    this->Context = nullptr;
    this->ContextAddress = nullptr;
  }
};

//------------------------------------------------------------------------------
vtkParticleFragmentLists::vtkParticleFragmentLists()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkParticleFragmentLists::~vtkParticleFragmentLists()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
std::string vtkParticleFragmentLists::GetAppendExtension()
{
  return ExtensionLine;
}

//------------------------------------------------------------------------------
std::string vtkParticleFragmentLists::GetAppendDeclarations()
{
  return "//PR::Include FragmentListAppend\n";
}

//------------------------------------------------------------------------------
void vtkParticleFragmentLists::PrepareProgram(vtkShaderProgram* program)
{
  if (!program || program->GetHandle() == 0)
  {
    return;
  }
  this->PrepareProgram(static_cast<unsigned int>(program->GetHandle()));
}

//------------------------------------------------------------------------------
void vtkParticleFragmentLists::PrepareProgram(unsigned int handle)
{
  vtkInternals& internals = *this->Internals;
  using Program = vtkParticleComputeProgram;
  Program::BindStorageBlock(handle, "prListHeadBlock", HeadBinding, internals.Heads);
  Program::BindStorageBlock(handle, "prListNodeBlock", NodeBinding, internals.Nodes);
  Program::BindStorageBlock(handle, "prListCounterBlock", CounterBinding, internals.Counters);
  Program::BindStorageBlock(handle, "prListDeferredBlock", DeferredBinding, internals.Deferred);
  // the program is bound (glUniform acts on it)
  const GLint width = glGetUniformLocation(handle, "prListWidth");
  const GLint capacity = glGetUniformLocation(handle, "prListCapacity");
  if (width >= 0)
  {
    glUniform1i(width, internals.Width);
  }
  if (capacity >= 0)
  {
    glUniform1i(capacity, static_cast<GLint>(internals.Capacity));
  }
}

//------------------------------------------------------------------------------
// What the stages of one Render() share.
struct vtkParticleFragmentLists::vtkFrame
{
  int Width = 0; // of the accumulation image
  int Height = 0;
  std::size_t HeadBytes = 0;     // of the head array
  long long MaximumCapacity = 0; // the largest pool (nodes) within the budget
  bool Grown = false;            // the pool grew in this frame
};

//------------------------------------------------------------------------------
double vtkParticleFragmentLists::GetAllocatedListBytes(const vtkFrame& frame)
{
  return 2.0 * static_cast<double>(frame.HeadBytes) + this->Internals->Capacity * NodeBytes;
}

//------------------------------------------------------------------------------
bool vtkParticleFragmentLists::AllocateNodes(const vtkFrame& frame, long long capacity)
{
  vtkInternals& internals = *this->Internals;
  capacity = std::max<long long>(1, std::min(capacity, frame.MaximumCapacity));
  while (capacity >= frame.Width)
  {
    if (vtkParticleComputeProgram::AllocateStorage(
          internals.Nodes, static_cast<std::size_t>(capacity * NodeBytes)))
    {
      internals.Capacity = capacity;
      return true;
    }
    capacity /= 2; // out of GPU memory: try with less
  }
  internals.Capacity = 0;
  return false;
}

//------------------------------------------------------------------------------
bool vtkParticleFragmentLists::AllocateLists(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const int width = frame.Width;
  const int height = frame.Height;
  const double budget = this->MemoryBudget * 1048576.0;
  const std::size_t headBytes = static_cast<std::size_t>(width) * height * sizeof(GLuint);
  frame.HeadBytes = headBytes;
  // heads and the deferred pixels: 4 bytes per pixel each
  const long long maximumCapacity = static_cast<long long>(std::min(
    (budget - 2.0 * static_cast<double>(headBytes)) / NodeBytes, static_cast<double>(INT32_MAX)));
  frame.MaximumCapacity = maximumCapacity;
  if (maximumCapacity < width)
  {
    // said once per view size and budget, not every frame
    const std::pair<std::size_t, double> said(headBytes, this->MemoryBudget);
    if (said != internals.BudgetErrorSaid)
    {
      vtkErrorMacro(<< "The fragment lists of a " << width << " x " << height
                    << " view need more than their memory budget of " << this->MemoryBudget
                    << " MiB (the per-pixel arrays alone take "
                    << vtkParticleMemory::FormatBytes(2.0 * static_cast<double>(headBytes))
                    << "): raise FragmentListMemory. Drawn as sorted spheres instead.");
      internals.BudgetErrorSaid = said;
    }
    return false;
  }
  if (headBytes != internals.HeadBytes)
  {
    if (!vtkParticleComputeProgram::AllocateStorage(internals.Heads, headBytes) ||
      !vtkParticleComputeProgram::AllocateStorage(internals.Deferred, headBytes) ||
      !vtkParticleComputeProgram::AllocateStorage(internals.Counters, 3 * sizeof(GLuint)))
    {
      vtkErrorMacro(<< "Could not allocate "
                    << vtkParticleMemory::FormatBytes(static_cast<double>(headBytes))
                    << " of GPU memory for the fragment lists' heads.");
      internals.HeadBytes = 0;
      return false;
    }
    internals.HeadBytes = headBytes;
  }
  internals.Width = width;
  if (internals.Capacity == 0 || internals.Capacity > maximumCapacity)
  {
    const double pixels = static_cast<double>(width) * height;
    if (!this->AllocateNodes(frame,
          static_cast<long long>(
            std::min(static_cast<double>(maximumCapacity), InitialNodesPerPixel * pixels))))
    {
      vtkErrorMacro(<< "Could not allocate GPU memory for the fragment lists.");
      return false;
    }
  }
  this->AllocatedBytes = this->GetAllocatedListBytes(frame);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleFragmentLists::BuildResolvePrograms(vtkOpenGLRenderWindow* context)
{
  vtkInternals& internals = *this->Internals;
  vtkParticleComputeProgram* resolve = internals.Resolve;
  vtkParticleComputeProgram* resolveDeferred = internals.ResolveDeferred;
  if (internals.ResolveModel != this->DensityModel)
  {
    // the resolve's variants: the density model, the segments held, the pass
    auto variant = [this](int segments, bool deferred)
    {
      std::string source = vtkParticleShaders::Get("FragmentListResolve");
      vtkShaderProgram::Substitute(source, "#version 430\n",
        "#version 430\n#define PR_DENSITY_MODEL " + std::to_string(this->DensityModel) +
          "\n#define PR_LIST_LOCAL " + std::to_string(segments) + "\n" +
          (deferred ? "#define PR_LIST_DEFERRED\n" : ""));
      return source;
    };
    resolve->SetSource(variant(SegmentsHeldFirst, false));
    resolveDeferred->SetSource(variant(SegmentsHeld, true));
    internals.ResolveDeep->SetSource(variant(SegmentsHeldDeep, true));
    internals.ResolveModel = this->DensityModel;
  }
  internals.ResolveContext = context;
  if (!resolve->Build(context) || !resolveDeferred->Build(context))
  {
    vtkErrorMacro(<< "The fragment lists' resolve programs could not be built.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
long long vtkParticleFragmentLists::AppendBand(vtkOpenGLState* ostate,
  const std::function<void()>& draw, const vtkFrame& frame, const std::pair<int, int>& band)
{
  vtkInternals& internals = *this->Internals;
  const GLuint zeros[3] = { 0, 0, 0 };
  vtkParticleComputeProgram::ClearStorage(internals.Heads, frame.HeadBytes, 0xffffffffu);
  // the band's fragment and deferred-pixel counts (the incomplete pixels add up over bands)
  vtkParticleComputeProgram::UploadStorage(internals.Counters, 0, sizeof(GLuint), zeros);
  vtkParticleComputeProgram::UploadStorage(
    internals.Counters, 2 * sizeof(GLuint), sizeof(GLuint), zeros);
  ostate->vtkglScissor(0, band.first, frame.Width, band.second - band.first);
  draw();
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint counters[3] = { 0, 0, 0 };
  vtkParticleComputeProgram::DownloadStorage(internals.Counters, 0, sizeof(counters), counters);
  return counters[0];
}

//------------------------------------------------------------------------------
void vtkParticleFragmentLists::ResolveBand(
  vtkTextureObject* accumulation, const vtkFrame& frame, const std::pair<int, int>& band)
{
  vtkInternals& internals = *this->Internals;
  vtkParticleComputeProgram* resolve = internals.Resolve;
  vtkParticleComputeProgram* resolveDeferred = internals.ResolveDeferred;
  const int width = frame.Width;
  resolve->Use();
  this->PrepareProgram(resolve->GetHandle());
  resolve->SetUniformf("prHollowFraction2", static_cast<float>(this->HollowFraction2));
  resolve->SetUniform2i("prBandOrigin", 0, band.first);
  resolve->SetUniform2i("prBandSize", width, band.second - band.first);
  glBindImageTexture(
    0, static_cast<GLuint>(accumulation->GetHandle()), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  resolve->Dispatch(static_cast<unsigned int>((width + 7) / 8),
    static_cast<unsigned int>((band.second - band.first + 7) / 8));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint counters[3] = { 0, 0, 0 };
  vtkParticleComputeProgram::DownloadStorage(internals.Counters, 0, sizeof(counters), counters);
  this->LastNumberOfDeferredPixels += counters[2];
  if (counters[2] > 0)
  {
    this->DispatchDeferred(resolveDeferred, counters[2]);
    this->ResolveDeepPixels(counters);
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  vtkParticleComputeProgram::UseNone();
}

//------------------------------------------------------------------------------
void vtkParticleFragmentLists::DispatchDeferred(
  vtkParticleComputeProgram* program, unsigned int pixels)
{
  // a resolve over the band's deferred pixels (the accumulation image bound)
  program->Use();
  this->PrepareProgram(program->GetHandle());
  program->SetUniformf("prHollowFraction2", static_cast<float>(this->HollowFraction2));
  program->SetUniformi("prDeferredCount", static_cast<int>(pixels));
  program->Dispatch((pixels + 63) / 64);
}

//------------------------------------------------------------------------------
void vtkParticleFragmentLists::ResolveDeepPixels(const unsigned int countersBefore[3])
{
  // Pixels where more segments overlap at one point than the deferred pass holds were counted
  // (counter 1): this band's deferred pixels are resolved again, holding SegmentsHeldDeep
  // segments, which overwrites their colour; only pixels beyond that stay counted.
  vtkInternals& internals = *this->Internals;
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint counters[3] = { 0, 0, 0 };
  vtkParticleComputeProgram::DownloadStorage(internals.Counters, 0, sizeof(counters), counters);
  if (counters[1] == countersBefore[1])
  {
    return;
  }
  vtkParticleComputeProgram* deep = internals.ResolveDeep;
  if (!deep->Build(internals.ResolveContext))
  {
    vtkErrorMacro(<< "The fragment lists' deep resolve program could not be built.");
    return;
  }
  vtkParticleComputeProgram::UploadStorage(
    internals.Counters, sizeof(GLuint), sizeof(GLuint), &countersBefore[1]);
  // (the second pass's colours are overwritten: its image stores come first)
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  this->DispatchDeferred(deep, countersBefore[2]);
  this->LastNumberOfDeepPixels += counters[1] - countersBefore[1];
}

//------------------------------------------------------------------------------
bool vtkParticleFragmentLists::DrawBands(vtkOpenGLState* ostate, vtkTextureObject* accumulation,
  const std::function<void()>& draw, vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  std::vector<std::pair<int, int>> bands{ { 0, frame.Height } };
  while (!bands.empty())
  {
    const std::pair<int, int> band = bands.back();
    bands.pop_back();
    const long long count = this->AppendBand(ostate, draw, frame, band);
    if (count > internals.Capacity)
    {
      // more room within the budget (once per frame), else bands of half the height
      if (!frame.Grown && internals.Capacity < frame.MaximumCapacity)
      {
        frame.Grown = true;
        if (this->AllocateNodes(frame, count + count / 4 + 1024))
        {
          this->AllocatedBytes = this->GetAllocatedListBytes(frame);
          bands.push_back(band);
          continue;
        }
        vtkErrorMacro(<< "Could not allocate GPU memory for the fragment lists.");
        return false;
      }
      if (band.second - band.first > 1)
      {
        const int middle = (band.first + band.second) / 2;
        bands.emplace_back(middle, band.second);
        bands.emplace_back(band.first, middle);
        continue;
      }
      // one row beyond the pool: composite what fits
      this->LastNumberOfDroppedFragments += count - internals.Capacity;
    }
    this->LastNumberOfFragments += std::min(count, internals.Capacity);
    ++this->LastNumberOfBands;

    // resolve the band into the accumulation image: every pixel with a short list, then the
    // pixels with longer ones
    this->ResolveBand(accumulation, frame, band);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleFragmentLists::FinishLists()
{
  vtkInternals& internals = *this->Internals;
  // the accumulation is read by texture fetches and blending afterwards
  glMemoryBarrier(
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint counters[3] = { 0, 0, 0 };
  vtkParticleComputeProgram::DownloadStorage(internals.Counters, 0, sizeof(counters), counters);
  this->LastNumberOfIncompletePixels = counters[1];
  for (unsigned int binding : { HeadBinding, NodeBinding, CounterBinding, DeferredBinding })
  {
    vtkParticleComputeProgram::BindStorage(binding, nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkParticleFragmentLists::WarnOfLosses()
{
  vtkInternals& internals = *this->Internals;
  if (this->LastNumberOfDroppedFragments > 0 && !internals.DroppedWarned)
  {
    vtkWarningMacro(<< this->LastNumberOfDroppedFragments
                    << " translucent fragments did not fit into the fragment lists' memory ("
                    << this->MemoryBudget
                    << " MiB) even one pixel row at a time and were left out: raise "
                       "FragmentListMemory.");
  }
  internals.DroppedWarned = this->LastNumberOfDroppedFragments > 0;
  if (this->LastNumberOfIncompletePixels > 0 && !internals.IncompleteWarned)
  {
    vtkWarningMacro(<< this->LastNumberOfIncompletePixels << " pixels have more than "
                    << SegmentsHeldDeep - 1
                    << " translucent spheres overlapping at one point of their ray: there the "
                       "spheres that found no room were left out of the exact compositing.");
  }
  internals.IncompleteWarned = this->LastNumberOfIncompletePixels > 0;
}

//------------------------------------------------------------------------------
bool vtkParticleFragmentLists::Render(
  vtkOpenGLRenderWindow* context, vtkTextureObject* accumulation, const std::function<void()>& draw)
{
  vtkInternals& internals = *this->Internals;
  vtkFrame frame;
  frame.Width = accumulation ? static_cast<int>(accumulation->GetWidth()) : 0;
  frame.Height = accumulation ? static_cast<int>(accumulation->GetHeight()) : 0;
  this->LastNumberOfFragments = 0;
  this->LastNumberOfBands = 0;
  this->LastNumberOfIncompletePixels = 0;
  this->LastNumberOfDroppedFragments = 0;
  this->LastNumberOfDeferredPixels = 0;
  this->LastNumberOfDeepPixels = 0;
  if (!context || frame.Width <= 0 || frame.Height <= 0)
  {
    return false;
  }
  if (internals.Context && internals.Context != context)
  {
    internals.Release(internals.Context);
    context->MakeCurrent();
  }
  internals.Context = context;
  internals.ContextAddress = context;

  // the head array, and the pool within the budget
  if (!this->AllocateLists(frame))
  {
    return false;
  }
  // the resolve programs (first and second pass), for the density model
  if (!this->BuildResolvePrograms(context))
  {
    return false;
  }

  vtkOpenGLState* ostate = context->GetState();
  vtkOpenGLState::ScopedglEnableDisable scissorSaved(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglScissor scissorBoxSaved(ostate);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  const GLuint zeros[3] = { 0, 0, 0 };
  vtkParticleComputeProgram::UploadStorage(internals.Counters, 0, sizeof(zeros), zeros);

  // the lists of each band drawn and resolved (the whole view when the pool holds it)
  if (!this->DrawBands(ostate, accumulation, draw, frame))
  {
    return false;
  }
  // the incomplete pixels counted, the lists unbound; what was left out said
  this->FinishLists();
  this->WarnOfLosses();
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleFragmentLists::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internals->Release(window);
  this->AllocatedBytes = 0.0;
}

//------------------------------------------------------------------------------
void vtkParticleFragmentLists::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MemoryBudget: " << this->MemoryBudget << " MiB\n";
  os << indent << "DensityModel: " << this->DensityModel << "\n";
  os << indent << "HollowFraction2: " << this->HollowFraction2 << "\n";
  os << indent << "Capacity: " << this->Internals->Capacity << " fragments\n";
  os << indent << "AllocatedBytes: " << this->AllocatedBytes << "\n";
  os << indent << "LastNumberOfFragments: " << this->LastNumberOfFragments << "\n";
  os << indent << "LastNumberOfBands: " << this->LastNumberOfBands << "\n";
  os << indent << "LastNumberOfIncompletePixels: " << this->LastNumberOfIncompletePixels << "\n";
  os << indent << "LastNumberOfDroppedFragments: " << this->LastNumberOfDroppedFragments << "\n";
  os << indent << "LastNumberOfDeferredPixels: " << this->LastNumberOfDeferredPixels << "\n";
  os << indent << "LastNumberOfDeepPixels: " << this->LastNumberOfDeepPixels << "\n";
}
