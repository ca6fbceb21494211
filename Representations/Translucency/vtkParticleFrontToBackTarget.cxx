#include "vtkParticleFrontToBackTarget.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkParticleCompat.h"

#include <memory>

vtkStandardNewMacro(vtkParticleFrontToBackTarget);

namespace
{
const int MaxSavedDrawBuffers = 8;

// Copy the depth of the bound (single-sample) read framebuffer into a depth texture.
// vtkTextureObject::CopyFromFrameBuffer is not used: with a multisampled window it resolves
// through its own 24-bit buffer whatever the bound framebuffer is.
void CopyDepth(vtkTextureObject* texture, int x, int y, int width, int height)
{
  texture->Activate();
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, x, y, width, height);
  texture->Deactivate();
}
}

//------------------------------------------------------------------------------
class vtkParticleFrontToBackTarget::vtkInternals
{
public:
  vtkOpenGLRenderWindow* Context = nullptr;
  vtkOpenGLState* State = nullptr;
  vtkNew<vtkTextureObject> Accumulation;
  vtkNew<vtkTextureObject> MaskDepth;
  vtkNew<vtkTextureObject> OpaqueDepth;
  vtkNew<vtkOpenGLFramebufferObject> AccumulationFBO;
  vtkNew<vtkOpenGLFramebufferObject> MaskFBO;
  // multisampled opaque images: their depth is resolved into a single-sample buffer of the
  // window's depth format first (glBlitFramebuffer needs equal formats, glCopyTexSubImage2D a
  // single-sample source)
  vtkNew<vtkTextureObject> ResolvedDepth;
  vtkNew<vtkOpenGLFramebufferObject> ResolveFBO;
  bool ResolveAllocated = false;
  int ResolveFormat = 0;
  // downsampled accumulation: the opaque depth at full resolution, reduced into OpaqueDepth
  vtkNew<vtkTextureObject> FullDepth;
  // CompositeOver: the image to blend, uploaded
  vtkNew<vtkTextureObject> Upload;
  vtkNew<vtkOpenGLFramebufferObject> ReduceFBO;
  bool ReduceAllocated = false;
  std::unique_ptr<vtkOpenGLQuadHelper> MaskQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> BlendQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> ReduceQuad;
  bool Allocated = false;
  bool Active = false;

  // where the opaque image lives and the state to restore
  unsigned int OuterFramebuffer = 0;
  int OuterViewport[4] = { 0, 0, 0, 0 };
  unsigned int InnerFramebuffer = 0;
  unsigned int InnerDrawBuffers[MaxSavedDrawBuffers];
  unsigned int MaskQuery = 0;
  std::vector<float> Retained;

  bool Allocate(vtkOpenGLRenderWindow* ctx, int w, int h)
  {
    if (this->Allocated && this->Context == ctx)
    {
      if (this->Accumulation->GetWidth() != static_cast<unsigned int>(w) ||
        this->Accumulation->GetHeight() != static_cast<unsigned int>(h))
      {
        this->Accumulation->Resize(w, h);
        this->MaskDepth->Resize(w, h);
        this->OpaqueDepth->Resize(w, h);
      }
      return true;
    }
    this->Context = ctx;
    for (vtkTextureObject* tex :
      { this->Accumulation.Get(), this->MaskDepth.Get(), this->OpaqueDepth.Get() })
    {
      tex->SetContext(ctx);
      tex->SetMinificationFilter(vtkTextureObject::Nearest);
      tex->SetMagnificationFilter(vtkTextureObject::Nearest);
      tex->SetWrapS(vtkTextureObject::ClampToEdge);
      tex->SetWrapT(vtkTextureObject::ClampToEdge);
    }
    this->Accumulation->SetInternalFormat(GL_RGBA32F);
    this->Accumulation->SetFormat(GL_RGBA);
    this->Accumulation->SetDataType(GL_FLOAT);
    if (!this->Accumulation->Allocate2D(w, h, 4, VTK_FLOAT) ||
      !this->MaskDepth->AllocateDepth(w, h, vtkTextureObject::Float32) ||
      !this->OpaqueDepth->AllocateDepth(w, h, vtkTextureObject::Float32))
    {
      return false;
    }
    this->AccumulationFBO->SetContext(ctx);
    this->MaskFBO->SetContext(ctx);
    this->State->PushFramebufferBindings();
    this->AccumulationFBO->Bind();
    this->AccumulationFBO->AddColorAttachment(0, this->Accumulation);
    this->AccumulationFBO->AddDepthAttachment(this->MaskDepth);
    this->MaskFBO->Bind();
    this->MaskFBO->AddDepthAttachment(this->MaskDepth);
    this->State->PopFramebufferBindings();
    this->Allocated = true;
    return true;
  }

  // The full-resolution depth texture and the framebuffer that writes the reduced one.
  bool AllocateReduction(int w, int h)
  {
    if (this->ReduceAllocated)
    {
      if (this->FullDepth->GetWidth() != static_cast<unsigned int>(w) ||
        this->FullDepth->GetHeight() != static_cast<unsigned int>(h))
      {
        this->FullDepth->Resize(w, h);
      }
      return true;
    }
    vtkTextureObject* full = this->FullDepth;
    full->SetContext(this->Context);
    full->SetMinificationFilter(vtkTextureObject::Nearest);
    full->SetMagnificationFilter(vtkTextureObject::Nearest);
    full->SetWrapS(vtkTextureObject::ClampToEdge);
    full->SetWrapT(vtkTextureObject::ClampToEdge);
    if (!full->AllocateDepth(w, h, vtkTextureObject::Float32))
    {
      return false;
    }
    this->ReduceFBO->SetContext(this->Context);
    this->State->PushFramebufferBindings();
    this->ReduceFBO->Bind();
    this->ReduceFBO->AddDepthAttachment(this->OpaqueDepth);
    this->State->PopFramebufferBindings();
    this->ReduceAllocated = true;
    return true;
  }

  vtkOpenGLQuadHelper* Quad(
    std::unique_ptr<vtkOpenGLQuadHelper>& quad, const char* decl, const char* impl)
  {
    if (!quad)
    {
      std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
      vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl", decl);
      vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", impl);
      quad.reset(new vtkOpenGLQuadHelper(this->Context, nullptr, fs.c_str(), nullptr));
    }
    else
    {
      this->Context->GetShaderCache()->ReadyShaderProgram(quad->Program);
    }
    return quad->Program ? quad.get() : nullptr;
  }

  // Blend `source` (premultiplied RGBA) over the bound framebuffer within the viewport:
  // C = C_source + (1 - A_source) C_framebuffer, float until the framebuffer's one write.
  // Changes the blending and depth state (the callers restore it).
  void BlendOver(vtkTextureObject* source)
  {
    vtkOpenGLQuadHelper* quad = this->Quad(this->BlendQuad, "uniform sampler2D accumulation;\n",
      "  gl_FragData[0] = texture(accumulation, texCoord);\n");
    if (!quad)
    {
      return;
    }
    this->State->vtkglEnable(GL_BLEND);
    this->State->vtkglBlendEquation(GL_FUNC_ADD);
    this->State->vtkglBlendFuncSeparate(
      GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    this->State->vtkglDisable(GL_DEPTH_TEST);
    this->State->vtkglDepthMask(GL_FALSE);
    source->Activate();
    quad->Program->SetUniformi("accumulation", source->GetTextureUnit());
    quad->Render();
    source->Deactivate();
  }
};

//------------------------------------------------------------------------------
vtkParticleFrontToBackTarget::vtkParticleFrontToBackTarget()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkParticleFrontToBackTarget::~vtkParticleFrontToBackTarget()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
bool vtkParticleFrontToBackTarget::Begin(vtkRenderer* ren, bool savedByPass)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLRenderWindow* ctx = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!ctx)
  {
    vtkErrorMacro(<< "An OpenGL render window is required.");
    return false;
  }
  if (internals.Context && internals.Context != ctx)
  {
    this->ReleaseGraphicsResources(internals.Context);
    ctx->MakeCurrent(); // back to the context drawing now
  }
  vtkOpenGLState* ostate = ctx->GetState();
  internals.State = ostate;

  // The framebuffer holding the opaque image. A translucency pass saved it on the binding stack:
  // look at it by popping and pushing it back, then rebind the pass's own framebuffer.
  unsigned int inner = 0;
  unsigned int firstDrawBuffer = 0;
  ostate->GetCurrentDrawFramebufferState(inner, firstDrawBuffer);
  for (int i = 0; i < MaxSavedDrawBuffers; ++i)
  {
    GLint buffer = GL_NONE;
    glGetIntegerv(GL_DRAW_BUFFER0 + i, &buffer);
    internals.InnerDrawBuffers[i] = static_cast<unsigned int>(buffer);
  }
  unsigned int outer = inner;
  if (savedByPass)
  {
    ostate->PopDrawFramebufferBinding();
    ostate->GetCurrentDrawFramebufferState(outer, firstDrawBuffer);
    ostate->PushDrawFramebufferBinding();
    ostate->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, inner);
    ostate->vtkglDrawBuffers(MaxSavedDrawBuffers, internals.InnerDrawBuffers);
  }
  internals.InnerFramebuffer = inner;
  internals.OuterFramebuffer = outer;

  // Its viewport: the current one when it is bound; a pass drew into its own buffers at the
  // origin, so use the renderer's tiled viewport in a window framebuffer and the origin in any
  // other (an image-processing pass's buffer has the viewport's size).
  int* vp = internals.OuterViewport;
  if (!savedByPass)
  {
    ostate->vtkglGetIntegerv(GL_VIEWPORT, vp);
  }
  else
  {
    ren->GetTiledSizeAndOrigin(&vp[2], &vp[3], &vp[0], &vp[1]);
    const bool windowBuffer = outer == 0 ||
      (ctx->GetRenderFramebuffer() && outer == ctx->GetRenderFramebuffer()->GetFBOIndex()) ||
      (ctx->GetDisplayFramebuffer() && outer == ctx->GetDisplayFramebuffer()->GetFBOIndex());
    if (!windowBuffer)
    {
      vp[0] = vp[1] = 0;
    }
  }
  if (vp[2] <= 0 || vp[3] <= 0)
  {
    return false;
  }
  const int factor = this->Downsampling;
  this->Size[0] = (vp[2] + factor - 1) / factor;
  this->Size[1] = (vp[3] + factor - 1) / factor;

  ostate->Push(); // everything, including the current framebuffer bindings, back in End()
  if (!internals.Allocate(ctx, this->Size[0], this->Size[1]) ||
    (factor > 1 && !internals.AllocateReduction(vp[2], vp[3])))
  {
    vtkErrorMacro(<< "Cannot allocate the " << this->Size[0] << "x" << this->Size[1]
                  << " float accumulation buffers of the translucent particles.");
    ostate->Pop();
    return false;
  }
  internals.Active = true;
  // bilinear upsampling in End() when downsampled; never filtered at full resolution
  const int filter = factor > 1 ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
  internals.Accumulation->SetMinificationFilter(filter);
  internals.Accumulation->SetMagnificationFilter(filter);
  vtkTextureObject* depthCopy =
    factor > 1 ? internals.FullDepth.Get() : internals.OpaqueDepth.Get();

  // the opaque depth
  ostate->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, outer);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  ostate->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, outer);
  if (samples > 0)
  {
    vtkTextureObject* resolved = internals.ResolvedDepth;
    // the depth format of the opaque image, which the blit must match exactly
    GLint depthBits = 0;
    GLint stencilBits = 0;
    GLint componentType = GL_UNSIGNED_NORMALIZED;
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
      GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencilBits);
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
      GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &componentType);
    const int format = depthBits * 100 + stencilBits * 10 + (componentType == GL_FLOAT ? 1 : 0);
    if (!internals.ResolveAllocated || internals.ResolveFormat != format)
    {
      resolved->ReleaseGraphicsResources(ctx);
      resolved->SetContext(ctx);
      if (stencilBits > 0)
      {
        resolved->AllocateDepthStencil(vp[2], vp[3]);
      }
      else
      {
        resolved->AllocateDepth(vp[2], vp[3],
          componentType == GL_FLOAT
            ? vtkTextureObject::Float32
            : (depthBits == 32
                  ? vtkTextureObject::Fixed32
                  : (depthBits == 16 ? vtkTextureObject::Fixed16 : vtkTextureObject::Fixed24)));
      }
      internals.ResolveFormat = format;
      internals.ResolveFBO->SetContext(ctx);
      internals.ResolveFBO->Bind(GL_DRAW_FRAMEBUFFER);
      // (the texture has a new name: the framebuffer attaches it again only after removing
      // the old one, it ignores the same vtkTextureObject)
      internals.ResolveFBO->RemoveDepthAttachment();
      internals.ResolveFBO->AddDepthAttachment(resolved);
      internals.ResolveAllocated = true;
    }
    else if (resolved->GetWidth() != static_cast<unsigned int>(vp[2]) ||
      resolved->GetHeight() != static_cast<unsigned int>(vp[3]))
    {
      resolved->Resize(vp[2], vp[3]);
    }
    internals.ResolveFBO->Bind(GL_DRAW_FRAMEBUFFER);
    ostate->vtkglBlitFramebuffer(vp[0], vp[1], vp[0] + vp[2], vp[1] + vp[3], 0, 0, vp[2], vp[3],
      GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    internals.ResolveFBO->Bind(GL_READ_FRAMEBUFFER);
    CopyDepth(depthCopy, 0, 0, vp[2], vp[3]);
  }
  else
  {
    CopyDepth(depthCopy, vp[0], vp[1], vp[2], vp[3]);
  }
  if (factor > 1)
  {
    this->ReduceOpaqueDepth(vp[2], vp[3]);
  }

  internals.AccumulationFBO->Bind();
  internals.AccumulationFBO->ActivateDrawBuffer(0);
  ostate->vtkglViewport(0, 0, this->Size[0], this->Size[1]);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  this->ActivateDrawingState();
  this->NumberOfMaskedPixels = 0;
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleFrontToBackTarget::ReduceOpaqueDepth(int width, int height)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLState* ostate = internals.State;
  // the farthest opaque depth of each Downsampling x Downsampling block
  vtkOpenGLQuadHelper* quad = internals.Quad(internals.ReduceQuad,
    "uniform sampler2D fullDepth;\nuniform int factor;\nuniform ivec2 fullSize;\n"
    "uniform ivec2 size;\n",
    "  ivec2 first = ivec2(floor(texCoord * vec2(size))) * factor;\n"
    "  float depth = 0.0;\n"
    "  for (int j = 0; j < factor; ++j)\n"
    "  {\n"
    "    for (int i = 0; i < factor; ++i)\n"
    "    {\n"
    "      depth = max(depth,\n"
    "        texelFetch(fullDepth, min(first + ivec2(i, j), fullSize - 1), 0).r);\n"
    "    }\n"
    "  }\n"
    "  gl_FragDepth = depth;\n");
  if (!quad)
  {
    return;
  }
  internals.ReduceFBO->Bind();
  internals.ReduceFBO->DeactivateDrawBuffers();
  ostate->vtkglViewport(0, 0, this->Size[0], this->Size[1]);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  internals.FullDepth->Activate();
  quad->Program->SetUniformi("fullDepth", internals.FullDepth->GetTextureUnit());
  quad->Program->SetUniformi("factor", this->Downsampling);
  const int fullSize[2] = { width, height };
  quad->Program->SetUniform2i("fullSize", fullSize);
  quad->Program->SetUniform2i("size", this->Size);
  quad->Render();
  internals.FullDepth->Deactivate();
}

//------------------------------------------------------------------------------
void vtkParticleFrontToBackTarget::ActivateDrawingState()
{
  vtkOpenGLState* ostate = this->Internals->State;
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendEquation(GL_FUNC_ADD);
  // premultiplied front-to-back ("under"): C += (1 - A) c, A += (1 - A) a
  ostate->vtkglBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
  // the mask: fragments are at depth 0.5 (the imposter's clip z is 0), masked pixels at 0
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LESS);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDisable(GL_CULL_FACE);
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkParticleFrontToBackTarget::GetOpaqueDepthTexture()
{
  return this->Internals->OpaqueDepth;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkParticleFrontToBackTarget::GetAccumulationTexture()
{
  return this->Internals->Accumulation;
}

//------------------------------------------------------------------------------
void vtkParticleFrontToBackTarget::MaskSaturatedPixels(double threshold)
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Active)
  {
    return;
  }
  vtkOpenGLState* ostate = internals.State;
  vtkOpenGLQuadHelper* quad = internals.Quad(internals.MaskQuad,
    "uniform sampler2D accumulation;\nuniform float threshold;\n",
    "  if (!(texture(accumulation, texCoord).a > threshold))\n"
    "  {\n"
    "    discard;\n"
    "  }\n"
    "  gl_FragDepth = 0.0;\n");
  if (!quad)
  {
    return;
  }
  internals.MaskFBO->Bind();
  internals.MaskFBO->DeactivateDrawBuffers();
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  internals.Accumulation->Activate();
  quad->Program->SetUniformi("accumulation", internals.Accumulation->GetTextureUnit());
  quad->Program->SetUniformf("threshold", static_cast<float>(threshold));
  if (this->CountMaskedPixels)
  {
    if (!internals.MaskQuery)
    {
      glGenQueries(1, &internals.MaskQuery);
    }
    glBeginQuery(GL_SAMPLES_PASSED, internals.MaskQuery);
  }
  quad->Render();
  if (this->CountMaskedPixels)
  {
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 samples = 0;
    glGetQueryObjectui64v(internals.MaskQuery, GL_QUERY_RESULT, &samples);
    this->NumberOfMaskedPixels = static_cast<long long>(samples);
  }
  internals.Accumulation->Deactivate();
  internals.AccumulationFBO->Bind();
  internals.AccumulationFBO->ActivateDrawBuffer(0);
  this->ActivateDrawingState();
}

//------------------------------------------------------------------------------
void vtkParticleFrontToBackTarget::End()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.Active)
  {
    return;
  }
  internals.Active = false;
  vtkOpenGLState* ostate = internals.State;
  this->LastDeferred = this->DeferComposite && this->Downsampling == 1;
  if (this->KeepAccumulation || this->LastDeferred)
  {
    internals.Retained.resize(4 * static_cast<size_t>(this->Size[0]) * this->Size[1]);
    internals.AccumulationFBO->Bind();
    internals.AccumulationFBO->ActivateReadBuffer(0);
    ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, this->Size[0], this->Size[1], GL_RGBA, GL_FLOAT, internals.Retained.data());
  }

  if (!this->LastDeferred)
  {
    // over the opaque image: C = C_acc + (1 - A_acc) C_opaque
    ostate->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, internals.OuterFramebuffer);
    const int* vp = internals.OuterViewport;
    ostate->vtkglViewport(vp[0], vp[1], vp[2], vp[3]);
    internals.BlendOver(internals.Accumulation);
  }
  ostate->Pop();
  // the pass's framebuffer is bound again; resynchronise the state's draw-buffer cache with it
  ostate->vtkglDrawBuffers(MaxSavedDrawBuffers, internals.InnerDrawBuffers);
}

//------------------------------------------------------------------------------
void vtkParticleFrontToBackTarget::CompositeOver(
  vtkOpenGLRenderWindow* context, int width, int height, const float* rgba)
{
  vtkInternals& internals = *this->Internals;
  if (internals.Active || !context || width <= 0 || height <= 0 || !rgba)
  {
    return;
  }
  if (internals.Context != context)
  {
    if (internals.Context)
    {
      this->ReleaseGraphicsResources(internals.Context);
    }
    internals.Context = context;
    internals.State = context->GetState();
  }
  vtkTextureObject* upload = internals.Upload;
  if (upload->GetHandle() == 0 || upload->GetWidth() != static_cast<unsigned int>(width) ||
    upload->GetHeight() != static_cast<unsigned int>(height))
  {
    upload->SetContext(context);
    upload->SetInternalFormat(GL_RGBA32F);
    upload->SetFormat(GL_RGBA);
    upload->SetDataType(GL_FLOAT);
    upload->SetMinificationFilter(vtkTextureObject::Nearest);
    upload->SetMagnificationFilter(vtkTextureObject::Nearest);
    upload->Allocate2D(width, height, 4, VTK_FLOAT);
  }
  upload->Activate();
  internals.State->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, rgba);
  upload->Deactivate();
  vtkOpenGLState* ostate = internals.State;
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
  vtkOpenGLState::ScopedglColorMask colorMask(ostate);
  vtkOpenGLState::ScopedglViewport viewport(ostate);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglViewport(0, 0, width, height);
  internals.BlendOver(upload);
}

//------------------------------------------------------------------------------
bool vtkParticleFrontToBackTarget::GetAccumulation(std::vector<float>& rgba)
{
  rgba = this->Internals->Retained;
  return !rgba.empty();
}

//------------------------------------------------------------------------------
void vtkParticleFrontToBackTarget::ClearRetainedAccumulation()
{
  this->Internals->Retained.clear();
  this->LastDeferred = false;
}

//------------------------------------------------------------------------------
void vtkParticleFrontToBackTarget::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& internals = *this->Internals;
  // (framebuffers and queries belong to the context that made them, which need not be current:
  // ParaView releases a view's props while another view's context is current)
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (context && context == internals.Context)
  {
    context->MakeCurrent();
  }
  if (internals.MaskQuad)
  {
    internals.MaskQuad->ReleaseGraphicsResources(window);
    internals.MaskQuad.reset();
  }
  if (internals.BlendQuad)
  {
    internals.BlendQuad->ReleaseGraphicsResources(window);
    internals.BlendQuad.reset();
  }
  if (internals.ReduceQuad)
  {
    internals.ReduceQuad->ReleaseGraphicsResources(window);
    internals.ReduceQuad.reset();
  }
  internals.FullDepth->ReleaseGraphicsResources(window);
  internals.Upload->ReleaseGraphicsResources(window);
  internals.ReduceFBO->ReleaseGraphicsResources(window);
  internals.ReduceAllocated = false;
  internals.Accumulation->ReleaseGraphicsResources(window);
  internals.MaskDepth->ReleaseGraphicsResources(window);
  internals.OpaqueDepth->ReleaseGraphicsResources(window);
  internals.AccumulationFBO->ReleaseGraphicsResources(window);
  internals.MaskFBO->ReleaseGraphicsResources(window);
  internals.ResolvedDepth->ReleaseGraphicsResources(window);
  internals.ResolveFBO->ReleaseGraphicsResources(window);
  internals.ResolveAllocated = false;
  if (internals.MaskQuery)
  {
    glDeleteQueries(1, &internals.MaskQuery);
    internals.MaskQuery = 0;
  }
  internals.Allocated = false;
  internals.Context = nullptr;
}

//------------------------------------------------------------------------------
void vtkParticleFrontToBackTarget::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "Downsampling: " << this->Downsampling << "\n";
  os << indent << "CountMaskedPixels: " << this->CountMaskedPixels << "\n";
  os << indent << "NumberOfMaskedPixels: " << this->NumberOfMaskedPixels << "\n";
  os << indent << "KeepAccumulation: " << this->KeepAccumulation << "\n";
  os << indent << "DeferComposite: " << this->DeferComposite << "\n";
  os << indent << "LastDeferred: " << this->LastDeferred << "\n";
}
