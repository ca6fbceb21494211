#include "vtkPointAOPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleGBufferExchange.h"
#include "vtkParticleGBufferGuard.h"
#include "vtkParticleShaders.h"
#include "vtkParticleSphereMapper.h"
#include "vtkParticleStageTimer.h"
#include "vtkParticleViewport.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkPointAOPass);

namespace
{
// the tag the pass puts after VTK's lighting (PreReplaceShaderValues) and fills in
// PostReplaceShaderValues: the G-buffer's normal
const char* const NormalTag = "//PR::PointAO::Normal";

// the G-buffer: colour, normal (times 3 + the sphere's radius), the stamp of the normal's fragment
const unsigned int NumberOfGBufferTargets = 3;

// The stamp a hooked fragment writes with its normal: its window depth plus this key, a value no
// other shader computes (an undefined output of a foreign shader that sampled the depth buffer
// cannot pass for a stamp by holding that depth). Exact in binary; passed to the occlusion as
// prStampKey.
const char* const StampKeyGLSL = "19.75";
const float StampKey = 19.75f;

// The mean world radius of the spheres of one particle prop: at most 65536 of the radii the
// mapper draws with, evenly spaced (the positive ones), times the mapper's radius scale and the
// actor's scale. Returns false when the prop has no particle to draw.
bool MeanRadius(vtkActor* actor, vtkParticleSphereMapper* mapper, double& mean, double& count)
{
  vtkFloatArray* radii = mapper->GetParticleRadii();
  const vtkIdType n = radii ? radii->GetNumberOfTuples() : 0;
  const vtkIdType step = std::max<vtkIdType>(1, n / 65536);
  double sum = 0.0;
  vtkIdType used = 0;
  for (vtkIdType i = 0; i < n; i += step)
  {
    const float r = radii->GetValue(i);
    if (std::isfinite(r) && r > 0.0f)
    {
      sum += r;
      ++used;
    }
  }
  const double radius = used > 0 ? sum / used * mapper->GetRadiusScaleVC(actor) : 0.0;
  if (!(radius > 0.0) || !std::isfinite(radius))
  {
    return false;
  }
  mean = radius;
  count = static_cast<double>(n);
  return true;
}
}

class vtkPointAOPass::vtkInternals
{
public:
  vtkOpenGLRenderWindow* Context = nullptr;
  int Width = 0;
  int Height = 0;
  int Step = 1; // G-buffer pixels per occlusion texel along each axis
  vtkNew<vtkOpenGLFramebufferObject> GBuffer;
  vtkNew<vtkTextureObject> Colour;
  vtkNew<vtkTextureObject> Normal;
  vtkNew<vtkTextureObject> NormalDepth; // the stamp of the fragment that wrote Normal
  vtkNew<vtkTextureObject> Depth;
  // distributed rendering: the nearest depth over all processes (the occlusion reads it; the
  // composite writes this process's own depth)
  vtkNew<vtkTextureObject> ExchangedDepth;
  vtkNew<vtkParticleGBufferExchange> Exchange;
  vtkNew<vtkOpenGLFramebufferObject> Work;
  vtkNew<vtkTextureObject> Occlusion;
  vtkNew<vtkTextureObject> Blurred;
  std::unique_ptr<vtkOpenGLQuadHelper> OcclusionQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> BlurQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> CompositeQuad;
  vtkSmartPointer<vtkOpenGLFXAAFilter> FXAA;
  bool WarnedTranslucent = false;
  // the automatic Radius: the sum and number of this process's particles' mean radii, and what
  // they were computed from
  double RadiusSum = 0.0;
  double RadiusCount = 0.0;
  std::vector<double> RadiusKey;
  bool WarnedViewport = false;
  // GPU times: G-buffer, occlusion, blur, composite
  vtkParticleStageTimer Timer{ 4 };

  // this frame (PrepareFrame and the stages after it)
  vtkOpenGLRenderer* Renderer = nullptr;
  int LowWidth = 0; // the occlusion's size (Step: half resolution)
  int LowHeight = 0;
  bool StoredNormals = true; // the G-buffer holds the normals (InspectProps)
  bool HeldBackFXAA = false; // the renderer's FXAA, applied after the composite
  bool Occlude = false;      // a radius and a strength: the occlusion is computed
  double BlurTolerance = 0.0;
  float Projection[16];        // view -> clip, column-major
  float InverseProjection[16]; // clip -> view
  double ClipRange[2] = { 0.0, 1.0 };
  vtkTextureObject* OcclusionDepth = nullptr; // the depth the occlusion reads
  vtkTextureObject* Result = nullptr;         // the occlusion the composite reads
  bool VerticalBlur = false;                  // the composite blurs vertically

  void ReleaseTextures(vtkWindow* w)
  {
    for (vtkTextureObject* t :
      { this->Colour.Get(), this->Normal.Get(), this->NormalDepth.Get(), this->Depth.Get(),
        this->ExchangedDepth.Get(), this->Occlusion.Get(), this->Blurred.Get() })
    {
      t->ReleaseGraphicsResources(w);
    }
    this->GBuffer->ReleaseGraphicsResources(w);
    this->Work->ReleaseGraphicsResources(w);
    this->Width = 0;
    this->Height = 0;
  }

  // the textures and framebuffers for a width x height viewport
  void Allocate(vtkOpenGLRenderWindow* context, int width, int height, int step)
  {
    if (width == this->Width && height == this->Height && step == this->Step &&
      this->Colour->GetHandle() &&
      (!this->Exchange->IsDistributed() || this->ExchangedDepth->GetHandle()))
    {
      return;
    }
    this->ReleaseTextures(context);
    auto setUp = [&](vtkTextureObject* t)
    {
      t->SetContext(context);
      t->SetMinificationFilter(vtkTextureObject::Nearest);
      t->SetMagnificationFilter(vtkTextureObject::Nearest);
      t->SetWrapS(vtkTextureObject::ClampToEdge);
      t->SetWrapT(vtkTextureObject::ClampToEdge);
    };
    setUp(this->Colour);
    this->Colour->SetInternalFormat(GL_RGBA8);
    this->Colour->SetFormat(GL_RGBA);
    this->Colour->SetDataType(GL_UNSIGNED_BYTE);
    this->Colour->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
    setUp(this->Normal);
    this->Normal->SetInternalFormat(GL_RGBA32F);
    this->Normal->SetFormat(GL_RGBA);
    this->Normal->SetDataType(GL_FLOAT);
    this->Normal->Allocate2D(width, height, 4, VTK_FLOAT);
    setUp(this->NormalDepth);
    this->NormalDepth->SetInternalFormat(GL_R32F);
    this->NormalDepth->SetFormat(GL_RED);
    this->NormalDepth->SetDataType(GL_FLOAT);
    this->NormalDepth->Allocate2D(width, height, 1, VTK_FLOAT);
    setUp(this->Depth);
    this->Depth->AllocateDepth(width, height, vtkTextureObject::Float32);
    if (this->Exchange->IsDistributed())
    {
      setUp(this->ExchangedDepth);
      this->ExchangedDepth->SetInternalFormat(GL_R32F);
      this->ExchangedDepth->SetFormat(GL_RED);
      this->ExchangedDepth->SetDataType(GL_FLOAT);
      this->ExchangedDepth->Allocate2D(width, height, 1, VTK_FLOAT);
    }
    for (vtkTextureObject* t : { this->Occlusion.Get(), this->Blurred.Get() })
    {
      setUp(t);
      // (occlusion, view depth, geometry flag)
      t->SetInternalFormat(GL_RGBA16F);
      t->SetFormat(GL_RGBA);
      t->SetDataType(GL_FLOAT);
      t->Allocate2D((width + step - 1) / step, (height + step - 1) / step, 4, VTK_FLOAT);
    }
    this->GBuffer->SetContext(context);
    context->GetState()->PushFramebufferBindings();
    this->GBuffer->Bind();
    this->GBuffer->AddColorAttachment(0, this->Colour);
    this->GBuffer->AddColorAttachment(1, this->Normal);
    this->GBuffer->AddColorAttachment(2, this->NormalDepth);
    this->GBuffer->AddDepthAttachment(this->Depth);
    context->GetState()->PopFramebufferBindings();
    this->Work->SetContext(context);
    this->Width = width;
    this->Height = height;
    this->Step = step;
  }

  vtkOpenGLQuadHelper* Quad(
    std::unique_ptr<vtkOpenGLQuadHelper>& quad, const std::string& decl, const std::string& impl)
  {
    if (!quad)
    {
      std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
      vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl", decl);
      vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", impl);
      quad.reset(new vtkOpenGLQuadHelper(this->Context, nullptr, fs.c_str(), nullptr));
    }
    else if (quad->Program)
    {
      this->Context->GetShaderCache()->ReadyShaderProgram(quad->Program);
    }
    return (quad->Program && quad->Program->GetCompiled()) ? quad.get() : nullptr;
  }
};

//------------------------------------------------------------------------------
vtkPointAOPass::vtkPointAOPass()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkPointAOPass::~vtkPointAOPass()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
void vtkPointAOPass::SetController(vtkMultiProcessController* controller)
{
  if (this->Internals->Exchange->GetController() != controller)
  {
    this->Internals->Exchange->SetController(controller);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkPointAOPass::GetController()
{
  return this->Internals->Exchange->GetController();
}

//------------------------------------------------------------------------------
double vtkPointAOPass::GetStageSeconds(int stage)
{
  return this->Internals->Timer.Seconds(stage);
}

//------------------------------------------------------------------------------
bool vtkPointAOPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  // after VTK's lighting the normal (unit, facing the viewer) and the position are in scope in
  // VTK's polygonal shaders and in the particle templates (vtkParticleShaderHooks)
  if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl",
      std::string("//VTK::Light::Impl\n  ") + NormalTag + "\n", false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkPointAOPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  if (fragmentShader.find(NormalTag) == std::string::npos)
  {
    return true;
  }
  // the normal where the shader has one, scaled to length 3 + the sphere's radius for particles
  // and 3 for other geometry: the length marks a normal (the delegate's clear leaves colours in
  // [0, 1]^3, length <= sqrt(3)) and gives the radius, which tells the occlusion which surface
  // is the pixel's own sphere. Alpha 1: VTK blends opaque geometry too (SRC_ALPHA,
  // ONE_MINUS_SRC_ALPHA), which then keeps the written value. Geometry without normals (unlit
  // lines and points) writes 0: the occlusion takes the depth buffer's normal.
  const bool hasNormal = fragmentShader.find("normalVCVSOutput") != std::string::npos &&
    fragmentShader.find("vertexVC") != std::string::npos;
  std::string code = "gl_FragData[1] = vec4(0.0, 0.0, 0.0, 1.0);\n";
  if (vtkParticleSphereMapper::SafeDownCast(mapper) && hasNormal)
  {
    code = "gl_FragData[1] = vec4(normalize(normalVCVSOutput) * (3.0 + radiusVC), 1.0);\n";
  }
  else if (hasNormal)
  {
    code = "gl_FragData[1] = vec4(normalize(normalVCVSOutput) * 3.0, 1.0);\n";
  }
  // With the normal, its stamp: the window depth this fragment gives the depth buffer (VTK's and
  // the particle shaders write gl_FragDepth before the lighting, if at all; stored clamped to
  // [0, 1]) plus the key. The occlusion trusts a normal only where the stamp equals the depth
  // buffer's value plus the key, i.e. where the fragment that won the depth test wrote it.
  // Whatever else the delegate draws into the G-buffer after the opaque geometry (depth
  // peeling's and volumes' full-screen quads, overlays) writes undefined values to these
  // targets (its shader has no such output); a fragment that writes no depth
  // (PR_NO_DEPTH_WRITE: translucent spheres) writes -1, which no stamp equals.
  const std::string key = StampKeyGLSL;
  const bool writesDepth = fragmentShader.find("gl_FragDepth =") != std::string::npos;
  code += writesDepth
    ? "#ifdef PR_NO_DEPTH_WRITE\n  gl_FragData[2] = vec4(-1.0, 0.0, 0.0, 1.0);\n#else\n"
      "  gl_FragData[2] = vec4(clamp(gl_FragDepth, 0.0, 1.0) + " +
      key + ", 0.0, 0.0, 1.0);\n#endif\n"
    : "  gl_FragData[2] = vec4(gl_FragCoord.z + " + key + ", 0.0, 0.0, 1.0);\n";
  vtkShaderProgram::Substitute(fragmentShader, NormalTag, code, false);
  return true;
}

//------------------------------------------------------------------------------
void vtkPointAOPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass: nothing is rendered.");
    return;
  }
  if (!this->PrepareFrame(s))
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }
  this->InspectProps(s);
  this->UpdateEffectiveRadius(s);
  this->RenderGBuffer(s);
  this->ExchangeGBuffer();
  this->SetUpProjection();
  {
    // the image-space stages draw full-screen quads without blending or scissor
    vtkOpenGLState* ostate = this->Internals->Context->GetState();
    vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable scissorTest(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    this->FrameBudget->StartTiming(); // the occlusion and its composite, not the scene
    this->ComputeOcclusion();
    this->Composite();
    this->FrameBudget->EndFrame();
    this->ApplyHeldBackFXAA();
    this->Internals->Timer.End();
  }
  vtkOpenGLCheckErrorMacro("failed after vtkPointAOPass::Render");
}

//------------------------------------------------------------------------------
bool vtkPointAOPass::PrepareFrame(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkOpenGLRenderWindow* context =
    ren ? vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()) : nullptr;
  int width = 0;
  int height = 0;
  int x0 = 0;
  int y0 = 0;
  if (ren)
  {
    ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  }
  if (!context || width < 1 || height < 1)
  {
    return false;
  }
  std::string part;
  if (!vtkParticleViewport::FillsTarget(s, part))
  {
    if (!internals.WarnedViewport)
    {
      vtkWarningMacro(<< "PointAO needs a renderer that fills its window (this one covers " << part
                      << "): it is drawn without ambient occlusion.");
      internals.WarnedViewport = true;
    }
    return false;
  }
  if (internals.Context != context)
  {
    if (internals.Context)
    {
      this->ReleaseGraphicsResources(internals.Context);
    }
    internals.Context = context;
  }
  internals.Renderer = ren;
  internals.Timer.StartFrame(this->CollectTimings);
  // the frame budget's levels: 0 half resolution, 1 the resolution set
  const bool exact = this->FrameBudget->ChooseFrameLevel(ren, 2) == 1;
  const int step = this->HalfResolution || !exact ? 2 : 1;
  internals.Allocate(context, width, height, step);
  internals.LowWidth = (width + step - 1) / step;
  internals.LowHeight = (height + step - 1) / step;
  return true;
}

//------------------------------------------------------------------------------
void vtkPointAOPass::InspectProps(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  // What the delegate will draw, in one walk over the props:
  // - translucent particles are drawn over the opaque scene without depth: they are neither
  //   darkened nor occluders (said once, until the scene has none again);
  // - the G-buffer's normals: only when every visible prop is opaque geometry of a vtkActor. The
  //   passes that draw translucent geometry (depth peeling), volumes and 2D overlays write into
  //   the G-buffer with shaders that leave the normal targets undefined, and whether a driver
  //   writes garbage there or keeps the values varies (llvmpipe: by tile and thread): with any
  //   of them in view the occlusion takes the depth buffer's normals, the same each frame.
  bool translucent = false;
  bool storedNormals = true;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (!prop->GetVisibility())
    {
      continue;
    }
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    const bool translucentGeometry = prop->HasTranslucentPolygonalGeometry() != 0;
    translucent = translucent ||
      (actor && vtkParticleSphereMapper::SafeDownCast(actor->GetMapper()) && translucentGeometry);
    storedNormals = storedNormals && actor && !translucentGeometry;
  }
  if (translucent && !internals.WarnedTranslucent)
  {
    vtkWarningMacro(<< "PointAO darkens opaque geometry only: translucent particles are shown "
                    << "without ambient occlusion (the density-volume and voxel-cone passes "
                    << "occlude them).");
  }
  internals.WarnedTranslucent = translucent;
  internals.StoredNormals = storedNormals;
}

//------------------------------------------------------------------------------
void vtkPointAOPass::UpdateEffectiveRadius(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  // the radius: set, or four mean particle radii, or 2 % of the visible props' diagonal
  double radius = this->Radius;
  if (!(radius > 0.0))
  {
    // the particle props and what their mean radius depends on: read again only when that
    // changed (new particles, radii, radius scale or actor placement), not every frame
    std::vector<std::pair<vtkActor*, vtkParticleSphereMapper*>> particles;
    std::vector<double> key;
    for (int i = 0; i < s->GetPropArrayCount(); ++i)
    {
      vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
      auto* mapper = actor ? vtkParticleSphereMapper::SafeDownCast(actor->GetMapper()) : nullptr;
      if (mapper && actor->GetVisibility())
      {
        particles.emplace_back(actor, mapper);
        key.insert(key.end(),
          { static_cast<double>(reinterpret_cast<std::uintptr_t>(actor)),
            static_cast<double>(mapper->GetParticleGeometryTime()),
            mapper->GetRadiusScaleVC(actor) });
      }
    }
    if (key != internals.RadiusKey)
    {
      internals.RadiusSum = 0.0;
      internals.RadiusCount = 0.0;
      for (const auto& particle : particles)
      {
        double mean = 0.0;
        double n = 0.0;
        if (MeanRadius(particle.first, particle.second, mean, n))
        {
          internals.RadiusSum += mean * n;
          internals.RadiusCount += n;
        }
      }
      internals.RadiusKey = key;
    }
    // over every process's particles under distributed rendering (each frame: collective)
    double totals[2] = { internals.RadiusSum, internals.RadiusCount };
    internals.Exchange->Sum(totals, 2);
    if (totals[1] > 0.0 && totals[0] > 0.0)
    {
      radius = 4.0 * (totals[0] / totals[1]);
    }
    else
    {
      double bounds[6];
      internals.Renderer->ComputeVisiblePropBounds(bounds);
      // (minima of the lower bounds and of the negated upper ones)
      double extremes[6];
      for (int a = 0; a < 3; ++a)
      {
        const bool valid = bounds[2 * a] <= bounds[2 * a + 1];
        extremes[2 * a] = valid ? bounds[2 * a] : VTK_DOUBLE_MAX;
        extremes[2 * a + 1] = valid ? -bounds[2 * a + 1] : VTK_DOUBLE_MAX;
      }
      internals.Exchange->Minimum(extremes, 6);
      for (int a = 0; a < 3; ++a)
      {
        bounds[2 * a] = extremes[2 * a];
        bounds[2 * a + 1] = -extremes[2 * a + 1];
      }
      double diagonal = 0.0;
      if (vtkMath::AreBoundsInitialized(bounds) && bounds[0] < VTK_DOUBLE_MAX)
      {
        for (int a = 0; a < 3; ++a)
        {
          diagonal += (bounds[2 * a + 1] - bounds[2 * a]) * (bounds[2 * a + 1] - bounds[2 * a]);
        }
        diagonal = std::sqrt(diagonal);
      }
      radius = 0.02 * diagonal;
    }
  }
  this->EffectiveRadius = (std::isfinite(radius) && radius > 0.0) ? radius : 0.0;
  // the blur's depth tolerance: half the innermost hemisphere's radius
  const double L = this->NumberOfLevels;
  const double r0 = this->BaseRadius;
  internals.BlurTolerance = 0.5 * this->EffectiveRadius * (1.0 + r0) / (L * L + L * r0);
  internals.Occlude = this->EffectiveRadius > 0.0 && this->Strength > 0.0;
}

//------------------------------------------------------------------------------
void vtkPointAOPass::RenderGBuffer(const vtkRenderState* s)
{
  // 1. the scene into the G-buffer: colour, normal, depth
  vtkInternals& internals = *this->Internals;
  vtkOpenGLRenderer* ren = internals.Renderer;
  vtkOpenGLState* ostate = internals.Context->GetState();
  const unsigned int targets = internals.StoredNormals ? NumberOfGBufferTargets : 1;
  internals.Timer.Begin(0);
  ostate->PushFramebufferBindings();
  internals.GBuffer->Bind();
  internals.GBuffer->ActivateDrawBuffers(targets);
  {
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    vtkOpenGLState::ScopedglScissor scissor(ostate);
    ostate->vtkglViewport(0, 0, internals.Width, internals.Height);
    ostate->vtkglScissor(0, 0, internals.Width, internals.Height);
    ren->Clear();
    // the G-buffer's depth is this frame's whatever the renderer preserves in its own target
    // (ParaView's renderers may keep the depth buffer: a stale depth would be taken for geometry)
    ostate->vtkglDepthMask(GL_TRUE);
    const GLfloat far = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far);
    const GLfloat zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    if (internals.StoredNormals)
    {
      const GLfloat noStamp[4] = { -1.0f, 0.0f, 0.0f, 0.0f };
      glClearBufferfv(GL_COLOR, 1, zero);
      glClearBufferfv(GL_COLOR, 2, noStamp);
    }
    // the colour's alpha 0 (the background as cleared or drawn stays): blended over it, the
    // alpha becomes the coverage of what the delegate draws, so that a pixel only partly
    // covered (the translucent rim of an emission-absorption sphere) is darkened only as much
    vtkOpenGLState::ScopedglColorMask colourMask(ostate);
    ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    glClearBufferfv(GL_COLOR, 0, zero);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    vtkRenderState state(ren);
    state.SetFrameBuffer(internals.GBuffer);
    state.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
    // normals and depths as written; the renderer's FXAA on the composite (step 5)
    vtkParticleGBufferGuard guard(ren, targets);
    internals.HeldBackFXAA = guard.GetHeldBackFXAA();
    this->PreRender(&state);
    this->DelegatePass->Render(&state);
    this->PostRender(&state);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  }
  ostate->PopFramebufferBindings();
  internals.Timer.End();
}

//------------------------------------------------------------------------------
void vtkPointAOPass::ExchangeGBuffer()
{
  // 1b. distributed rendering: the occlusion reads the whole picture's G-buffer -- per pixel the
  // nearest depth over all processes with its process's normal and stamp -- while the colour and
  // the depth this process composites stay its own
  vtkInternals& internals = *this->Internals;
  internals.OcclusionDepth = internals.Depth;
  if (!internals.Exchange->IsDistributed() || !internals.Occlude)
  {
    return;
  }
  // the normal and its stamp; a process whose normal targets were not drawn gives no stamp (the
  // depth's normal there). Afterwards the normal targets hold stamps, also where this process
  // drew none.
  const std::vector<vtkParticleGBufferExchange::vtkTarget> targets = {
    { internals.StoredNormals ? 1 : -1, 4, false, 0.0f, internals.Normal },
    { internals.StoredNormals ? 2 : -1, 1, false, -1.0f, internals.NormalDepth }
  };
  internals.Exchange->CompositeFramebuffer(internals.Context, internals.GBuffer, internals.Width,
    internals.Height, targets, internals.ExchangedDepth, false);
  internals.StoredNormals = true;
  internals.OcclusionDepth = internals.ExchangedDepth;
}

//------------------------------------------------------------------------------
void vtkPointAOPass::SetUpProjection()
{
  // the camera's matrices (view -> clip) in the G-buffer's aspect
  vtkInternals& internals = *this->Internals;
  vtkCamera* camera = internals.Renderer->GetActiveCamera();
  vtkNew<vtkMatrix4x4> projection;
  const double aspect = static_cast<double>(internals.Width) / internals.Height;
  projection->DeepCopy(camera->GetProjectionTransformMatrix(aspect, -1.0, 1.0));
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(projection, inverse);
  // GLSL matrices are column-major: upload the transposes
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      internals.Projection[c * 4 + r] = static_cast<float>(projection->GetElement(r, c));
      internals.InverseProjection[c * 4 + r] = static_cast<float>(inverse->GetElement(r, c));
    }
  }
  camera->GetClippingRange(internals.ClipRange);
}

//------------------------------------------------------------------------------
void vtkPointAOPass::ComputeOcclusion()
{
  // 2. the occlusion, then 3. its depth-aware blur
  vtkInternals& internals = *this->Internals;
  internals.Result = internals.Occlusion;
  internals.VerticalBlur = false;
  if (!internals.Occlude)
  {
    return;
  }
  vtkOpenGLState* ostate = internals.Context->GetState();
  internals.Timer.Begin(1);
  vtkOpenGLQuadHelper* quad =
    internals.Quad(internals.OcclusionQuad, vtkParticleShaders::Get("PointAO"),
      "gl_FragData[0] = prPointAOTarget(ivec2(texCoord * vec2(prTargetSize)));\n");
  if (!quad)
  {
    vtkErrorMacro(<< "Could not build the PointAO shader: the image is drawn without it.");
  }
  ostate->PushFramebufferBindings();
  internals.Work->Bind();
  internals.Work->AddColorAttachment(0, internals.Occlusion);
  internals.Work->ActivateDrawBuffers(1);
  {
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    ostate->vtkglViewport(0, 0, internals.LowWidth, internals.LowHeight);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    if (quad)
    {
      vtkShaderProgram* program = quad->Program;
      internals.OcclusionDepth->Activate();
      internals.Normal->Activate();
      internals.NormalDepth->Activate();
      program->SetUniformi("prDepth", internals.OcclusionDepth->GetTextureUnit());
      program->SetUniformi("prNormal", internals.Normal->GetTextureUnit());
      program->SetUniformi("prNormalDepth", internals.NormalDepth->GetTextureUnit());
      program->SetUniformf("prStampKey", StampKey);
      program->SetUniformi("prStoredNormals", internals.StoredNormals ? 1 : 0);
      program->SetUniformMatrix4x4("prProjection", internals.Projection);
      program->SetUniformMatrix4x4("prInverseProjection", internals.InverseProjection);
      const float size[2] = { static_cast<float>(internals.Width),
        static_cast<float>(internals.Height) };
      program->SetUniform2f("prSize", size);
      const int target[2] = { internals.LowWidth, internals.LowHeight };
      program->SetUniform2i("prTargetSize", target);
      program->SetUniformi("prStep", internals.Step);
      program->SetUniformi("prLevels", this->NumberOfLevels);
      program->SetUniformi("prSamples", this->SamplesPerLevel);
      program->SetUniformf("prRadius", static_cast<float>(this->EffectiveRadius));
      program->SetUniformf("prBaseRadius", static_cast<float>(this->BaseRadius));
      program->SetUniformi("prDepthScaling", this->DepthScaling ? 1 : 0);
      program->SetUniformf(
        "prThickness", static_cast<float>(this->Thickness * this->EffectiveRadius));
      program->SetUniformf("prHidden", static_cast<float>(this->HiddenFraction));
      const float clip[2] = { static_cast<float>(internals.ClipRange[0]),
        static_cast<float>(internals.ClipRange[1]) };
      program->SetUniform2f("prClipRange", clip);
      quad->Render();
      internals.OcclusionDepth->Deactivate();
      internals.Normal->Deactivate();
      internals.NormalDepth->Deactivate();
    }
    else
    {
      const GLfloat zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
      glClearBufferfv(GL_COLOR, 0, zero);
    }
  }
  internals.Timer.End();
  if (quad)
  {
    this->BlurOcclusion();
  }
  ostate->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
void vtkPointAOPass::BlurOcclusion()
{
  // 3. the depth-aware blur: horizontal into Blurred here, vertical in the composite
  vtkInternals& internals = *this->Internals;
  vtkOpenGLState* ostate = internals.Context->GetState();
  vtkOpenGLQuadHelper* blurQuad = this->Blur
    ? internals.Quad(internals.BlurQuad, vtkParticleShaders::Get("PointAOBlur"),
        "gl_FragData[0] = prBlurOcclusion(ivec2(texCoord * vec2(textureSize(prOcclusion, "
        "0))));\n")
    : nullptr;
  if (blurQuad)
  {
    // full resolution: horizontal here, vertical in the composite; half resolution: both
    // here (back into Occlusion), the composite upsamples
    internals.Timer.Begin(2);
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    ostate->vtkglViewport(0, 0, internals.LowWidth, internals.LowHeight);
    vtkShaderProgram* program = blurQuad->Program;
    program->SetUniformf("prDepthTolerance", static_cast<float>(internals.BlurTolerance));
    vtkTextureObject* from[2] = { internals.Occlusion, internals.Blurred };
    vtkTextureObject* to[2] = { internals.Blurred, internals.Occlusion };
    const int directions[2][2] = { { 1, 0 }, { 0, 1 } };
    for (int pass = 0; pass < (internals.Step > 1 ? 2 : 1); ++pass)
    {
      internals.Work->AddColorAttachment(0, to[pass]);
      internals.Work->ActivateDrawBuffers(1);
      from[pass]->Activate();
      program->SetUniformi("prOcclusion", from[pass]->GetTextureUnit());
      program->SetUniform2i("prDirection", directions[pass]);
      blurQuad->Render();
      from[pass]->Deactivate();
    }
    internals.Timer.End();
    internals.Result = internals.Step > 1 ? internals.Occlusion : internals.Blurred;
    internals.VerticalBlur = internals.Step == 1;
  }
}

//------------------------------------------------------------------------------
void vtkPointAOPass::Composite()
{
  // 4. the composite: colour times A and depth into the render state's target
  vtkInternals& internals = *this->Internals;
  vtkOpenGLState* ostate = internals.Context->GetState();
  internals.Timer.Begin(3);
  vtkOpenGLQuadHelper* composite = internals.Quad(internals.CompositeQuad,
    vtkParticleShaders::Get("PointAOBlur") +
      "uniform sampler2D prColour;\nuniform sampler2D prCompositeDepth;\n"
      "uniform sampler2D prFrontDepth;\nuniform int prDistributed;\n"
      "uniform float prStrength;\nuniform float prBackgroundAlpha;\nuniform int prVerticalBlur;\n"
      "uniform int prStep;\nuniform mat4 prCompositeInverseProjection;\n"
      // half resolution: the 2 x 2 occlusion texels around the pixel, bilinear and weighted by
      // their view depth's difference to the pixel's (as the blur), background texels left out
      "float prUpsample(ivec2 pixel, float depth)\n{\n"
      "  vec2 size = vec2(textureSize(prCompositeDepth, 0));\n"
      "  vec4 v = prCompositeInverseProjection * vec4(vec3((vec2(pixel) + 0.5) / size, depth)"
      " * 2.0 - 1.0, 1.0);\n"
      "  float z = -v.z / v.w;\n"
      "  ivec2 low = textureSize(prOcclusion, 0);\n"
      "  vec2 f = vec2(pixel) / float(prStep);\n"
      "  ivec2 i0 = ivec2(floor(f));\n"
      "  vec2 t = f - vec2(i0);\n"
      "  float sum = 0.0;\n  float weights = 0.0;\n  float nearest = 1e30;\n"
      "  float fallback = 0.0;\n"
      "  for (int k = 0; k < 4; ++k)\n  {\n"
      "    ivec2 o = ivec2(k & 1, k >> 1);\n"
      "    vec4 tap = texelFetch(prOcclusion, clamp(i0 + o, ivec2(0), low - 1), 0);\n"
      "    float dz = (tap.y - z) / prDepthTolerance;\n"
      "    float w = tap.z * (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y)"
      " / (1.0 + dz * dz);\n"
      "    sum += w * tap.x;\n    weights += w;\n"
      "    if (tap.z > 0.5 && abs(tap.y - z) < nearest) { nearest = abs(tap.y - z); "
      "fallback = tap.x; }\n"
      "  }\n"
      "  return weights > 1e-6 ? sum / weights : fallback;\n}\n",
    // the occlusion (blurred vertically here when the blur is on); colour.a is the coverage of
    // the drawn geometry (see the G-buffer's clear)
    "vec4 colour = texture(prColour, texCoord);\n"
    "  float depth = texture(prCompositeDepth, texCoord).r;\n"
    // the picture's front surface: this process's own, or under MPI the processes' nearest
    "  float front = texture(prFrontDepth, texCoord).r;\n"
    "  ivec2 pixel = ivec2(texCoord * vec2(textureSize(prCompositeDepth, 0)));\n"
    "  float occlusion = prStep > 1 ? (front < 1.0 ? prUpsample(pixel, front) : 0.0) :\n"
    "    (prVerticalBlur != 0 ? prBlurOcclusion(pixel).x : texelFetch(prOcclusion, pixel, 0).x);\n"
    "  float a = front < 1.0 ? clamp(1.0 - prStrength * occlusion, 0.0, 1.0) : 1.0;\n"
    "  float coverage = clamp(colour.a, 0.0, 1.0);\n"
    // under MPI every process's premultiplied colour, translucent particles in front of another
    // process's surface too, times the front surface's A: the images composite to one process's
    // picture times A, as one process darkens its whole colour there
    "  vec3 shaded = prDistributed != 0 ? colour.rgb * a\n"
    "    : colour.rgb * (1.0 - coverage * (1.0 - a));\n"
    "  gl_FragData[0] = vec4(shaded, coverage + (1.0 - coverage) * prBackgroundAlpha);\n"
    "  gl_FragDepth = depth;\n");
  if (composite)
  {
    vtkShaderProgram* program = composite->Program;
    const bool exchanged = internals.OcclusionDepth && internals.OcclusionDepth != internals.Depth;
    internals.Colour->Activate();
    internals.Depth->Activate();
    internals.Result->Activate();
    if (exchanged)
    {
      internals.OcclusionDepth->Activate();
    }
    program->SetUniformi("prColour", internals.Colour->GetTextureUnit());
    program->SetUniformi("prCompositeDepth", internals.Depth->GetTextureUnit());
    program->SetUniformi("prFrontDepth",
      (exchanged ? internals.OcclusionDepth : internals.Depth.Get())->GetTextureUnit());
    program->SetUniformi("prDistributed", exchanged ? 1 : 0);
    program->SetUniformi("prOcclusion", internals.Result->GetTextureUnit());
    program->SetUniformi("prVerticalBlur", internals.VerticalBlur ? 1 : 0);
    program->SetUniformi("prStep", internals.Step);
    program->SetUniformMatrix4x4("prCompositeInverseProjection", internals.InverseProjection);
    const int vertical[2] = { 0, 1 };
    program->SetUniform2i("prDirection", vertical);
    program->SetUniformf("prDepthTolerance", static_cast<float>(internals.BlurTolerance));
    program->SetUniformf(
      "prStrength", internals.Occlude ? static_cast<float>(this->Strength) : 0.0f);
    program->SetUniformf("prBackgroundAlpha",
      internals.Renderer->Transparent()
        ? 0.0f
        : static_cast<float>(internals.Renderer->GetBackgroundAlpha()));
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    ostate->vtkglDepthMask(GL_TRUE);
    composite->Render();
    internals.Colour->Deactivate();
    internals.Depth->Deactivate();
    internals.Result->Deactivate();
    if (exchanged)
    {
      internals.OcclusionDepth->Deactivate();
    }
  }
  else
  {
    vtkErrorMacro(<< "Could not build the PointAO composite shader.");
  }
}

//------------------------------------------------------------------------------
void vtkPointAOPass::ApplyHeldBackFXAA()
{
  // 5. the renderer's FXAA, held back from the delegate, on the final picture
  vtkInternals& internals = *this->Internals;
  if (!internals.HeldBackFXAA)
  {
    return;
  }
  if (!internals.FXAA)
  {
    internals.FXAA = vtkSmartPointer<vtkOpenGLFXAAFilter>::New();
  }
  if (internals.Renderer->GetFXAAOptions())
  {
    internals.FXAA->UpdateConfiguration(internals.Renderer->GetFXAAOptions());
  }
  internals.FXAA->Execute(internals.Renderer);
}

//------------------------------------------------------------------------------
void vtkPointAOPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& internals = *this->Internals;
  internals.ReleaseTextures(w);
  for (auto* quad : { &internals.OcclusionQuad, &internals.BlurQuad, &internals.CompositeQuad })
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(w);
      quad->reset();
    }
  }
  if (internals.FXAA)
  {
    internals.FXAA->ReleaseGraphicsResources();
  }
  internals.Timer.Release(vtkParticleComputeProgram::MakeCurrentForRelease(internals.Context));
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
int vtkPointAOPass::GetOcclusionSpace()
{
  return SCREEN_SPACE;
}

//------------------------------------------------------------------------------
void vtkPointAOPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfLevels: " << this->NumberOfLevels << "\n";
  os << indent << "SamplesPerLevel: " << this->SamplesPerLevel << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "EffectiveRadius: " << this->EffectiveRadius << "\n";
  os << indent << "BaseRadius: " << this->BaseRadius << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "HiddenFraction: " << this->HiddenFraction << "\n";
  os << indent << "DepthScaling: " << this->DepthScaling << "\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "Blur: " << this->Blur << "\n";
  os << indent << "HalfResolution: " << this->HalfResolution << "\n";
  os << indent << "CollectTimings: " << this->CollectTimings << "\n";
  os << indent << "Controller: " << this->GetController() << "\n";
}
