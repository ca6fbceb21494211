#include "vtkDensityVolumeAOPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleDensityVolume.h"
#include "vtkParticleShaderHooks.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include "vtk_glew.h"

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
  explicit vtkInternals(vtkDensityVolumeAOPass* self)
    : Hooks(self)
  {
  }
  vtkSmartPointer<vtkParticleDensityVolume> Volume;
  unsigned long VolumeProgressTag = 0;
  vtkNew<vtkTextureObject> Texture;
  // what the volume was built from
  std::vector<double> BuiltState;
  bool TextureValid = false;
  bool Attempted = false; // a build was attempted for BuiltState
  // the renderer being drawn (between PreRender and PostRender)
  vtkRenderer* Renderer = nullptr;
  // the shader hooks this pass fills (warns once per missing hook)
  vtkParticleShaderHooks Hooks;

  // progress of the build under way (ProgressThreshold): its text, and which part of the whole
  // the volume's own progress (0..1) covers
  std::string ProgressText;
  bool Reporting = false;
  double VolumeProgressBase = 0.0;
  double VolumeProgressSpan = 1.0;
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
  : Internals(new vtkInternals(this))
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
  internals.Attempted = false; // a new volume object: build it
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
  const vtkInternals& internals = *this->Internals;
  this->ReportProgress(
    internals.VolumeProgressBase + internals.VolumeProgressSpan * *static_cast<double*>(callData));
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
void vtkDensityVolumeAOPass::UpdateVolume(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  // the particle props and what their volume depends on
  std::vector<std::pair<vtkActor*, vtkParticleSphereMapper*>> particles;
  std::vector<double> state;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    vtkParticleSphereMapper* mapper =
      actor ? vtkParticleSphereMapper::SafeDownCast(actor->GetMapper()) : nullptr;
    if (!mapper || !mapper->GetInput() || !actor->GetVisibility())
    {
      continue;
    }
    particles.emplace_back(actor, mapper);
    state.push_back(static_cast<double>(reinterpret_cast<uintptr_t>(mapper)));
    state.push_back(static_cast<double>(mapper->GetParticleGeometryTime()));
    state.push_back(mapper->GetRadiusScaleVC(actor));
    vtkMatrix4x4* m = actor->GetMatrix();
    state.insert(state.end(), m->GetData(), m->GetData() + 16);
  }
  state.push_back(static_cast<double>(reinterpret_cast<uintptr_t>(internals.Volume.Get())));
  state.push_back(static_cast<double>(internals.Volume->GetMTime()));
  state.push_back(this->GenerationMode);
  if (state == internals.BuiltState && internals.Attempted)
  {
    return; // built already (or failed for the same input: no retry, no repeated message)
  }
  internals.BuiltState = state;
  internals.Attempted = true;
  internals.TextureValid = false;
  if (particles.empty())
  {
    vtkWarningMacro(<< "No visible props with a vtkParticleSphereMapper (or subclass) and input "
                       "in the renderer: no ambient occlusion to compute.");
    return;
  }

  // All particles in world coordinates: their bounds and mean radius set up the grid; the
  // positions and radii themselves are kept only for a CPU build.
  vtkIdType total = 0;
  for (auto& item : particles)
  {
    total += item.second->GetParticleRadii()->GetNumberOfTuples();
  }
  // Progress (for a long build): the gathering of positions and bounds is about the first
  // half of a CPU build (10^7 particles on two llvmpipe cores: 0.76 s of 1.4 s), the splat the rest.
  const vtkProgressScope progressScope(this, total);
  const double gatherShare = 0.5;
  vtkNew<vtkFloatArray> positions;
  positions->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> radii;
  double bounds[6];
  double radiusSum = 0.0;
  vtkIdType valid = 0;
  // in parallel (vtkSMPTools): per thread bounds, radius sum and count, merged afterwards
  struct Partial
  {
    double Bounds[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
      VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
    double RadiusSum = 0.0;
    vtkIdType Valid = 0;
  };
  auto gather = [&](bool keep) {
    for (int k = 0; k < 3; ++k)
    {
      bounds[2 * k] = VTK_DOUBLE_MAX;
      bounds[2 * k + 1] = VTK_DOUBLE_MIN;
    }
    radiusSum = 0.0;
    valid = 0;
    positions->SetNumberOfTuples(keep ? total : 0);
    radii->SetNumberOfTuples(keep ? total : 0);
    float* outPositions = keep ? positions->GetPointer(0) : nullptr;
    float* outRadii = keep ? radii->GetPointer(0) : nullptr;
    vtkIdType offset = 0;
    for (auto& item : particles)
    {
      const vtkIdType n = item.second->GetParticleRadii()->GetNumberOfTuples();
      vtkPoints* inputPoints = item.second->GetInput()->GetPoints();
      if (n == 0 || !inputPoints || inputPoints->GetNumberOfPoints() < n)
      {
        if (outRadii)
        {
          std::fill(outRadii + offset, outRadii + offset + n, 0.0f); // skipped
        }
        offset += n; // nothing drawn (the mapper reported why)
        continue;
      }
      const float* r = item.second->GetParticleRadii()->GetPointer(0);
      vtkDataArray* points = inputPoints->GetData();
      vtkFloatArray* floatPoints = vtkFloatArray::FastDownCast(points);
      const float* xyz = floatPoints ? floatPoints->GetPointer(0) : nullptr;
      const double scale = item.second->GetRadiusScaleVC(item.first);
      const double* m = item.first->GetMatrix()->GetData();
      vtkSMPThreadLocal<Partial> partials;
      vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
        Partial& partial = partials.Local();
        for (vtkIdType i = begin; i < end; ++i)
        {
          const double radius = r[i] * scale;
          double q[3];
          if (xyz)
          {
            q[0] = xyz[3 * i];
            q[1] = xyz[3 * i + 1];
            q[2] = xyz[3 * i + 2];
          }
          else
          {
            points->GetTuple(i, q);
          }
          double p[3];
          for (int k = 0; k < 3; ++k)
          {
            p[k] = m[4 * k] * q[0] + m[4 * k + 1] * q[1] + m[4 * k + 2] * q[2] + m[4 * k + 3];
          }
          if (radius > 0.0 && std::isfinite(p[0] + p[1] + p[2]))
          {
            for (int k = 0; k < 3; ++k)
            {
              partial.Bounds[2 * k] = std::min(partial.Bounds[2 * k], p[k]);
              partial.Bounds[2 * k + 1] = std::max(partial.Bounds[2 * k + 1], p[k]);
            }
            partial.RadiusSum += radius;
            ++partial.Valid;
          }
          if (outPositions)
          {
            for (int k = 0; k < 3; ++k)
            {
              outPositions[3 * (offset + i) + k] = static_cast<float>(p[k]);
            }
            outRadii[offset + i] = static_cast<float>(radius > 0.0 ? radius : 0.0);
          }
        }
      });
      for (const Partial& partial : partials)
      {
        for (int k = 0; k < 3; ++k)
        {
          bounds[2 * k] = std::min(bounds[2 * k], partial.Bounds[2 * k]);
          bounds[2 * k + 1] = std::max(bounds[2 * k + 1], partial.Bounds[2 * k + 1]);
        }
        radiusSum += partial.RadiusSum;
        valid += partial.Valid;
      }
      offset += n;
    }
  };
  const bool tryGPU = this->GenerationMode == GPU_GENERATION &&
    vtkParticleComputeProgram::IsSupported(
      vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow()), nullptr);
  gather(!tryGPU);
  this->ReportProgress(gatherShare);
  if (valid == 0)
  {
    vtkWarningMacro(<< "The particle props have no particle with a finite position and a "
                       "radius > 0: no ambient occlusion.");
    return;
  }
  // the GPU's largest 3D texture bounds the voxels per axis
  GLint maxTexture3D = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxTexture3D);
  if (!internals.Volume->SetUpGrid(bounds, radiusSum / valid, maxTexture3D))
  {
    return;
  }
  const int* dims = internals.Volume->GetDimensions();
  vtkOpenGLRenderWindow* ctx =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  vtkTextureObject* texture = internals.Texture;
  texture->SetContext(ctx);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  // outside the volume there is nothing: density 0
  texture->SetWrapS(vtkTextureObject::ClampToBorder);
  texture->SetWrapT(vtkTextureObject::ClampToBorder);
  texture->SetWrapR(vtkTextureObject::ClampToBorder);
  texture->SetBorderColor(0.0f, 0.0f, 0.0f, 0.0f);

  // GPU: splat every mapper's own vertex buffers into one volume
  bool generated = false;
  if (tryGPU)
  {
    generated = texture->Create3DFromRaw(dims[0], dims[1], dims[2], 1, VTK_FLOAT, nullptr);
    bool first = true;
    std::size_t index = 0;
    for (auto& item : particles)
    {
      internals.VolumeProgressSpan = (1.0 - gatherShare) / static_cast<double>(particles.size());
      internals.VolumeProgressBase = gatherShare + internals.VolumeProgressSpan * index++;
      unsigned int positionBuffer = 0;
      unsigned int stride = 0;
      unsigned int radiusBuffer = 0;
      vtkIdType count = 0;
      vtkNew<vtkMatrix4x4> bufferToModel;
      if (!generated ||
        !item.second->GetParticleBuffers(positionBuffer, stride, radiusBuffer, count, bufferToModel))
      {
        generated = false; // not drawn yet (first frame): the CPU builds this one
        break;
      }
      vtkNew<vtkMatrix4x4> bufferToWorld;
      vtkMatrix4x4::Multiply4x4(item.first->GetMatrix(), bufferToModel, bufferToWorld);
      generated = internals.Volume->ComputeOnGPU(ctx, positionBuffer, stride,
        bufferToWorld->GetData(), radiusBuffer, item.second->GetRadiusScaleVC(item.first), count,
        !first);
      first = false;
    }
    generated = generated && internals.Volume->CopyVolumeBufferToTexture(texture->GetHandle());
  }
  this->LastGenerationMode = generated ? GPU_GENERATION : CPU_GENERATION;
  if (!generated)
  {
    if (tryGPU)
    {
      gather(true); // the GPU could not build it: the CPU needs the particles after all
    }
    internals.VolumeProgressBase = gatherShare;
    internals.VolumeProgressSpan = 1.0 - gatherShare;
    if (!internals.Volume->ComputeOnCPU(positions, radii))
    {
      return;
    }
    generated = texture->Create3DFromRaw(dims[0], dims[1], dims[2], 1, VTK_FLOAT,
      const_cast<float*>(internals.Volume->GetVolume().data()));
  }
  if (!generated)
  {
    vtkErrorMacro(<< "Cannot create the " << dims[0] << "x" << dims[1] << "x" << dims[2]
                  << " density texture: ambient occlusion is off.");
    return;
  }
  internals.TextureValid = true;
  ++this->NumberOfVolumeBuilds;
}

//------------------------------------------------------------------------------
void vtkDensityVolumeAOPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro(<< "No delegate pass: nothing is rendered.");
    return;
  }
  this->UpdateVolume(s);
  vtkInternals& internals = *this->Internals;
  if (internals.TextureValid)
  {
    internals.Texture->Activate();
    internals.Renderer = s->GetRenderer();
    this->PreRender(s);
  }
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  if (internals.TextureValid)
  {
    this->PostRender(s);
    internals.Texture->Deactivate();
    internals.Renderer = nullptr;
  }
}

//------------------------------------------------------------------------------
bool vtkDensityVolumeAOPass::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  if (!vtkParticleSphereMapper::SafeDownCast(mapper))
  {
    return true;
  }
  vtkParticleShaderHooks& hooks = this->Internals->Hooks;
  hooks.Begin(vertexShader, geometryShader, fragmentShader);
  using Hooks = vtkParticleShaderHooks;
  const std::string uniforms = "uniform sampler3D prDensityVolume;\n"
                               "uniform mat4 prViewToVolume;\n"
                               "uniform mat3 prViewToWorld;\n"
                               "uniform vec3 prFetchStep;\n"
                               "uniform float prFetchDistance;\n"
                               "uniform float prStrength;";
  if (this->RetrievalMode == PER_FRAGMENT)
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
  hooks.Insert(Hooks::Vertex, "//PR::Sphere::Impl",
    "vec3 prCentreVolume = (prViewToVolume * vec4(centerVC, 1.0)).xyz;\n"
    "  for (int k = 0; k < 3; ++k)\n"
    "  {\n"
    "    vec3 prStep = vec3(0.0);\n"
    "    prStep[k] = prFetchStep[k];\n"
    "    prAOPlusVSOutput[k] = 1.0 - texture(prDensityVolume, prCentreVolume + prStep).r;\n"
    "    prAOMinusVSOutput[k] = 1.0 - texture(prDensityVolume, prCentreVolume - prStep).r;\n"
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
  vtkInternals& internals = *this->Internals;
  if (!vtkParticleSphereMapper::SafeDownCast(mapper) || !internals.TextureValid ||
    !program->IsUniformUsed("prDensityVolume"))
  {
    return true;
  }
  vtkCamera* camera = internals.Renderer ? internals.Renderer->GetActiveCamera() : nullptr;
  if (!camera)
  {
    return true;
  }
  // view -> world -> volume texture coordinates, in double
  vtkParticleDensityVolume* volume = internals.Volume;
  vtkNew<vtkMatrix4x4> viewToWorld;
  vtkMatrix4x4::Invert(camera->GetModelViewTransformMatrix(), viewToWorld);
  vtkNew<vtkMatrix4x4> worldToVolume;
  const double* origin = volume->GetOrigin();
  const int* dims = volume->GetDimensions();
  for (int k = 0; k < 3; ++k)
  {
    const double size = dims[k] * volume->GetVoxelSize();
    worldToVolume->SetElement(k, k, 1.0 / size);
    worldToVolume->SetElement(k, 3, -origin[k] / size);
  }
  vtkNew<vtkMatrix4x4> viewToVolume;
  vtkMatrix4x4::Multiply4x4(worldToVolume, viewToWorld, viewToVolume);
  vtkNew<vtkMatrix4x4> transposed; // vtkShaderProgram uploads row-major data as columns
  vtkMatrix4x4::Transpose(viewToVolume, transposed);
  program->SetUniformMatrix("prViewToVolume", transposed);
  // the rotation part, for normals (row-major data uploaded as columns: transposed)
  float rotation[9];
  for (int row = 0; row < 3; ++row)
  {
    for (int col = 0; col < 3; ++col)
    {
      rotation[col * 3 + row] = static_cast<float>(viewToWorld->GetElement(row, col));
    }
  }
  program->SetUniformMatrix3x3("prViewToWorld", rotation);
  const float fetchStep[3] = {
    static_cast<float>(this->FetchDistance / dims[0]),
    static_cast<float>(this->FetchDistance / dims[1]),
    static_cast<float>(this->FetchDistance / dims[2]),
  };
  program->SetUniform3f("prFetchStep", fetchStep);
  program->SetUniformi("prDensityVolume", internals.Texture->GetTextureUnit());
  program->SetUniformf("prFetchDistance",
    static_cast<float>(this->FetchDistance * volume->GetVoxelSize()));
  program->SetUniformf("prStrength", static_cast<float>(this->Strength));
  return true;
}

//------------------------------------------------------------------------------
void vtkDensityVolumeAOPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Internals->Volume->ReleaseGraphicsResources(w);
  this->Internals->Texture->ReleaseGraphicsResources(w);
  this->Internals->TextureValid = false;
  this->Internals->Attempted = false;
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkDensityVolumeAOPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GenerationMode: "
     << (this->GenerationMode == CPU_GENERATION ? "CPU" : "GPU") << "\n";
  os << indent << "RetrievalMode: "
     << (this->RetrievalMode == PER_FRAGMENT ? "PerFragment" : "PerSphere") << "\n";
  os << indent << "FetchDistance: " << this->FetchDistance << "\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "NumberOfVolumeBuilds: " << this->NumberOfVolumeBuilds << "\n";
  os << indent << "ProgressThreshold: " << this->ProgressThreshold << "\n";
}
