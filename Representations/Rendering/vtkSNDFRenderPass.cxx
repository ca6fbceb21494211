#include "vtkSNDFRenderPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightsPass.h"
#include "vtkMatrix4x4.h"
#include "vtkMetaballMapper.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleShaderHooks.h"
#include "vtkParticleShaders.h"
#include "vtkParticleSphereMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"

#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace
{
// the colour attachments of the G-buffer (0: colour as drawn; see SNDFAccumulate.glsl)
const unsigned int NumberOfAttachments = 3;
// bytes per pixel besides the bin counts: four vec4 of sums
const double SumBytesPerPixel = 64.0;
// sub-samples per axis of the whole [-1, 1] square for the lighting table (per bin: this over
// the bins per axis, at least 8)
const int TableSubsamplesPerAxis = 512;

// sample passes in one Render() from which it reports progress
const int ProgressSamples = 8;

// words per pixel of the bin buffer: two per bin (count and mean colour), then one bit per bin
// marking the occupied ones
int WordsPerPixel(int bins)
{
  return 2 * bins * bins + std::max(1, bins * bins / 32);
}

// the radical inverse in base b of k (Halton sequence)
double RadicalInverse(unsigned int k, unsigned int base)
{
  double inverse = 1.0 / base;
  double f = inverse;
  double value = 0.0;
  while (k > 0)
  {
    value += f * (k % base);
    k /= base;
    f *= inverse;
  }
  return value;
}

// the sub-pixel offset of sample k in [-0.5, 0.5)^2: the Halton (2, 3) point shifted so that
// sample 0 lies at the pixel centre
void JitterOffset(int k, double offset[2])
{
  for (int a = 0; a < 2; ++a)
  {
    double v = RadicalInverse(static_cast<unsigned int>(k), a == 0 ? 2u : 3u) + 0.5;
    offset[a] = v - std::floor(v) - 0.5;
  }
}

void AppendMatrix(std::vector<double>& state, vtkMatrix4x4* m)
{
  if (m)
  {
    state.insert(state.end(), m->GetData(), m->GetData() + 16);
  }
}

// a particle mapper whose opaque spheres the pass samples: the core, and vtkTransparentSphereMapper
// (ParaView's Particles representation), which draws opaque particles through the core's opaque
// path (its actor's translucency is checked separately); vtkMetaballMapper draws through its own
// targets
bool IsSampledParticleMapper(vtkAbstractMapper* mapper)
{
  return vtkParticleSphereMapper::SafeDownCast(mapper) && !vtkMetaballMapper::SafeDownCast(mapper);
}
}

//------------------------------------------------------------------------------
class vtkSNDFRenderPass::vtkInternals
{
public:
  explicit vtkInternals(vtkObject* owner)
    : Hooks(owner)
  {
  }

  vtkWeakPointer<vtkOpenGLRenderWindow> Context;
  // the view-sized objects, made anew for each size
  vtkSmartPointer<vtkOpenGLFramebufferObject> Target;
  vtkSmartPointer<vtkTextureObject> Attachments[NumberOfAttachments];
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkTextureObject> Image;
  vtkSmartPointer<vtkTextureObject> ImageDepth;
  vtkNew<vtkOpenGLFramebufferObject> TableTarget;
  vtkNew<vtkTextureObject> Table;
  std::unique_ptr<vtkOpenGLQuadHelper> TableQuad;
  std::string TableQuadSource;
  std::unique_ptr<vtkOpenGLQuadHelper> CompositeQuad;
  vtkNew<vtkParticleComputeProgram> Accumulate;
  vtkNew<vtkParticleComputeProgram> Resolve;
  vtkSmartPointer<vtkOpenGLBufferObject> Counts = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> Sums = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkParticleShaderHooks Hooks;
  vtkTimeStamp ShaderTime;
  vtkNew<vtkLightsPass> Lights;

  int Width = 0;
  int Height = 0;
  int Bins = 0;
  int WordsPerPixel = 0;
  bool HaveTable = false;
  // the shaded bin sums need summing again over the bins (the table changed under samples)
  bool Rebake = false;
  int TableBins = 0;
  std::vector<double> SampleState;
  // the state but for the camera position and focal point, and those (pans)
  std::vector<double> FixedState;
  double Position[3] = { 0.0, 0.0, 0.0 };
  double FocalPoint[3] = { 0.0, 0.0, 0.0 };
  vtkSmartPointer<vtkOpenGLBufferObject> Row = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  std::vector<double> TableKey;
  std::vector<double> ResolveKey;
  std::set<std::string> Warned;
  std::string ProgressText;

  // timer queries of the last Render() per stage (sample, accumulate, shade)
  std::vector<GLuint> Queries[3];
  double Seconds[3] = { 0.0, 0.0, 0.0 };
  bool TimesRead = true;

  void BeginStage(bool on, int stage)
  {
    if (on)
    {
      GLuint query = 0;
      glGenQueries(1, &query);
      glBeginQuery(GL_TIME_ELAPSED, query);
      this->Queries[stage].push_back(query);
    }
  }
  void EndStage(bool on)
  {
    if (on)
    {
      glEndQuery(GL_TIME_ELAPSED);
    }
  }
  void ReadTimes()
  {
    if (this->TimesRead)
    {
      return;
    }
    for (int stage = 0; stage < 3; ++stage)
    {
      GLuint64 total = 0;
      for (GLuint query : this->Queries[stage])
      {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
        total += ns;
      }
      if (!this->Queries[stage].empty())
      {
        glDeleteQueries(static_cast<GLsizei>(this->Queries[stage].size()), this->Queries[stage].data());
      }
      this->Queries[stage].clear();
      this->Seconds[stage] = 1e-9 * static_cast<double>(total);
    }
    this->TimesRead = true;
  }

  // Moves the S-NDFs (bins and sums) with a pan of the picture: the new pixel (x, y) takes the
  // old pixel (x + pan[0], y + pan[1]); pixels with no old one are cleared. Row by row through
  // a one-row scratch buffer, in the order that reads every old row before it is overwritten.
  void ShiftPixels(int width, int height, const int pan[2])
  {
    const std::size_t binBytes = static_cast<std::size_t>(this->WordsPerPixel) * 4;
    const std::size_t sumBytes = static_cast<std::size_t>(SumBytesPerPixel);
    vtkParticleComputeProgram::AllocateStorage(this->Row, width * std::max(binBytes, sumBytes));
    const int x0 = std::max(0, -pan[0]);
    const int x1 = std::min(width, width - pan[0]);
    const GLuint zero = 0;
    auto clear = [&](GLintptr start, GLsizeiptr bytes) {
      glClearBufferSubData(
        GL_COPY_WRITE_BUFFER, GL_R32UI, start, bytes, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    };
    for (vtkOpenGLBufferObject* buffer : { this->Counts.Get(), this->Sums.Get() })
    {
      const std::size_t pixelBytes = buffer == this->Counts.Get() ? binBytes : sumBytes;
      const GLsizeiptr rowBytes = static_cast<GLsizeiptr>(pixelBytes * width);
      const GLsizeiptr segment = static_cast<GLsizeiptr>(pixelBytes * (x1 - x0));
      for (int k = 0; k < height; ++k)
      {
        const int y = pan[1] >= 0 ? k : height - 1 - k;
        const int oldY = y + pan[1];
        const GLintptr rowStart = static_cast<GLintptr>(y) * rowBytes;
        glBindBuffer(GL_COPY_WRITE_BUFFER, buffer->GetHandle());
        if (oldY < 0 || oldY >= height)
        {
          clear(rowStart, rowBytes);
          continue;
        }
        // old row segment -> scratch -> new row segment (the two may overlap)
        glBindBuffer(GL_COPY_READ_BUFFER, buffer->GetHandle());
        glBindBuffer(GL_COPY_WRITE_BUFFER, this->Row->GetHandle());
        glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER,
          static_cast<GLintptr>(oldY) * rowBytes + static_cast<GLintptr>(pixelBytes * (x0 + pan[0])),
          0, segment);
        glBindBuffer(GL_COPY_READ_BUFFER, this->Row->GetHandle());
        glBindBuffer(GL_COPY_WRITE_BUFFER, buffer->GetHandle());
        glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0,
          rowStart + static_cast<GLintptr>(pixelBytes * x0), segment);
        // the columns the pan uncovers
        clear(rowStart, static_cast<GLsizeiptr>(pixelBytes * x0));
        clear(rowStart + static_cast<GLintptr>(pixelBytes * x1),
          static_cast<GLsizeiptr>(pixelBytes * (width - x1)));
      }
    }
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  }

  // true the first time `what` is reported
  bool FirstWarning(const std::string& what) { return this->Warned.insert(what).second; }

  void ReleaseTextures(vtkWindow* w)
  {
    if (this->Target)
    {
      this->Target->ReleaseGraphicsResources(w);
    }
    for (auto& attachment : this->Attachments)
    {
      if (attachment)
      {
        attachment->ReleaseGraphicsResources(w);
      }
      attachment = nullptr;
    }
    for (auto* texture : { &this->Depth, &this->Image, &this->ImageDepth })
    {
      if (*texture)
      {
        (*texture)->ReleaseGraphicsResources(w);
      }
      *texture = nullptr;
    }
    this->Target = nullptr;
    this->Width = 0;
    this->Height = 0;
  }

  void NewTextures()
  {
    this->Target = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    for (auto& attachment : this->Attachments)
    {
      attachment = vtkSmartPointer<vtkTextureObject>::New();
    }
    this->Depth = vtkSmartPointer<vtkTextureObject>::New();
    this->Image = vtkSmartPointer<vtkTextureObject>::New();
    this->ImageDepth = vtkSmartPointer<vtkTextureObject>::New();
  }
};

vtkStandardNewMacro(vtkSNDFRenderPass);

//------------------------------------------------------------------------------
vtkSNDFRenderPass::vtkSNDFRenderPass()
  : Internals(new vtkInternals(this))
{
  this->Internals->ShaderTime.Modified();
}

//------------------------------------------------------------------------------
vtkSNDFRenderPass::~vtkSNDFRenderPass()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::SetBinsPerAxis(int bins)
{
  if (bins != 4 && bins != 8 && bins != 16)
  {
    vtkErrorMacro(<< "BinsPerAxis must be 4, 8 or 16, not " << bins << "; it stays "
                  << this->BinsPerAxis << ".");
    return;
  }
  if (bins != this->BinsPerAxis)
  {
    this->BinsPerAxis = bins;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::Restart()
{
  this->Internals->SampleState.clear();
  this->NumberOfSamples = 0;
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::PanShift(vtkCamera* camera, const double oldPosition[3],
  const double oldFocalPoint[3], int height, int pan[2])
{
  // exact only where the picture moves as a whole: parallel projection, position and focal
  // point moved by the same vector in the view plane, a whole number of pixels
  if (!camera->GetParallelProjection() || height < 1)
  {
    return false;
  }
  double move[3];
  const double* position = camera->GetPosition();
  const double* focal = camera->GetFocalPoint();
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  const double pixel = 2.0 * camera->GetParallelScale() / height;
  double along[3] = { 0.0, 0.0, 0.0 };
  for (int a = 0; a < 3; ++a)
  {
    move[a] = position[a] - oldPosition[a];
    if (std::abs(move[a] - (focal[a] - oldFocalPoint[a])) > 1e-9 * (pixel + std::abs(move[a])))
    {
      return false;
    }
  }
  for (int row = 0; row < 3; ++row)
  {
    for (int a = 0; a < 3; ++a)
    {
      along[row] += view->GetElement(row, a) * move[a];
    }
  }
  if (!(pixel > 0.0) || std::abs(along[2]) > 1e-6 * pixel)
  {
    return false;
  }
  for (int axis = 0; axis < 2; ++axis)
  {
    const double shift = along[axis] / pixel;
    pan[axis] = static_cast<int>(std::lround(shift));
    if (std::abs(shift - pan[axis]) > 1e-3)
    {
      return false;
    }
  }
  return pan[0] != 0 || pan[1] != 0;
}

//------------------------------------------------------------------------------
const char* vtkSNDFRenderPass::GetProgressText()
{
  return this->Internals->ProgressText.c_str();
}

//------------------------------------------------------------------------------
double vtkSNDFRenderPass::GetLastSampleSeconds()
{
  this->Internals->ReadTimes();
  return this->Internals->Seconds[0];
}

//------------------------------------------------------------------------------
double vtkSNDFRenderPass::GetLastAccumulateSeconds()
{
  this->Internals->ReadTimes();
  return this->Internals->Seconds[1];
}

//------------------------------------------------------------------------------
double vtkSNDFRenderPass::GetLastShadeSeconds()
{
  this->Internals->ReadTimes();
  return this->Internals->Seconds[2];
}

//------------------------------------------------------------------------------
vtkMTimeType vtkSNDFRenderPass::GetShaderStageMTime()
{
  return this->Internals->ShaderTime.GetMTime();
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::PreReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  if (IsSampledParticleMapper(mapper))
  {
    return true; // PostReplaceShaderValues writes the particle samples
  }
  // every other shader replaces the particle sample with "no particle" (VTK declares an output
  // per gl_FragData index it finds; outputs not written would be undefined). Alpha 1: VTK
  // blends opaque geometry too (SRC_ALPHA, ONE_MINUS_SRC_ALPHA), so a write with alpha 0 would
  // leave the particle sample behind it in place.
  const std::string tag = "//VTK::DepthPeeling::Impl";
  vtkShaderProgram::Substitute(fragmentShader, tag,
    "gl_FragData[1] = vec4(0.0, 0.0, -1.0, 1.0);\n  gl_FragData[2] = vec4(0.0, 0.0, 0.0, 1.0);\n  " +
      tag,
    false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{

  if (!IsSampledParticleMapper(mapper))
  {
    return true;
  }
  vtkParticleShaderHooks& hooks = this->Internals->Hooks;
  hooks.Begin(vertexShader, geometryShader, fragmentShader);
  // the sample: the view-space normal (facing the viewer), the ambient visibility plus 2 (it
  // marks a particle sample: the delegate's clear may fill the target with the background
  // colour, components in [0, 1]) and the diffuse colour; the colour target keeps the shading
  // that needs no normal (the occluded ambient colour and what the AO source adds)
  hooks.Insert(vtkParticleShaderHooks::Fragment, "//PR::Shading::Impl",
    "gl_FragData[1] = vec4(normalVCVSOutput.xy, 2.0 + clamp(prAmbientOcclusion, 0.0, 1.0), 1.0);\n"
    "    gl_FragData[2] = vec4(diffuseColor, 1.0);\n"
    "    gl_FragData[0] = vec4(prAmbientOcclusion * ambientColor + prAmbientLight, 1.0);");
  return true;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::Render(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass: nothing is rendered.");
    return;
  }
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkOpenGLRenderWindow* context =
    ren ? vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()) : nullptr;

  // the scene: the sampled particle props, the reason to render plainly, the sampling state
  std::vector<vtkActor*> particles;
  std::string unsupported;
  std::vector<double> state;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (!prop->GetVisibility())
    {
      continue;
    }
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
    state.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(prop)));
    if (vtkParticleSphereMapper::SafeDownCast(mapper))
    {
      if (!IsSampledParticleMapper(mapper))
      {
        unsupported = std::string("a ") + mapper->GetClassName() +
          " is in the view (it draws through its own targets)";
      }
      else if (actor->HasTranslucentPolygonalGeometry())
      {
        unsupported = "a particle actor is translucent (S-NDFs shade opaque spheres)";
      }
      particles.push_back(actor);
      // the actor's placement and its material but for the specular settings (they re-shade)
      AppendMatrix(state, actor->GetMatrix());
      vtkProperty* p = actor->GetProperty();
      state.push_back(p->GetAmbient());
      state.push_back(p->GetDiffuse());
      state.insert(state.end(), p->GetAmbientColor(), p->GetAmbientColor() + 3);
      state.insert(state.end(), p->GetDiffuseColor(), p->GetDiffuseColor() + 3);
      state.push_back(p->GetOpacity());
      state.push_back(p->GetLighting());
    }
    else
    {
      // Other opaque geometry is sampled with the particles: its colour goes into the colour
      // target and its fragments mark the other targets "no particle" (PreReplaceShaderValues).
      // Translucent geometry would have to attenuate the particle samples behind it, and props
      // that are not actors (volumes, images, 2D actors) do not take the marking.
      if (!actor || !mapper)
      {
        unsupported = std::string("a ") + prop->GetClassName() +
          " is in the view (S-NDFs are drawn for views of particles and opaque polygonal props)";
      }
      else if (actor->HasTranslucentPolygonalGeometry())
      {
        unsupported = std::string("translucent geometry (") + mapper->GetClassName() +
          ") is in the view (S-NDFs are drawn for views of particles and opaque polygonal props)";
      }
      state.push_back(static_cast<double>(prop->GetMTime()));
      state.push_back(static_cast<double>(prop->GetRedrawMTime()));
    }
    if (mapper)
    {
      state.push_back(static_cast<double>(mapper->GetMTime()));
      vtkDataObject* input = mapper->GetInputDataObject(0, 0);
      state.push_back(input ? static_cast<double>(input->GetMTime()) : 0.0);
    }
  }
  auto renderPlain = [&]() {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    this->NumberOfSamples = 0;
    this->ActiveBinsPerAxis = 0;
    internals.SampleState.clear();
  };
  if (particles.empty() || !ren || !context)
  {
    renderPlain();
    return;
  }
  if (!unsupported.empty())
  {
    if (internals.FirstWarning(unsupported))
    {
      vtkWarningMacro(<< "S-NDF shading is off while " << unsupported
                      << "; the view is rendered as without it.");
    }
    renderPlain();
    return;
  }
  std::string reason;
  if (!vtkParticleComputeProgram::IsSupported(context, &reason))
  {
    if (internals.FirstWarning(reason))
    {
      vtkErrorMacro(<< "S-NDF shading needs compute shaders: " << reason
                    << ". The view is rendered as without it.");
    }
    renderPlain();
    return;
  }
  int width = 0;
  int height = 0;
  int x0 = 0;
  int y0 = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (width < 1 || height < 1)
  {
    renderPlain();
    return;
  }

  // bins that fit the memory limit
  int bins = this->BinsPerAxis;
  auto bytesFor = [&](int b) {
    return static_cast<double>(width) * height * (4.0 * WordsPerPixel(b) + SumBytesPerPixel);
  };
  while (bins >= 4 && bytesFor(bins) > this->MaximumMemory * 1048576.0)
  {
    bins /= 2;
  }
  if (bins < 4)
  {
    const std::string what = "memory " + std::to_string(width) + "x" + std::to_string(height);
    if (internals.FirstWarning(what))
    {
      vtkWarningMacro(<< "The S-NDFs of a " << width << " x " << height << " view need "
                      << bytesFor(4) / 1048576.0 << " MB even with 4 x 4 bins, more than "
                      << "MaximumMemory (" << this->MaximumMemory
                      << " MB): the view is rendered as without S-NDF shading.");
    }
    renderPlain();
    return;
  }
  if (bins != this->BinsPerAxis)
  {
    const std::string what = "bins " + std::to_string(width) + "x" + std::to_string(height) +
      " " + std::to_string(bins);
    if (internals.FirstWarning(what))
    {
      vtkWarningMacro(<< "MaximumMemory (" << this->MaximumMemory << " MB) holds the S-NDFs of "
                      << "this " << width << " x " << height << " view with " << bins << " x "
                      << bins << " bins only, not " << this->BinsPerAxis << " x "
                      << this->BinsPerAxis << ".");
    }
  }

  // the view: camera, size, bins, background. The camera's values are compared in single
  // precision: vtkWindowToImageFilter restores the view angle with a last-bit difference.
  vtkCamera* camera = ren->GetActiveCamera();
  const std::size_t panAt = state.size(); // camera position and focal point: state[panAt, +6)
  std::vector<double> view;
  view.insert(view.end(), camera->GetPosition(), camera->GetPosition() + 3);
  view.insert(view.end(), camera->GetFocalPoint(), camera->GetFocalPoint() + 3);
  view.insert(view.end(), camera->GetViewUp(), camera->GetViewUp() + 3);
  view.insert(view.end(), camera->GetClippingRange(), camera->GetClippingRange() + 2);
  view.insert(view.end(), camera->GetWindowCenter(), camera->GetWindowCenter() + 2);
  view.push_back(camera->GetViewAngle());
  view.push_back(camera->GetParallelScale());
  view.push_back(camera->GetParallelProjection());
  AppendMatrix(view, camera->GetModelTransformMatrix());
  for (double v : view)
  {
    state.push_back(static_cast<float>(v));
  }
  state.push_back(width);
  state.push_back(height);
  state.push_back(x0);
  state.push_back(y0);
  state.push_back(bins);
  state.insert(state.end(), ren->GetBackground(), ren->GetBackground() + 3);
  state.insert(state.end(), ren->GetBackground2(), ren->GetBackground2() + 3);
  state.push_back(ren->GetGradientBackground());
  state.push_back(ren->GetTexturedBackground());
  state.push_back(ren->GetBackgroundAlpha());
  state.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(context)));
  // the passes inside this one (an AO pass put into the chain or changed samples anew)
  vtkRenderPass* inner = this->DelegatePass;
  for (int depth = 0; inner && depth < 16; ++depth)
  {
    state.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(inner)));
    state.push_back(static_cast<double>(inner->GetMTime()));
    auto* wrapping = vtkImageProcessingPass::SafeDownCast(inner);
    inner = wrapping ? wrapping->GetDelegatePass() : nullptr;
  }

  vtkOpenGLState* ostate = context->GetState();
  if (internals.Context != context)
  {
    if (internals.Context)
    {
      this->ReleaseGraphicsResources(internals.Context);
    }
    internals.Context = context;
  }
  const bool timing = this->CollectTimings;
  if (timing)
  {
    internals.ReadTimes(); // (deletes the queries of an unread frame)
    internals.TimesRead = false;
  }

  // a pan: the S-NDFs move with the picture, only the pixels it uncovers start empty
  std::vector<double> fixedState = state;
  fixedState.erase(fixedState.begin() + panAt, fixedState.begin() + panAt + 6);
  int pan[2] = { 0, 0 };
  if (state != internals.SampleState && this->NumberOfSamples > 0 &&
    fixedState == internals.FixedState && width == internals.Width &&
    height == internals.Height && bins == internals.Bins &&
    this->PanShift(camera, internals.Position, internals.FocalPoint, height, pan) &&
    std::abs(pan[0]) < width && std::abs(pan[1]) < height)
  {
    internals.ShiftPixels(width, height, pan);
    internals.SampleState = state;
    internals.ResolveKey.clear();
    // the uncovered pixels refine from their first sample on; the others get more samples
    this->NumberOfSamples = 0;
    ++this->NumberOfPans;
  }
  internals.FixedState = fixedState;
  camera->GetPosition(internals.Position);
  camera->GetFocalPoint(internals.FocalPoint);

  // (re)start
  if (state != internals.SampleState)
  {
    if (width != internals.Width || height != internals.Height || bins != internals.Bins ||
      !internals.Depth || !internals.Depth->GetHandle())
    {
      internals.ReleaseTextures(context);
      internals.NewTextures();
      internals.Target->SetContext(context);
      for (unsigned int a = 0; a < NumberOfAttachments; ++a)
      {
        vtkTextureObject* t = internals.Attachments[a];
        t->SetContext(context);
        if (a > 0)
        {
          t->SetInternalFormat(GL_RGBA16F);
          t->SetFormat(GL_RGBA);
          t->SetDataType(GL_FLOAT);
          t->Allocate2D(width, height, 4, VTK_FLOAT);
        }
        else
        {
          // 8 bits, as the window: the background and other geometry come out exactly as drawn
          // without the pass (a particle's ambient term is quantised per sample, < 0.5/255)
          t->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
        }
      }
      internals.Depth->SetContext(context);
      internals.Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
      internals.Image->SetContext(context);
      internals.Image->SetInternalFormat(GL_RGBA32F);
      internals.Image->SetFormat(GL_RGBA);
      internals.Image->SetDataType(GL_FLOAT);
      internals.Image->Allocate2D(width, height, 4, VTK_FLOAT);
      internals.ImageDepth->SetContext(context);
      internals.ImageDepth->SetInternalFormat(GL_R32F);
      internals.ImageDepth->SetFormat(GL_RED);
      internals.ImageDepth->SetDataType(GL_FLOAT);
      internals.ImageDepth->Allocate2D(width, height, 1, VTK_FLOAT);
      ostate->PushFramebufferBindings();
      internals.Target->Bind();
      for (unsigned int a = 0; a < NumberOfAttachments; ++a)
      {
        internals.Target->AddColorAttachment(a, internals.Attachments[a]);
      }
      internals.Target->AddDepthAttachment(internals.Depth);
      ostate->PopFramebufferBindings();

      internals.WordsPerPixel = WordsPerPixel(bins);
      const std::size_t pixels = static_cast<std::size_t>(width) * height;
      if (!vtkParticleComputeProgram::AllocateStorage(
            internals.Counts, pixels * internals.WordsPerPixel * 4) ||
        !vtkParticleComputeProgram::AllocateStorage(
          internals.Sums, pixels * static_cast<std::size_t>(SumBytesPerPixel)))
      {
        vtkErrorMacro(<< "Could not allocate " << bytesFor(bins) / 1048576.0
                      << " MB for the S-NDFs: the view is rendered as without them.");
        internals.ReleaseTextures(context);
        renderPlain();
        return;
      }
      internals.Width = width;
      internals.Height = height;
      internals.Bins = bins;
      this->MemoryBytes = bytesFor(bins);
    }
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    vtkParticleComputeProgram::ClearStorage(internals.Counts, pixels * internals.WordsPerPixel * 4, 0u);
    vtkParticleComputeProgram::ClearStorage(
      internals.Sums, pixels * static_cast<std::size_t>(SumBytesPerPixel), 0u);
    internals.Rebake = false;
    internals.SampleState = state;
    internals.ResolveKey.clear();
    this->NumberOfSamples = 0;
    ++this->NumberOfRestarts;
    // The frame of a change (e.g. each frame of an interaction) is the plain image: one S-NDF
    // sample would shade with bin means, coarser than the exact normal. Sampling starts with the
    // next frame -- unless this render is to converge (ConvergeOnRender).
    if (!this->ConvergeOnRender)
    {
      this->DelegatePass->Render(s);
      this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
      this->ActiveBinsPerAxis = bins;
      return;
    }
  }
  this->ActiveBinsPerAxis = bins;

  if (!internals.Accumulate->IsBuilt())
  {
    internals.Accumulate->SetSource(vtkParticleShaders::Get("SNDFAccumulate"));
    internals.Resolve->SetSource(vtkParticleShaders::Get("SNDFResolve"));
    if (!internals.Accumulate->Build(context) || !internals.Resolve->Build(context))
    {
      renderPlain();
      return;
    }
  }

  // the lighting table (Eqs. 12-14) for the renderer's lights and the first particle actor's
  // specular power
  vtkProperty* material = particles[0]->GetProperty();
  for (vtkActor* actor : particles)
  {
    vtkProperty* p = actor->GetProperty();
    if ((p->GetSpecular() != material->GetSpecular() ||
          p->GetSpecularPower() != material->GetSpecularPower()) &&
      internals.FirstWarning("specular"))
    {
      vtkWarningMacro(<< "The particle actors differ in their specular material; S-NDF shading "
                         "uses the first one's.");
    }
  }
  // the renderer's light geometry (lights that follow the camera), uniforms and complexity are
  // brought up to date by its lights pass, which
  // does not run when nothing is sampled
  internals.BeginStage(timing, 2);
  internals.Lights->Render(s);
  std::vector<double> tableKey = { static_cast<double>(ren->GetLightingComplexity()),
    static_cast<double>(ren->GetLightingCount()), material->GetSpecularPower(),
    static_cast<double>(bins), camera->GetDistance() };
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    tableKey.push_back(static_cast<double>(light->GetMTime()));
    AppendMatrix(tableKey, light->GetTransformMatrix());
  }
  AppendMatrix(tableKey, camera->GetModelViewTransformMatrix());
  if (tableKey != internals.TableKey || !internals.HaveTable)
  {
    const std::string uniforms = ren->GetLightingUniforms();
    const int complexity = ren->GetLightingComplexity();
    const int count = ren->GetLightingCount();
    std::string body = "vec3 prLightSum(vec3 normalVCVSOutput, int row)\n{\n"
                       "  float specularPower = prSpecularPower;\n"
                       "  vec4 vertexVC = vec4(0.0, 0.0, -prViewDistance, 1.0);\n" +
      vtkParticleSphereMapper::GetLightSumCode(complexity, count) +
      "  return row == 0 ? diffuse : specular;\n}\n";
    const std::string source = uniforms + "\n" + body;
    if (!internals.TableQuad || source != internals.TableQuadSource)
    {
      std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
      vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl",
        vtkParticleShaders::Get("SNDFLightingTable") + "\n" + source);
      vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl",
        "ivec2 prTexel = ivec2(texCoord * vec2(float(prBins * prBins), 2.0));\n"
        "  vec3 prSum = vec3(0.0);\n"
        "  float prN = 0.0;\n"
        "  for (int i = 0; i < prSubsamples; ++i)\n"
        "  {\n"
        "    for (int j = 0; j < prSubsamples; ++j)\n"
        "    {\n"
        "      vec3 prNormal;\n"
        "      if (prSNDFBinPoint(prTexel.x, prBins, (vec2(i, j) + 0.5) / float(prSubsamples),"
        " prNormal))\n"
        "      {\n"
        "        prSum += prLightSum(prNormal, prTexel.y);\n"
        "        prN += 1.0;\n"
        "      }\n"
        "    }\n"
        "  }\n"
        "  if (prN == 0.0)\n"
        "  {\n"
        "    // a bin outside the disk holds no sample; give it the normal of the rim point nearest\n"
        "    // to its centre\n"
        "    vec3 prCentre;\n"
        "    prSNDFBinPoint(prTexel.x, prBins, vec2(0.5), prCentre);\n"
        "    vec2 prRim = normalize(prCentre.xy) * 0.9999;\n"
        "    prSum = prLightSum(vec3(prRim, sqrt(max(0.0, 1.0 - dot(prRim, prRim)))), prTexel.y);\n"
        "    prN = 1.0;\n"
        "  }\n"
        "  gl_FragData[0] = vec4(prSum / prN, 1.0);\n");
      internals.TableQuad.reset(new vtkOpenGLQuadHelper(context, nullptr, fs.c_str(), nullptr));
      internals.TableQuadSource = source;
    }
    vtkOpenGLQuadHelper* quad = internals.TableQuad.get();
    if (!quad->Program)
    {
      internals.EndStage(timing);
      vtkErrorMacro(<< "The S-NDF lighting table shader did not build.");
      renderPlain();
      return;
    }
    if (internals.TableBins != bins || !internals.Table->GetHandle())
    {
      internals.Table->SetContext(context);
      internals.Table->SetInternalFormat(GL_RGBA32F);
      internals.Table->SetFormat(GL_RGBA);
      internals.Table->SetDataType(GL_FLOAT);
      internals.Table->Allocate2D(bins * bins, 2, 4, VTK_FLOAT);
      internals.TableTarget->SetContext(context);
      ostate->PushFramebufferBindings();
      internals.TableTarget->Bind();
      internals.TableTarget->AddColorAttachment(0, internals.Table);
      internals.TableTarget->ActivateDrawBuffers(1);
      ostate->PopFramebufferBindings();
      internals.TableBins = bins;
    }
    context->GetShaderCache()->ReadyShaderProgram(quad->Program);
    ren->UpdateLightingUniforms(quad->Program);
    quad->Program->SetUniformi("prBins", bins);
    quad->Program->SetUniformi("prSubsamples", std::max(32, TableSubsamplesPerAxis / bins));
    quad->Program->SetUniformf("prSpecularPower", static_cast<float>(material->GetSpecularPower()));
    quad->Program->SetUniformf("prViewDistance", static_cast<float>(camera->GetDistance()));
    ostate->PushFramebufferBindings();
    internals.TableTarget->Bind();
    internals.TableTarget->ActivateDrawBuffers(1);
    {
      vtkOpenGLState::ScopedglViewport viewport(ostate);
      vtkOpenGLState::ScopedglScissor scissor(ostate);
      vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
      vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
      ostate->vtkglDisable(GL_DEPTH_TEST);
      ostate->vtkglDisable(GL_BLEND);
      ostate->vtkglViewport(0, 0, bins * bins, 2);
      ostate->vtkglScissor(0, 0, bins * bins, 2);
      quad->Render();
    }
    ostate->PopFramebufferBindings();
    internals.TableKey = tableKey;
    internals.HaveTable = true;
    ++this->NumberOfTableBuilds;
    // the samples taken so far were shaded with the old table (none after a restart)
    internals.Rebake = internals.Rebake || this->NumberOfSamples > 0;
  }

  internals.EndStage(timing);

  // sample passes
  const int samples = this->ConvergeOnRender
    ? this->TargetSamples - this->NumberOfSamples
    : std::min(this->SamplesPerFrame, this->TargetSamples - this->NumberOfSamples);
  const unsigned int groupsX = static_cast<unsigned int>((width + 15) / 16);
  const unsigned int groupsY = static_cast<unsigned int>((height + 15) / 16);
  // a render of many sample passes (ConvergeOnRender, a large SamplesPerFrame) reports them
  const bool reporting = samples >= ProgressSamples;
  if (reporting)
  {
    internals.ProgressText = "S-NDF shading: " + std::to_string(this->TargetSamples) +
      " samples per pixel";
    double fraction = 0.0;
    this->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
  }
  for (int k = 0; k < samples; ++k)
  {
    double centre[2];
    camera->GetWindowCenter(centre);
    double offset[2];
    JitterOffset(this->NumberOfSamples, offset);
    camera->SetWindowCenter(centre[0] + 2.0 * offset[0] / width, centre[1] + 2.0 * offset[1] / height);

    internals.BeginStage(timing, 0);
    ostate->PushFramebufferBindings();
    internals.Target->Bind();
    internals.Target->ActivateDrawBuffers(NumberOfAttachments);
    {
      vtkOpenGLState::ScopedglViewport viewport(ostate);
      vtkOpenGLState::ScopedglScissor scissor(ostate);
      ostate->vtkglViewport(0, 0, width, height);
      ostate->vtkglScissor(0, 0, width, height);
      ren->Clear();
      const GLfloat zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
      for (unsigned int a = 1; a < NumberOfAttachments; ++a)
      {
        glClearBufferfv(GL_COLOR, static_cast<GLint>(a), zero);
      }
      vtkRenderState sampleState(ren);
      sampleState.SetFrameBuffer(internals.Target);
      sampleState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
      this->PreRender(&sampleState);
      this->DelegatePass->Render(&sampleState);
      this->PostRender(&sampleState);
      this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    }
    ostate->PopFramebufferBindings();
    internals.EndStage(timing);
    camera->SetWindowCenter(centre[0], centre[1]);
    ++this->NumberOfSamplePasses;

    // into the S-NDFs
    internals.BeginStage(timing, 1);
    vtkParticleComputeProgram* accumulate = internals.Accumulate;
    accumulate->Use();
    const char* samplers[NumberOfAttachments] = { "prColour", "prNormal", "prDiffuse" };
    for (unsigned int a = 0; a < NumberOfAttachments; ++a)
    {
      internals.Attachments[a]->Activate();
      accumulate->SetUniformi(samplers[a], internals.Attachments[a]->GetTextureUnit());
    }
    internals.Depth->Activate();
    accumulate->SetUniformi("prDepth", internals.Depth->GetTextureUnit());
    internals.Table->Activate();
    accumulate->SetUniformi("prTable", internals.Table->GetTextureUnit());
    accumulate->SetUniform2i("prSize", width, height);
    accumulate->SetUniformi("prBins", bins);
    accumulate->SetUniformi("prWordsPerPixel", internals.WordsPerPixel);
    vtkParticleComputeProgram::BindStorage(0, internals.Counts);
    vtkParticleComputeProgram::BindStorage(1, internals.Sums);
    accumulate->Dispatch(groupsX, groupsY);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    for (unsigned int a = 0; a < NumberOfAttachments; ++a)
    {
      internals.Attachments[a]->Deactivate();
    }
    internals.Depth->Deactivate();
    internals.Table->Deactivate();
    vtkParticleComputeProgram::UseNone();
    internals.EndStage(timing);
    ++this->NumberOfSamples;
    if (reporting)
    {
      double fraction = static_cast<double>(k + 1) / samples;
      this->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
    }
  }

  // shade when samples, table or specular colour changed
  internals.BeginStage(timing, 2);
  double specular[3];
  material->GetSpecularColor(specular);
  for (double& c : specular)
  {
    c *= material->GetSpecular();
  }
  std::vector<double> resolveKey = { static_cast<double>(this->NumberOfSamples),
    static_cast<double>(this->NumberOfTableBuilds), specular[0], specular[1], specular[2] };
  if (resolveKey != internals.ResolveKey)
  {
    vtkParticleComputeProgram* resolve = internals.Resolve;
    resolve->Use();
    internals.Table->Activate();
    resolve->SetUniformi("prTable", internals.Table->GetTextureUnit());
    resolve->SetUniform2i("prSize", width, height);
    resolve->SetUniformi("prBins", bins);
    resolve->SetUniformi("prWordsPerPixel", internals.WordsPerPixel);
    resolve->SetUniformi("prRebake", internals.Rebake ? 1 : 0);
    resolve->SetUniform3f("prSpecularColour", static_cast<float>(specular[0]),
      static_cast<float>(specular[1]), static_cast<float>(specular[2]));
    vtkParticleComputeProgram::BindStorage(0, internals.Counts);
    vtkParticleComputeProgram::BindStorage(1, internals.Sums);
    glBindImageTexture(0, internals.Image->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, internals.ImageDepth->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    resolve->Dispatch(groupsX, groupsY);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    internals.Table->Deactivate();
    vtkParticleComputeProgram::UseNone();
    internals.ResolveKey = resolveKey;
    internals.Rebake = false;
    ++this->NumberOfResolves;
  }

  // the composite: colour and depth into the render state's target, over the whole viewport
  if (!internals.CompositeQuad)
  {
    std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl",
      "uniform sampler2D prImage;\nuniform sampler2D prImageDepth;\n");
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl",
      "gl_FragData[0] = texture(prImage, texCoord);\n"
      "  gl_FragDepth = texture(prImageDepth, texCoord).r;\n");
    internals.CompositeQuad.reset(new vtkOpenGLQuadHelper(context, nullptr, fs.c_str(), nullptr));
  }
  vtkOpenGLQuadHelper* composite = internals.CompositeQuad.get();
  if (composite->Program)
  {
    context->GetShaderCache()->ReadyShaderProgram(composite->Program);
    internals.Image->Activate();
    internals.ImageDepth->Activate();
    composite->Program->SetUniformi("prImage", internals.Image->GetTextureUnit());
    composite->Program->SetUniformi("prImageDepth", internals.ImageDepth->GetTextureUnit());
    vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    ostate->vtkglDepthMask(GL_TRUE);
    ostate->vtkglDisable(GL_BLEND);
    composite->Render();
    internals.Image->Deactivate();
    internals.ImageDepth->Deactivate();
  }
  internals.EndStage(timing);
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::GetLightingTable(vtkFloatArray* table)
{
  vtkInternals& internals = *this->Internals;
  if (!table || !internals.HaveTable || !internals.Table->GetHandle())
  {
    return false;
  }
  const int n = internals.TableBins * internals.TableBins;
  std::vector<float> texels(static_cast<std::size_t>(n) * 2 * 4);
  internals.Table->Bind();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, texels.data());
  table->SetNumberOfComponents(3);
  table->SetNumberOfTuples(2 * n);
  for (int t = 0; t < 2 * n; ++t)
  {
    table->SetTypedTuple(t, &texels[4 * static_cast<std::size_t>(t)]);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& internals = *this->Internals;
  internals.ReleaseTextures(w);
  internals.Table->ReleaseGraphicsResources(w);
  internals.TableTarget->ReleaseGraphicsResources(w);
  internals.HaveTable = false;
  internals.TableBins = 0;
  if (internals.TableQuad)
  {
    internals.TableQuad->ReleaseGraphicsResources(w);
    internals.TableQuad.reset();
  }
  if (internals.CompositeQuad)
  {
    internals.CompositeQuad->ReleaseGraphicsResources(w);
    internals.CompositeQuad.reset();
  }
  internals.Accumulate->ReleaseGraphicsResources(w);
  internals.Resolve->ReleaseGraphicsResources(w);
  const bool current = vtkParticleComputeProgram::MakeCurrentForRelease(internals.Context);
  vtkParticleComputeProgram::ReleaseStorage(internals.Counts, current);
  vtkParticleComputeProgram::ReleaseStorage(internals.Sums, current);
  vtkParticleComputeProgram::ReleaseStorage(internals.Row, current);
  internals.SampleState.clear();
  internals.FixedState.clear();
  internals.TableKey.clear();
  internals.ResolveKey.clear();
  internals.Bins = 0;
  this->NumberOfSamples = 0;
  this->MemoryBytes = 0.0;
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SamplesPerFrame: " << this->SamplesPerFrame << "\n";
  os << indent << "TargetSamples: " << this->TargetSamples << "\n";
  os << indent << "BinsPerAxis: " << this->BinsPerAxis << "\n";
  os << indent << "MaximumMemory: " << this->MaximumMemory << " MB\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "ActiveBinsPerAxis: " << this->ActiveBinsPerAxis << "\n";
  os << indent << "MemoryBytes: " << this->MemoryBytes << "\n";
  os << indent << "ConvergeOnRender: " << this->ConvergeOnRender << "\n";
  os << indent << "CollectTimings: " << this->CollectTimings << "\n";
}
