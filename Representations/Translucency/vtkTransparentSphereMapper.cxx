#include "vtkTransparentSphereMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkParticleCellList.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleDepthSort.h"
#include "vtkParticleEmissionModel.h"
#include "vtkParticleFragmentLists.h"
#include "vtkParticleFrameBudget.h"
#include "vtkParticleFrontToBackTarget.h"
#include "vtkParticleOverlapError.h"
#include "vtkParticleShaderHooks.h"
#include "vtkParticleShaders.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTransparentSphereMapper);

namespace
{
// the frame budget's levels (GetQualityLevelNames): half resolution sorted spheres, full
// resolution sorted spheres with early termination, exact
const int NumberOfQualityLevels = 3;
// the accumulation's resolution divisor at the cheapest level
const int InteractiveDownsampling = 2;

// which shader a helper holds
enum class Variant
{
  Opaque,         // the core: opaque particles (depth writes) and picking
  Translucent,    // the emission-absorption composite of the translucent stage
  TranslucentList // the same segments appended to per-pixel lists (exact overlaps)
};

// GS culling modes (uniform prCullMode)
const int CullOpaqueStage = 0;     // opaque variant: only Theta_a = 1
const int CullAllVisible = 1;      // either variant: everything with Theta_a > 0
const int CullTranslucentOnly = 0; // translucent variant: Theta_a in (0, 1)

struct OpacitySummary
{
  bool AnyOpaque = false;
  bool AnyTranslucent = false;
  vtkIdType NaNs = 0;
};

// The render passes registered with an actor for its next draw (vtkOpenGLRenderPass::
// RenderPasses), and what they mean for the translucent particles: which translucency pass
// composites the scene, and -- while an object of this class lives, after HideTranslucencyPasses()
// -- the list without the translucency passes, whose shader replacements and uniforms must not
// reach the particles' own front-to-back composite (they are put back on destruction).
class RenderPassList
{
public:
  explicit RenderPassList(vtkActor* actor)
    : Info(actor->GetPropertyKeys())
  {
    vtkInformationObjectBaseVectorKey* key = vtkOpenGLRenderPass::RenderPasses();
    if (!this->Info || !this->Info->Has(key))
    {
      return;
    }
    for (int i = 0; i < key->Length(this->Info); ++i)
    {
      vtkObjectBase* pass = key->Get(this->Info, i);
      this->Passes.emplace_back(pass);
      if (auto* peeling = vtkDualDepthPeelingPass::SafeDownCast(pass))
      {
        this->Peeling = peeling;
      }
      else if (vtkOrderIndependentTranslucentPass::SafeDownCast(pass))
      {
        this->OrderIndependent = true;
      }
      else if (vtkDepthPeelingPass::SafeDownCast(pass))
      {
        this->SinglePeeling = true;
      }
    }
  }
  ~RenderPassList()
  {
    if (this->Hidden)
    {
      this->Set(false);
    }
  }
  RenderPassList(const RenderPassList&) = delete;
  void operator=(const RenderPassList&) = delete;

  void HideTranslucencyPasses()
  {
    if (!this->Passes.empty() && !this->Hidden)
    {
      this->Set(true);
      this->Hidden = true;
    }
  }

  vtkDualDepthPeelingPass* Peeling = nullptr; // dual depth peeling composites
  bool OrderIndependent = false;              // the order-independent pass composites
  bool SinglePeeling = false;                 // single-layer depth peeling (no dual) composites

private:
  void Set(bool withoutTranslucency)
  {
    this->Info->Remove(vtkOpenGLRenderPass::RenderPasses());
    for (auto& pass : this->Passes)
    {
      if (!withoutTranslucency ||
        (!vtkDualDepthPeelingPass::SafeDownCast(pass) &&
          !vtkOrderIndependentTranslucentPass::SafeDownCast(pass)))
      {
        vtkOpenGLRenderPass::RenderPasses()->Append(this->Info, pass);
      }
    }
  }

  vtkInformation* Info;
  std::vector<vtkSmartPointer<vtkObjectBase>> Passes;
  bool Hidden = false;
};
}

//------------------------------------------------------------------------------
class vtkTransparentSphereMapper::vtkInternals
{
public:
  explicit vtkInternals(vtkTransparentSphereMapper* self)
    : Hooks(self)
  {
  }

  // the shader hooks of the sphere templates this mapper fills
  vtkParticleShaderHooks Hooks;
  // the translucent variant's program, vertex array and shader times, beside the opaque one
  // (the superclass's triangle helper); its index count is the number of particles
  vtkOpenGLHelper Translucent;
  // the exact-overlap variant's program (fragments appended to per-pixel lists)
  vtkOpenGLHelper TranslucentList;
  vtkNew<vtkParticleFragmentLists> Lists;
  // overlap of the drawn spheres (AUTOMATIC), and what it was computed from
  bool Overlapping = false;
  std::vector<vtkMTimeType> OverlapKey;
  double OverlapScale = 0.0;
  double OverlapTolerance = -1.0;
  bool ExactOverlapInUse = false;
  // AUTOMATIC's error estimate: the pairs whose lens may be off, what they were found from, and
  // the pixels of the last view
  vtkParticleOverlapError OverlapError;
  std::vector<double> OverlapErrorKey;
  double OverlapErrorPixels = 0.0;

  // per-particle opacity
  vtkNew<vtkDoubleArray> Opacities;    // Theta_a
  vtkNew<vtkFloatArray> OpticalDepths; // -ln(1 - Theta_a); -1 for Theta_a = 1
  bool AnyOpaque = true;
  bool AnyTranslucent = false;
  // what they were computed from
  vtkMTimeType GeometryTime = 0;
  vtkAbstractArray* OpacityArray = nullptr;
  vtkMTimeType OpacityArrayTime = 0;
  std::string OpacityArrayName;
  double OpacityRange[2] = { 0.0, 0.0 };
  bool OpacitiesValid = false;
  std::string LastWarning;

  // shader variant being built and the culling mode of the next draw
  Variant Building = Variant::Opaque;
  int CullMode = CullOpaqueStage;
  // scalar colours carry alpha < 1 (set per translucent frame)
  bool ScalarAlpha = false;

  // sorting
  vtkNew<vtkParticleComputeProgram> KeyProgram;
  vtkNew<vtkParticleDepthSort> Sort;
  std::vector<double> SortState;
  int Support = -1; // OpenGL 4.3: -1 not checked yet, 0 no, 1 yes
  vtkOpenGLRenderWindow* SupportContext = nullptr;
  bool SupportWarned = false;

  // compositing
  vtkNew<vtkParticleFrontToBackTarget> Target;
  vtkMTimeType LastPeelingStageTime = 0;
  bool SinglePeelingWarned = false;
  bool UnsortedWarned = false;
  vtkIdType FailedSortCount = -1;

  // timings
  vtkOpenGLRenderTimer TotalTimer;
  vtkOpenGLRenderTimer SortTimer;
  vtkOpenGLRenderTimer DrawTimer;
  bool SortTimed = false;
  bool TimingsPending = false;
};

//------------------------------------------------------------------------------
vtkTransparentSphereMapper::vtkTransparentSphereMapper()
  : Internals(new vtkInternals(this))
{
  // spheres are lit surfaces: VTK lights the triangle primitives (GetNeedToRebuildShaders)
  this->Internals->Translucent.PrimitiveType = PrimitiveTris;
  this->Internals->TranslucentList.PrimitiveType = PrimitiveTris;
  this->Internals->Opacities->SetName("ParticleOpacity");
  this->Internals->OpticalDepths->SetName("ParticleOpticalDepth");
}

//------------------------------------------------------------------------------
vtkTransparentSphereMapper::~vtkTransparentSphereMapper()
{
  this->SetOpacityArrayName(nullptr);
  delete this->Internals;
}

//------------------------------------------------------------------------------
double vtkTransparentSphereMapper::GetMaximumPathIntegral(int model, double f)
{
  return vtkParticleEmissionModel::GetMaximumPathIntegral(model, f);
}

//------------------------------------------------------------------------------
bool vtkTransparentSphereMapper::GetEmissionAbsorptionGlyphs()
{
  return true;
}

//------------------------------------------------------------------------------
int vtkTransparentSphereMapper::GetEmissionDensityModel()
{
  return this->DensityModel;
}

//------------------------------------------------------------------------------
double vtkTransparentSphereMapper::GetEmissionHollowFraction()
{
  return this->HollowFraction;
}

//------------------------------------------------------------------------------
vtkDoubleArray* vtkTransparentSphereMapper::GetEmissionOpacities()
{
  return this->GetParticleOpacities();
}

//------------------------------------------------------------------------------
vtkDoubleArray* vtkTransparentSphereMapper::GetParticleOpacities()
{
  this->PrepareOpacities();
  return this->Internals->Opacities;
}

//------------------------------------------------------------------------------
vtkParticleFrontToBackTarget* vtkTransparentSphereMapper::GetFrontToBackTarget()
{
  return this->Internals->Target;
}

//------------------------------------------------------------------------------
vtkParticleDepthSort* vtkTransparentSphereMapper::GetDepthSort()
{
  return this->Internals->Sort;
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::PrepareOpacities()
{
  vtkInternals& internals = *this->Internals;
  vtkPolyData* input = this->GetInput();
  const vtkMTimeType geometryTime = this->GetParticleGeometryTime(); // prepares the particles
  vtkFloatArray* radii = this->GetParticleRadii();
  const vtkIdType numPts = radii->GetNumberOfTuples();

  const std::string name = this->OpacityArrayName ? this->OpacityArrayName : "";
  vtkAbstractArray* abstractArray = (input && !name.empty() && numPts > 0)
    ? input->GetPointData()->GetAbstractArray(name.c_str())
    : nullptr;
  const vtkMTimeType arrayTime = abstractArray ? abstractArray->GetMTime() : 0;
  if (internals.OpacitiesValid && internals.GeometryTime == geometryTime &&
    internals.OpacityArray == abstractArray && internals.OpacityArrayTime == arrayTime &&
    internals.OpacityArrayName == name && internals.OpacityRange[0] == this->OpacityRange[0] &&
    internals.OpacityRange[1] == this->OpacityRange[1] &&
    internals.Opacities->GetNumberOfTuples() == numPts)
  {
    return;
  }
  internals.GeometryTime = geometryTime;
  internals.OpacityArray = abstractArray;
  internals.OpacityArrayTime = arrayTime;
  internals.OpacityArrayName = name;
  internals.OpacityRange[0] = this->OpacityRange[0];
  internals.OpacityRange[1] = this->OpacityRange[1];
  internals.OpacitiesValid = true;

  std::ostringstream warnings;
  vtkDataArray* array = numPts > 0 ? GetScalarPointArray(input, name.c_str(), "Opacity",
                                       "every particle has maximum opacity 1 (times the actor's "
                                       "opacity)",
                                       warnings)
                                   : nullptr;

  internals.Opacities->SetNumberOfTuples(numPts);
  internals.OpticalDepths->SetNumberOfTuples(numPts);
  double* theta = internals.Opacities->GetPointer(0);
  float* kappa = internals.OpticalDepths->GetPointer(0);
  const float* r = radii->GetPointer(0);
  const double lo = this->OpacityRange[0];
  const double hi = this->OpacityRange[1];

  vtkSMPThreadLocal<OpacitySummary> local;
  vtkSMPTools::For(0, numPts,
    [&](vtkIdType begin, vtkIdType end)
    {
      OpacitySummary& s = local.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        double t = 1.0;
        if (array)
        {
          const double v = array->GetComponent(i, 0);
          if (std::isnan(v))
          {
            ++s.NaNs;
            t = 0.0;
          }
          else if (hi == lo)
          {
            t = v < lo ? 0.0 : 1.0;
          }
          else
          {
            t = std::min(1.0, std::max(0.0, (v - lo) / (hi - lo)));
          }
        }
        theta[i] = t;
        // the optical depth in double: Theta = 1 - 1e-7 is not representable as a float
        kappa[i] = t >= 1.0 ? -1.0f : (t <= 0.0 ? 0.0f : static_cast<float>(-std::log1p(-t)));
        if (r[i] > 0.0f)
        {
          s.AnyOpaque |= t >= 1.0;
          s.AnyTranslucent |= (t > 0.0 && t < 1.0);
        }
      }
    });
  OpacitySummary total;
  for (const OpacitySummary& s : local)
  {
    total.AnyOpaque |= s.AnyOpaque;
    total.AnyTranslucent |= s.AnyTranslucent;
    total.NaNs += s.NaNs;
  }
  internals.AnyOpaque = total.AnyOpaque;
  internals.AnyTranslucent = total.AnyTranslucent;
  internals.Opacities->Modified();
  internals.OpticalDepths->Modified();
  ++this->NumberOfOpacityUploads;
  if (total.NaNs > 0)
  {
    warnings << total.NaNs << " of " << numPts << " values of opacity array '" << name
             << "' are NaN: those particles are fully transparent. ";
  }
  this->WarnOnChange(warnings.str(), internals.LastWarning);
}

//------------------------------------------------------------------------------
bool vtkTransparentSphereMapper::HasOpaqueGeometry()
{
  if (!this->GetInput() || this->GetInput()->GetNumberOfPoints() == 0)
  {
    return true;
  }
  this->PrepareOpacities();
  return this->Internals->AnyOpaque;
}

//------------------------------------------------------------------------------
bool vtkTransparentSphereMapper::HasTranslucentPolygonalGeometry()
{
  if (!this->GetInput() || this->GetInput()->GetNumberOfPoints() == 0)
  {
    return false;
  }
  this->PrepareOpacities();
  // Theta_a < 1, or scalar colours with alpha < 1 (a lookup table with opacity mapping)
  return this->Internals->AnyTranslucent ||
    (this->Internals->AnyOpaque && this->Superclass::HasTranslucentPolygonalGeometry());
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::CacheParticleAttributes(vtkRenderer* ren, vtkActor*)
{
  this->PrepareOpacities();
  this->VBOs->CacheDataArray(
    "opticalDepthMC", this->StrideForUpload(this->Internals->OpticalDepths), ren, VTK_FLOAT);
}

//------------------------------------------------------------------------------
bool vtkTransparentSphereMapper::GetOcclusionCullingCompiled(vtkRenderer* ren)
{
  return this->Internals->Building == Variant::Opaque &&
    this->Superclass::GetOcclusionCullingCompiled(ren);
}

//------------------------------------------------------------------------------
bool vtkTransparentSphereMapper::GetClipBoxBySegment()
{
  return this->Internals->Building != Variant::Opaque;
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::BuildBufferObjects(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::BuildBufferObjects(ren, act);
  // the translucent variant's helper draws the same particles
  this->Internals->Translucent.IBO->IndexCount = this->Primitives[PrimitiveTris].IBO->IndexCount;
  this->Internals->TranslucentList.IBO->IndexCount =
    this->Primitives[PrimitiveTris].IBO->IndexCount;
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
  const bool translucent = this->Internals->Building != Variant::Opaque;
  const bool lists = this->Internals->Building == Variant::TranslucentList;

  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string gs = shaders[vtkShader::Geometry]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  vtkParticleShaderHooks& hooks = this->Internals->Hooks;
  hooks.Begin(vs, gs, fs);
  using Hooks = vtkParticleShaderHooks;

  // the particle's optical depth kappa_a (< 0: Theta_a = 1), per sphere
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Dec", "in float opticalDepthMC;");
  hooks.AddSphereVarying("float", "opticalDepth");
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Impl", "opticalDepthVSOutput = opticalDepthMC;");
  // Theta_a = 0 is never drawn; the opaque stage draws only Theta_a = 1, the translucent stage
  // skips Theta_a = 1 when those are drawn opaque (see prCullMode)
  hooks.Insert(Hooks::Geometry, "//PR::Sphere::Dec", "uniform int prCullMode;");
  hooks.Insert(Hooks::Geometry, "//PR::Sphere::Cull",
    "float kappaA = opticalDepthVSOutput[0];\n"
    "  if (kappaA == 0.0 || (prCullMode == 0 && (kappaA < 0.0) != " +
      std::string(translucent ? "false" : "true") +
      "))\n"
      "  {\n"
      "    return;\n"
      "  }");

  if (!translucent)
  {
    hooks.Insert(Hooks::Fragment, "//PR::Sphere::Dec", "uniform int prCullMode;");
    // the opaque stage keeps Theta_i = Theta_a * opacity = 1 only; picking keeps all
    hooks.Insert(Hooks::Fragment, "//PR::Shading::Impl",
      "if (prCullMode == 0 && !(opticalDepthVSOutput < 0.0 && opacity >= 1.0))\n"
      "    {\n"
      "      discard;\n"
      "    }");
  }
  else
  {
    // no depth writes: the early-termination mask is tested before shading
    std::ostringstream dec;
    dec << "#define PR_NO_DEPTH_WRITE\n"
           "uniform float prVolumeMix;\n"
           "uniform vec2 prActorOpacity;\n"
           "uniform int prCullMode;\n"
           "uniform float prMaximumIntegral;\n"
           "uniform float prHollowFraction2;\n"
           "uniform sampler2D prOpaqueDepth;\n"
           "#define PR_DENSITY_MODEL "
        << this->DensityModel << "\n//PR::Include TransparentSphereShading";
    if (lists)
    {
      dec << "\n" << vtkParticleFragmentLists::GetAppendDeclarations();
    }
    hooks.Insert(Hooks::Fragment, "//PR::Sphere::Dec", dec.str());
    if (lists)
    {
      // the segment goes to the pixel's list; colour writes are off while the lists are built
      vtkParticleShaders::ReplaceHook(fs, "//VTK::System::Dec",
        "//VTK::System::Dec\n" + vtkParticleFragmentLists::GetAppendExtension());
      hooks.Insert(Hooks::Fragment, "//PR::Shading::Impl",
        "prSegment prSeg;\n"
        "    if (!prTranslucentSegment(opticalDepthVSOutput, opacity, prSurfaceColor,\n"
        "          diffuseColor, prAmbientOcclusion, prAmbientLight, prRayS, prRayD, prT0, prT1,\n"
        "          radiusVC, centerOffsetVCVSOutput, prSeg) || any(isnan(prSeg.radiance)) ||\n"
        "        any(isinf(prSeg.radiance)))\n"
        "    {\n"
        "      discard;\n"
        "    }\n"
        "    prAppendSegment(prSeg, prRayD, centerOffsetVCVSOutput, prMaximumIntegral);\n"
        "    gl_FragData[0] = vec4(0.0, 0.0, 0.0, 1.0);");
    }
    else
    {
      hooks.Insert(Hooks::Fragment, "//PR::Shading::Impl",
        "if (!prShadeTranslucentSphere(opticalDepthVSOutput, opacity, prSurfaceColor,\n"
        "          diffuseColor, prAmbientOcclusion, prAmbientLight, prRayS, prRayD, prT0, prT1,\n"
        "          radiusVC, centerOffsetVCVSOutput, gl_FragData[0]))\n"
        "    {\n"
        "      discard;\n"
        "    }");
    }
    fs = vtkParticleShaders::ResolveIncludes(fs);
  }
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Geometry]->SetSource(gs);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

//------------------------------------------------------------------------------
double vtkTransparentSphereMapper::GetEffectiveColumnLayers()
{
  if (this->OpacityReference != COLUMN_OPACITY)
  {
    return 1.0;
  }
  if (this->ColumnLayers > 0.0)
  {
    return std::max(1.0, this->ColumnLayers);
  }
  // cached until the particles or the settings change
  vtkPolyData* input = this->GetInput();
  const vtkMTimeType key = std::max(this->GetMTime(), input ? input->GetMTime() : 0);
  if (key == this->EstimatedColumnLayersTime)
  {
    return this->EstimatedColumnLayers;
  }
  this->EstimatedColumnLayersTime = key;
  this->EstimatedColumnLayers = 1.0;
  // the expected number of full chords a ray crosses along the longest side of the particles'
  // box: (N / A) pi r^2 (2/3), A the area of the box face across that side, r the mean radius,
  // 2/3 the mean chord of a sphere over its diameter (uniform impact parameters)
  const double* b = this->GetBounds(); // spheres, radii included
  vtkFloatArray* radii = this->GetParticleRadii();
  if (!b || !(b[0] <= b[1]) || !radii || radii->GetNumberOfTuples() == 0)
  {
    return this->EstimatedColumnLayers;
  }
  double sum = 0.0;
  vtkIdType count = 0;
  for (vtkIdType i = 0; i < radii->GetNumberOfTuples(); ++i)
  {
    const double r = radii->GetValue(i);
    if (r > 0.0 && std::isfinite(r))
    {
      sum += r;
      ++count;
    }
  }
  if (vtkFloatArray* axes = this->GetParticleAxes())
  {
    // Ellipsoids: in any direction the chords through a particle integrate to its volume
    // 4/3 pi a b c; over its longest chord 2 a_max that is (2/3) pi (a b c / a_max) full chords,
    // a sphere's (2/3) pi r^2: each counts with the radius sqrt(a b c / a_max)
    sum = 0.0;
    for (vtkIdType i = 0; i < axes->GetNumberOfTuples(); ++i)
    {
      const float* a = axes->GetPointer(3 * i);
      const double largest = std::max({ a[0], a[1], a[2] });
      if (largest > 0.0 && radii->GetValue(i) > 0.0)
      {
        sum += std::sqrt(static_cast<double>(a[0]) * a[1] * a[2] / largest);
      }
    }
  }
  this->EstimatedColumnLayers = EstimateColumnLayers(static_cast<double>(count), sum, b);
  return this->EstimatedColumnLayers;
}

//------------------------------------------------------------------------------
double vtkTransparentSphereMapper::EstimateColumnLayers(
  double count, double radiusSum, const double bounds[6])
{
  if (!bounds || !(bounds[0] <= bounds[1]) || !(count > 0.0))
  {
    return 1.0;
  }
  double sides[3] = { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] };
  std::sort(sides, sides + 3);
  const double face = sides[0] * sides[1];
  if (!(face > 0.0))
  {
    return 1.0;
  }
  const double r = radiusSum / count;
  const double layers = count / face * vtkMath::Pi() * r * r * (2.0 / 3.0);
  return std::isfinite(layers) ? std::max(1.0, layers) : 1.0;
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  vtkInternals& internals = *this->Internals;
  program->SetUniformi("prCullMode", internals.CullMode);
  if (&cellBO == &internals.Translucent || &cellBO == &internals.TranslucentList)
  {
    program->SetUniformf("prVolumeMix", static_cast<float>(this->VolumeMix));
    // Opacity and 1 - Opacity from double (Opacity = 1 - 1e-7 or 1e-6 does not survive 1 - x in
    // float); (-1, -1) when scalar colours carry alpha and the shader uses VTK's opacity
    const double opacity = std::min(1.0, std::max(0.0, act->GetProperty()->GetOpacity()));
    const bool scalarAlpha = internals.ScalarAlpha;
    const float actorOpacity[2] = { scalarAlpha ? -1.0f : static_cast<float>(opacity),
      scalarAlpha ? -1.0f : static_cast<float>(1.0 - opacity) };
    program->SetUniform2f("prActorOpacity", actorOpacity);
    program->SetUniformf(
      "prHollowFraction2", static_cast<float>(this->HollowFraction * this->HollowFraction));
    // COLUMN_OPACITY: kappa / L, i.e. L times the maximum integral (Theta = 1 - exp(-kappa I /
    // I_max) in the shader)
    program->SetUniformf("prMaximumIntegral",
      static_cast<float>(GetMaximumPathIntegral(this->DensityModel, this->HollowFraction) *
        this->GetEffectiveColumnLayers()));
    program->SetUniformi(
      "prOpaqueDepth", internals.Target->GetOpaqueDepthTexture()->GetTextureUnit());
    // (the list variant's storage is bound per band by RenderTranslucentLists' draw)
  }
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& internals = *this->Internals;
  const vtkIdType numPts = static_cast<vtkIdType>(this->Primitives[PrimitiveTris].IBO->IndexCount);
  if (numPts <= 0)
  {
    return;
  }
  if (ren->GetSelector() || !act->IsRenderingTranslucentPolygonalGeometry())
  {
    internals.Building = Variant::Opaque;
    internals.CullMode = ren->GetSelector() ? CullAllVisible : CullOpaqueStage;
    this->Superclass::RenderPieceDraw(ren, act);
    return;
  }

  // The translucent stage. Which pass (if any) composites translucency?
  RenderPassList passes(act);
  vtkDualDepthPeelingPass* peeling = passes.Peeling;
  const bool singlePeeling = passes.SinglePeeling;

  // OpenGL 4.3 for the sort
  vtkOpenGLRenderWindow* ctx = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (internals.SupportContext != ctx)
  {
    std::string why;
    internals.Support = vtkParticleComputeProgram::IsSupported(ctx, &why) ? 1 : 0;
    internals.SupportContext = ctx;
    if (!internals.Support && !internals.SupportWarned)
    {
      vtkErrorMacro(<< why
                    << " Translucent particles are drawn as opaque spheres composited by "
                       "VTK's translucency pass, without the emission-absorption model.");
      internals.SupportWarned = true;
    }
  }
  if (!internals.Support || singlePeeling)
  {
    if (singlePeeling && !internals.SinglePeelingWarned)
    {
      vtkWarningMacro(<< "Single-layer depth peeling (no dual depth peeling on this context): "
                         "translucent particles are drawn as opaque spheres in every peel.");
      internals.SinglePeelingWarned = true;
    }
    internals.Building = Variant::Opaque;
    internals.CullMode = CullAllVisible;
    this->Superclass::RenderPieceDraw(ren, act);
    return;
  }

  if (peeling)
  {
    // Dual depth peeling renders the translucent props once to initialise its depths (two draw
    // buffers) and then once per peel: composite the particles once, in that first render.
    if (peeling->GetActiveDrawBuffers() != 2 ||
      peeling->GetShaderStageMTime() == internals.LastPeelingStageTime)
    {
      return;
    }
    internals.LastPeelingStageTime = peeling->GetShaderStageMTime();
  }

  // Our own drawing must not get the translucency passes' shader replacements (put back when
  // `passes` goes).
  passes.HideTranslucencyPasses();
  this->RenderTranslucentParticles(ren, act, peeling != nullptr || passes.OrderIndependent);
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::RenderTranslucentParticles(
  vtkRenderer* ren, vtkActor* act, bool savedByPass)
{
  vtkParticleFrameBudget* budget = this->GetFrameBudget();
  const int level = budget->BeginFrame(ren, NumberOfQualityLevels);
  this->Internals->Target->SetDownsampling(level == 0 ? InteractiveDownsampling : 1);
  this->RenderTranslucentLevel(ren, act, savedByPass, level == NumberOfQualityLevels - 1);
  this->Internals->Target->SetDownsampling(1);
  budget->EndFrame();
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::RenderTranslucentLevel(
  vtkRenderer* ren, vtkActor* act, bool savedByPass, bool exact)
{
  vtkInternals& internals = *this->Internals;
  const vtkIdType numPts = static_cast<vtkIdType>(this->Primitives[PrimitiveTris].IBO->IndexCount);
  if (this->CollectTimings)
  {
    internals.TotalTimer.Reset();
    internals.TotalTimer.Start();
  }
  internals.SortTimed = false;
  internals.ExactOverlapInUse = exact &&
    (this->OverlapCompositing == EXACT_OVERLAP ||
      (this->OverlapCompositing == AUTOMATIC &&
        (this->GetDrawsEllipsoids() || this->AutomaticNeedsExactOverlap(ren, act))));
  if (internals.ExactOverlapInUse)
  {
    if (this->RenderTranslucentLists(ren, act, savedByPass))
    {
      return;
    }
    // the lists could not be made (budget below the view's per-pixel arrays, no memory, no
    // program; said by vtkParticleFragmentLists): the sorted spheres, a sane picture
    internals.ExactOverlapInUse = false;
  }
  // Without a sort (too many particles for the GPU's buffers, compute shaders failing) the
  // particles are still composited, in index order: a sane picture, with one warning.
  const bool sorted = this->UpdateSortedOrder(ren, act, numPts);
  if (!sorted && !internals.UnsortedWarned)
  {
    vtkWarningMacro(<< "The " << numPts
                    << " particles could not be depth-sorted on this GPU (see the previous error): "
                       "translucent particles are composited in input order, which is wrong "
                       "where they overlap.");
    internals.UnsortedWarned = true;
  }
  if (!internals.Target->Begin(ren, savedByPass))
  {
    return;
  }
  vtkTextureObject* opaqueDepth = internals.Target->GetOpaqueDepthTexture();
  opaqueDepth->Activate();

  vtkOpenGLHelper& cellBO = internals.Translucent;
  this->ReadyTranslucentVariant(ren, act, false);
  if (cellBO.Program)
  {
    if (sorted)
    {
      internals.Sort->GetIndexBuffer()->Bind(); // the element array of the bound VAO
      glMemoryBarrier(GL_ELEMENT_ARRAY_BARRIER_BIT);
    }
    if (this->CollectTimings)
    {
      internals.DrawTimer.Reset();
      internals.DrawTimer.Start();
    }
    // early termination: as set at the exact level; on at the full-resolution interactive
    // level; off at half resolution (a quarter of the fragments leaves too little for the mask
    // passes to save; the interactive picture's error against the still one was the same with
    // and without on the bundled scenes)
    const bool terminate =
      exact ? this->EarlyTermination : internals.Target->GetDownsampling() == 1;
    const int chunks =
      terminate ? static_cast<int>(std::min<vtkIdType>(this->NumberOfChunks, numPts)) : 1;
    vtkOpenGLRenderWindow* ctx = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
    for (int c = 0; c < chunks; ++c)
    {
      const vtkIdType first = numPts * c / chunks;
      const vtkIdType last = numPts * (c + 1) / chunks;
      if (sorted)
      {
        glDrawElements(GL_POINTS, static_cast<GLsizei>(last - first), GL_UNSIGNED_INT,
          reinterpret_cast<const void*>(static_cast<size_t>(first) * sizeof(GLuint)));
      }
      else
      {
        glDrawArrays(GL_POINTS, static_cast<GLint>(first), static_cast<GLsizei>(last - first));
      }
      if (c + 1 < chunks)
      {
        internals.Target->MaskSaturatedPixels(this->TerminationOpacity);
        ctx->GetShaderCache()->ReadyShaderProgram(cellBO.Program);
        cellBO.VAO->Bind();
      }
    }
    if (this->CollectTimings)
    {
      internals.DrawTimer.Stop();
    }
    internals.Sort->GetIndexBuffer()->Release();
  }
  internals.Building = Variant::Opaque;
  opaqueDepth->Deactivate();
  internals.Target->End();
  if (this->CollectTimings)
  {
    internals.TotalTimer.Stop();
    // the results are read when asked for (GetLast...GPUSeconds): reading them here would
    // return 0 while the GPU is still working
    internals.TimingsPending = true;
  }
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::ReadyTranslucentVariant(
  vtkRenderer* ren, vtkActor* act, bool lists)
{
  vtkInternals& internals = *this->Internals;
  internals.Building = lists ? Variant::TranslucentList : Variant::Translucent;
  // Theta_a = 1 particles are drawn opaque unless the actor or its colours lower the opacity
  // (scalar colours with alpha < 1: asked once per frame, used here and by the shader uniforms)
  internals.ScalarAlpha = this->Superclass::HasTranslucentPolygonalGeometry();
  const bool opaqueDrawnSeparately =
    act->GetProperty()->GetOpacity() >= 1.0 && !internals.ScalarAlpha;
  internals.CullMode = opaqueDrawnSeparately ? CullTranslucentOnly : CullAllVisible;
  this->UpdateShaders(lists ? internals.TranslucentList : internals.Translucent, ren, act);
}

//------------------------------------------------------------------------------
bool vtkTransparentSphereMapper::HasOverlappingSpheres()
{
  vtkInternals& internals = *this->Internals;
  vtkPolyData* input = this->GetInput();
  vtkFloatArray* radii = this->GetParticleRadii();
  vtkFloatArray* kappas = internals.OpticalDepths;
  const std::vector<vtkMTimeType> key = { this->GetParticleGeometryTime(), kappas->GetMTime() };
  if (key == internals.OverlapKey && this->RadiusScaleFactor == internals.OverlapScale &&
    this->OverlapTolerance == internals.OverlapTolerance)
  {
    return internals.Overlapping;
  }
  internals.OverlapKey = key;
  internals.OverlapScale = this->RadiusScaleFactor;
  internals.OverlapTolerance = this->OverlapTolerance;
  internals.Overlapping = false;
  vtkPoints* points = input ? input->GetPoints() : nullptr;
  const vtkIdType numPts = points ? points->GetNumberOfPoints() : 0;
  if (numPts < 2 || !radii || radii->GetNumberOfTuples() != numPts ||
    kappas->GetNumberOfTuples() != numPts)
  {
    return false;
  }
  // the drawn spheres (radius > 0, Theta_a > 0)
  std::vector<double> xyz;
  std::vector<double> drawnRadii;
  xyz.reserve(3 * static_cast<size_t>(numPts));
  drawnRadii.reserve(static_cast<size_t>(numPts));
  double largest = 0.0;
  for (vtkIdType i = 0; i < numPts; ++i)
  {
    const double r = radii->GetValue(i);
    double p[3];
    points->GetPoint(i, p);
    if (r > 0.0 && std::isfinite(r) && kappas->GetValue(i) != 0.0 && std::isfinite(p[0]) &&
      std::isfinite(p[1]) && std::isfinite(p[2]))
    {
      xyz.insert(xyz.end(), p, p + 3);
      drawnRadii.push_back(r);
      largest = std::max(largest, r);
    }
  }
  const vtkIdType count = static_cast<vtkIdType>(drawnRadii.size());
  if (count < 2)
  {
    return false;
  }
  // i and j penetrate by more than the tolerance t when |p_i - p_j| < s (r_i + r_j - t min(r_i,
  // r_j)) <= 2 s max(r_i, r_j): cells of edge 2 s max(r) hold every such pair among the 27
  // around each particle (vtkParticleCellList: a particle far away costs one cell). Touching
  // spheres (to rounding) do not overlap.
  const double s = this->RadiusScaleFactor;
  const double tolerance = this->OverlapTolerance;
  const std::vector<float> binned(static_cast<size_t>(count), 1.0f); // every one of them
  const double edge = 2.0 * std::abs(s) * largest;
  if (!(edge > 0.0) || !std::isfinite(edge))
  {
    internals.Overlapping = false;
    return false;
  }
  vtkParticleCellList cells;
  cells.Build(xyz.data(), count, binned.data(), edge);
  std::atomic<bool> found(false);
  vtkSMPTools::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end && !found.load(std::memory_order_relaxed); ++i)
      {
        const double ri = drawnRadii[i];
        cells.ForEachCandidate(i,
          [&](vtkIdType j, double d2)
          {
            const double rj = drawnRadii[j];
            const double reach = s * (ri + rj - tolerance * std::min(ri, rj)) * (1.0 - 1e-6);
            if (d2 < reach * reach)
            {
              found = true;
            }
          });
      }
    });
  internals.Overlapping = found.load();
  return internals.Overlapping;
}

//------------------------------------------------------------------------------
bool vtkTransparentSphereMapper::AutomaticNeedsExactOverlap(vtkRenderer* ren, vtkActor* act)
{
  vtkInternals& internals = *this->Internals;
  internals.OverlapErrorPixels = 0.0;
  if (!this->HasOverlappingSpheres())
  {
    return false; // (the cheap geometric test first: no pair deeper than the floor)
  }
  vtkProperty* property = act->GetProperty();
  vtkUnsignedCharArray* colors = this->Colors;
  vtkPolyData* input = this->GetInput();
  vtkPoints* points = input ? input->GetPoints() : nullptr;
  vtkFloatArray* radii = this->GetParticleRadii();
  vtkDoubleArray* opacities = internals.Opacities;
  const vtkIdType numPts = points ? points->GetNumberOfPoints() : 0;
  if (!radii || radii->GetNumberOfTuples() != numPts || opacities->GetNumberOfTuples() != numPts)
  {
    return true; // (cannot estimate: the exact path)
  }
  const double shading = (1.0 - this->VolumeMix) * 255.0 *
    (property->GetDiffuse() *
        std::max({ property->GetColor()[0], property->GetColor()[1], property->GetColor()[2] }) +
      property->GetSpecular());
  const std::vector<double> key = { static_cast<double>(this->GetParticleGeometryTime()),
    static_cast<double>(opacities->GetMTime()),
    static_cast<double>(colors ? colors->GetMTime() : 0), this->RadiusScaleFactor,
    this->OverlapTolerance, this->AutomaticErrorTolerance, shading, property->GetOpacity(),
    static_cast<double>(this->DensityModel), this->HollowFraction };
  if (key != internals.OverlapErrorKey)
  {
    internals.OverlapErrorKey = key;
    const double* actorColour = property->GetColor();
    std::vector<vtkParticleOverlapError::Sphere> spheres;
    spheres.reserve(static_cast<size_t>(numPts));
    for (vtkIdType i = 0; i < numPts; ++i)
    {
      vtkParticleOverlapError::Sphere sphere;
      points->GetPoint(i, sphere.Centre);
      sphere.Radius = this->RadiusScaleFactor * radii->GetValue(i);
      double alpha = property->GetOpacity() * opacities->GetValue(i);
      for (int k = 0; k < 3; ++k)
      {
        sphere.Colour[k] = colors && colors->GetNumberOfComponents() >= 3
          ? colors->GetTypedComponent(i, k)
          : 255.0 * actorColour[k];
      }
      if (colors && colors->GetNumberOfComponents() == 4)
      {
        alpha *= colors->GetTypedComponent(i, 3) / 255.0;
      }
      sphere.OpticalDepth = alpha < 1.0 ? -std::log1p(-alpha) : 0.0; // opaque: depth-tested
      if (sphere.Radius > 0.0 && std::isfinite(sphere.Radius) && sphere.OpticalDepth > 0.0 &&
        std::isfinite(sphere.Centre[0]) && std::isfinite(sphere.Centre[1]) &&
        std::isfinite(sphere.Centre[2]))
      {
        spheres.push_back(sphere);
      }
    }
    internals.OverlapError.Build(spheres,
      GetMaximumPathIntegral(this->DensityModel, this->HollowFraction), shading,
      this->AutomaticErrorTolerance, this->OverlapTolerance);
  }
  int width = 0;
  int height = 0;
  ren->GetTiledSize(&width, &height);
  internals.OverlapErrorPixels = internals.OverlapError.EstimatePixels(ren);
  return internals.OverlapErrorPixels >
    this->AutomaticPixelShare * static_cast<double>(width) * static_cast<double>(height);
}

//------------------------------------------------------------------------------
std::string vtkTransparentSphereMapper::GetQualityLevelNames()
{
  return "half resolution, sorted spheres|sorted spheres, early termination|exact";
}

//------------------------------------------------------------------------------
double vtkTransparentSphereMapper::GetEstimatedOverlapErrorPixels()
{
  return this->Internals->OverlapErrorPixels;
}

//------------------------------------------------------------------------------
double vtkTransparentSphereMapper::GetLargestOverlapErrorBound()
{
  return this->Internals->OverlapError.GetLargestAmplitude();
}

//------------------------------------------------------------------------------
bool vtkTransparentSphereMapper::GetExactOverlapInUse()
{
  return this->Internals->ExactOverlapInUse;
}

//------------------------------------------------------------------------------
vtkParticleFragmentLists* vtkTransparentSphereMapper::GetFragmentLists()
{
  return this->Internals->Lists;
}

//------------------------------------------------------------------------------
bool vtkTransparentSphereMapper::RenderTranslucentLists(
  vtkRenderer* ren, vtkActor* act, bool savedByPass)
{
  vtkInternals& internals = *this->Internals;
  const vtkIdType numPts = static_cast<vtkIdType>(this->Primitives[PrimitiveTris].IBO->IndexCount);
  if (!internals.Target->Begin(ren, savedByPass))
  {
    return true; // said by the target; nothing to fall back to
  }
  vtkTextureObject* opaqueDepth = internals.Target->GetOpaqueDepthTexture();
  opaqueDepth->Activate();
  vtkParticleFragmentLists* lists = internals.Lists;
  bool drawn = true;
  lists->SetMemoryBudget(this->FragmentListMemory);
  lists->SetDensityModel(this->DensityModel);
  lists->SetHollowFraction2(this->HollowFraction * this->HollowFraction);

  vtkOpenGLHelper& cellBO = internals.TranslucentList;
  this->ReadyTranslucentVariant(ren, act, true);
  if (cellBO.Program)
  {
    if (this->CollectTimings)
    {
      internals.DrawTimer.Reset();
      internals.DrawTimer.Start();
    }
    vtkOpenGLRenderWindow* ctx = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
    vtkOpenGLState* ostate = ctx->GetState();
    drawn = lists->Render(ctx, internals.Target->GetAccumulationTexture(),
      [&]()
      {
        ctx->GetShaderCache()->ReadyShaderProgram(cellBO.Program);
        cellBO.VAO->Bind();
        lists->PrepareProgram(cellBO.Program);
        vtkOpenGLState::ScopedglColorMask colorMask(ostate);
        ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(numPts));
      });
    if (this->CollectTimings)
    {
      internals.DrawTimer.Stop();
    }
  }
  internals.Building = Variant::Opaque;
  opaqueDepth->Deactivate();
  internals.Target->End(); // an empty accumulation when nothing was drawn: the image unchanged
  if (drawn && this->CollectTimings)
  {
    internals.TotalTimer.Stop();
    internals.TimingsPending = true;
  }
  return drawn;
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::FetchTimings()
{
  vtkInternals& internals = *this->Internals;
  if (!internals.TimingsPending)
  {
    return;
  }
  internals.TimingsPending = false;
  auto seconds = [](vtkOpenGLRenderTimer& timer) -> double
  {
    if (!timer.Stopped())
    {
      return 0.0;
    }
    while (!timer.Ready())
    {
      // the timer queries complete with the frame; wait for them (benchmarks only)
    }
    return timer.GetElapsedSeconds();
  };
  const double total = seconds(internals.TotalTimer);
  this->LastSortGPUSeconds = internals.SortTimed ? seconds(internals.SortTimer) : 0.0;
  this->LastTranslucentDrawGPUSeconds = seconds(internals.DrawTimer);
  this->LastCompositeGPUSeconds =
    std::max(0.0, total - this->LastSortGPUSeconds - this->LastTranslucentDrawGPUSeconds);
}

//------------------------------------------------------------------------------
double vtkTransparentSphereMapper::GetLastSortGPUSeconds()
{
  this->FetchTimings();
  return this->LastSortGPUSeconds;
}

//------------------------------------------------------------------------------
double vtkTransparentSphereMapper::GetLastTranslucentDrawGPUSeconds()
{
  this->FetchTimings();
  return this->LastTranslucentDrawGPUSeconds;
}

//------------------------------------------------------------------------------
double vtkTransparentSphereMapper::GetLastCompositeGPUSeconds()
{
  this->FetchTimings();
  return this->LastCompositeGPUSeconds;
}

//------------------------------------------------------------------------------
bool vtkTransparentSphereMapper::UpdateSortedOrder(vtkRenderer* ren, vtkActor* act, vtkIdType count)
{
  vtkInternals& internals = *this->Internals;
  vtkCamera* cam = ren->GetActiveCamera();

  // MC -> VC as the shaders use it: view * actor * VBO shift/scale, in double
  vtkNew<vtkMatrix4x4> mcvc;
  this->GetBufferToViewMatrix(ren, act, mcvc);
  const double radiusScale = this->GetRadiusScaleVC(act);
  const int parallel = cam->GetParallelProjection() ? 1 : 0;

  std::vector<double> state(mcvc->GetData(), mcvc->GetData() + 16);
  state.push_back(parallel);
  state.push_back(radiusScale);
  state.push_back(static_cast<double>(this->GetParticleGeometryTime()));
  state.push_back(static_cast<double>(count));
  if (state == internals.SortState)
  {
    return true; // neither the camera nor the particles moved
  }

  vtkOpenGLRenderWindow* ctx = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  if (count == internals.FailedSortCount)
  {
    return false; // said once already
  }
  if (!internals.Sort->Reserve(ctx, count))
  {
    internals.SortState.clear();
    internals.FailedSortCount = count;
    return false;
  }
  vtkParticleComputeProgram* keys = internals.KeyProgram;
  if (!keys->IsBuilt())
  {
    keys->SetSource(vtkParticleShaders::Get("ParticleDepthKeys"));
  }
  if (!keys->Build(ctx))
  {
    internals.SortState.clear();
    return false;
  }
  vtkOpenGLVertexBufferObject* positions = this->VBOs->GetVBO("vertexMC");
  vtkOpenGLVertexBufferObject* radii = this->VBOs->GetVBO("radiusMC");
  if (!positions || !radii)
  {
    return false;
  }
  if (this->CollectTimings)
  {
    internals.SortTimer.Reset();
    internals.SortTimer.Start();
    internals.SortTimed = true;
  }
  keys->Use();
  float linear[16]; // column-major, linear part only
  for (int col = 0; col < 4; ++col)
  {
    for (int row = 0; row < 4; ++row)
    {
      linear[col * 4 + row] =
        (row < 3 && col < 3) ? static_cast<float>(mcvc->GetElement(row, col)) : 0.0f;
    }
  }
  keys->SetUniformMatrix4x4("matrixMCVC", linear);
  keys->SetUniform3f("translationVC", static_cast<float>(mcvc->GetElement(0, 3)),
    static_cast<float>(mcvc->GetElement(1, 3)), static_cast<float>(mcvc->GetElement(2, 3)));
  keys->SetUniformf("radiusScale", static_cast<float>(radiusScale));
  keys->SetUniformi("parallelProjection", parallel);
  keys->SetUniformui("count", static_cast<unsigned int>(count));
  keys->SetUniformui("positionStride", positions->GetStride() / sizeof(float));
  vtkParticleComputeProgram::BindStorage(0, positions);
  vtkParticleComputeProgram::BindStorage(1, radii);
  vtkParticleComputeProgram::BindStorage(2, internals.Sort->GetKeyBuffer());
  keys->Dispatch(static_cast<unsigned int>((count + 255) / 256));
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  for (unsigned int binding = 0; binding < 3; ++binding)
  {
    vtkParticleComputeProgram::BindStorage(binding, nullptr);
  }
  vtkParticleComputeProgram::UseNone();
  // a long sort reports its radix passes as this mapper's progress (ParaView's progress bar)
  unsigned long progressTag = 0;
  if (count >= this->ProgressThreshold)
  {
    const std::string text = "Sorting " + std::to_string(count) + " translucent particles";
    this->SetProgressText(text.c_str());
    progressTag = internals.Sort->AddObserver(
      vtkCommand::ProgressEvent, this, &vtkTransparentSphereMapper::ForwardSortProgress);
  }
  const bool sorted = internals.Sort->Sort(count);
  if (progressTag)
  {
    internals.Sort->RemoveObserver(progressTag);
    this->SetProgressText(nullptr);
  }
  if (this->CollectTimings)
  {
    internals.SortTimer.Stop();
  }
  if (!sorted)
  {
    internals.SortState.clear();
    return false;
  }
  internals.SortState = state;
  ++this->NumberOfSorts;
  return true;
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::ForwardSortProgress(vtkObject*, unsigned long, void* callData)
{
  this->UpdateProgress(*static_cast<double*>(callData));
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& internals = *this->Internals;
  internals.KeyProgram->ReleaseGraphicsResources(window);
  internals.Sort->ReleaseGraphicsResources(window);
  internals.Target->ReleaseGraphicsResources(window);
  internals.Translucent.ReleaseGraphicsResources(window);
  internals.TranslucentList.ReleaseGraphicsResources(window);
  internals.Lists->ReleaseGraphicsResources(window);
  internals.TotalTimer.ReleaseGraphicsResources();
  internals.SortTimer.ReleaseGraphicsResources();
  internals.DrawTimer.ReleaseGraphicsResources();
  internals.SortState.clear();
  internals.SupportContext = nullptr;
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkTransparentSphereMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DensityModel: "
     << (this->DensityModel == CONSTANT_DENSITY ? "Constant" : "SquaredDistance") << "\n";
  os << indent << "HollowFraction: " << this->HollowFraction << "\n";
  os << indent << "VolumeMix: " << this->VolumeMix << "\n";
  os << indent << "OpacityReference: " << this->OpacityReference << "\n";
  os << indent << "ColumnLayers: " << this->ColumnLayers << "\n";
  os << indent
     << "OpacityArrayName: " << (this->OpacityArrayName ? this->OpacityArrayName : "(none)")
     << "\n";
  os << indent << "OpacityRange: " << this->OpacityRange[0] << " " << this->OpacityRange[1] << "\n";
  os << indent << "EarlyTermination: " << this->EarlyTermination << "\n";
  os << indent << "NumberOfChunks: " << this->NumberOfChunks << "\n";
  os << indent << "TerminationOpacity: " << this->TerminationOpacity << "\n";
  os << indent << "OverlapCompositing: " << this->OverlapCompositing << "\n";
  os << indent << "FragmentListMemory: " << this->FragmentListMemory << " MiB\n";
  os << indent << "OverlapTolerance: " << this->OverlapTolerance << "\n";
  os << indent << "AutomaticErrorTolerance: " << this->AutomaticErrorTolerance << "\n";
  os << indent << "AutomaticPixelShare: " << this->AutomaticPixelShare << "\n";
  os << indent << "NumberOfSorts: " << this->NumberOfSorts << "\n";
  os << indent << "NumberOfOpacityUploads: " << this->NumberOfOpacityUploads << "\n";
}
