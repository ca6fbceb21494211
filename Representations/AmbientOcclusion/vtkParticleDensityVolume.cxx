#include "vtkParticleDensityVolume.h"
#include "vtkParticleMemory.h"

#include "vtkActor.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleShaders.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkParticleDensityVolume);

namespace
{
// Particles are splatted in this many blocks (fewer for small counts, at least 65536 particles
// per block), each followed by a ProgressEvent when someone listens.
constexpr vtkIdType ProgressBlocks = 16;
constexpr vtkIdType MinimumBlockSize = 65536;

vtkIdType BlockSize(vtkObject* self, vtkIdType n)
{
  if (!self->HasObserver(vtkCommand::ProgressEvent))
  {
    return std::max<vtkIdType>(n, 1);
  }
  return std::max(MinimumBlockSize, (n + ProgressBlocks - 1) / ProgressBlocks);
}

}

namespace
{
// fixed point of the GPU accumulation: 2^-20 voxel volumes
const double FixedPointScale = 1048576.0;
}

//------------------------------------------------------------------------------
class vtkParticleDensityVolume::vtkInternals
{
public:
  vtkNew<vtkParticleComputeProgram> Splat;
  vtkNew<vtkParticleComputeProgram> Convert;
  vtkNew<vtkOpenGLBufferObject> Counts;          // fixed-point sums per voxel
  vtkNew<vtkOpenGLBufferObject> VolumeBuffer;    // densities per voxel
  size_t Capacity = 0;                           // voxels
  vtkWeakPointer<vtkOpenGLRenderWindow> Context; // of the buffers

  // the particle props of BeginParticles ... EndParticles
  std::vector<std::pair<vtkActor*, vtkParticleSphereMapper*>> Props;
  // the part of the whole progress (0..1) the current block loop covers (EndParticles)
  double ProgressBase = 0.0;
  double ProgressSpan = 1.0;
};

//------------------------------------------------------------------------------
void vtkParticleDensityVolume::ReportProgress(vtkIdType done, vtkIdType n)
{
  if (this->HasObserver(vtkCommand::ProgressEvent))
  {
    const vtkInternals& internals = *this->Internals;
    const double part = n > 0 ? static_cast<double>(done) / static_cast<double>(n) : 1.0;
    double fraction = internals.ProgressBase + internals.ProgressSpan * part;
    this->InvokeEvent(vtkCommand::ProgressEvent, &fraction);
  }
}

//------------------------------------------------------------------------------
vtkParticleDensityVolume::vtkParticleDensityVolume()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkParticleDensityVolume::~vtkParticleDensityVolume()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
bool vtkParticleDensityVolume::SetUpGrid(
  const double bounds[6], double meanRadius, int deviceAxisLimit)
{
  bool finite = std::isfinite(meanRadius);
  for (int k = 0; k < 6; ++k)
  {
    finite = finite && std::isfinite(bounds[k]);
  }
  if (!(meanRadius > 0.0) || !finite || !vtkMath::AreBoundsInitialized(bounds))
  {
    vtkErrorMacro(<< "Cannot set up a density volume for mean radius " << meanRadius
                  << " and bounds " << bounds[0] << " " << bounds[1] << " " << bounds[2] << " "
                  << bounds[3] << " " << bounds[4] << " " << bounds[5] << ".");
    this->Dimensions[0] = this->Dimensions[1] = this->Dimensions[2] = 0;
    return false;
  }
  double extent[3];
  double longest = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    extent[k] = std::max(0.0, bounds[2 * k + 1] - bounds[2 * k]);
    longest = std::max(longest, extent[k]);
  }
  double edge = 4.0 * meanRadius;
  if (this->Resolution > 0 && longest > 0.0)
  {
    edge = longest / this->Resolution;
  }
  // no axis beyond MaximumResolution or the device's limit: grow the (cubic) voxels instead
  int axisLimit = this->MaximumResolution;
  if (deviceAxisLimit > 0 && deviceAxisLimit < axisLimit)
  {
    axisLimit = deviceAxisLimit;
  }
  if (longest / edge > axisLimit)
  {
    vtkWarningMacro(<< "A density volume of " << std::ceil(longest / edge)
                    << " voxels along the longest axis exceeds the limit of " << axisLimit
                    << (axisLimit == this->MaximumResolution ? " (MaximumResolution)"
                                                             : " (the GPU's largest 3D texture)")
                    << ": using " << axisLimit << ".");
    edge = longest / axisLimit;
  }
  auto count = [&](double e)
  {
    double voxels = 1.0;
    for (int k = 0; k < 3; ++k)
    {
      voxels *= std::max(1.0, std::ceil(extent[k] / e - 1e-9));
    }
    return voxels;
  };
  if (count(edge) > static_cast<double>(this->MaximumVoxelCount))
  {
    const double requested = count(edge);
    // grow the edge until the grid fits (the flat axes keep one voxel)
    while (count(edge) > static_cast<double>(this->MaximumVoxelCount))
    {
      edge *= std::max(1.001, 0.999 * std::cbrt(count(edge) / this->MaximumVoxelCount));
    }
    vtkWarningMacro(<< "A density volume of " << requested << " voxels exceeds MaximumVoxelCount "
                    << this->MaximumVoxelCount << ": using voxels of edge " << edge << " ("
                    << count(edge) << " voxels).");
  }
  this->VoxelSize = edge;
  for (int k = 0; k < 3; ++k)
  {
    this->Dimensions[k] =
      std::max(1, std::min(axisLimit, static_cast<int>(std::ceil(extent[k] / edge - 1e-9))));
    const double centre = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]);
    this->Origin[k] = centre - 0.5 * this->Dimensions[k] * edge;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleDensityVolume::ComputeOnCPU(vtkDataArray* positions, vtkFloatArray* radii)
{
  if (!this->ComputeSumsOnCPU(positions, radii))
  {
    return false;
  }
  this->FinishSums();
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleDensityVolume::FinishSums()
{
  float* out = this->Volume.data();
  const double g = this->DensityFactor;
  vtkSMPTools::For(0, static_cast<vtkIdType>(this->Volume.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        out[i] = static_cast<float>(std::min(1.0, g * out[i]));
      }
    });
}

//------------------------------------------------------------------------------
bool vtkParticleDensityVolume::UploadVolumeOf(
  vtkParticleDensityVolume* other, vtkOpenGLRenderWindow* context, vtkTextureObject* texture)
{
  const int* dims = other ? other->Dimensions : nullptr;
  if (!other || !context || !texture ||
    other->Volume.size() != static_cast<size_t>(dims[0]) * dims[1] * dims[2] ||
    other->Volume.empty())
  {
    vtkErrorMacro(<< "UploadVolumeOf() needs a built volume, a context and a texture.");
    return false;
  }
  std::copy(dims, dims + 3, this->Dimensions);
  std::copy(other->Origin, other->Origin + 3, this->Origin);
  this->VoxelSize = other->VoxelSize;
  this->Volume = other->Volume;
  this->LastBuiltOnGPU = false;
  texture->SetContext(context);
  if (!texture->Create3DFromRaw(
        dims[0], dims[1], dims[2], 1, VTK_FLOAT, const_cast<float*>(this->Volume.data())))
  {
    vtkErrorMacro(<< "Cannot create the " << dims[0] << "x" << dims[1] << "x" << dims[2]
                  << " density texture.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
namespace
{
// One sphere's volume (`contribution`, in voxel units) at p into `local`: the voxel that holds p
// (nearest), or cloud in cell: the 8 voxels whose centres surround p with tent weights, corners
// beyond the grid folded onto its boundary voxels (nothing is lost).
void SplatSphere(const double p[3], double contribution, const int* dims, const double* origin,
  double inverseEdge, bool trilinear, std::vector<float>& local)
{
  if (!trilinear)
  {
    int v[3];
    for (int k = 0; k < 3; ++k)
    {
      v[k] = std::min(
        dims[k] - 1, std::max(0, static_cast<int>(std::floor((p[k] - origin[k]) * inverseEdge))));
    }
    local[v[0] + dims[0] * (v[1] + static_cast<vtkIdType>(dims[1]) * v[2])] +=
      static_cast<float>(contribution);
    return;
  }
  int lower[3];
  double weight[3];
  for (int k = 0; k < 3; ++k)
  {
    const double v = (p[k] - origin[k]) * inverseEdge - 0.5;
    const double f = std::floor(v);
    lower[k] = static_cast<int>(std::max(-1.0, std::min(f, static_cast<double>(dims[k]))));
    weight[k] = std::min(1.0, std::max(0.0, v - f));
  }
  for (int corner = 0; corner < 8; ++corner)
  {
    double w = contribution;
    vtkIdType index = 0;
    vtkIdType step = 1;
    for (int k = 0; k < 3; ++k)
    {
      const int high = (corner >> k) & 1;
      w *= high ? weight[k] : 1.0 - weight[k];
      index += step * std::min(dims[k] - 1, std::max(0, lower[k] + high));
      step *= dims[k];
    }
    local[index] += static_cast<float>(w);
  }
}

// The threads' partial volumes summed (in double) into out[0, voxels).
void SumPartialVolumes(vtkSMPThreadLocal<std::vector<float>>& partial, float* out, vtkIdType voxels)
{
  std::vector<const float*> parts;
  for (auto& local : partial)
  {
    if (!local.empty())
    {
      parts.push_back(local.data());
    }
  }
  vtkSMPTools::For(0, voxels,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double sum = 0.0;
        for (const float* part : parts)
        {
          sum += part[i];
        }
        out[i] = static_cast<float>(sum);
      }
    });
}
}

//------------------------------------------------------------------------------
bool vtkParticleDensityVolume::ComputeSumsOnCPU(vtkDataArray* positions, vtkFloatArray* radii)
{
  const vtkIdType voxels =
    static_cast<vtkIdType>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
  if (voxels <= 0 || !positions || !radii ||
    radii->GetNumberOfTuples() != positions->GetNumberOfTuples())
  {
    vtkErrorMacro(<< "No grid (SetUpGrid) or mismatched positions and radii.");
    this->Volume.clear();
    return false;
  }
  const vtkIdType n = positions->GetNumberOfTuples();
  const float* r = radii->GetPointer(0);
  const double unit = 4.0 / 3.0 * vtkMath::Pi() / std::pow(this->VoxelSize, 3);
  const int* dims = this->Dimensions;
  const double* origin = this->Origin;
  const double inverseEdge = 1.0 / this->VoxelSize;
  const bool trilinear = this->SplatMode == TRILINEAR_SPLAT;

  // each thread into its own partial volume (no races), then a sum over the voxels: threads + 1
  // volumes of floats. Checked first: a volume that does not fit is an error, not an abort.
  const double bytes =
    static_cast<double>(voxels) * sizeof(float) * (vtkSMPTools::GetEstimatedNumberOfThreads() + 1);
  std::string why;
  if (!vtkParticleMemory::CanAllocate(bytes, why))
  {
    vtkErrorMacro(<< "The " << dims[0] << "x" << dims[1] << "x" << dims[2]
                  << " density volume built on the CPU " << why
                  << ": no ambient occlusion. Lower Resolution or MaximumVoxelCount.");
    this->Volume.clear();
    return false;
  }
  std::atomic<bool> outOfMemory(false);
  vtkSMPThreadLocal<std::vector<float>> partial;
  auto splat = [&](vtkIdType begin, vtkIdType end)
  {
    std::vector<float>& local = partial.Local();
    if (local.empty())
    {
      try
      {
        local.assign(voxels, 0.0f);
      }
      catch (const std::bad_alloc&)
      {
        outOfMemory = true; // (an exception must not leave an SMP worker)
        return;
      }
    }
    double p[3];
    for (vtkIdType i = begin; i < end; ++i)
    {
      if (!(r[i] > 0.0f))
      {
        continue;
      }
      positions->GetTuple(i, p);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      {
        continue; // NaN/Inf positions are not drawn either
      }
      const double radius = r[i];
      SplatSphere(p, unit * radius * radius * radius, dims, origin, inverseEdge, trilinear, local);
    }
  };
  const vtkIdType block = BlockSize(this, n);
  this->ReportProgress(0, n);
  for (vtkIdType first = 0; first < n; first += block)
  {
    vtkSMPTools::For(first, std::min(n, first + block), splat);
    this->ReportProgress(std::min(n, first + block), n);
  }
  if (!outOfMemory)
  {
    try
    {
      this->Volume.assign(voxels, 0.0f);
    }
    catch (const std::bad_alloc&)
    {
      outOfMemory = true;
    }
  }
  if (outOfMemory)
  {
    vtkErrorMacro(<< "Out of memory for the " << dims[0] << "x" << dims[1] << "x" << dims[2]
                  << " density volume (" << vtkParticleMemory::FormatBytes(bytes)
                  << "): no ambient occlusion. Lower Resolution or MaximumVoxelCount.");
    this->Volume.clear();
    return false;
  }
  SumPartialVolumes(partial, this->Volume.data(), voxels);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleDensityVolume::ComputeOnGPU(vtkOpenGLRenderWindow* context,
  vtkOpenGLBufferObject* positionBuffer, unsigned int positionStride, const double bufferToGrid[16],
  vtkOpenGLBufferObject* radiusBuffer, double radiusScale, vtkIdType count, bool accumulate)
{
  vtkInternals& internals = *this->Internals;
  const size_t voxels =
    static_cast<size_t>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
  std::string why;
  if (voxels == 0 || !vtkParticleComputeProgram::IsSupported(context, &why))
  {
    vtkErrorMacro(<< (voxels == 0 ? std::string("No grid (SetUpGrid).") : why));
    return false;
  }
  if (internals.Context && internals.Context != context)
  {
    this->ReleaseGraphicsResources(internals.Context); // programs and buffers of another
    context->MakeCurrent();                            // back to the one drawing now
  }
  internals.Context = context;
  if (!internals.Splat->IsBuilt() || !internals.Convert->IsBuilt())
  {
    const std::string source = vtkParticleShaders::Get("DensityVolume");
    const size_t afterVersion = source.find('\n') + 1;
    internals.Splat->SetSource(
      source.substr(0, afterVersion) + "#define PR_DENSITY_SPLAT\n" + source.substr(afterVersion));
    internals.Convert->SetSource(source);
  }
  if (!internals.Splat->Build(context) || !internals.Convert->Build(context))
  {
    return false;
  }
  if (internals.Capacity < voxels)
  {
    if (!vtkParticleComputeProgram::AllocateStorage(internals.Counts, voxels * sizeof(GLuint)) ||
      !vtkParticleComputeProgram::AllocateStorage(internals.VolumeBuffer, voxels * sizeof(float)))
    {
      vtkErrorMacro(<< "Cannot allocate the GPU buffers of " << voxels << " voxels.");
      internals.Capacity = 0;
      return false;
    }
    internals.Capacity = voxels;
  }
  if (!accumulate)
  {
    vtkParticleComputeProgram::ClearStorage(internals.Counts, voxels * sizeof(GLuint), 0);
  }

  // voxel coordinate = (M p - origin) / edge, folded in double; column-major for GL
  float toVoxel[16];
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      double value = bufferToGrid[4 * row + col];
      if (row < 3)
      {
        value = (value - (col == 3 ? this->Origin[row] : 0.0)) / this->VoxelSize;
      }
      toVoxel[4 * col + row] = static_cast<float>(value);
    }
  }
  vtkParticleComputeProgram* splat = internals.Splat;
  splat->Use();
  splat->SetUniformui("positionStride", positionStride);
  splat->SetUniformMatrix4x4("toVoxel", toVoxel);
  splat->SetUniformf("radiusScale", static_cast<float>(radiusScale));
  splat->SetUniformi("trilinear", this->SplatMode == TRILINEAR_SPLAT ? 1 : 0);
  glUniform3i(splat->GetUniformLocation("dimensions"), this->Dimensions[0], this->Dimensions[1],
    this->Dimensions[2]);
  splat->SetUniformf("unitContribution",
    static_cast<float>(4.0 / 3.0 * vtkMath::Pi() / std::pow(this->VoxelSize, 3) * FixedPointScale));
  vtkParticleComputeProgram::BindStorage(0, positionBuffer);
  vtkParticleComputeProgram::BindStorage(1, radiusBuffer);
  vtkParticleComputeProgram::BindStorage(2, internals.Counts);
  const vtkIdType block = BlockSize(this, count);
  this->ReportProgress(0, count);
  for (vtkIdType first = 0; first < count; first += block)
  {
    const vtkIdType blockCount = std::min(count - first, block);
    splat->SetUniformui("first", static_cast<unsigned int>(first));
    splat->SetUniformui("count", static_cast<unsigned int>(first + blockCount));
    splat->Dispatch(static_cast<unsigned int>((blockCount + 255) / 256));
    this->ReportProgress(first + blockCount, count);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  vtkParticleComputeProgram* convert = internals.Convert;
  convert->Use();
  convert->SetUniformui("voxelCount", static_cast<unsigned int>(voxels));
  convert->SetUniformf("toDensity", static_cast<float>(this->DensityFactor / FixedPointScale));
  vtkParticleComputeProgram::BindStorage(3, internals.VolumeBuffer);
  convert->Dispatch(static_cast<unsigned int>((voxels + 255) / 256));
  glMemoryBarrier(
    GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  for (unsigned int binding = 0; binding < 4; ++binding)
  {
    vtkParticleComputeProgram::BindStorage(binding, nullptr);
  }
  vtkParticleComputeProgram::UseNone();
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleDensityVolume::CopyVolumeBufferToTexture(vtkTextureObject* texture)
{
  vtkOpenGLBufferObject* volume = this->Internals->VolumeBuffer;
  if (volume->GetHandle() == 0 || !texture || texture->GetHandle() == 0 ||
    texture->GetTarget() != GL_TEXTURE_3D)
  {
    return false;
  }
  // from the buffer as the pixel source: no round trip through the CPU
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(volume->GetHandle()));
  texture->Bind();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, this->Dimensions[0], this->Dimensions[1],
    this->Dimensions[2], GL_RED, GL_FLOAT, nullptr);
  glBindTexture(GL_TEXTURE_3D, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  return true;
}

//------------------------------------------------------------------------------
vtkOpenGLBufferObject* vtkParticleDensityVolume::GetVolumeBuffer()
{
  return this->Internals->VolumeBuffer;
}

//------------------------------------------------------------------------------
bool vtkParticleDensityVolume::ReadVolumeBuffer()
{
  const size_t voxels =
    static_cast<size_t>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
  if (this->Internals->VolumeBuffer->GetHandle() == 0 || voxels > this->Internals->Capacity)
  {
    return false;
  }
  try
  {
    this->Volume.resize(voxels);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "Out of memory for reading back the density volume ("
                  << vtkParticleMemory::FormatBytes(voxels * sizeof(float)) << ").");
    this->Volume.clear();
    return false;
  }
  return vtkParticleComputeProgram::DownloadStorage(
    this->Internals->VolumeBuffer, 0, voxels * sizeof(float), this->Volume.data());
}

//------------------------------------------------------------------------------
void vtkParticleDensityVolume::BeginParticles()
{
  this->Internals->Props.clear();
}

//------------------------------------------------------------------------------
void vtkParticleDensityVolume::AddParticles(vtkActor* actor, vtkParticleSphereMapper* mapper)
{
  if (actor && mapper && mapper->GetInput())
  {
    this->Internals->Props.emplace_back(actor, mapper);
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkParticleDensityVolume::GetNumberOfParticles()
{
  vtkIdType total = 0;
  for (auto& item : this->Internals->Props)
  {
    total += item.second->GetParticleVolumeRadii()->GetNumberOfTuples();
  }
  return total;
}

//------------------------------------------------------------------------------
bool vtkParticleDensityVolume::GatherParticles(
  vtkFloatArray* positions, vtkFloatArray* radii, double bounds[6], double& meanRadius)
{
  const vtkIdType total = this->GetNumberOfParticles();
  double radiusSum = 0.0;
  vtkIdType valid = 0;
  for (int k = 0; k < 3; ++k)
  {
    bounds[2 * k] = VTK_DOUBLE_MAX;
    bounds[2 * k + 1] = VTK_DOUBLE_MIN;
  }
  const bool keep = positions && radii;
  if (keep)
  {
    positions->SetNumberOfComponents(3);
    positions->SetNumberOfTuples(total);
    radii->SetNumberOfTuples(total);
  }
  float* outPositions = keep ? positions->GetPointer(0) : nullptr;
  float* outRadii = keep ? radii->GetPointer(0) : nullptr;
  // in parallel (vtkSMPTools): per thread bounds, radius sum and count, merged afterwards
  struct Partial
  {
    double Bounds[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
      VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
    double RadiusSum = 0.0;
    vtkIdType Valid = 0;
  };
  vtkIdType offset = 0;
  for (auto& item : this->Internals->Props)
  {
    const vtkIdType n = item.second->GetParticleVolumeRadii()->GetNumberOfTuples();
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
    const float* r = item.second->GetParticleVolumeRadii()->GetPointer(0);
    vtkDataArray* points = inputPoints->GetData();
    vtkFloatArray* floatPoints = vtkFloatArray::FastDownCast(points);
    const float* xyz = floatPoints ? floatPoints->GetPointer(0) : nullptr;
    const double scale = item.second->GetRadiusScaleVC(item.first);
    const double* m = item.first->GetMatrix()->GetData();
    vtkSMPThreadLocal<Partial> partials;
    vtkSMPTools::For(0, n,
      [&](vtkIdType begin, vtkIdType end)
      {
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
  meanRadius = valid > 0 ? radiusSum / valid : 0.0;
  return valid > 0;
}

//------------------------------------------------------------------------------
bool vtkParticleDensityVolume::EndParticles(
  vtkOpenGLRenderWindow* context, bool onGPU, vtkTextureObject* texture)
{
  vtkInternals& internals = *this->Internals;
  this->LastBuiltOnGPU = false;
  if (internals.Props.empty() || !context || !texture)
  {
    vtkErrorMacro(
      << "EndParticles() needs particle props (AddParticles), a context and a texture.");
    return false;
  }
  onGPU = onGPU && vtkParticleComputeProgram::IsSupported(context, nullptr);
  // the particles in world coordinates: bounds and mean radius set up the grid; positions and
  // radii are kept only for a CPU build. Progress: gathering is about the first half of a CPU
  // build (10^7 particles on two llvmpipe cores: 0.76 s of 1.4 s), the splat the rest.
  const double gatherShare = 0.5;
  vtkNew<vtkFloatArray> positions;
  vtkNew<vtkFloatArray> radii;
  double bounds[6];
  double meanRadius = 0.0;
  const bool any = this->GatherParticles(
    onGPU ? nullptr : positions.Get(), onGPU ? nullptr : radii.Get(), bounds, meanRadius);
  // gathered: the first gatherShare of the whole
  internals.ProgressBase = gatherShare;
  internals.ProgressSpan = 1.0 - gatherShare;
  this->ReportProgress(0, 1);
  if (!any)
  {
    vtkWarningMacro(<< "The particle props have no particle with a finite position and a "
                       "radius > 0: the density volume stays empty.");
    return false;
  }
  // the GPU's largest 3D texture bounds the voxels per axis
  if (!this->SetUpGrid(bounds, meanRadius, vtkTextureObject::GetMaximumTextureSize3D(context)))
  {
    return false;
  }
  const int* dims = this->Dimensions;
  // the texture (and, on a software rasteriser, the GPU build's buffers) in host memory
  {
    const double bytes = static_cast<double>(dims[0]) * dims[1] * dims[2] * sizeof(float);
    std::string why;
    if (!vtkParticleMemory::CanAllocate(bytes, why))
    {
      vtkErrorMacro(<< "The " << dims[0] << "x" << dims[1] << "x" << dims[2]
                    << " density volume texture " << why
                    << ": no ambient occlusion. Lower Resolution or MaximumVoxelCount.");
      return false;
    }
  }
  texture->SetContext(context);

  // GPU: splat every mapper's own vertex buffers into one volume
  bool generated = false;
  if (onGPU)
  {
    generated = texture->Create3DFromRaw(dims[0], dims[1], dims[2], 1, VTK_FLOAT, nullptr);
    bool first = true;
    std::size_t index = 0;
    for (auto& item : internals.Props)
    {
      internals.ProgressSpan = (1.0 - gatherShare) / static_cast<double>(internals.Props.size());
      internals.ProgressBase = gatherShare + internals.ProgressSpan * index++;
      vtkOpenGLBufferObject* positionBuffer = nullptr;
      unsigned int stride = 0;
      vtkOpenGLBufferObject* radiusBuffer = nullptr;
      vtkIdType count = 0;
      vtkNew<vtkMatrix4x4> bufferToModel;
      if (!generated ||
        !item.second->GetParticleBuffers(
          positionBuffer, stride, radiusBuffer, count, bufferToModel))
      {
        generated = false; // not drawn yet (first frame): the CPU builds this one
        break;
      }
      vtkNew<vtkMatrix4x4> bufferToWorld;
      vtkMatrix4x4::Multiply4x4(item.first->GetMatrix(), bufferToModel, bufferToWorld);
      generated = this->ComputeOnGPU(context, positionBuffer, stride, bufferToWorld->GetData(),
        radiusBuffer, item.second->GetRadiusScaleVC(item.first), count, !first);
      first = false;
    }
    generated = generated && this->CopyVolumeBufferToTexture(texture);
    if (!generated)
    {
      // the GPU could not build it: the CPU needs the particles after all
      this->GatherParticles(positions, radii, bounds, meanRadius);
    }
  }
  this->LastBuiltOnGPU = generated;
  if (!generated)
  {
    internals.ProgressBase = gatherShare;
    internals.ProgressSpan = 1.0 - gatherShare;
    if (this->ComputeOnCPU(positions, radii))
    {
      generated = texture->Create3DFromRaw(
        dims[0], dims[1], dims[2], 1, VTK_FLOAT, const_cast<float*>(this->Volume.data()));
    }
  }
  internals.ProgressBase = 0.0;
  internals.ProgressSpan = 1.0;
  if (!generated)
  {
    vtkErrorMacro(<< "Cannot create the " << dims[0] << "x" << dims[1] << "x" << dims[2]
                  << " density texture.");
  }
  return generated;
}

//------------------------------------------------------------------------------
void vtkParticleDensityVolume::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& internals = *this->Internals;
  internals.Splat->ReleaseGraphicsResources(window);
  internals.Convert->ReleaseGraphicsResources(window);
  if (internals.Counts->GetHandle() != 0 &&
    vtkParticleComputeProgram::MakeCurrentForRelease(internals.Context))
  {
    internals.Counts->ReleaseGraphicsResources();
    internals.VolumeBuffer->ReleaseGraphicsResources();
  }
  internals.Context = nullptr;
  internals.Capacity = 0;
}

//------------------------------------------------------------------------------
void vtkParticleDensityVolume::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "MaximumResolution: " << this->MaximumResolution << "\n";
  os << indent << "MaximumVoxelCount: " << this->MaximumVoxelCount << "\n";
  os << indent << "DensityFactor: " << this->DensityFactor << "\n";
  os << indent
     << "SplatMode: " << (this->SplatMode == TRILINEAR_SPLAT ? "Trilinear" : "NearestVoxel")
     << "\n";
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
  os << indent << "VoxelSize: " << this->VoxelSize << "\n";
}
