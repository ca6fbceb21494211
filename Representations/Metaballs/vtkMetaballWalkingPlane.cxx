#include "vtkMetaballWalkingPlane.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkParticleShaders.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <string>

vtkStandardNewMacro(vtkMetaballWalkingPlane);

namespace
{
enum Target
{
  PlaneTarget = 0,
  DensityTarget = 1,
  GradientTarget = 2,
  ColorTarget = 3,
  NumberOfTargets = 4
};
}

//------------------------------------------------------------------------------
class vtkMetaballWalkingPlane::vtkInternals
{
public:
  vtkOpenGLRenderWindow* Context = nullptr;
  vtkOpenGLState* State = nullptr;
  // one framebuffer per texture: a texture sampled by a pass is never attached to the
  // framebuffer it draws into
  vtkNew<vtkTextureObject> Textures[NumberOfTargets];
  vtkNew<vtkOpenGLFramebufferObject> Framebuffers[NumberOfTargets];
  // the finished-pixel mask (the paper's shared depth attachment): 0 finished or inactive, 1
  // active; the density draws (at depth 0.5, GL_LESS) skip the masked pixels
  vtkNew<vtkTextureObject> Mask;
  std::unique_ptr<vtkOpenGLQuadHelper> StepQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> MaskQuad;
  bool Allocated = false;
  bool Active = false;
  // the occlusion query of the last step pass (its active pixels), read before the next pass
  unsigned int Query = 0;
  int Issued = 0; // step passes issued in this walk
  // the active count of the last pass, and for how many passes it has not changed
  long long LastActive = -1;
  int UnchangedPasses = 0;
  double Start = 0.0;

  bool Allocate(vtkOpenGLRenderWindow* ctx, int w, int h)
  {
    if (this->Allocated && this->Context == ctx)
    {
      if (this->Mask->GetWidth() != static_cast<unsigned int>(w) ||
        this->Mask->GetHeight() != static_cast<unsigned int>(h))
      {
        this->Mask->Resize(w, h);
      }
      for (auto& texture : this->Textures)
      {
        if (texture->GetWidth() != static_cast<unsigned int>(w) ||
          texture->GetHeight() != static_cast<unsigned int>(h))
        {
          texture->Resize(w, h);
        }
      }
      return true;
    }
    this->Context = ctx;
    this->State->PushFramebufferBindings();
    this->Mask->SetContext(ctx);
    bool ok = this->Mask->AllocateDepth(w, h, vtkTextureObject::Float32);
    for (int i = 0; i < NumberOfTargets && ok; ++i)
    {
      vtkTextureObject* texture = this->Textures[i];
      texture->SetContext(ctx);
      texture->SetMinificationFilter(vtkTextureObject::Nearest);
      texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      texture->SetWrapS(vtkTextureObject::ClampToEdge);
      texture->SetWrapT(vtkTextureObject::ClampToEdge);
      texture->SetInternalFormat(GL_RGBA32F);
      texture->SetFormat(GL_RGBA);
      texture->SetDataType(GL_FLOAT);
      ok = texture->Allocate2D(w, h, 4, VTK_FLOAT);
      if (ok)
      {
        this->Framebuffers[i]->SetContext(ctx);
        this->Framebuffers[i]->Bind();
        this->Framebuffers[i]->AddColorAttachment(0, texture);
        this->Framebuffers[i]->ActivateDrawBuffer(0);
        if (i == PlaneTarget || i == DensityTarget)
        {
          this->Framebuffers[i]->AddDepthAttachment(this->Mask);
        }
      }
    }
    this->State->PopFramebufferBindings();
    if (ok && !this->Query)
    {
      glGenQueries(1, &this->Query);
    }
    this->Allocated = ok;
    return ok;
  }

  // bind a target for drawing with additive (or MIN) blending, cleared to (clear, clear, 0, 0)
  // unless keep
  void Bind(int target, float clear, bool minimum, bool keep = false)
  {
    vtkOpenGLState* ostate = this->State;
    this->Framebuffers[target]->Bind();
    this->Framebuffers[target]->ActivateDrawBuffer(0);
    if (!keep)
    {
      ostate->vtkglClearColor(clear, clear, 0.0f, 0.0f);
      ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    }
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendEquation(minimum ? GL_MIN : GL_FUNC_ADD);
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // the mask: tested (not written) by the density draws and the step; off otherwise
    if (target == DensityTarget || (target == PlaneTarget && keep))
    {
      ostate->vtkglEnable(GL_DEPTH_TEST);
      ostate->vtkglDepthFunc(GL_LESS);
    }
    else
    {
      ostate->vtkglDisable(GL_DEPTH_TEST);
    }
    ostate->vtkglDepthMask(GL_FALSE);
  }

  vtkOpenGLQuadHelper* Quad(std::unique_ptr<vtkOpenGLQuadHelper>& quad, const std::string& impl)
  {
    if (!quad)
    {
      std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
      vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl",
        vtkParticleShaders::Get("MetaballWalkingStep") + "\nuniform sampler2D prDensity;\n");
      vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", impl);
      quad.reset(new vtkOpenGLQuadHelper(this->Context, nullptr, fs.c_str(), nullptr));
    }
    return quad->Program ? quad.get() : nullptr;
  }

  // the active pixels the last step pass counted
  long long Count()
  {
    GLuint64 samples = 0;
    glGetQueryObjectui64v(this->Query, GL_QUERY_RESULT, &samples);
    return static_cast<long long>(samples);
  }
};

//------------------------------------------------------------------------------
vtkMetaballWalkingPlane::vtkMetaballWalkingPlane()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkMetaballWalkingPlane::~vtkMetaballWalkingPlane()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
bool vtkMetaballWalkingPlane::Begin(vtkRenderer* ren)
{
  vtkInternals& internals = *this->Internals;
  this->Termination = NOT_RUN;
  this->NumberOfPasses = 0;
  this->CoveredPixels = 0;
  this->ActivePixels = 0;
  this->Seconds = 0.0;
  vtkOpenGLRenderWindow* ctx = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!ctx)
  {
    vtkErrorMacro(<< "An OpenGL render window is required.");
    return false;
  }
  if (internals.Context && internals.Context != ctx)
  {
    this->ReleaseGraphicsResources(internals.Context);
    ctx->MakeCurrent();
  }
  vtkOpenGLState* ostate = ctx->GetState();
  internals.State = ostate;
  ostate->vtkglGetIntegerv(GL_VIEWPORT, this->Viewport);
  const int w = this->Viewport[2];
  const int h = this->Viewport[3];
  if (w <= 0 || h <= 0)
  {
    return false;
  }
  ostate->Push(); // everything back in End()
  if (!internals.Allocate(ctx, w, h))
  {
    vtkErrorMacro(<< "Cannot allocate the " << w << "x" << h
                  << " float buffers of the walking depth plane.");
    ostate->Pop();
    return false;
  }
  internals.Active = true;
  internals.Issued = 0;
  internals.LastActive = -1;
  internals.UnchangedPasses = 0;
  internals.Start = vtkTimerLog::GetUniversalTime();
  ostate->vtkglViewport(0, 0, w, h);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  return true;
}

//------------------------------------------------------------------------------
void vtkMetaballWalkingPlane::StartInitialization()
{
  this->Internals->Bind(PlaneTarget, std::numeric_limits<float>::max(), true);
}

//------------------------------------------------------------------------------
bool vtkMetaballWalkingPlane::StartDensity()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Active)
  {
    return false;
  }
  // the active pixels of the last step (the occlusion query waits for it: one small stall per
  // pass, which lets the walk stop as soon as it may)
  const int issued = internals.Issued;
  if (issued >= 1)
  {
    this->ActivePixels = internals.Count();
    if (issued == 1)
    {
      // the first step saw every covered pixel active
      this->CoveredPixels = this->ActivePixels;
    }
    internals.UnchangedPasses =
      this->ActivePixels == internals.LastActive ? internals.UnchangedPasses + 1 : 0;
    internals.LastActive = this->ActivePixels;
  }
  if (issued >= 1)
  {
    const double finished = this->CoveredPixels > 0
      ? 1.0 - static_cast<double>(this->ActivePixels) / this->CoveredPixels
      : 1.0;
    int termination = NOT_RUN;
    if (this->ActivePixels == 0)
    {
      termination = CONVERGED;
    }
    else if (finished >= this->FinishedShare)
    {
      termination = FINISHED_SHARE;
    }
    else if (internals.UnchangedPasses >= this->StallPasses &&
      static_cast<double>(this->ActivePixels) <= std::max(1.0, 1e-2 * this->CoveredPixels))
    {
      termination = STALLED;
    }
    else if (this->NumberOfPasses >= this->MaximumPasses)
    {
      termination = PASS_LIMIT;
    }
    else if (vtkTimerLog::GetUniversalTime() - internals.Start >= this->TimeBudget)
    {
      termination = TIME_BUDGET;
    }
    if (termination != NOT_RUN)
    {
      this->Termination = termination;
      this->Seconds = vtkTimerLog::GetUniversalTime() - internals.Start;
      return false;
    }
  }
  internals.Bind(DensityTarget, 0.0f, false);
  if (internals.Issued == 0)
  {
    // every pixel open
    internals.State->vtkglDepthMask(GL_TRUE);
    internals.State->vtkglClearDepth(1.0);
    internals.State->vtkglClear(GL_DEPTH_BUFFER_BIT);
    internals.State->vtkglDepthMask(GL_FALSE);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkMetaballWalkingPlane::Step()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Active)
  {
    return;
  }
  // the step: added to the plane in the pixels the mask leaves (counted), then the mask
  // closed over the pixels that finished or left (lambda past lambda_max: no particle saw them
  // active)
  vtkOpenGLQuadHelper* step = internals.Quad(internals.StepQuad,
    "  vec4 density = texture(prDensity, texCoord);\n"
    "  if (!(density.w > 0.5))\n"
    "  {\n"
    "    discard;\n"
    "  }\n"
    "  gl_FragData[0] = prWalkingStep(density);\n");
  vtkOpenGLQuadHelper* mask = internals.Quad(internals.MaskQuad,
    "  vec4 density = texture(prDensity, texCoord);\n"
    "  if (density.w > 0.5 && prWalkingStep(density).z < 0.5)\n"
    "  {\n"
    "    discard;\n"
    "  }\n"
    "  gl_FragData[0] = vec4(0.0);\n"
    "  gl_FragDepth = 0.0;\n");
  vtkShaderProgram* program = step ? step->Program : nullptr;
  ++this->NumberOfPasses;
  if (!program || !mask)
  {
    vtkErrorMacro(<< "The step programs of the walking depth plane do not compile.");
    internals.Active = false;
    this->Termination = PASS_LIMIT;
    return;
  }
  // into the plane, additively: the step is added to lambda, the finished flag set
  internals.Bind(PlaneTarget, 0.0f, false, true);
  vtkTextureObject* density = internals.Textures[DensityTarget];
  density->Activate();
  // both programs read the density with the oracle's settings
  auto ready = [&](vtkShaderProgram* p)
  {
    internals.Context->GetShaderCache()->ReadyShaderProgram(p);
    p->SetUniformi("prDensity", density->GetTextureUnit());
    p->SetUniformf("prIsoValue", static_cast<float>(this->IsoValue));
    p->SetUniformf("prDepthTolerance", static_cast<float>(this->DepthTolerance));
    p->SetUniformf("prDensityTolerance", static_cast<float>(this->DensityTolerance));
    p->SetUniformf("prMaximumStep", static_cast<float>(this->MaximumStep));
    p->SetUniformi("prOracle", this->StepOracle);
  };
  ready(program);
  glBeginQuery(GL_SAMPLES_PASSED, internals.Query);
  step->Render();
  glEndQuery(GL_SAMPLES_PASSED);
  // the mask (no colour written)
  vtkOpenGLState* ostate = internals.State;
  ready(mask->Program);
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  mask->Render();
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglDepthMask(GL_FALSE);
  density->Deactivate();
  ++internals.Issued;
}

//------------------------------------------------------------------------------
void vtkMetaballWalkingPlane::StartShading(bool color)
{
  this->Internals->Bind(color ? ColorTarget : GradientTarget, 0.0f, false);
}

//------------------------------------------------------------------------------
void vtkMetaballWalkingPlane::End()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Active)
  {
    return;
  }
  internals.Active = false;
  if (this->Termination == NOT_RUN)
  {
    this->Seconds = vtkTimerLog::GetUniversalTime() - internals.Start;
  }
  internals.State->Pop();
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkMetaballWalkingPlane::GetPlaneTexture()
{
  return this->Internals->Textures[PlaneTarget];
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkMetaballWalkingPlane::GetGradientTexture()
{
  return this->Internals->Textures[GradientTarget];
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkMetaballWalkingPlane::GetColorTexture()
{
  return this->Internals->Textures[ColorTarget];
}

//------------------------------------------------------------------------------
const char* vtkMetaballWalkingPlane::GetTerminationAsString(int termination)
{
  switch (termination)
  {
    case CONVERGED:
      return "converged";
    case FINISHED_SHARE:
      return "finished share";
    case PASS_LIMIT:
      return "pass limit";
    case TIME_BUDGET:
      return "time budget";
    case STALLED:
      return "stalled";
    default:
      return "not run";
  }
}

//------------------------------------------------------------------------------
void vtkMetaballWalkingPlane::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& internals = *this->Internals;
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!context || context != internals.Context)
  {
    return;
  }
  context->MakeCurrent();
  for (auto* quad : { &internals.StepQuad, &internals.MaskQuad })
  {
    if (*quad)
    {
      (*quad)->ReleaseGraphicsResources(window);
      quad->reset();
    }
  }
  internals.Mask->ReleaseGraphicsResources(window);
  for (int i = 0; i < NumberOfTargets; ++i)
  {
    internals.Textures[i]->ReleaseGraphicsResources(window);
    internals.Framebuffers[i]->ReleaseGraphicsResources(window);
  }
  if (internals.Query)
  {
    glDeleteQueries(1, &internals.Query);
    internals.Query = 0;
  }
  internals.Allocated = false;
  internals.Context = nullptr;
}

//------------------------------------------------------------------------------
void vtkMetaballWalkingPlane::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "MaximumStep: " << this->MaximumStep << "\n";
  os << indent << "DepthTolerance: " << this->DepthTolerance << "\n";
  os << indent << "DensityTolerance: " << this->DensityTolerance << "\n";
  os << indent << "StepOracle: " << this->StepOracle << "\n";
  os << indent << "MaximumPasses: " << this->MaximumPasses << "\n";
  os << indent << "TimeBudget: " << this->TimeBudget << "\n";
  os << indent << "StallPasses: " << this->StallPasses << "\n";
  os << indent << "FinishedShare: " << this->FinishedShare << "\n";
  os << indent << "NumberOfPasses: " << this->NumberOfPasses << "\n";
  os << indent << "Seconds: " << this->Seconds << "\n";
  os << indent << "CoveredPixels: " << this->CoveredPixels << "\n";
  os << indent << "ActivePixels: " << this->ActivePixels << "\n";
  os << indent << "Termination: " << GetTerminationAsString(this->Termination) << "\n";
}
