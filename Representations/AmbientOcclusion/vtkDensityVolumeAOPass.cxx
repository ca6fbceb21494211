#include "vtkDensityVolumeAOPass.h"
#include "vtkMath.h"

#include "vtkActor.h"
#include "vtkCommand.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticleDensityVolume.h"
#include "vtkParticleShaderHooks.h"
#include "vtkParticleSphereMapper.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkDensityVolumeAOPass);

//------------------------------------------------------------------------------
class vtkDensityVolumeAOPass::vtkInternals
{
public:
  vtkSmartPointer<vtkParticleDensityVolume> Volume;
  unsigned long VolumeProgressTag = 0;

  // progress of the build under way (ProgressThreshold): its text
  std::string ProgressText;
  bool Reporting = false;
};

//------------------------------------------------------------------------------
// Reports the progress of one volume build when it is long enough, and ends the report (1.0,
// text cleared) on every way out of the build.
class vtkDensityVolumeAOPass::vtkProgressScope
{
public:
  vtkProgressScope(vtkDensityVolumeAOPass* self, vtkIdType particles)
    : Self(self)
  {
    vtkInternals& internals = *self->Internals;
    internals.Reporting = particles >= self->ProgressThreshold;
    if (internals.Reporting)
    {
      internals.ProgressText =
        "Ambient occlusion: density volume of " + std::to_string(particles) + " particles";
      self->ReportProgress(0.0);
    }
  }
  ~vtkProgressScope()
  {
    vtkInternals& internals = *this->Self->Internals;
    if (internals.Reporting)
    {
      this->Self->ReportProgress(1.0);
    }
    internals.Reporting = false;
    internals.ProgressText.clear();
  }
  vtkProgressScope(const vtkProgressScope&) = delete;
  void operator=(const vtkProgressScope&) = delete;

private:
  vtkDensityVolumeAOPass* Self;
};

//------------------------------------------------------------------------------
vtkDensityVolumeAOPass::vtkDensityVolumeAOPass()
  : Internals(new vtkInternals)
{
  this->SetDensityVolume(vtkSmartPointer<vtkParticleDensityVolume>::New());
}

//------------------------------------------------------------------------------
void vtkDensityVolumeAOPass::SetDensityVolume(vtkParticleDensityVolume* volume)
{
  vtkInternals& internals = *this->Internals;
  if (!volume || volume == internals.Volume)
  {
    return;
  }
  if (internals.Volume)
  {
    internals.Volume->RemoveObserver(internals.VolumeProgressTag);
  }
  internals.Volume = volume;
  internals.VolumeProgressTag = volume->AddObserver(
    vtkCommand::ProgressEvent, this, &vtkDensityVolumeAOPass::ForwardVolumeProgress);
  this->ForgetBuild(); // a new volume object: build it
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkDensityVolumeAOPass::GetProgressText()
{
  return this->Internals->ProgressText.c_str();
}

//------------------------------------------------------------------------------
void vtkDensityVolumeAOPass::ReportProgress(double fraction)
{
  if (this->Internals->Reporting)
  {
    this->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
  }
}

//------------------------------------------------------------------------------
void vtkDensityVolumeAOPass::ForwardVolumeProgress(vtkObject*, unsigned long, void* callData)
{
  this->ReportProgress(*static_cast<double*>(callData));
}

//------------------------------------------------------------------------------
vtkDensityVolumeAOPass::~vtkDensityVolumeAOPass()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
vtkParticleDensityVolume* vtkDensityVolumeAOPass::GetDensityVolume()
{
  return this->Internals->Volume;
}

//------------------------------------------------------------------------------
namespace
{
// linear interpolation; outside the volume there is nothing: density 0
void SetVolumeSampling(vtkTextureObject* texture)
{
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetWrapS(vtkTextureObject::ClampToBorder);
  texture->SetWrapT(vtkTextureObject::ClampToBorder);
  texture->SetWrapR(vtkTextureObject::ClampToBorder);
  texture->SetBorderColor(0.0f, 0.0f, 0.0f, 0.0f);
}
}

//------------------------------------------------------------------------------
void vtkDensityVolumeAOPass::UpdateVolume(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  // the particle props and what their volume depends on
  ParticleProps particles;
  std::vector<double> state;
  this->GatherParticleProps(s, particles, state);
  state.push_back(static_cast<double>(reinterpret_cast<uintptr_t>(internals.Volume.Get())));
  state.push_back(static_cast<double>(internals.Volume->GetMTime()));
  state.push_back(this->GenerationMode);
  // distributed rendering: the volume of all processes' particles, summed in the pipeline
  auto* distributed = vtkParticleDensityVolume::SafeDownCast(
    this->FindDistributedVolume(particles, vtkDensityVolumeAOPass::DISTRIBUTED_VOLUME(), state));
  if (!this->NeedsBuild(state))
  {
    return; // built already (or failed for the same input: no retry, no repeated message)
  }
  if (!this->CheckParticleProps(particles, vtkDensityVolumeAOPass::DISTRIBUTED_VOLUME(),
        "no ambient occlusion to compute", "density volume"))
  {
    return;
  }

  vtkParticleDensityVolume* volume = internals.Volume;
  vtkOpenGLRenderWindow* context =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  if (distributed)
  {
    vtkTextureObject* texture = this->VolumeTexture;
    SetVolumeSampling(texture);
    if (volume->UploadVolumeOf(distributed, context, texture))
    {
      this->LastGenerationMode = CPU_GENERATION;
      this->VolumeValid = true;
      ++this->NumberOfVolumeBuilds;
    }
    return;
  }

  // voxelise every particle prop into the volume and its texture (vtkParticleDensityVolume)
  volume->BeginParticles();
  for (auto& item : particles)
  {
    volume->AddParticles(item.first, item.second);
  }
  const vtkProgressScope progressScope(this, volume->GetNumberOfParticles());
  vtkTextureObject* texture = this->VolumeTexture;
  SetVolumeSampling(texture);
  const bool generated =
    volume->EndParticles(context, this->GenerationMode == GPU_GENERATION, texture);
  this->LastGenerationMode = volume->GetLastBuiltOnGPU() ? GPU_GENERATION : CPU_GENERATION;
  if (!generated)
  {
    return; // the volume said why; no ambient occlusion
  }
  this->VolumeValid = true;
  ++this->NumberOfVolumeBuilds;
}

//------------------------------------------------------------------------------
bool vtkDensityVolumeAOPass::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  if (!vtkParticleSphereMapper::SafeDownCast(mapper))
  {
    return true;
  }
  vtkParticleShaderHooks& hooks = *this->Hooks;
  hooks.Begin(vertexShader, geometryShader, fragmentShader);
  using Hooks = vtkParticleShaderHooks;
  const std::string uniforms = "uniform sampler3D prDensityVolume;\n"
                               "uniform mat4 prViewToVolume;\n"
                               "uniform mat3 prViewToWorld;\n"
                               "uniform vec3 prFetchStep;\n"
                               "uniform float prFetchDistance;\n"
                               "uniform float prStrength;";
  if (this->RetrievalMode == PER_FRAGMENT && this->GetExactLevel())
  {
    hooks.Insert(Hooks::Fragment, "//PR::Sphere::Dec", uniforms);
    // Eq. 4 with the strength s: A = 1 - s D(p + eps n), the density fetched with trilinear
    // filtering; it multiplies what other AO sources found
    hooks.Insert(Hooks::Fragment, "//PR::AmbientOcclusion::Impl",
      "vec3 prFetchVolume = (prViewToVolume *\n"
      "      vec4(vertexVC.xyz + prFetchDistance * normalVCVSOutput, 1.0)).xyz;\n"
      "    prAmbientOcclusion *=\n"
      "      clamp(1.0 - prStrength * texture(prDensityVolume, prFetchVolume).r, 0.0, 1.0);");
    return true;
  }
  // per sphere: six fetches (1 - D) in the vertex stage, once per sphere, carried to the fragments
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Dec", uniforms);
  hooks.AddSphereVarying("vec3", "prAOPlus");
  hooks.AddSphereVarying("vec3", "prAOMinus");
  // The sphere's own density is not its occlusion: subtract what the sphere itself splatted into
  // the voxels the fetch interpolates (otherwise voxels finer than the sphere hold its whole
  // volume at its centre and the six fetches find it there: the picture goes dark).
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Dec",
    "uniform vec3 prVolumeDimensions;\n"
    "uniform float prOwnDensity;\n"
    "uniform int prTrilinearSplat;\n"
    "//PR::Include DensityVolumeOwn");
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Impl",
    "vec3 prCentreVolume = (prViewToVolume * vec4(centerVC, 1.0)).xyz;\n"
    "#ifdef PR_ELLIPSOID\n"
    "  float prOwn = prOwnDensity * abs(determinant(ellipsoidToVCVSOutput));\n"
    "#else\n"
    "  float prOwn = prOwnDensity * radiusVC * radiusVC * radiusVC;\n"
    "#endif\n"
    "  for (int k = 0; k < 3; ++k)\n"
    "  {\n"
    "    vec3 prStep = vec3(0.0);\n"
    "    prStep[k] = prFetchStep[k];\n"
    "    float prOwnPlus = prOwn * prOwnDensityWeight(prCentreVolume, prCentreVolume + prStep,\n"
    "      prVolumeDimensions, prTrilinearSplat != 0);\n"
    "    float prOwnMinus = prOwn * prOwnDensityWeight(prCentreVolume, prCentreVolume - prStep,\n"
    "      prVolumeDimensions, prTrilinearSplat != 0);\n"
    "    prAOPlusVSOutput[k] = 1.0 - max(0.0,\n"
    "      texture(prDensityVolume, prCentreVolume + prStep).r - prOwnPlus);\n"
    "    prAOMinusVSOutput[k] = 1.0 - max(0.0,\n"
    "      texture(prDensityVolume, prCentreVolume - prStep).r - prOwnMinus);\n"
    "  }");
  hooks.Insert(Hooks::Fragment, "//PR::Sphere::Dec", uniforms);
  hooks.Insert(Hooks::Fragment, "//PR::AmbientOcclusion::Impl",
    "vec3 prNormalWC = prViewToWorld * normalVCVSOutput;\n"
    "    vec3 prSide = mix(prAOMinusVSOutput, prAOPlusVSOutput, step(0.0, prNormalWC));\n"
    "    float prSphereAO = dot(prNormalWC * prNormalWC, prSide);\n"
    "    prAmbientOcclusion *= clamp(1.0 - prStrength * (1.0 - prSphereAO), 0.0, 1.0);");
  return true;
}

//------------------------------------------------------------------------------
bool vtkDensityVolumeAOPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  if (!this->SetVolumeSampler(program, mapper, "prDensityVolume"))
  {
    return true;
  }
  vtkInternals& internals = *this->Internals;
  // view -> world -> volume texture coordinates, in double; the rotation for normals
  vtkParticleDensityVolume* volume = internals.Volume;
  const int* dims = volume->GetDimensions();
  const double scale[3] = { 1.0 / (dims[0] * volume->GetVoxelSize()),
    1.0 / (dims[1] * volume->GetVoxelSize()), 1.0 / (dims[2] * volume->GetVoxelSize()) };
  if (!this->SetViewToGridUniform(program, "prViewToVolume", volume->GetOrigin(), scale))
  {
    return true;
  }
  this->SetViewToWorldRotationUniform(program, "prViewToWorld");
  const float fetchStep[3] = {
    static_cast<float>(this->FetchDistance / dims[0]),
    static_cast<float>(this->FetchDistance / dims[1]),
    static_cast<float>(this->FetchDistance / dims[2]),
  };
  program->SetUniform3f("prFetchStep", fetchStep);
  program->SetUniformf(
    "prFetchDistance", static_cast<float>(this->FetchDistance * volume->GetVoxelSize()));
  program->SetUniformf("prStrength", static_cast<float>(this->Strength));
  if (program->IsUniformUsed("prOwnDensity"))
  {
    // a sphere of radius r adds g (4/3 pi r^3) / voxel^3 to the voxels, split by the splat weights
    // (an ellipsoid g (4/3 pi |det A|) / voxel^3)
    const float dimensions[3] = { static_cast<float>(dims[0]), static_cast<float>(dims[1]),
      static_cast<float>(dims[2]) };
    program->SetUniform3f("prVolumeDimensions", dimensions);
    const double voxel = volume->GetVoxelSize();
    program->SetUniformf("prOwnDensity",
      static_cast<float>(
        volume->GetDensityFactor() * 4.0 / 3.0 * vtkMath::Pi() / (voxel * voxel * voxel)));
    program->SetUniformi("prTrilinearSplat",
      volume->GetSplatMode() == vtkParticleDensityVolume::TRILINEAR_SPLAT ? 1 : 0);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkDensityVolumeAOPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Internals->Volume->ReleaseGraphicsResources(w);
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
vtkInformationKeyMacro(vtkDensityVolumeAOPass, DISTRIBUTED_VOLUME, ObjectBase);

//------------------------------------------------------------------------------
void vtkDensityVolumeAOPass::SetDistributedVolume(vtkProp* prop, vtkParticleDensityVolume* volume)
{
  vtkParticleVolumeAOPass::SetPropVolume(
    prop, vtkDensityVolumeAOPass::DISTRIBUTED_VOLUME(), volume);
}

//------------------------------------------------------------------------------
vtkParticleDensityVolume* vtkDensityVolumeAOPass::GetDistributedVolume(vtkProp* prop)
{
  return vtkParticleDensityVolume::SafeDownCast(
    vtkParticleVolumeAOPass::GetPropVolume(prop, vtkDensityVolumeAOPass::DISTRIBUTED_VOLUME()));
}

//------------------------------------------------------------------------------
void vtkDensityVolumeAOPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GenerationMode: " << (this->GenerationMode == CPU_GENERATION ? "CPU" : "GPU")
     << "\n";
  os << indent
     << "RetrievalMode: " << (this->RetrievalMode == PER_FRAGMENT ? "PerFragment" : "PerSphere")
     << "\n";
  os << indent << "FetchDistance: " << this->FetchDistance << "\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "ProgressThreshold: " << this->ProgressThreshold << "\n";
}
