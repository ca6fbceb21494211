#include "vtkSNDFRenderPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightsPass.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkParticleAmbientLightPass.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleGBufferExchange.h"
#include "vtkParticleGBufferGuard.h"
#include "vtkParticleShaderHooks.h"
#include "vtkParticleShaders.h"
#include "vtkParticleSphereMapper.h"
#include "vtkParticleStageTimer.h"
#include "vtkParticleViewport.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkSNDFColourCoordinates.h"
#include "vtkSNDFLightingTable.h"
#include "vtkSNDFRecolouring.h"
#include "vtkSNDFTargets.h"
#include "vtkSNDFTileCache.h"
#include "vtkSNDFViewPlacement.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace
{
// the colour attachments of the G-buffer (vtkSNDFTargets)
const unsigned int NumberOfAttachments = vtkSNDFTargets::NumberOfAttachments;

// sample passes in one Render() from which it reports progress
const int ProgressSamples = 8;

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

// a particle mapper whose opaque spheres the pass samples: one that draws sphere glyphs through
// the core's opaque path (the core, and the translucent mapper of ParaView's Particles
// representation, whose actor's translucency is checked separately), not one that draws a
// surface through its own targets (metaballs)
bool IsSampledParticleMapper(vtkAbstractMapper* mapper)
{
  auto* particles = vtkParticleSphereMapper::SafeDownCast(mapper);
  return particles && particles->GetDrawsSphereGlyphs();
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
  // the view-sized targets (G-buffer, shaded picture, checkpoint, display), made anew for each
  // size
  vtkSNDFTargets Targets;
  // the lighting table (Eqs. 12-14) and what it was built for
  vtkSNDFLightingTable LightingTable;
  std::unique_ptr<vtkOpenGLQuadHelper> CompositeQuad;
  vtkNew<vtkParticleComputeProgram> Accumulate;
  vtkNew<vtkParticleComputeProgram> Resolve;
  // the error estimate: the difference program and its sums (the picture at the last check:
  // Targets.Checkpoint)
  vtkNew<vtkParticleComputeProgram> Difference;
  vtkSmartPointer<vtkOpenGLBufferObject> Totals = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  int CheckedSamples = 0;
  vtkNew<vtkSNDFTileCache> Cache;
  vtkParticleShaderHooks Hooks;
  vtkTimeStamp ShaderTime;
  vtkNew<vtkLightsPass> Lights;
  // distributed rendering: the sample passes' G-buffers composited over the processes
  vtkNew<vtkParticleGBufferExchange> Exchange;
  vtkNew<vtkProperty> NoParticleMaterial; // (the lighting table of a process without particles)

  // The S-MIP's frame: the state that every view of its levels shares (all but the camera's
  // position, focal point and parallel scale in parallel projection), and its virtual plane
  // (View).
  std::vector<double> FixedState;
  bool FrameValid = false;
  vtkSNDFViewPlacement View;
  using Between = vtkSNDFViewPlacement::Between;
  vtkNew<vtkParticleComputeProgram> BoxFilter;
  // the view of the last MapView() and its size in texels, and the view of the last frame
  // (mapped or plain)
  int PlacedSize[2] = { 0, 0 };
  vtkSNDFTileCache::Placement Placement;
  bool Placed = false;
  vtkSNDFTileCache::Placement ShownView;
  bool Shown = false;
  // jittered sample passes since the frame started (the Halton index of the next one)
  int Sequence = 0;
  std::vector<double> ResolveKey;
  std::set<std::string> Warned;
  std::string ProgressText;
  // Material re-shading (class description): with one particle actor the samples store its
  // colours without the property's coefficients, and the shade applies them. RawMaterial is
  // this frame's mode (SetShaderParameters): 0 the colours as drawn, 1 the diffuse colour
  // without diffuseIntensity (colours from scalars), 2 white for the diffuse colour and the
  // ambient term left to the shade (the property's colours). Per particle mapper, what its
  // shader's colour code showed when it was built (PostReplaceShaderValues): whether it can
  // write raw colours (VTK's intensities declared) and whether its colours are the
  // property's; a mapper whose shader disagrees with the prediction samples its material.
  struct ColourSource
  {
    bool Raw = false;
    bool Solid = false;
  };
  std::map<vtkAbstractMapper*, ColourSource> ColourSources;
  int RawMaterial = 0;
  // Colour-map changes (class description, "Colour"): the colour coordinates of the particle
  // actors and the colours their samples hold, recoloured where a new map allows
  vtkSNDFColourCoordinates Coordinates;
  vtkSNDFRecolouring Recolouring{ this->Cache, &this->Coordinates };

  // GPU times of the last timed Render() per stage (sample, accumulate, shade)
  vtkParticleStageTimer Timer{ 3 };

  // Starts the S-MIP's frame at this view (View: its plane; no view placed yet).
  void StartFrame(vtkCamera* camera, int width, int height)
  {
    this->View.Start(camera, width, height);
    this->Placement = vtkSNDFTileCache::Placement();
    this->FrameValid = true;
  }

  // true the first time `what` is reported
  bool FirstWarning(const std::string& what) { return this->Warned.insert(what).second; }
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
  this->Internals->FrameValid = false;
  this->NumberOfSamples = 0;
}

//------------------------------------------------------------------------------
vtkSNDFTileCache* vtkSNDFRenderPass::GetTileCache()
{
  return this->Internals->Cache;
}

//------------------------------------------------------------------------------
const char* vtkSNDFRenderPass::GetProgressText()
{
  return this->Internals->ProgressText.c_str();
}

//------------------------------------------------------------------------------
double vtkSNDFRenderPass::GetLastSampleSeconds()
{
  return this->Internals->Timer.Seconds(0);
}

//------------------------------------------------------------------------------
double vtkSNDFRenderPass::GetLastAccumulateSeconds()
{
  return this->Internals->Timer.Seconds(1);
}

//------------------------------------------------------------------------------
double vtkSNDFRenderPass::GetLastShadeSeconds()
{
  return this->Internals->Timer.Seconds(2);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkSNDFRenderPass::GetShaderStageMTime()
{
  return this->Internals->ShaderTime.GetMTime();
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
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
    "gl_FragData[1] = vec4(0.0, 0.0, -1.0, 1.0);\n  gl_FragData[2] = vec4(0.0, 0.0, 0.0, 1.0);\n "
    " " +
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
  // Where the shade applies the material (RawMaterial, SetShaderParameters) the sample keeps
  // the diffuse colour without diffuseIntensity (1), or white and no ambient term where the
  // colours are the property's (2). VTK's colour code (ReplaceShaderColor) computes
  // diffuseColor = diffuseIntensity * (vertex colour, texture colour or diffuseColorUniform).
  vtkInternals::ColourSource source;
  const std::string& fs = fragmentShader;
  source.Raw = fs.find("uniform float diffuseIntensity") != std::string::npos;
  source.Solid = fs.find("diffuseIntensity * diffuseColorUniform") != std::string::npos &&
    fs.find("diffuseIntensity * vertexColorVSOutput") == std::string::npos &&
    fs.find("diffuseIntensity * texColor") == std::string::npos;
  this->Internals->ColourSources[mapper] = source;
  const std::string raw = source.Raw
    ? "    if (prRawMaterial == 1)\n"
      "    {\n"
      "      prSampleDiffuse = diffuseColor / max(diffuseIntensity, 1.0e-30);\n"
      "    }\n"
      "    else if (prRawMaterial == 2)\n"
      "    {\n"
      "      prSampleDiffuse = vec3(1.0);\n"
      "      prSampleAmbient = prAmbientLight;\n"
      "    }\n"
    : "";
  // with the colour coordinates' moments kept (class description, "Colour") the particle's
  // coordinate goes into the diffuse target's alpha (blending is off there during the sample pass)
  const bool coordinates = this->Internals->Coordinates.InShader;
  // (t' = offset + scale t, t read by particle id; a solid actor reads t = 0 from a one-value
  // buffer: vtkSNDFColourCoordinates::Source)
  hooks.Insert(vtkParticleShaderHooks::Fragment, "//PR::Sphere::Dec",
    coordinates ? "uniform int prRawMaterial;\nuniform samplerBuffer prColourCoordinates;\n"
                  "uniform float prCoordinateOffset;\nuniform float prCoordinateScale;\n"
                  "uniform int prCoordinateSolid;"
                : "uniform int prRawMaterial;");
  const std::string coordinate = coordinates
    ? "prCoordinateOffset + prCoordinateScale * texelFetch(prColourCoordinates, "
      "prCoordinateSolid != 0 ? 0 : particleIdVSOutput * particleIdStride).r"
    : "1.0";
  hooks.Insert(vtkParticleShaderHooks::Fragment, "//PR::Shading::Impl",
    "vec3 prSampleDiffuse = diffuseColor;\n"
    "    vec3 prSampleAmbient = prAmbientOcclusion * ambientColor + prAmbientLight;\n" +
      raw +
      "    gl_FragData[1] = vec4(normalVCVSOutput.xy, 2.0 + clamp(prAmbientOcclusion, 0.0, 1.0), "
      "1.0);\n"
      "    gl_FragData[2] = vec4(prSampleDiffuse, " +
      coordinate +
      ");\n"
      "    gl_FragData[0] = vec4(prSampleAmbient, 1.0);");
  return true;
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (IsSampledParticleMapper(mapper) && program->IsUniformUsed("prRawMaterial"))
  {
    program->SetUniformi("prRawMaterial", this->Internals->RawMaterial);
  }
  float offset = 0.0f;
  float scale = 1.0f;
  int solid = 0;
  vtkTextureObject* coordinates = IsSampledParticleMapper(mapper)
    ? this->Internals->Coordinates.Source(prop, offset, scale, solid)
    : nullptr;
  if (coordinates && program->IsUniformUsed("prColourCoordinates"))
  {
    // (active until the sample pass ends: vtkSNDFColourCoordinates::Deactivate)
    coordinates->Activate();
    program->SetUniformi("prColourCoordinates", coordinates->GetTextureUnit());
    program->SetUniformf("prCoordinateOffset", offset);
    program->SetUniformf("prCoordinateScale", scale);
    program->SetUniformi("prCoordinateSolid", solid);
  }
  return true;
}

//------------------------------------------------------------------------------
// What the stages of one Render() share: the scene, the view, the bins and the placement of
// the view in the S-MIP, the material of the shade.
struct vtkSNDFRenderPass::vtkFrame
{
  const vtkRenderState* RenderState = nullptr;
  vtkOpenGLRenderer* Renderer = nullptr;
  vtkOpenGLRenderWindow* Context = nullptr;
  vtkCamera* Camera = nullptr;
  std::vector<vtkActor*> Particles; // the sampled particle actors
  std::string Unsupported;          // why the view cannot be sampled ("": it can)
  std::vector<double> State;        // what the samples depend on (a change restarts them)
  std::vector<double> ColourKey;    // what their colours depend on (a change recolours them)
  double DiffuseScale[3] = { 1.0, 1.0, 1.0 };
  double AmbientTerm[3] = { 0.0, 0.0, 0.0 };
  int Width = 0;
  int Height = 0;
  int X0 = 0;
  int Y0 = 0;
  int Bins = 0;
  int Slots = 0;
  bool Moments = false;
  bool ColouredLight = false;
  vtkSNDFTileCache::Placement Placement;
  vtkInternals::Between BetweenLevels;
  bool SameFrame = false;
  int TexelsX = 0;
  int TexelsY = 0;
  vtkProperty* Material = nullptr;
  double Specular[3] = { 0.0, 0.0, 0.0 };
  vtkTextureObject* Shown = nullptr; // the shaded picture the composite draws
  vtkTextureObject* ShownDepth = nullptr;
  bool NothingDrawn = false; // distributed: no particle of this process in the view
};

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass: nothing is rendered.");
    return;
  }
  // Each stage returns false when it has drawn the frame itself, without S-NDFs (a view the
  // pass cannot sample, the frame of a change, a failure), after saying why where that helps.
  // Under distributed rendering (SetController) the processes decide together wherever a
  // decision changes what is sampled: AgreeToSample after the stages that may fail, the restart
  // and the frame of a change inside their stages.
  vtkFrame frame;
  frame.RenderState = s;
  this->CollectScene(frame);
  if (!this->AgreeToSample(this->CheckSupport(frame) && this->ChooseBins(frame), frame))
  {
    return;
  }
  if (this->AllProcesses(frame.NothingDrawn))
  {
    this->RenderWithoutParticles(frame);
    return;
  }
  this->DescribeView(frame);
  this->PrepareContext(frame);
  if (!this->KeepOrRestartSamples(frame) || !this->ShowChangeFrame(frame))
  {
    return;
  }
  bool ready = this->PrepareTargets(frame);
  if (ready)
  {
    this->ChooseMaterial(frame);
    ready = this->UpdateLightingTable(frame) && this->MapTiles(frame);
  }
  if (!this->AgreeToSample(ready, frame))
  {
    return;
  }
  this->TakeSamples(frame);
  if (frame.Particles.empty())
  {
    // distributed, no particle actor on this process: the others shade and composite the whole
    // picture; this one adds its own view, nothing nearer than theirs
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    return;
  }
  this->Shade(frame);
  this->Composite(frame);
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::RenderPlain(const vtkRenderState* s)
{
  // the view as the delegate draws it; the samples restart with the next S-NDF frame
  vtkInternals& internals = *this->Internals;
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  this->NumberOfSamples = 0;
  this->ActiveBinsPerAxis = 0;
  this->ErrorTargetReached = false;
  internals.FrameValid = false;
  internals.Shown = false;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::CollectScene(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const vtkRenderState* s = frame.RenderState;
  std::vector<vtkActor*>& particles = frame.Particles;
  std::string& unsupported = frame.Unsupported;
  std::vector<double>& state = frame.State;
  std::vector<double>& colourKey = frame.ColourKey;
  double(&diffuseScale)[3] = frame.DiffuseScale;
  double(&ambientTerm)[3] = frame.AmbientTerm;
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  frame.Renderer = ren;
  frame.Context = ren ? vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()) : nullptr;

  // the scene: the sampled particle props, the reason to render plainly, the sampling state
  // The renderer's props, not those of the render state: the renderer leaves out the props
  // outside the view, and a pan to empty space and back keeps the S-MIP.
  std::vector<vtkProp*> props;
  if (ren)
  {
    vtkCollectionSimpleIterator pit;
    vtkPropCollection* viewProps = ren->GetViewProps();
    viewProps->InitTraversal(pit);
    while (vtkProp* prop = viewProps->GetNextProp(pit))
    {
      props.push_back(prop);
    }
  }
  for (vtkProp* prop : props)
  {
    if (!prop->GetVisibility())
    {
      continue;
    }
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
    if (actor && !mapper)
    {
      continue; // an actor without a mapper draws nothing (e.g. a bounds-only prop)
    }
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
      // the actor's placement and its material but for the specular settings (they re-shade);
      // the ambient and diffuse settings are added below unless the shade applies them
      AppendMatrix(state, actor->GetMatrix());
      vtkProperty* p = actor->GetProperty();
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
      // a particle mapper's lookup table goes into the colour key: a new colour map keeps the
      // samples where it can (vtkSNDFRecolouring)
      if (vtkParticleSphereMapper::SafeDownCast(mapper))
      {
        state.push_back(static_cast<double>(mapper->vtkAbstractMapper::GetMTime()));
        colourKey.push_back(static_cast<double>(mapper->GetLookupTable()->GetMTime()));
      }
      else
      {
        state.push_back(static_cast<double>(mapper->GetMTime()));
      }
      vtkDataObject* input = mapper->GetInputDataObject(0, 0);
      state.push_back(input ? static_cast<double>(input->GetMTime()) : 0.0);
    }
  }
  // The particle material (class description, "Material"): with one particle actor the shade
  // applies the diffuse coefficient (mode 1) or the whole ambient and diffuse material where the
  // colours are the property's (mode 2); what the samples hold restarts when it changes.
  internals.RawMaterial = 0;
  if (particles.size() == 1)
  {
    vtkMapper* mapper = particles[0]->GetMapper();
    const auto known = internals.ColourSources.find(mapper);
    const bool seen = known != internals.ColourSources.end();
    if (!seen || known->second.Raw)
    {
      if (!vtkSNDFColourCoordinates::UsesScalarColours(mapper) && (!seen || known->second.Solid))
      {
        internals.RawMaterial = 2;
      }
      else if (particles[0]->GetProperty()->GetDiffuse() > 0.0)
      {
        internals.RawMaterial = 1;
      }
    }
  }
  state.push_back(internals.RawMaterial);
  for (vtkActor* actor : particles)
  {
    vtkProperty* p = actor->GetProperty();
    if (internals.RawMaterial == 2)
    {
      for (int c = 0; c < 3; ++c)
      {
        diffuseScale[c] = p->GetDiffuse() * p->GetDiffuseColor()[c];
        ambientTerm[c] = p->GetAmbient() * p->GetAmbientColor()[c];
      }
      continue;
    }
    // the ambient term is drawn into the colour target (sampled); the diffuse colour the samples
    // hold goes into the colour key (vtkSNDFRecolouring)
    state.push_back(p->GetAmbient());
    if (p->GetAmbient() != 0.0)
    {
      state.insert(state.end(), p->GetAmbientColor(), p->GetAmbientColor() + 3);
    }
    colourKey.insert(colourKey.end(), p->GetDiffuseColor(), p->GetDiffuseColor() + 3);
    if (internals.RawMaterial == 1)
    {
      diffuseScale[0] = diffuseScale[1] = diffuseScale[2] = p->GetDiffuse();
    }
    else
    {
      colourKey.push_back(p->GetDiffuse());
    }
  }
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::CheckSupport(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const vtkRenderState* s = frame.RenderState;
  vtkOpenGLRenderer* ren = frame.Renderer;
  vtkOpenGLRenderWindow* context = frame.Context;
  std::vector<vtkActor*>& particles = frame.Particles;
  std::string& unsupported = frame.Unsupported;
  int& width = frame.Width;
  int& height = frame.Height;
  int& x0 = frame.X0;
  int& y0 = frame.Y0;
  // (distributed, a process without particle actors samples with the others: Render)
  if (!ren || !context || (particles.empty() && !internals.Exchange->IsDistributed()))
  {
    this->RenderPlain(s);
    return false;
  }
  // a screen-space AO pass inside: it darkens the composited pixels after the scene, where the
  // samples cannot take it (they need the occlusion per fragment, as the object-space passes give)
  for (vtkRenderPass* inner = this->DelegatePass; inner && unsupported.empty();)
  {
    auto* ambient = vtkParticleAmbientLightPass::SafeDownCast(inner);
    if (ambient && ambient->GetOcclusionSpace() == vtkParticleAmbientLightPass::SCREEN_SPACE)
    {
      unsupported = std::string(inner->GetClassName()) +
        " is in the pass chain (S-NDF samples take ambient occlusion per fragment: the "
        "density-volume or voxel-cone pass)";
    }
    auto* wrapping = vtkImageProcessingPass::SafeDownCast(inner);
    inner = wrapping ? wrapping->GetDelegatePass() : nullptr;
  }
  bool drawn = false; // a particle actor in the view
  for (int i = 0; i < s->GetPropArrayCount() && !drawn; ++i)
  {
    drawn = std::find(particles.begin(), particles.end(), s->GetPropArray()[i]) != particles.end();
  }
  if (!drawn && !internals.Exchange->IsDistributed())
  {
    this->RenderWithoutParticles(frame);
    return false;
  }
  // distributed: this process samples with the others, its G-buffer empty, unless no process
  // has particles in the view (Render)
  frame.NothingDrawn = !drawn;
  if (!unsupported.empty())
  {
    if (internals.FirstWarning(unsupported))
    {
      vtkWarningMacro(<< "S-NDF shading is off while " << unsupported
                      << "; the view is rendered as without it.");
    }
    this->RenderPlain(s);
    return false;
  }
  std::string reason;
  if (!vtkParticleComputeProgram::IsSupported(context, &reason))
  {
    if (internals.FirstWarning(reason))
    {
      vtkErrorMacro(<< "S-NDF shading needs compute shaders: " << reason
                    << ". The view is rendered as without it.");
    }
    this->RenderPlain(s);
    return false;
  }
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (width < 1 || height < 1)
  {
    this->RenderPlain(s);
    return false;
  }
  std::string part;
  if (!vtkParticleViewport::FillsTarget(s, part))
  {
    if (internals.FirstWarning("viewport"))
    {
      vtkWarningMacro(<< "S-NDF shading needs a renderer that fills its window (this one covers "
                      << part << "): the view is rendered as without it.");
    }
    this->RenderPlain(s);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::RenderWithoutParticles(vtkFrame& frame)
{
  // no particle in the view (panned off): the plain image is exact (converged); the S-MIP stays
  // for the way back
  vtkInternals& internals = *this->Internals;
  this->DelegatePass->Render(frame.RenderState);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  this->NumberOfSamples = this->TargetSamples;
  internals.Shown = false;
  internals.Placed = false;
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::ChooseBins(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const vtkRenderState* s = frame.RenderState;
  vtkOpenGLRenderWindow* context = frame.Context;
  std::vector<vtkActor*>& particles = frame.Particles;
  const int width = frame.Width;
  const int height = frame.Height;
  int& bins = frame.Bins;
  int& slots = frame.Slots;
  bool& moments = frame.Moments;
  // bins whose S-MIP cache holds the view's tiles within the memory limit; the cache takes up
  // to eight views' worth of tiles where the limit allows (a zoom out by one level over a view
  // sampled whole needs five: four of the finer level, one of the coarser)
  // With particle actors coloured through lookup tables (vtkSNDFColourCoordinates::CanKeep) the
  // bins keep the moments of their colour coordinate (KeepColourCoordinates) where the memory holds
  // them with the bins asked for.
  const int viewTiles = vtkSNDFTileCache::GetTilesForView(width, height);
  moments = this->KeepColourCoordinates && vtkSNDFColourCoordinates::CanKeep(particles);
  auto slotsFor = [&](int b)
  {
    return static_cast<int>(std::min({ 8.0 * viewTiles,
      std::floor(this->MaximumMemory * 1048576.0 / vtkSNDFTileCache::GetTileBytes(b, moments)),
      static_cast<double>(internals.Cache->GetMaximumSlots(context, b, moments)) }));
  };
  if (moments && slotsFor(this->BinsPerAxis) < viewTiles)
  {
    moments = false;
    if (internals.FirstWarning("moments " + std::to_string(width) + "x" + std::to_string(height)))
    {
      vtkWarningMacro(<< "MaximumMemory (" << this->MaximumMemory << " MB) does not hold the "
                      << "colour coordinates' moments for this " << width << " x " << height
                      << " view: a new colour map samples again unless its colours are linear "
                         "in the old ones (KeepColourCoordinates).");
    }
  }
  bins = this->BinsPerAxis;
  while (bins >= 4 && slotsFor(bins) < viewTiles)
  {
    bins /= 2;
  }
  if (bins < 4)
  {
    const std::string what = "memory " + std::to_string(width) + "x" + std::to_string(height);
    if (internals.FirstWarning(what))
    {
      vtkWarningMacro(<< "The S-MIP cache of a " << width << " x " << height << " view needs "
                      << viewTiles * vtkSNDFTileCache::GetTileBytes(4) / 1048576.0 << " MB for its "
                      << viewTiles << " tiles even with 4 x 4 bins, more than "
                      << "MaximumMemory (" << this->MaximumMemory << " MB) or the GPU's "
                      << "shader-storage limits hold ("
                      << internals.Cache->GetMaximumSlots(context, 4)
                      << " tiles): the view is rendered as without S-NDF shading.");
    }
    this->RenderPlain(s);
    return false;
  }
  if (bins != this->BinsPerAxis)
  {
    const std::string what =
      "bins " + std::to_string(width) + "x" + std::to_string(height) + " " + std::to_string(bins);
    if (internals.FirstWarning(what))
    {
      vtkWarningMacro(<< "MaximumMemory (" << this->MaximumMemory << " MB) and the GPU's "
                      << "shader-storage limits hold the S-MIP tiles of this " << width << " x "
                      << height << " view with " << bins << " x " << bins << " bins only, not "
                      << this->BinsPerAxis << " x " << this->BinsPerAxis << ".");
    }
  }
  slots = slotsFor(bins);
  return true;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::DescribeView(vtkFrame& frame)
{
  vtkOpenGLRenderer* ren = frame.Renderer;
  vtkOpenGLRenderWindow* context = frame.Context;
  std::vector<double>& state = frame.State;
  const int width = frame.Width;
  const int height = frame.Height;
  const int x0 = frame.X0;
  const int y0 = frame.Y0;
  const int bins = frame.Bins;
  const int slots = frame.Slots;
  const bool moments = frame.Moments;
  bool& colouredLight = frame.ColouredLight;
  // The view: camera, size, bins, background. The camera's values are compared in single
  // precision: vtkWindowToImageFilter restores the view angle with a last-bit difference. In
  // parallel projection the position, focal point and parallel scale are left out: a view
  // whose pixels are the texels of an S-MIP level keeps the samples
  // (vtkSNDFViewPlacement::Place()).
  vtkCamera* camera = ren->GetActiveCamera();
  frame.Camera = camera;
  const bool parallel = camera->GetParallelProjection() != 0;
  std::vector<double> view;
  if (!parallel)
  {
    view.insert(view.end(), camera->GetPosition(), camera->GetPosition() + 3);
    view.insert(view.end(), camera->GetFocalPoint(), camera->GetFocalPoint() + 3);
    view.push_back(camera->GetParallelScale());
  }
  view.insert(view.end(), camera->GetViewUp(), camera->GetViewUp() + 3);
  view.insert(view.end(), camera->GetClippingRange(), camera->GetClippingRange() + 2);
  view.insert(view.end(), camera->GetWindowCenter(), camera->GetWindowCenter() + 2);
  view.push_back(camera->GetViewAngle());
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
  state.push_back(slots);
  state.push_back(moments);
  state.insert(state.end(), ren->GetBackground(), ren->GetBackground() + 3);
  state.insert(state.end(), ren->GetBackground2(), ren->GetBackground2() + 3);
  state.push_back(ren->GetGradientBackground());
  state.push_back(ren->GetTexturedBackground());
  state.push_back(ren->GetBackgroundAlpha());
  state.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(context)));
  // the passes inside this one (an AO pass put into the chain or changed samples anew), and
  // whether one adds an ambient light that carries the particles' colours (vtkSNDFRecolouring)
  colouredLight = false;
  vtkRenderPass* inner = this->DelegatePass;
  for (int depth = 0; inner && depth < 16; ++depth)
  {
    auto* ambient = vtkParticleAmbientLightPass::SafeDownCast(inner);
    colouredLight = colouredLight || (ambient && ambient->GetAddsColouredAmbientLight());
    state.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(inner)));
    state.push_back(static_cast<double>(inner->GetMTime()));
    auto* wrapping = vtkImageProcessingPass::SafeDownCast(inner);
    inner = wrapping ? wrapping->GetDelegatePass() : nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::PrepareContext(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLRenderWindow* context = frame.Context;
  std::vector<vtkActor*>& particles = frame.Particles;
  const bool moments = frame.Moments;
  if (internals.Context != context)
  {
    if (internals.Context)
    {
      this->ReleaseGraphicsResources(internals.Context);
    }
    internals.Context = context;
  }
  // the colour coordinates (computed again when their array changed) and the shader variant
  // that writes them
  const bool coordinates = moments &&
    internals.Coordinates.Update(particles, context, this,
      [&internals](const std::string& what) { return internals.FirstWarning(what); });
  if (coordinates != internals.Coordinates.InShader)
  {
    internals.Coordinates.InShader = coordinates;
    internals.ShaderTime.Modified();
  }
  const bool timing = this->CollectTimings;
  internals.Timer.StartFrame(timing);
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::KeepOrRestartSamples(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const vtkRenderState* s = frame.RenderState;
  vtkOpenGLRenderWindow* context = frame.Context;
  vtkCamera* camera = frame.Camera;
  std::vector<vtkActor*>& particles = frame.Particles;
  std::vector<double>& state = frame.State;
  std::vector<double>& colourKey = frame.ColourKey;
  const int width = frame.Width;
  const int height = frame.Height;
  const int bins = frame.Bins;
  const int slots = frame.Slots;
  const bool moments = frame.Moments;
  const bool colouredLight = frame.ColouredLight;
  vtkSNDFTileCache::Placement& placement = frame.Placement;
  vtkInternals::Between& between = frame.BetweenLevels;
  bool& sameFrame = frame.SameFrame;
  // the same frame (a pan or zoom by levels of the S-MIP keeps the samples), or a restart
  sameFrame = internals.FrameValid && state == internals.FixedState &&
    internals.Cache->GetNumberOfSlots() == slots && internals.Cache->GetBins() == bins &&
    internals.Cache->GetMoments() == moments &&
    internals.View.Place(camera, width, height, slots,
      this->ZoomBetweenLevels && !camera->GetUseExplicitProjectionTransformMatrix(), placement,
      between);
  // a new colour map: the samples are recoloured where the new colours are a linear function of
  // the old ones, else taken again
  if (sameFrame && colourKey != internals.Recolouring.Key)
  {
    const int recoloured = internals.Recolouring.Recolour(
      particles, colouredLight, internals.RawMaterial, internals.Context);
    sameFrame = recoloured >= 0;
    if (recoloured > 0)
    {
      internals.ResolveKey.clear(); // (the bins changed)
    }
    if (sameFrame)
    {
      internals.Recolouring.Key = colourKey;
      this->NumberOfRecolours += recoloured;
    }
  }
  if (internals.Exchange->IsDistributed())
  {
    // every process restarts when one does, or when their samples differ (a frame that some
    // drew alone, e.g. one not rendered distributed)
    const double counts[2] = { static_cast<double>(this->NumberOfSamples),
      static_cast<double>(internals.Sequence) };
    const bool equal = internals.Exchange->AllEqual(counts, 2);
    sameFrame = this->AllProcesses(sameFrame && equal);
  }
  if (!sameFrame)
  {
    bool allocated = true;
    if (internals.Cache->GetNumberOfSlots() != slots || internals.Cache->GetBins() != bins ||
      internals.Cache->GetMoments() != moments)
    {
      allocated = internals.Cache->Allocate(context, bins, slots, moments);
      if (!allocated)
      {
        vtkErrorMacro(<< "Could not allocate "
                      << slots * vtkSNDFTileCache::GetTileBytes(bins, moments) / 1048576.0
                      << " MB for the S-MIP cache: the view is rendered as without S-NDFs.");
      }
      this->MemoryBytes = internals.Cache->GetBytes();
    }
    if (!this->AllProcesses(allocated))
    {
      internals.Targets.Release(context);
      this->RenderPlain(s);
      return false;
    }
    internals.Cache->Clear();
    internals.StartFrame(camera, width, height);
    internals.FixedState = state;
    internals.Recolouring.Key = colourKey;
    internals.Recolouring.KeepColours(particles, internals.RawMaterial);
    internals.Placed = false;
    internals.Sequence = 0;
    internals.ResolveKey.clear();
    placement = internals.Placement;
    between = vtkInternals::Between();
    this->NumberOfSamples = 0;
    internals.CheckedSamples = 0;
    this->ErrorTargetReached = false;
    this->EstimatedError = -1.0;
    ++this->NumberOfRestarts;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::ShowChangeFrame(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const vtkRenderState* s = frame.RenderState;
  const int width = frame.Width;
  const int height = frame.Height;
  const int bins = frame.Bins;
  const bool sameFrame = frame.SameFrame;
  vtkSNDFTileCache::Placement& placement = frame.Placement;
  vtkInternals::Between& between = frame.BetweenLevels;
  int& texelsX = frame.TexelsX;
  int& texelsY = frame.TexelsY;
  // the texels sampled and shaded: the window's pixels, or the rectangle of a view between two
  // levels (its window pixels are their box filter)
  texelsX = between.Active ? between.Size[0] : width;
  texelsY = between.Active ? between.Size[1] : height;
  // The frame of a change (e.g. each frame of an interaction: a restart, a pan off the grids in
  // the cache) is the plain image: one S-NDF sample would shade with bin means, coarser than the
  // exact normal. Sampling starts with the next frame -- unless this render is to converge
  // (ConvergeOnRender). A view with tiles in the cache shows them at once.
  const bool changed = !sameFrame || !internals.Shown || !(placement == internals.ShownView);
  internals.ShownView = placement;
  internals.Shown = true;
  const bool plain = changed && !this->ConvergeOnRender &&
    internals.Cache->CountAvailable(placement, texelsX, texelsY) == 0;
  if (!this->AllProcesses(!plain))
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    this->ActiveBinsPerAxis = bins;
    this->NumberOfSamples = 0;
    this->ErrorTargetReached = false;
    return false;
  }
  this->ActiveBinsPerAxis = bins;
  return true;
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::PrepareTargets(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const vtkRenderState* s = frame.RenderState;
  vtkOpenGLRenderWindow* context = frame.Context;
  const int width = frame.Width;
  const int height = frame.Height;
  const int texelsX = frame.TexelsX;
  const int texelsY = frame.TexelsY;
  vtkInternals::Between& between = frame.BetweenLevels;
  if (!internals.Accumulate->IsBuilt())
  {
    internals.Accumulate->SetSource(internals.Cache->GetShaderSource("SNDFAccumulate"));
    internals.Resolve->SetSource(internals.Cache->GetShaderSource("SNDFResolve"));
    internals.BoxFilter->SetSource(vtkParticleShaders::Get("SNDFBoxFilter"));
    if (!internals.Accumulate->Build(context) || !internals.Resolve->Build(context) ||
      !internals.BoxFilter->Build(context))
    {
      this->RenderPlain(s);
      return false;
    }
  }
  if (texelsX != internals.Targets.Width || texelsY != internals.Targets.Height ||
    !internals.Targets.Depth || !internals.Targets.Depth->GetHandle())
  {
    internals.Targets.Allocate(context, texelsX, texelsY);
  }
  if (between.Active)
  {
    internals.Targets.AllocateDisplay(context, width, height);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::ChooseMaterial(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  std::vector<vtkActor*>& particles = frame.Particles;
  vtkProperty*& material = frame.Material;
  double(&specular)[3] = frame.Specular;
  // the lighting table (Eqs. 12-14) for the renderer's lights and the first particle actor's
  // specular power
  material = particles.empty() ? internals.NoParticleMaterial.Get() : particles[0]->GetProperty();
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
  // the specular colour of the shade
  material->GetSpecularColor(specular);
  for (double& c : specular)
  {
    c *= material->GetSpecular();
  }
}

//------------------------------------------------------------------------------
std::vector<double> vtkSNDFRenderPass::LightingTableKey(vtkFrame& frame)
{
  vtkOpenGLRenderer* ren = frame.Renderer;
  vtkCamera* camera = frame.Camera;
  vtkProperty*& material = frame.Material;
  const int bins = frame.Bins;
  // (the view distance places positional lights only (prViewDistance), and to six digits: a
  // pan moves position and focal point together, changing the distance by rounding errors,
  // and a new table would rebake every cached tile)
  const double distance = camera->GetDistance();
  const double distanceKey = ren->GetLightingComplexity() > 2 && distance > 0.0
    ? std::round(1e6 * distance / std::pow(10.0, std::floor(std::log10(distance))))
    : 0.0;
  std::vector<double> tableKey = { static_cast<double>(ren->GetLightingComplexity()),
    static_cast<double>(ren->GetLightingCount()), material->GetSpecularPower(),
    static_cast<double>(bins), distanceKey };
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  // what the table depends on: each light's colour, its direction in view coordinates and,
  // for positional lights, its position there and its cone (a pan moves neither the view
  // direction nor a directional light's: the tiles keep their shading)
  vtkMatrix4x4* modelView = camera->GetModelViewTransformMatrix();
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch())
    {
      continue;
    }
    double colour[3];
    light->GetDiffuseColor(colour);
    double position[4] = { 0.0, 0.0, 0.0, 1.0 };
    double focal[4] = { 0.0, 0.0, 0.0, 1.0 };
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    double positionVC[4];
    double focalVC[4];
    modelView->MultiplyPoint(position, positionVC);
    modelView->MultiplyPoint(focal, focalVC);
    tableKey.push_back(light->GetIntensity());
    tableKey.insert(tableKey.end(), colour, colour + 3);
    // (the direction to six digits: a pan there and back moves a headlight by rounding errors)
    double direction[3] = { focalVC[0] - positionVC[0], focalVC[1] - positionVC[1],
      focalVC[2] - positionVC[2] };
    const double length = vtkMath::Norm(direction);
    for (double d : direction)
    {
      tableKey.push_back(length > 0.0 ? std::round(1e6 * d / length) : 0.0);
    }
    tableKey.push_back(light->GetPositional());
    if (light->GetPositional())
    {
      tableKey.insert(tableKey.end(), positionVC, positionVC + 3);
      tableKey.insert(
        tableKey.end(), light->GetAttenuationValues(), light->GetAttenuationValues() + 3);
      tableKey.push_back(light->GetExponent());
      tableKey.push_back(light->GetConeAngle());
    }
  }
  return tableKey;
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::UpdateLightingTable(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const vtkRenderState* s = frame.RenderState;
  vtkOpenGLRenderer* ren = frame.Renderer;
  vtkOpenGLRenderWindow* context = frame.Context;
  vtkCamera* camera = frame.Camera;
  vtkProperty*& material = frame.Material;
  const int bins = frame.Bins;
  // the renderer's light geometry (lights that follow the camera), uniforms and complexity are
  // brought up to date by its lights pass, which does not run when nothing is sampled
  internals.Timer.Begin(2);
  internals.Lights->Render(s);
  const std::vector<double> tableKey = this->LightingTableKey(frame);
  if (internals.LightingTable.IsCurrent(tableKey))
  {
    return true;
  }
  if (!internals.LightingTable.Build(ren, context, camera, material, bins, tableKey))
  {
    internals.Timer.End();
    vtkErrorMacro(<< "The S-NDF lighting table shader did not build.");
    this->RenderPlain(s);
    return false;
  }
  ++this->NumberOfTableBuilds;
  return true;
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::MapTiles(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const vtkRenderState* s = frame.RenderState;
  const int texelsX = frame.TexelsX;
  const int texelsY = frame.TexelsY;
  vtkSNDFTileCache::Placement& placement = frame.Placement;
  // the view's tiles of the S-MIP: found in the cache, averaged from a finer level, or new;
  // rebaked where shaded with an older table (re-lighting)
  const long long changes =
    internals.Cache->GetNumberOfDownsampledTiles() + internals.Cache->GetNumberOfClearedTiles();
  if (!internals.Cache->MapView(placement, texelsX, texelsY, internals.LightingTable.GetTexture(),
        static_cast<long long>(this->NumberOfTableBuilds)))
  {
    internals.Timer.End();
    vtkErrorMacro(<< "The S-MIP cache does not hold the view's tiles.");
    this->RenderPlain(s);
    return false;
  }
  const bool moved = !internals.Placed || !(placement == internals.Placement) ||
    internals.PlacedSize[0] != texelsX || internals.PlacedSize[1] != texelsY;
  if (moved && internals.Placed)
  {
    ++(placement.Level == internals.Placement.Level ? this->NumberOfPans : this->NumberOfZooms);
  }
  if (moved ||
    changes !=
      internals.Cache->GetNumberOfDownsampledTiles() + internals.Cache->GetNumberOfClearedTiles())
  {
    // a pan or zoom brought other texels into the view: count the fewest samples a pixel holds
    this->NumberOfSamples = static_cast<int>(
      std::min<unsigned int>(internals.Cache->CountMinimumSamples(texelsX, texelsY),
        static_cast<unsigned int>(this->TargetSamples)));
    internals.CheckedSamples = 0;
    this->ErrorTargetReached = false;
    this->EstimatedError = -1.0;
  }
  internals.Placement = placement;
  internals.PlacedSize[0] = texelsX;
  internals.PlacedSize[1] = texelsY;
  internals.Placed = true;
  internals.Timer.End();
  return true;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::ResolveView(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const int texelsX = frame.TexelsX;
  const int texelsY = frame.TexelsY;
  vtkSNDFTileCache::Placement& placement = frame.Placement;
  double(&specular)[3] = frame.Specular;
  double(&diffuseScale)[3] = frame.DiffuseScale;
  double(&ambientTerm)[3] = frame.AmbientTerm;
  std::vector<double> resolveKey = { static_cast<double>(this->NumberOfSamplePasses),
    static_cast<double>(placement.Level), static_cast<double>(placement.Origin[0]),
    static_cast<double>(placement.Origin[1]), static_cast<double>(placement.Phase[0]),
    static_cast<double>(placement.Phase[1]), static_cast<double>(texelsX),
    static_cast<double>(texelsY),
    static_cast<double>(internals.Cache->GetNumberOfDownsampledTiles()),
    static_cast<double>(internals.Cache->GetNumberOfClearedTiles()),
    static_cast<double>(this->NumberOfTableBuilds), specular[0], specular[1], specular[2],
    diffuseScale[0], diffuseScale[1], diffuseScale[2], ambientTerm[0], ambientTerm[1],
    ambientTerm[2] };
  if (resolveKey == internals.ResolveKey)
  {
    return;
  }
  vtkParticleComputeProgram* resolve = internals.Resolve;
  resolve->Use();
  resolve->SetUniform2i("prSize", texelsX, texelsY);
  resolve->SetUniform3f("prSpecularColour", static_cast<float>(specular[0]),
    static_cast<float>(specular[1]), static_cast<float>(specular[2]));
  resolve->SetUniform3f("prDiffuseScale", static_cast<float>(diffuseScale[0]),
    static_cast<float>(diffuseScale[1]), static_cast<float>(diffuseScale[2]));
  resolve->SetUniform3f("prAmbientTerm", static_cast<float>(ambientTerm[0]),
    static_cast<float>(ambientTerm[1]), static_cast<float>(ambientTerm[2]));
  internals.Cache->BindView(resolve);
  glBindImageTexture(
    0, internals.Targets.Image->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindImageTexture(
    1, internals.Targets.ImageDepth->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  for (int part = 0; part < internals.Cache->GetNumberOfViewParts(); ++part)
  {
    resolve->Dispatch(4, 4, internals.Cache->BindViewPart(resolve, part));
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  vtkParticleComputeProgram::UseNone();
  internals.ResolveKey = resolveKey;
  ++this->NumberOfResolves;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::CheckError(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLRenderWindow* context = frame.Context;
  const int texelsX = frame.TexelsX;
  const int texelsY = frame.TexelsY;
  const unsigned int groupsX = static_cast<unsigned int>((texelsX + 15) / 16);
  const unsigned int groupsY = static_cast<unsigned int>((texelsY + 15) / 16);
  // The error estimate (ErrorTarget): the picture I_N after N samples against I_M, the one at
  // the last check (M <= N / 2): the mean |I_N - I_M| * sqrt(M / (N - M)) over the view
  // estimates the mean error of I_N (for independent samples I_N - I_M has the variance of
  // I_N's error times (N - M) / M). Checked at N >= 4 and N >= 2 M.
  const int n = this->NumberOfSamples;
  const int m = internals.CheckedSamples;
  if (!(this->ErrorTarget > 0.0) || n < 2 || (m > 0 && (n < 4 || n < 2 * m)))
  {
    return;
  }
  this->ResolveView(frame);
  if (m > 0)
  {
    if (!internals.Difference->IsBuilt())
    {
      internals.Difference->SetSource(vtkParticleShaders::Get("SNDFImageDifference"));
      internals.Difference->Build(context);
    }
    std::vector<unsigned int> totals(1024, 0u);
    if (!internals.Totals->GetHandle())
    {
      vtkParticleComputeProgram::AllocateStorage(internals.Totals, totals.size() * 4);
    }
    vtkParticleComputeProgram::UploadStorage(internals.Totals, 0, totals.size() * 4, totals.data());
    vtkParticleComputeProgram* difference = internals.Difference;
    difference->Use();
    difference->SetUniform2i("prSize", texelsX, texelsY);
    glBindImageTexture(
      0, internals.Targets.Image->GetHandle(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(
      1, internals.Targets.Checkpoint->GetHandle(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    vtkParticleComputeProgram::BindStorage(1, internals.Totals);
    difference->Dispatch(groupsX, groupsY);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    vtkParticleComputeProgram::UseNone();
    vtkParticleComputeProgram::DownloadStorage(
      internals.Totals, 0, totals.size() * 4, totals.data());
    double total = 0.0;
    for (unsigned int t : totals)
    {
      total += t;
    }
    // mean over pixels and channels, in 1/255
    const double mean = total / (64.0 * 3.0 * texelsX * texelsY);
    this->EstimatedError = mean * std::sqrt(static_cast<double>(m) / (n - m));
    // (distributed: every process resolves the same S-NDFs; decided together all the same)
    this->ErrorTargetReached = this->AllProcesses(this->EstimatedError <= this->ErrorTarget);
  }
  glCopyImageSubData(internals.Targets.Image->GetHandle(), GL_TEXTURE_2D, 0, 0, 0, 0,
    internals.Targets.Checkpoint->GetHandle(), GL_TEXTURE_2D, 0, 0, 0, 0, texelsX, texelsY, 1);
  internals.CheckedSamples = n;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::TakeSamples(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  vtkCamera* camera = frame.Camera;
  const int texelsX = frame.TexelsX;
  const int texelsY = frame.TexelsY;
  vtkSNDFTileCache::Placement& placement = frame.Placement;
  vtkInternals::Between& between = frame.BetweenLevels;
  // sample passes
  const int missing = this->ErrorTargetReached ? 0 : this->TargetSamples - this->NumberOfSamples;
  const int samples = this->ConvergeOnRender ? missing : std::min(this->SamplesPerFrame, missing);
  // a render of many sample passes (ConvergeOnRender, a large SamplesPerFrame) reports them
  const bool reporting = samples >= ProgressSamples;
  if (reporting)
  {
    internals.ProgressText =
      "S-NDF shading: " + std::to_string(this->TargetSamples) + " samples per pixel";
    double fraction = 0.0;
    this->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
  }
  // the camera of the sample passes: the view's, or one whose pixels are the texels of a view
  // between two levels (restored after them)
  double viewCentre[2];
  camera->GetWindowCenter(viewCentre);
  const double viewScale = camera->GetParallelScale();
  const bool viewExplicit = camera->GetUseExplicitAspectRatio();
  const double viewAspect = camera->GetExplicitAspectRatio();
  double centre[2] = { viewCentre[0], viewCentre[1] };
  if (between.Active && samples > 0)
  {
    double scale = viewScale;
    internals.View.SamplingWindow(camera, placement, texelsX, texelsY, scale, centre);
    camera->SetParallelScale(scale);
    camera->SetExplicitAspectRatio(static_cast<double>(texelsX) / texelsY);
    camera->UseExplicitAspectRatioOn();
  }
  // A camera with an explicit projection matrix (IceT's draw callback in ParaView sets one) does
  // not move with the window centre: the jitter then moves that matrix's picture as the window
  // centre would (vtkCamera: a window centre c shifts the picture by -c in normalised device
  // coordinates); a view between levels is not zoomed then.
  vtkSmartPointer<vtkMatrix4x4> explicitProjection =
    camera->GetUseExplicitProjectionTransformMatrix()
    ? camera->GetExplicitProjectionTransformMatrix()
    : nullptr;
  vtkNew<vtkMatrix4x4> jittered;
  for (int k = 0; k < samples; ++k)
  {
    double offset[2];
    JitterOffset(internals.Sequence++, offset);
    const double shift[2] = { 2.0 * offset[0] / texelsX, 2.0 * offset[1] / texelsY };
    if (explicitProjection)
    {
      jittered->DeepCopy(explicitProjection);
      for (int row = 0; row < 2; ++row)
      {
        for (int column = 0; column < 4; ++column)
        {
          jittered->SetElement(row, column,
            explicitProjection->GetElement(row, column) -
              shift[row] * explicitProjection->GetElement(3, column));
        }
      }
      camera->SetExplicitProjectionTransformMatrix(jittered);
    }
    else
    {
      camera->SetWindowCenter(centre[0] + shift[0], centre[1] + shift[1]);
    }

    this->RenderSampleTargets(frame);
    this->ExchangeSampleTargets(frame);
    if (explicitProjection)
    {
      camera->SetExplicitProjectionTransformMatrix(explicitProjection);
    }
    else
    {
      camera->SetWindowCenter(viewCentre[0], viewCentre[1]);
    }
    ++this->NumberOfSamplePasses;

    this->AccumulateSamples(frame);
    ++this->NumberOfSamples;
    this->CheckError(frame);
    if (reporting)
    {
      double fraction = this->ErrorTargetReached ? 1.0 : static_cast<double>(k + 1) / samples;
      this->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
    }
    if (this->ErrorTargetReached)
    {
      break;
    }
  }
  if (between.Active && samples > 0)
  {
    camera->SetParallelScale(viewScale);
    camera->SetExplicitAspectRatio(viewAspect);
    camera->SetUseExplicitAspectRatio(viewExplicit);
  }
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::RenderSampleTargets(vtkFrame& frame)
{
  // one sample pass: the scene, jittered, into the sample targets
  vtkInternals& internals = *this->Internals;
  const vtkRenderState* s = frame.RenderState;
  vtkOpenGLRenderer* ren = frame.Renderer;
  vtkOpenGLState* ostate = frame.Context->GetState();
  const int texelsX = frame.TexelsX;
  const int texelsY = frame.TexelsY;
  internals.Timer.Begin(0);
  ostate->PushFramebufferBindings();
  internals.Targets.Framebuffer->Bind();
  internals.Targets.Framebuffer->ActivateDrawBuffers(NumberOfAttachments);
  {
    vtkOpenGLState::ScopedglViewport viewport(ostate);
    vtkOpenGLState::ScopedglScissor scissor(ostate);
    ostate->vtkglViewport(0, 0, texelsX, texelsY);
    ostate->vtkglScissor(0, 0, texelsX, texelsY);
    ren->Clear();
    const GLfloat zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    for (unsigned int a = 1; a < NumberOfAttachments; ++a)
    {
      glClearBufferfv(GL_COLOR, static_cast<GLint>(a), zero);
    }
    vtkRenderState sampleState(ren);
    sampleState.SetFrameBuffer(internals.Targets.Framebuffer);
    sampleState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
    // the particle targets take each fragment as it is (every shader writes alpha 1 there:
    // blending, which VTK keeps on for opaque geometry too, would only add a read-modify-write
    // of two 16-bit float targets per fragment); no FXAA over them (nor over the S-NDF
    // picture, which is box-filtered over each pixel already)
    {
      vtkParticleGBufferGuard guard(ren, NumberOfAttachments);
      this->PreRender(&sampleState);
      this->DelegatePass->Render(&sampleState);
      this->PostRender(&sampleState);
    }
    internals.Coordinates.Deactivate(); // (SetShaderParameters activated them)
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  }
  ostate->PopFramebufferBindings();
  internals.Timer.End();
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::AccumulateSamples(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const int texelsX = frame.TexelsX;
  const int texelsY = frame.TexelsY;
  const int bins = frame.Bins;
  // into the S-NDFs
  internals.Timer.Begin(1);
  vtkParticleComputeProgram* accumulate = internals.Accumulate;
  accumulate->Use();
  const char* samplers[NumberOfAttachments] = { "prColour", "prNormal", "prDiffuse" };
  for (unsigned int a = 0; a < NumberOfAttachments; ++a)
  {
    internals.Targets.Attachments[a]->Activate();
    accumulate->SetUniformi(samplers[a], internals.Targets.Attachments[a]->GetTextureUnit());
  }
  internals.Targets.Depth->Activate();
  accumulate->SetUniformi("prDepth", internals.Targets.Depth->GetTextureUnit());
  vtkTextureObject* table = internals.LightingTable.GetTexture();
  table->Activate();
  accumulate->SetUniformi("prTable", table->GetTextureUnit());
  accumulate->SetUniform2i("prSize", texelsX, texelsY);
  accumulate->SetUniformi("prBins", bins);
  accumulate->SetUniformf("prTarget", static_cast<float>(this->TargetSamples));
  accumulate->SetUniformi(
    "prMoments", internals.Coordinates.InShader && internals.Cache->GetMoments() ? 1 : 0);
  internals.Cache->BindView(accumulate);
  for (int part = 0; part < internals.Cache->GetNumberOfViewParts(); ++part)
  {
    accumulate->Dispatch(4, 4, internals.Cache->BindViewPart(accumulate, part));
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  for (unsigned int a = 0; a < NumberOfAttachments; ++a)
  {
    internals.Targets.Attachments[a]->Deactivate();
  }
  internals.Targets.Depth->Deactivate();
  table->Deactivate();
  vtkParticleComputeProgram::UseNone();
  internals.Timer.End();
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::Shade(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  const int width = frame.Width;
  const int height = frame.Height;
  const int texelsX = frame.TexelsX;
  const int texelsY = frame.TexelsY;
  vtkInternals::Between& between = frame.BetweenLevels;
  // shade when samples, table or specular colour changed
  internals.Timer.Begin(2);
  this->ResolveView(frame);
  // a view between two levels: each window pixel the box filter of the shaded texels under it
  frame.Shown = internals.Targets.Image;
  frame.ShownDepth = internals.Targets.ImageDepth;
  if (between.Active)
  {
    vtkParticleComputeProgram* filter = internals.BoxFilter;
    filter->Use();
    filter->SetUniform2i("prSize", width, height);
    filter->SetUniform2i("prTexelSize", texelsX, texelsY);
    filter->SetUniformf("prScale", static_cast<float>(between.Scale));
    filter->SetUniform2f(
      "prOffset", static_cast<float>(between.Offset[0]), static_cast<float>(between.Offset[1]));
    glBindImageTexture(
      0, internals.Targets.Image->GetHandle(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(
      1, internals.Targets.ImageDepth->GetHandle(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
    glBindImageTexture(
      2, internals.Targets.DisplayImage->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(
      3, internals.Targets.DisplayDepth->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    filter->Dispatch(
      static_cast<unsigned int>((width + 15) / 16), static_cast<unsigned int>((height + 15) / 16));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    for (GLuint unit = 0; unit < 4; ++unit)
    {
      glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    }
    vtkParticleComputeProgram::UseNone();
    frame.Shown = internals.Targets.DisplayImage;
    frame.ShownDepth = internals.Targets.DisplayDepth;
  }
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::Composite(vtkFrame& frame)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLRenderWindow* context = frame.Context;
  vtkOpenGLState* ostate = frame.Context->GetState();
  vtkTextureObject* shown = frame.Shown;
  vtkTextureObject* shownDepth = frame.ShownDepth;
  // the composite: colour and depth into the render state's target, over the whole viewport
  if (!internals.CompositeQuad)
  {
    std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
    vtkShaderProgram::Substitute(
      fs, "//VTK::FSQ::Decl", "uniform sampler2D prImage;\nuniform sampler2D prImageDepth;\n");
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl",
      "gl_FragData[0] = texture(prImage, texCoord);\n"
      "  gl_FragDepth = texture(prImageDepth, texCoord).r;\n");
    internals.CompositeQuad.reset(new vtkOpenGLQuadHelper(context, nullptr, fs.c_str(), nullptr));
  }
  vtkOpenGLQuadHelper* composite = internals.CompositeQuad.get();
  if (composite->Program)
  {
    context->GetShaderCache()->ReadyShaderProgram(composite->Program);
    shown->Activate();
    shownDepth->Activate();
    composite->Program->SetUniformi("prImage", shown->GetTextureUnit());
    composite->Program->SetUniformi("prImageDepth", shownDepth->GetTextureUnit());
    vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    ostate->vtkglDepthMask(GL_TRUE);
    ostate->vtkglDisable(GL_BLEND);
    composite->Render();
    shown->Deactivate();
    shownDepth->Deactivate();
  }
  internals.Timer.End();
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::SetController(vtkMultiProcessController* controller)
{
  if (this->Internals->Exchange->GetController() != controller)
  {
    this->Internals->Exchange->SetController(controller);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkSNDFRenderPass::GetController()
{
  return this->Internals->Exchange->GetController();
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::AllProcesses(bool local)
{
  double value = local ? 1.0 : 0.0;
  this->Internals->Exchange->Minimum(&value, 1); // (nothing to do with one process)
  return value > 0.5;
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::AgreeToSample(bool local, vtkFrame& frame)
{
  // a process that is not ready has drawn the plain frame already; the others draw it too
  const bool all = this->AllProcesses(local);
  if (local && !all)
  {
    this->RenderPlain(frame.RenderState);
  }
  return all;
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::ExchangeSampleTargets(vtkFrame& frame)
{
  // Distributed rendering: the sample pass's G-buffer of the whole picture -- per texel the
  // nearest fragment of any process, with the colour, normal and diffuse values its process
  // wrote -- in every process's targets before they enter the S-NDFs. The 8-bit colour travels
  // as whole numbers 0-255 in floats and the 16-bit float targets as floats: both arrive
  // exactly (vtkParticleGBufferExchange adds zeros to the owner's values).
  vtkInternals& internals = *this->Internals;
  if (!internals.Exchange->IsDistributed())
  {
    return;
  }
  std::vector<vtkParticleGBufferExchange::vtkTarget> targets;
  for (unsigned int a = 0; a < NumberOfAttachments; ++a)
  {
    targets.push_back({ static_cast<int>(a), 4, a == 0, 0.0f, internals.Targets.Attachments[a] });
  }
  internals.Exchange->CompositeFramebuffer(frame.Context, internals.Targets.Framebuffer,
    frame.TexelsX, frame.TexelsY, targets, internals.Targets.Depth, true);
}

//------------------------------------------------------------------------------
bool vtkSNDFRenderPass::GetLightingTable(vtkFloatArray* table)
{
  return this->Internals->LightingTable.Read(table);
}

//------------------------------------------------------------------------------
void vtkSNDFRenderPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& internals = *this->Internals;
  internals.Targets.Release(w);
  internals.LightingTable.Release(w);
  if (internals.CompositeQuad)
  {
    internals.CompositeQuad->ReleaseGraphicsResources(w);
    internals.CompositeQuad.reset();
  }
  internals.Accumulate->ReleaseGraphicsResources(w);
  internals.Resolve->ReleaseGraphicsResources(w);
  internals.BoxFilter->ReleaseGraphicsResources(w);
  internals.Difference->ReleaseGraphicsResources(w);
  vtkParticleComputeProgram::ReleaseStorage(
    internals.Totals, vtkParticleComputeProgram::MakeCurrentForRelease(internals.Context));
  internals.CheckedSamples = 0;
  internals.Cache->ReleaseGraphicsResources(w);
  // the colour coordinates are uploaded again when next needed
  internals.Coordinates.Release(w);
  internals.Recolouring.Release(w);
  internals.FrameValid = false;
  internals.Placed = false;
  internals.FixedState.clear();
  internals.ColourSources.clear();
  internals.ResolveKey.clear();
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
  os << indent << "Controller: " << this->GetController() << "\n";
  os << indent << "ZoomBetweenLevels: " << this->ZoomBetweenLevels << "\n";
  os << indent << "ErrorTarget: " << this->ErrorTarget << "\n";
  os << indent << "EstimatedError: " << this->EstimatedError << "\n";
  os << indent << "CollectTimings: " << this->CollectTimings << "\n";
  os << indent << "NumberOfSamplePasses: " << this->NumberOfSamplePasses << "\n";
  os << indent << "NumberOfRestarts: " << this->NumberOfRestarts << "\n";
  os << indent << "NumberOfRecolours: " << this->NumberOfRecolours << "\n";
  os << indent << "KeepColourCoordinates: " << this->KeepColourCoordinates << "\n";
}
