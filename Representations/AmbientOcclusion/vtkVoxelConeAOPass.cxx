#include "vtkVoxelConeAOPass.h"

#include "vtkActor.h"
#include "vtkDoubleArray.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticleAmbientVolume.h"
#include "vtkParticleShaderHooks.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkVoxelConeAOPass);

//------------------------------------------------------------------------------
class vtkVoxelConeAOPass::vtkInternals
{
public:
  vtkSmartPointer<vtkParticleAmbientVolume> Volume;
  double SceneExtent = 0.0; // largest extent of the spheres (world)
};

//------------------------------------------------------------------------------
vtkVoxelConeAOPass::vtkVoxelConeAOPass()
  : Internals(new vtkInternals)
{
  this->SetAmbientVolume(vtkSmartPointer<vtkParticleAmbientVolume>::New());
}

//------------------------------------------------------------------------------
vtkVoxelConeAOPass::~vtkVoxelConeAOPass()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
vtkParticleAmbientVolume* vtkVoxelConeAOPass::GetAmbientVolume()
{
  return this->Internals->Volume;
}

//------------------------------------------------------------------------------
void vtkVoxelConeAOPass::SetAmbientVolume(vtkParticleAmbientVolume* volume)
{
  if (!volume || volume == this->Internals->Volume)
  {
    return;
  }
  this->Internals->Volume = volume;
  this->ForgetBuild();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkVoxelConeAOPass::AppendPropState(
  vtkActor* actor, vtkParticleSphereMapper* mapper, std::vector<double>& state)
{
  mapper->GetBounds(); // prepares the radii (and a transparent mapper's opacities)
  // colours (the mapper's settings and lookup table, the input's arrays), opacities
  state.push_back(static_cast<double>(mapper->GetMTime()));
  state.push_back(static_cast<double>(mapper->GetInput()->GetMTime()));
  vtkProperty* property = actor->GetProperty();
  state.push_back(property->GetOpacity());
  const double* color = property->GetColor();
  state.insert(state.end(), color, color + 3);
  if (vtkDoubleArray* opacities = mapper->GetEmissionOpacities())
  {
    state.push_back(static_cast<double>(opacities->GetMTime()));
  }
}

//------------------------------------------------------------------------------
void vtkVoxelConeAOPass::UpdateVolume(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  ParticleProps particles;
  std::vector<double> state;
  this->GatherParticleProps(s, particles, state);
  state.push_back(static_cast<double>(reinterpret_cast<uintptr_t>(internals.Volume.Get())));
  state.push_back(static_cast<double>(internals.Volume->GetMTime()));
  // distributed rendering: level 0 of all processes' spheres, summed in the pipeline
  auto* distributed = vtkParticleAmbientVolume::SafeDownCast(
    this->FindDistributedVolume(particles, vtkVoxelConeAOPass::DISTRIBUTED_VOLUME(), state));
  if (!this->NeedsBuild(state))
  {
    return; // built already (or failed for the same input: no retry, no repeated message)
  }
  if (!this->CheckParticleProps(particles, vtkVoxelConeAOPass::DISTRIBUTED_VOLUME(),
        "no voxel cone tracing", "ambient volume"))
  {
    return;
  }
  vtkParticleAmbientVolume* volume = internals.Volume;
  volume->BeginParticles();
  for (auto& item : particles)
  {
    volume->AddParticles(item.first, item.second);
  }
  vtkOpenGLRenderWindow* ctx =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  if (distributed ? !volume->UploadVolumeOf(distributed, ctx, this->VolumeTexture)
                  : !volume->EndParticles(ctx, this->VolumeTexture))
  {
    return; // the volume said why; no ambient occlusion
  }
  // the spheres' largest extent: the grid's longest axis holds it within one voxel
  const int* dims = volume->GetDimensions();
  internals.SceneExtent = volume->GetVoxelSize() * std::max(std::max(dims[0], dims[1]), dims[2]);
  this->VolumeValid = true;
  ++this->NumberOfVolumeBuilds;
}

//------------------------------------------------------------------------------
bool vtkVoxelConeAOPass::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  if (!vtkParticleSphereMapper::SafeDownCast(mapper))
  {
    return true;
  }
  vtkParticleShaderHooks& hooks = *this->Hooks;
  hooks.Begin(vertexShader, geometryShader, fragmentShader);
  using Hooks = vtkParticleShaderHooks;
  hooks.Insert(Hooks::Fragment, "//PR::Sphere::Dec", "//PR::Include VoxelConeTrace");
  if (this->RetrievalMode == PER_FRAGMENT && this->GetExactLevel())
  {
    // Eq. 7: the occlusion multiplies the lit colour, the ambient illumination is added
    hooks.Insert(Hooks::Fragment, "//PR::AmbientOcclusion::Impl",
      "vec4 prCones = prTraceCones(vertexVC.xyz, normalVCVSOutput);\n"
      "    prAmbientOcclusion *= clamp(prCones.a, 0.0, 1.0);\n"
      "    prAmbientLight += prAmbientScale * prCones.rgb;");
    return true;
  }
  // per sphere: the six axis results, traced once per sphere, carried to the fragments
  static const char* const names[6] = { "prConePX", "prConeMX", "prConePY", "prConeMY", "prConePZ",
    "prConeMZ" };
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Dec", "//PR::Include VoxelConeTrace");
  std::string impl = "vec4 prSphereCones[6];\n"
                     "#ifdef PR_ELLIPSOID\n"
                     "  prTraceEllipsoidCones(centerVC, ellipsoidToVCVSOutput, prSphereCones);\n"
                     "#else\n"
                     "  prTraceSphereCones(centerVC, radiusVC, prSphereCones);\n"
                     "#endif";
  std::string blend = "prViewToWorld * normalVCVSOutput";
  for (int k = 0; k < 6; ++k)
  {
    hooks.AddSphereVarying("vec4", names[k]);
    impl += "\n  " + std::string(names[k]) + "VSOutput = prSphereCones[" + std::to_string(k) + "];";
    blend += ", " + std::string(names[k]) + "VSOutput";
  }
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Impl", impl);
  hooks.Insert(Hooks::Fragment, "//PR::Sphere::Dec", "uniform mat3 prViewToWorld;");
  hooks.Insert(Hooks::Fragment, "//PR::AmbientOcclusion::Impl",
    "vec4 prCones = prBlendSphereCones(" + blend +
      ");\n"
      "    prAmbientOcclusion *= clamp(prCones.a, 0.0, 1.0);\n"
      "    prAmbientLight += prAmbientScale * prCones.rgb;");
  return true;
}

//------------------------------------------------------------------------------
bool vtkVoxelConeAOPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  if (!this->SetVolumeSampler(program, mapper, "prAmbientVolume"))
  {
    return true;
  }
  vtkInternals& internals = *this->Internals;
  // view -> world -> level-0 voxel units, in double
  vtkParticleAmbientVolume* volume = internals.Volume;
  const double edge = volume->GetVoxelSize();
  const double scale[3] = { 1.0 / edge, 1.0 / edge, 1.0 / edge };
  if (!this->SetViewToGridUniform(program, "prViewToVoxel", volume->GetOrigin(), scale))
  {
    return true;
  }
  const int* dims = volume->GetDimensions();
  const float dimensions[3] = { static_cast<float>(dims[0]), static_cast<float>(dims[1]),
    static_cast<float>(dims[2]) };
  program->SetUniform3f("prAmbientDimensions", dimensions);
  if (program->IsUniformUsed("prViewToWorld"))
  {
    this->SetViewToWorldRotationUniform(program, "prViewToWorld");
  }
  const double halfAngle = vtkMath::RadiansFromDegrees(0.5 * this->ConeAperture);
  program->SetUniformf("prConeTanHalf", static_cast<float>(std::tan(halfAngle)));
  program->SetUniformf("prConeStart", static_cast<float>(this->StartOffset));
  program->SetUniformf(
    "prConeLength", static_cast<float>(this->ConeLength * internals.SceneExtent / edge));
  program->SetUniformf("prAmbientScale", static_cast<float>(this->AmbientIllumination));

  // the cones in the normal's frame (u, v, n) and their cosine weights
  const int count = this->GetQualityLevel() == 0 && !this->GetExactLevel() ? 1 : this->ConeCount;
  const bool central = count >= 5;
  const int ring = central ? count - 1 : (count == 1 ? 0 : count);
  const double tilt = vtkMath::RadiansFromDegrees(
    central ? std::min(this->ConeAperture, 70.0) : std::min(0.6 * this->ConeAperture, 70.0));
  std::vector<float> cones(4 * 16, 0.0f);
  double total = 0.0;
  int k = 0;
  if (central || ring == 0)
  {
    cones[2] = 1.0f;
    cones[3] = 1.0f;
    total = 1.0;
    k = 1;
  }
  for (int i = 0; i < ring; ++i, ++k)
  {
    const double azimuth = 2.0 * vtkMath::Pi() * i / ring;
    cones[4 * k] = static_cast<float>(std::sin(tilt) * std::cos(azimuth));
    cones[4 * k + 1] = static_cast<float>(std::sin(tilt) * std::sin(azimuth));
    cones[4 * k + 2] = static_cast<float>(std::cos(tilt));
    cones[4 * k + 3] = static_cast<float>(std::cos(tilt));
    total += std::cos(tilt);
  }
  for (int i = 0; i < k; ++i)
  {
    cones[4 * i + 3] = static_cast<float>(cones[4 * i + 3] / total);
  }
  program->SetUniformi("prConeCount", k);
  program->SetUniform4fv("prCones", 16, reinterpret_cast<const float(*)[4]>(cones.data()));
  return true;
}

//------------------------------------------------------------------------------
void vtkVoxelConeAOPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Internals->Volume->ReleaseGraphicsResources(w);
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
vtkInformationKeyMacro(vtkVoxelConeAOPass, DISTRIBUTED_VOLUME, ObjectBase);

//------------------------------------------------------------------------------
void vtkVoxelConeAOPass::SetDistributedVolume(vtkProp* prop, vtkParticleAmbientVolume* volume)
{
  vtkParticleVolumeAOPass::SetPropVolume(prop, vtkVoxelConeAOPass::DISTRIBUTED_VOLUME(), volume);
}

//------------------------------------------------------------------------------
vtkParticleAmbientVolume* vtkVoxelConeAOPass::GetDistributedVolume(vtkProp* prop)
{
  return vtkParticleAmbientVolume::SafeDownCast(
    vtkParticleVolumeAOPass::GetPropVolume(prop, vtkVoxelConeAOPass::DISTRIBUTED_VOLUME()));
}

//------------------------------------------------------------------------------
bool vtkVoxelConeAOPass::GetAddsColouredAmbientLight()
{
  return true;
}

//------------------------------------------------------------------------------
void vtkVoxelConeAOPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent
     << "RetrievalMode: " << (this->RetrievalMode == PER_FRAGMENT ? "PerFragment" : "PerSphere")
     << "\n";
  os << indent << "ConeCount: " << this->ConeCount << "\n";
  os << indent << "ConeAperture: " << this->ConeAperture << "\n";
  os << indent << "StartOffset: " << this->StartOffset << "\n";
  os << indent << "ConeLength: " << this->ConeLength << "\n";
  os << indent << "AmbientIllumination: " << this->AmbientIllumination << "\n";
}
