#include "vtkParticleAmbientVolume.h"

#include "vtkActor.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleEmissionModel.h"
#include "vtkParticleMemory.h"
#include "vtkParticleShaders.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>

vtkStandardNewMacro(vtkParticleAmbientVolume);

namespace
{
int NextPowerOfTwo(int n)
{
  int p = 1;
  while (p < n && p < (1 << 30))
  {
    p <<= 1;
  }
  return p;
}

int PowerOfTwoAtMost(int n)
{
  int p = 1;
  while (2 * p <= n)
  {
    p <<= 1;
  }
  return p;
}

// one sphere prepared for voxelisation (world coordinates)
struct Sphere
{
  double Center[3];
  double Radius;
  // extinction per voxel edge of a full voxel (w = 1) and the emission it carries
  double Sigma;
  double Color[3];
};

// The z slabs of voxels a sphere touches, [z0, z1] (empty where z1 < z0).
void SlabRange(const Sphere& sp, int nz, int& z0, int& z1)
{
  z0 = std::max(0, static_cast<int>(std::floor(sp.Center[2] - sp.Radius)));
  z1 = std::min(nz - 1, static_cast<int>(std::floor(sp.Center[2] + sp.Radius)));
}

// The spheres per z slab of voxels (slab z holds slabSpheres[slabStart[z], slabStart[z + 1])):
// each slab is then voxelised by one thread, without races.
void BinBySlab(const std::vector<Sphere>& spheres, int nz, std::vector<vtkIdType>& slabStart,
  std::vector<vtkIdType>& slabSpheres)
{
  slabStart.assign(nz + 1, 0);
  for (const Sphere& s : spheres)
  {
    int z0, z1;
    SlabRange(s, nz, z0, z1);
    for (int z = z0; z <= z1; ++z)
    {
      ++slabStart[z + 1];
    }
  }
  for (int z = 0; z < nz; ++z)
  {
    slabStart[z + 1] += slabStart[z];
  }
  slabSpheres.assign(static_cast<size_t>(slabStart[nz]), 0);
  std::vector<vtkIdType> fill(slabStart.begin(), slabStart.end() - 1);
  for (size_t j = 0; j < spheres.size(); ++j)
  {
    int z0, z1;
    SlabRange(spheres[j], nz, z0, z1);
    for (int z = z0; z <= z1; ++z)
    {
      slabSpheres[fill[z]++] = static_cast<vtkIdType>(j);
    }
  }
}

// The overlap weight of a sphere (voxel units) with voxel (x, y, z): 1 where the voxel is covered,
// 0 where it is not touched, the sphere's volume where the voxel holds it whole, else minus the
// fraction of the s^3 sub-grid samples inside (negative: partial, rescaled by PartialScales).
double CellWeight(const Sphere& sp, int x, int y, int z, int s)
{
  const double lo[3] = { double(x), double(y), double(z) };
  double nearest = 0.0;
  double farthest = 0.0;
  bool inside = true;
  for (int k = 0; k < 3; ++k)
  {
    const double c = sp.Center[k];
    const double dn = c < lo[k] ? lo[k] - c : (c > lo[k] + 1.0 ? c - lo[k] - 1.0 : 0.0);
    const double df = std::max(std::abs(c - lo[k]), std::abs(c - lo[k] - 1.0));
    nearest += dn * dn;
    farthest += df * df;
    inside = inside && c - sp.Radius >= lo[k] && c + sp.Radius <= lo[k] + 1.0;
  }
  const double r2 = sp.Radius * sp.Radius;
  if (nearest > r2)
  {
    return 0.0;
  }
  if (farthest <= r2)
  {
    return 1.0;
  }
  if (inside)
  {
    return 4.0 / 3.0 * vtkMath::Pi() * r2 * sp.Radius;
  }
  int hits = 0;
  for (int a = 0; a < s; ++a)
  {
    const double pz = lo[2] + (a + 0.5) / s - sp.Center[2];
    for (int b = 0; b < s; ++b)
    {
      const double py = lo[1] + (b + 0.5) / s - sp.Center[1];
      for (int c = 0; c < s; ++c)
      {
        const double px = lo[0] + (c + 0.5) / s - sp.Center[0];
        hits += px * px + py * py + pz * pz <= r2 ? 1 : 0;
      }
    }
  }
  return -static_cast<double>(hits) / (s * s * s); // negative: partial
}

// Per sphere for the GPU voxelisation: centre and radius, emission and extinction (float, voxel
// units: the grid coordinates were formed in double, so the scene's distance from the origin
// does not matter), and the prefix sums of its (sphere, slice) items.
void PackSpheres(const std::vector<Sphere>& spheres, double ambientEmission, int nz,
  std::vector<float>& geometry, std::vector<float>& material, std::vector<std::uint64_t>& itemStart)
{
  const size_t n = spheres.size();
  geometry.assign(4 * n, 0.0f);
  material.assign(4 * n, 0.0f);
  itemStart.assign(n + 1, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(n),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType j = begin; j < end; ++j)
      {
        const Sphere& sp = spheres[j];
        for (int k = 0; k < 3; ++k)
        {
          geometry[4 * j + k] = static_cast<float>(sp.Center[k]);
          material[4 * j + k] = static_cast<float>(sp.Sigma * ambientEmission * sp.Color[k]);
        }
        geometry[4 * j + 3] = static_cast<float>(sp.Radius);
        material[4 * j + 3] = static_cast<float>(sp.Sigma);
        int z0, z1;
        SlabRange(sp, nz, z0, z1);
        itemStart[j + 1] = static_cast<std::uint64_t>(std::max(0, z1 - z0 + 1));
      }
    });
  for (size_t j = 0; j < n; ++j)
  {
    itemStart[j + 1] += itemStart[j];
  }
}

// The (sphere, slice) pairs, at the prefix sums of PackSpheres.
void PackItems(const std::vector<Sphere>& spheres, int nz,
  const std::vector<std::uint64_t>& itemStart, std::vector<std::uint32_t>& itemData)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(spheres.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType j = begin; j < end; ++j)
      {
        int z0, z1;
        SlabRange(spheres[j], nz, z0, z1);
        std::uint32_t* out = &itemData[2 * itemStart[j]];
        for (int z = z0; z <= z1; ++z, out += 2)
        {
          out[0] = static_cast<std::uint32_t>(j);
          out[1] = static_cast<std::uint32_t>(z);
        }
      }
    });
}

// The pyramid's level dimensions (each half the finer one, at least 1) and their float offsets in
// one RGBA buffer (offsets[levels] is its size).
void PyramidLayout(const int dimensions[3], int levels, std::vector<std::array<int, 3>>& dims,
  std::vector<size_t>& offsets)
{
  dims.assign(levels, { 0, 0, 0 });
  offsets.assign(levels + 1, 0);
  dims[0] = { dimensions[0], dimensions[1], dimensions[2] };
  for (int level = 0; level < levels; ++level)
  {
    if (level > 0)
    {
      for (int k = 0; k < 3; ++k)
      {
        dims[level][k] = std::max(1, dims[level - 1][k] / 2);
      }
    }
    offsets[level + 1] =
      offsets[level] + 4 * static_cast<size_t>(dims[level][0]) * dims[level][1] * dims[level][2];
  }
}

// Per sphere the rescale factor of its partial voxels so that sum w = V_sphere / V_voxel
// (computed once over all its voxels, then applied slab by slab), and whether it is lost between
// the sub-grid's samples (then its whole volume goes into its voxel).
void PartialScales(const std::vector<Sphere>& spheres, const int dims[3], int s,
  std::vector<double>& partialScale, std::vector<char>& lost)
{
  partialScale.assign(spheres.size(), 1.0);
  lost.assign(spheres.size(), 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(spheres.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType j = begin; j < end; ++j)
      {
        const Sphere& sp = spheres[j];
        int lo[3], hi[3];
        for (int k = 0; k < 3; ++k)
        {
          lo[k] = std::max(0, static_cast<int>(std::floor(sp.Center[k] - sp.Radius)));
          hi[k] = std::min(dims[k] - 1, static_cast<int>(std::floor(sp.Center[k] + sp.Radius)));
        }
        double full = 0.0;
        double partial = 0.0;
        for (int z = lo[2]; z <= hi[2]; ++z)
        {
          for (int y = lo[1]; y <= hi[1]; ++y)
          {
            for (int x = lo[0]; x <= hi[0]; ++x)
            {
              const double w = CellWeight(sp, x, y, z, s);
              (w < 0.0 ? partial : full) += std::abs(w);
            }
          }
        }
        const double volume = 4.0 / 3.0 * vtkMath::Pi() * sp.Radius * sp.Radius * sp.Radius;
        if (partial > 0.0)
        {
          partialScale[j] = std::max(0.0, volume - full) / partial;
        }
        else if (full == 0.0)
        {
          lost[j] = 1; // smaller than the sub-grid and between its samples: all into its voxel
        }
      }
    });
}
}

//------------------------------------------------------------------------------
class vtkParticleAmbientVolume::vtkInternals
{
public:
  std::vector<std::pair<vtkActor*, vtkParticleSphereMapper*>> Props;
  std::vector<std::vector<float>> Levels;
  bool LevelsValid = false;    // Levels hold the last build's pyramid
  std::vector<Sphere> Spheres; // the last PrepareSpheres(), voxel units

  // GPU voxelisation: the four compute stages, their buffers, the pyramid's float offsets
  vtkNew<vtkParticleComputeProgram> Weights;
  vtkNew<vtkParticleComputeProgram> Deposit;
  vtkNew<vtkParticleComputeProgram> Mip;
  vtkNew<vtkParticleComputeProgram> Store;
  vtkSmartPointer<vtkOpenGLBufferObject> Geometry = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> Material = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> Items = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> Sums = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  vtkSmartPointer<vtkOpenGLBufferObject> Accumulator =
    vtkSmartPointer<vtkOpenGLBufferObject>::New();
  size_t AccumulatorFloats = 0;
  std::vector<size_t> Offsets;
  vtkOpenGLRenderWindow* Context = nullptr;
  bool WarnedNoCompute = false;
  unsigned int TextureHandle = 0; // the texture AllocateTexture() made all levels of
  // VoxeliseLevelZero: the grid comes from these (all processes') bounds and mean radius
  bool GivenGrid = false;
  double GivenBounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  double GivenMeanRadius = 0.0;
};

//------------------------------------------------------------------------------
vtkParticleAmbientVolume::vtkParticleAmbientVolume()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkParticleAmbientVolume::~vtkParticleAmbientVolume()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
double vtkParticleAmbientVolume::MeanDiscOpacity(
  double theta, int densityModel, double hollowFraction)
{
  return vtkParticleEmissionModel::MeanDiscOpacity(theta, densityModel, hollowFraction);
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::SetUpGrid(
  const double bounds[6], double meanRadius, int deviceAxisLimit)
{
  double extent[3];
  double longest = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    extent[k] = bounds[2 * k + 1] - bounds[2 * k];
    longest = std::max(longest, extent[k]);
  }
  if (!(longest > 0.0) || !std::isfinite(longest) || !(meanRadius > 0.0))
  {
    vtkErrorMacro(<< "Cannot set up an ambient volume for the extent " << longest
                  << " and mean radius " << meanRadius << ".");
    return false;
  }
  const int maximum = PowerOfTwoAtMost(this->MaximumResolution);
  int n = 0;
  if (this->Resolution > 0)
  {
    n = NextPowerOfTwo(this->Resolution);
  }
  else
  {
    // a voxel edge of one mean radius, 32 ... MaximumResolution voxels along the longest axis
    const double wanted = std::ceil(longest / meanRadius);
    n = NextPowerOfTwo(static_cast<int>(std::min(wanted, 4096.0)));
    n = std::max(n, 32);
  }
  if (n > maximum)
  {
    n = maximum;
  }
  // halve until the grid fits the memory bound and the GPU's 3D texture size; one warning
  // names the first grid and the one it became
  int wantedDims[3] = { 0, 0, 0 };
  double wantedBytes = 0.0;
  const char* reason = nullptr;
  for (;;)
  {
    const double edge = longest / n;
    int dims[3];
    bool tooLarge = false;
    for (int k = 0; k < 3; ++k)
    {
      dims[k] = NextPowerOfTwo(std::max(1, static_cast<int>(std::ceil(extent[k] / edge - 1e-9))));
      if (deviceAxisLimit > 0 && dims[k] > deviceAxisLimit)
      {
        tooLarge = true;
      }
    }
    const double voxels = static_cast<double>(dims[0]) * dims[1] * dims[2];
    // RGBA16F with all mips, and the float pyramid it is built from (16 bytes per voxel)
    const double bytes = voxels * (8.0 + 16.0) * 8.0 / 7.0;
    const bool tooMuch = bytes > this->MaximumMemory * 1048576.0;
    if ((tooLarge || tooMuch) && n > 1)
    {
      if (!reason)
      {
        std::copy(dims, dims + 3, wantedDims);
        wantedBytes = bytes;
        reason = tooMuch ? "MaximumMemory" : "the largest 3D texture";
      }
      n /= 2;
      continue;
    }
    if (reason)
    {
      vtkWarningMacro(<< "The ambient volume of " << wantedDims[0] << "x" << wantedDims[1] << "x"
                      << wantedDims[2] << " voxels (" << wantedBytes / 1048576.0
                      << " MiB with its mips and their float accumulator) exceeds " << reason
                      << ": reduced to " << dims[0] << "x" << dims[1] << "x" << dims[2]
                      << " voxels (" << bytes / 1048576.0 << " MiB).");
    }
    for (int k = 0; k < 3; ++k)
    {
      this->Dimensions[k] = dims[k];
      this->Origin[k] = 0.5 * (bounds[2 * k] + bounds[2 * k + 1]) - 0.5 * dims[k] * edge;
    }
    this->VoxelSize = edge;
    this->TextureBytes = voxels * 8.0 * 8.0 / 7.0;
    int levels = 1;
    while ((std::max(std::max(dims[0], dims[1]), dims[2]) >> (levels - 1)) > 1)
    {
      ++levels;
    }
    this->NumberOfLevels = levels;
    return true;
  }
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::Voxelise(const std::vector<double>& centers,
  const std::vector<double>& radii, const std::vector<double>& colors,
  const std::vector<double>& meanOpacities, int deviceAxisLimit)
{
  if (!this->PrepareSpheres(centers, radii, colors, meanOpacities, deviceAxisLimit))
  {
    return false;
  }
  this->DepositOnCPU();
  const double mipStart = vtkTimerLog::GetUniversalTime();
  this->BuildMips();
  this->LastMipSeconds = vtkTimerLog::GetUniversalTime() - mipStart;
  this->LastBuildOnGPU = false;
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::PrepareSpheres(const std::vector<double>& centers,
  const std::vector<double>& radii, const std::vector<double>& colors,
  const std::vector<double>& meanOpacities, int deviceAxisLimit)
{
  this->Internals->Spheres.clear();
  // the CPU pyramid's vectors keep their memory (a time series refills them: no page faults)
  this->Internals->LevelsValid = false;
  const size_t n = radii.size();
  if (centers.size() != 3 * n || colors.size() != 3 * n || meanOpacities.size() != n)
  {
    vtkErrorMacro(<< "Voxelise(): " << n
                  << " radii need 3 centre coordinates, 3 colour "
                     "components and one opacity each.");
    return false;
  }
  // bounds of the valid spheres and their mean radius
  double bounds[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  double radiusSum = 0.0;
  std::vector<size_t> valid;
  valid.reserve(n);
  for (size_t i = 0; i < n; ++i)
  {
    const double* c = &centers[3 * i];
    const double r = radii[i];
    // clear particles (<Theta> <= 0, or NaN) are not drawn and occlude nothing: they do not
    // stretch the grid either
    if (!(r > 0.0) || !std::isfinite(r) || !std::isfinite(c[0] + c[1] + c[2]) ||
      !(meanOpacities[i] > 0.0))
    {
      continue;
    }
    valid.push_back(i);
    radiusSum += r;
    for (int k = 0; k < 3; ++k)
    {
      bounds[2 * k] = std::min(bounds[2 * k], c[k] - r);
      bounds[2 * k + 1] = std::max(bounds[2 * k + 1], c[k] + r);
    }
  }
  if (valid.empty() && !this->Internals->GivenGrid)
  {
    vtkWarningMacro(<< "No particle with a finite position, a radius > 0 and an opacity > 0: "
                       "the ambient volume stays empty.");
    return false;
  }
  double meanRadius = valid.empty() ? 0.0 : radiusSum / static_cast<double>(valid.size());
  if (this->Internals->GivenGrid)
  {
    std::copy(this->Internals->GivenBounds, this->Internals->GivenBounds + 6, bounds);
    meanRadius = this->Internals->GivenMeanRadius;
  }
  const double prepareStart = vtkTimerLog::GetUniversalTime();
  if (!this->SetUpGrid(bounds, meanRadius, deviceAxisLimit))
  {
    return false;
  }
  const int nx = this->Dimensions[0];
  const int ny = this->Dimensions[1];
  const int nz = this->Dimensions[2];
  const double voxels = static_cast<double>(nx) * ny * nz;
  std::string why;
  // the float pyramid: in host memory on the CPU path, the accumulator on the GPU path (the
  // same memory on llvmpipe)
  if (!vtkParticleMemory::CanAllocate(voxels * 4.0 * sizeof(float) * 8.0 / 7.0, why))
  {
    vtkErrorMacro(<< "The " << nx << "x" << ny << "x" << nz << " ambient volume " << why
                  << ": no voxel cone tracing. Lower Resolution or MaximumMemory.");
    return false;
  }
  const double edge = this->VoxelSize;

  // the spheres with their extinction: sigma per voxel edge for w = 1 is
  // (3 / (4 r)) <Theta> edge (number density times cross-section, see the class description)
  std::vector<Sphere>& spheres = this->Internals->Spheres;
  spheres.resize(valid.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(valid.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType j = begin; j < end; ++j)
      {
        const size_t i = valid[j];
        Sphere& s = spheres[j];
        for (int k = 0; k < 3; ++k)
        {
          s.Center[k] = (centers[3 * i + k] - this->Origin[k]) / edge; // in voxel units
          s.Color[k] = std::min(std::max(colors[3 * i + k], 0.0), 1.0);
        }
        s.Radius = radii[i] / edge;
        const double theta = std::min(std::max(meanOpacities[i], 0.0), 1.0);
        s.Sigma = std::isfinite(theta) ? 0.75 / s.Radius * theta : 0.0;
      }
    });

  this->LastVoxeliseSeconds = vtkTimerLog::GetUniversalTime() - prepareStart;
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleAmbientVolume::DepositOnCPU()
{
  const double voxeliseStart = vtkTimerLog::GetUniversalTime();
  const std::vector<Sphere>& spheres = this->Internals->Spheres;
  const int nx = this->Dimensions[0];
  const int ny = this->Dimensions[1];
  const int nz = this->Dimensions[2];
  const vtkIdType voxels = static_cast<vtkIdType>(nx) * ny * nz;
  std::vector<vtkIdType> slabStart;
  std::vector<vtkIdType> slabSpheres;
  BinBySlab(spheres, nz, slabStart, slabSpheres);
  const int s = this->SubGridSamples;
  auto weightOfCell = [s](const Sphere& sp, int x, int y, int z) -> double
  { return CellWeight(sp, x, y, z, s); };
  std::vector<double> partialScale;
  std::vector<char> lost;
  PartialScales(spheres, this->Dimensions, s, partialScale, lost);

  std::vector<std::vector<float>>& levels = this->Internals->Levels;
  levels.resize(std::max<size_t>(1, levels.size()));
  std::vector<float>& level0 = levels[0];
  level0.assign(static_cast<size_t>(voxels) * 4, 0.0f);
  vtkSMPTools::For(0, nz,
    [&](vtkIdType zBegin, vtkIdType zEnd)
    {
      for (vtkIdType z = zBegin; z < zEnd; ++z)
      {
        for (vtkIdType e = slabStart[z]; e < slabStart[z + 1]; ++e)
        {
          const vtkIdType j = slabSpheres[e];
          const Sphere& sp = spheres[j];
          auto deposit = [&](int x, int y, double w)
          {
            float* v = &level0[4 * ((static_cast<size_t>(z) * ny + y) * nx + x)];
            const double sigma = w * sp.Sigma;
            v[0] += static_cast<float>(sigma * this->AmbientEmission * sp.Color[0]);
            v[1] += static_cast<float>(sigma * this->AmbientEmission * sp.Color[1]);
            v[2] += static_cast<float>(sigma * this->AmbientEmission * sp.Color[2]);
            v[3] += static_cast<float>(sigma);
          };
          if (lost[j])
          {
            const int cx = std::min(nx - 1, std::max(0, static_cast<int>(sp.Center[0])));
            const int cy = std::min(ny - 1, std::max(0, static_cast<int>(sp.Center[1])));
            const int cz = std::min(nz - 1, std::max(0, static_cast<int>(sp.Center[2])));
            if (cz == z)
            {
              deposit(cx, cy, 4.0 / 3.0 * vtkMath::Pi() * sp.Radius * sp.Radius * sp.Radius);
            }
            continue;
          }
          const int x0 = std::max(0, static_cast<int>(std::floor(sp.Center[0] - sp.Radius)));
          const int x1 = std::min(nx - 1, static_cast<int>(std::floor(sp.Center[0] + sp.Radius)));
          const int y0 = std::max(0, static_cast<int>(std::floor(sp.Center[1] - sp.Radius)));
          const int y1 = std::min(ny - 1, static_cast<int>(std::floor(sp.Center[1] + sp.Radius)));
          for (int y = y0; y <= y1; ++y)
          {
            for (int x = x0; x <= x1; ++x)
            {
              double w = weightOfCell(sp, x, y, static_cast<int>(z));
              w = w < 0.0 ? -w * partialScale[j] : w;
              if (w > 0.0)
              {
                deposit(x, y, w);
              }
            }
          }
        }
      }
    });
  this->LastVoxeliseSeconds += vtkTimerLog::GetUniversalTime() - voxeliseStart;
}

//------------------------------------------------------------------------------
void vtkParticleAmbientVolume::BuildMips()
{
  std::vector<std::vector<float>>& levels = this->Internals->Levels;
  levels.resize(std::max(1, this->NumberOfLevels));
  int dims[3] = { this->Dimensions[0], this->Dimensions[1], this->Dimensions[2] };
  for (int level = 1; level < this->NumberOfLevels; ++level)
  {
    const int child[3] = { dims[0], dims[1], dims[2] };
    for (int k = 0; k < 3; ++k)
    {
      dims[k] = std::max(1, dims[k] / 2);
    }
    const std::vector<float>& fine = levels[level - 1];
    std::vector<float>& coarse = levels[level];
    coarse.assign(static_cast<size_t>(dims[0]) * dims[1] * dims[2] * 4, 0.0f);
    // children per axis: 2, or 1 where the finer level is already 1 voxel thick
    const int sx = child[0] > 1 ? 2 : 1;
    const int sy = child[1] > 1 ? 2 : 1;
    const int sz = child[2] > 1 ? 2 : 1;
    const float norm = 1.0f / static_cast<float>(sx * sy * sz);
    vtkSMPTools::For(0, dims[2],
      [&](vtkIdType zBegin, vtkIdType zEnd)
      {
        for (vtkIdType z = zBegin; z < zEnd; ++z)
        {
          for (int y = 0; y < dims[1]; ++y)
          {
            for (int x = 0; x < dims[0]; ++x)
            {
              float sum[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
              for (int c = 0; c < sz; ++c)
              {
                for (int b = 0; b < sy; ++b)
                {
                  for (int a = 0; a < sx; ++a)
                  {
                    const size_t f = 4 *
                      ((static_cast<size_t>(sz * z + c) * child[1] + (sy * y + b)) * child[0] +
                        (sx * x + a));
                    for (int k = 0; k < 4; ++k)
                    {
                      sum[k] += fine[f + k];
                    }
                  }
                }
              }
              float* out = &coarse[4 * ((static_cast<size_t>(z) * dims[1] + y) * dims[0] + x)];
              for (int k = 0; k < 4; ++k)
              {
                out[k] = sum[k] * norm;
              }
            }
          }
        }
      });
  }
  this->Internals->LevelsValid = true;
}

//------------------------------------------------------------------------------
const std::vector<float>& vtkParticleAmbientVolume::GetLevel(int level) const
{
  static const std::vector<float> none;
  const auto& levels = this->Internals->Levels;
  return this->Internals->LevelsValid && level >= 0 && level < static_cast<int>(levels.size())
    ? levels[level]
    : none;
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::VoxeliseLevelZero(const std::vector<double>& centers,
  const std::vector<double>& radii, const std::vector<double>& colors,
  const std::vector<double>& meanOpacities, const double sphereBounds[6], double meanRadius)
{
  vtkInternals& internals = *this->Internals;
  internals.GivenGrid = true;
  std::copy(sphereBounds, sphereBounds + 6, internals.GivenBounds);
  internals.GivenMeanRadius = meanRadius;
  const bool prepared = this->PrepareSpheres(centers, radii, colors, meanOpacities, 0);
  internals.GivenGrid = false;
  if (!prepared)
  {
    return false;
  }
  this->DepositOnCPU();
  internals.Levels.resize(1);
  internals.LevelsValid = true;
  return true;
}

//------------------------------------------------------------------------------
std::vector<float>& vtkParticleAmbientVolume::GetMutableLevelZero()
{
  if (this->Internals->Levels.empty())
  {
    this->Internals->Levels.resize(1);
  }
  return this->Internals->Levels[0];
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::UploadVolumeOf(
  vtkParticleAmbientVolume* other, vtkOpenGLRenderWindow* context, vtkTextureObject* texture)
{
  const int* dims = other ? other->Dimensions : nullptr;
  if (!other || !context || !texture || other->Internals->Levels.empty() ||
    other->Internals->Levels[0].size() != 4 * static_cast<size_t>(dims[0]) * dims[1] * dims[2] ||
    other->Internals->Levels[0].empty())
  {
    vtkErrorMacro(<< "UploadVolumeOf() needs a voxelised level 0, a context and a texture.");
    return false;
  }
  std::copy(dims, dims + 3, this->Dimensions);
  std::copy(other->Origin, other->Origin + 3, this->Origin);
  this->VoxelSize = other->VoxelSize;
  this->NumberOfLevels = other->NumberOfLevels;
  this->TextureBytes = other->TextureBytes;
  this->Internals->Levels.resize(std::max(1, this->NumberOfLevels));
  this->Internals->Levels[0] = other->Internals->Levels[0];
  const double mipStart = vtkTimerLog::GetUniversalTime();
  this->BuildMips();
  this->LastMipSeconds = vtkTimerLog::GetUniversalTime() - mipStart;
  this->LastBuildOnGPU = false;
  return this->UploadLevels(context, texture);
}

//------------------------------------------------------------------------------
void vtkParticleAmbientVolume::BeginParticles()
{
  this->Internals->Props.clear();
}

//------------------------------------------------------------------------------
void vtkParticleAmbientVolume::AddParticles(vtkActor* actor, vtkParticleSphereMapper* mapper)
{
  if (actor && mapper && mapper->GetInput())
  {
    this->Internals->Props.emplace_back(actor, mapper);
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkParticleAmbientVolume::GetNumberOfParticles()
{
  vtkIdType total = 0;
  for (auto& item : this->Internals->Props)
  {
    total += item.second->GetParticleVolumeRadii()->GetNumberOfTuples();
  }
  return total;
}

//------------------------------------------------------------------------------
void vtkParticleAmbientVolume::GatherSpheres(vtkActor* actor, vtkParticleSphereMapper* mapper,
  bool ownedOnly, std::vector<double>& centers, std::vector<double>& radii,
  std::vector<double>& colors, std::vector<double>& opacities)
{
  if (!actor || !mapper || !mapper->GetInput())
  {
    return;
  }
  const vtkIdType n = mapper->GetParticleVolumeRadii()->GetNumberOfTuples();
  vtkPoints* points = mapper->GetInput()->GetPoints();
  if (n == 0 || !points || points->GetNumberOfPoints() < n)
  {
    return;
  }
  const vtkIdType offset = static_cast<vtkIdType>(radii.size());
  centers.resize(3 * (offset + n));
  radii.resize(offset + n, 0.0);
  colors.resize(3 * (offset + n), 1.0);
  opacities.resize(offset + n, 1.0);
  auto ghosts = ownedOnly
    ? vtkUnsignedCharArray::SafeDownCast(
        mapper->GetInput()->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName()))
    : nullptr;
  if (ghosts && ghosts->GetNumberOfTuples() < n)
  {
    ghosts = nullptr;
  }
  const float* r = mapper->GetParticleVolumeRadii()->GetPointer(0);
  const double scale = mapper->GetRadiusScaleVC(actor);
  const double* m = actor->GetMatrix()->GetData();
  vtkUnsignedCharArray* mapped = mapper->MapScalars(1.0);
  if (mapped && (mapped->GetNumberOfComponents() != 4 || mapped->GetNumberOfTuples() < n))
  {
    mapped = nullptr;
  }
  vtkProperty* property = actor->GetProperty();
  double propertyColor[3];
  property->GetColor(propertyColor);
  const double propertyOpacity = property->GetOpacity();
  // the glyphs' emission model: an emission-absorption profile, or the core's flat opacity
  const bool profiled = mapper->GetEmissionAbsorptionGlyphs();
  vtkDoubleArray* thetaA = mapper->GetEmissionOpacities();
  if (thetaA && thetaA->GetNumberOfTuples() < n)
  {
    thetaA = nullptr;
  }
  const int model = mapper->GetEmissionDensityModel();
  const double hollow = mapper->GetEmissionHollowFraction();
  vtkDataArray* xyz = points->GetData();
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double q[3];
        xyz->GetTuple(i, q);
        for (int k = 0; k < 3; ++k)
        {
          centers[3 * (offset + i) + k] =
            m[4 * k] * q[0] + m[4 * k + 1] * q[1] + m[4 * k + 2] * q[2] + m[4 * k + 3];
        }
        // a ghost copy (another process's particle) is left out: radius 0
        const bool ghost = ghosts && (ghosts->GetValue(i) & vtkDataSetAttributes::DUPLICATEPOINT);
        radii[offset + i] = ghost ? 0.0 : r[i] * scale;
        double theta = propertyOpacity;
        if (mapped)
        {
          const unsigned char* c = mapped->GetPointer(4 * i);
          for (int k = 0; k < 3; ++k)
          {
            colors[3 * (offset + i) + k] = c[k] / 255.0;
          }
          theta *= c[3] / 255.0;
        }
        else
        {
          for (int k = 0; k < 3; ++k)
          {
            colors[3 * (offset + i) + k] = propertyColor[k];
          }
        }
        if (thetaA)
        {
          theta *= thetaA->GetValue(i);
        }
        // the opaque core draws a flat opacity over the disc; the emission-absorption glyphs
        // their profile
        opacities[offset + i] =
          profiled ? vtkParticleEmissionModel::MeanDiscOpacity(theta, model, hollow) : theta;
      }
    });
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::EndParticles(
  vtkOpenGLRenderWindow* context, vtkTextureObject* texture)
{
  vtkInternals& internals = *this->Internals;
  if (internals.Props.empty() || !context || !texture)
  {
    vtkErrorMacro(
      << "EndParticles() needs particle props (AddParticles), a context and a texture.");
    return false;
  }
  // the spheres as drawn: world centres, radii, colours and mean disc opacities
  const double gatherStart = vtkTimerLog::GetUniversalTime();
  std::vector<double> centers;
  std::vector<double> radii;
  std::vector<double> colors;
  std::vector<double> opacities;
  for (auto& item : internals.Props)
  {
    GatherSpheres(item.first, item.second, false, centers, radii, colors, opacities);
  }
  this->LastGatherSeconds = vtkTimerLog::GetUniversalTime() - gatherStart;
  return this->BuildTexture(context, texture, centers, radii, colors, opacities);
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::BuildTexture(vtkOpenGLRenderWindow* context,
  vtkTextureObject* texture, const std::vector<double>& centers, const std::vector<double>& radii,
  const std::vector<double>& colors, const std::vector<double>& meanOpacities)
{
  if (!context || !texture)
  {
    vtkErrorMacro(<< "BuildTexture() needs a context and a texture.");
    return false;
  }
  if (!this->PrepareSpheres(
        centers, radii, colors, meanOpacities, vtkTextureObject::GetMaximumTextureSize3D(context)))
  {
    return false;
  }
  if (this->GPUVoxelisation)
  {
    std::string why;
    if (!vtkParticleComputeProgram::IsSupported(context, &why))
    {
      if (!this->Internals->WarnedNoCompute)
      {
        vtkWarningMacro(<< why << ": the ambient volume is voxelised on the CPU.");
        this->Internals->WarnedNoCompute = true;
      }
    }
    else if (this->VoxeliseOnGPU(context, texture))
    {
      return true;
    }
    else
    {
      vtkWarningMacro(<< "The GPU voxelisation failed (see above): voxelising on the CPU.");
    }
  }
  this->DepositOnCPU();
  const double mipStart = vtkTimerLog::GetUniversalTime();
  this->BuildMips();
  this->LastMipSeconds = vtkTimerLog::GetUniversalTime() - mipStart;
  this->LastBuildOnGPU = false;
  return this->UploadLevels(context, texture);
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::AllocateTexture(
  vtkOpenGLRenderWindow* context, vtkTextureObject* texture)
{
  // level 0's storage through vtkTextureObject, the mips' with glTexImage3D (no data); kept when
  // the grid did not change (a time series overwrites every level: no reallocation)
  const int* dims = this->Dimensions;
  if (texture->GetHandle() != 0 && texture->GetContext() == context &&
    texture->GetTarget() == GL_TEXTURE_3D &&
    texture->GetWidth() == static_cast<unsigned>(dims[0]) &&
    texture->GetHeight() == static_cast<unsigned>(dims[1]) &&
    texture->GetDepth() == static_cast<unsigned>(dims[2]) &&
    texture->GetMaxLevel() == this->NumberOfLevels - 1 &&
    texture->GetHandle() == this->Internals->TextureHandle)
  {
    texture->Bind();
    return true;
  }
  texture->SetContext(context);
  texture->SetInternalFormat(GL_RGBA16F);
  if (!texture->Create3DFromRaw(dims[0], dims[1], dims[2], 4, VTK_FLOAT, nullptr))
  {
    vtkErrorMacro(<< "Could not create the " << dims[0] << "x" << dims[1] << "x" << dims[2]
                  << " ambient volume texture: no voxel cone tracing.");
    return false;
  }
  texture->Bind();
  int size[3] = { dims[0], dims[1], dims[2] };
  for (int level = 1; level < this->NumberOfLevels; ++level)
  {
    for (int k = 0; k < 3; ++k)
    {
      size[k] = std::max(1, size[k] / 2);
    }
    glTexImage3D(GL_TEXTURE_3D, level, GL_RGBA16F, size[0], size[1], size[2], 0, GL_RGBA,
      GL_HALF_FLOAT, nullptr);
  }
  texture->SetBaseLevel(0);
  texture->SetMaxLevel(this->NumberOfLevels - 1);
  texture->SetMinificationFilter(vtkTextureObject::LinearMipmapLinear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetWrapS(vtkTextureObject::ClampToBorder);
  texture->SetWrapT(vtkTextureObject::ClampToBorder);
  texture->SetWrapR(vtkTextureObject::ClampToBorder);
  texture->SetBorderColor(0.0f, 0.0f, 0.0f, 0.0f);
  texture->SendParameters();
  this->Internals->TextureHandle = texture->GetHandle();
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::UploadLevels(
  vtkOpenGLRenderWindow* context, vtkTextureObject* texture)
{
  const double uploadStart = vtkTimerLog::GetUniversalTime();
  if (!this->AllocateTexture(context, texture))
  {
    return false;
  }
  // converted to half floats here, in parallel (a float upload into RGBA16F makes the driver
  // convert on one core: 1.1 s for 256^3 on llvmpipe)
  std::vector<std::uint16_t> half;
  int size[3] = { this->Dimensions[0], this->Dimensions[1], this->Dimensions[2] };
  for (int level = 0; level < this->NumberOfLevels; ++level)
  {
    if (level > 0)
    {
      for (int k = 0; k < 3; ++k)
      {
        size[k] = std::max(1, size[k] / 2);
      }
    }
    const std::vector<float>& values = this->Internals->Levels[level];
    half.resize(values.size());
    vtkSMPTools::For(0, static_cast<vtkIdType>(values.size()),
      [&](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType i = b; i < e; ++i)
        {
          half[i] = vtkParticleAmbientVolume::FloatToHalf(values[i]);
        }
      });
    glTexSubImage3D(GL_TEXTURE_3D, level, 0, 0, 0, size[0], size[1], size[2], GL_RGBA,
      GL_HALF_FLOAT, half.data());
  }
  texture->Deactivate();
  glFinish(); // the upload's cost, not the next draw's
  this->LastUploadSeconds = vtkTimerLog::GetUniversalTime() - uploadStart;
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::BuildGPUPrograms(vtkOpenGLRenderWindow* context)
{
  vtkInternals& internals = *this->Internals;
  vtkParticleComputeProgram* programs[4] = { internals.Weights, internals.Deposit, internals.Mip,
    internals.Store };
  const char* variants[4] = { "PR_AMBIENT_WEIGHTS", "PR_AMBIENT_DEPOSIT", "PR_AMBIENT_MIP",
    "PR_AMBIENT_STORE" };
  if (internals.Context && internals.Context != context)
  {
    this->ReleaseGraphicsResources(internals.Context); // programs and buffers of another
    context->MakeCurrent();                            // back to the one drawing now
  }
  if (!programs[0]->IsBuilt())
  {
    const std::string source = vtkParticleShaders::Get("AmbientVolume");
    const size_t afterVersion = source.find('\n') + 1;
    for (int p = 0; p < 4; ++p)
    {
      programs[p]->SetSource(source.substr(0, afterVersion) + "#define " + variants[p] + "\n" +
        source.substr(afterVersion));
    }
  }
  for (int p = 0; p < 4; ++p)
  {
    if (!programs[p]->Build(context))
    {
      return false;
    }
  }
  internals.Context = context;
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::VoxeliseOnGPU(
  vtkOpenGLRenderWindow* context, vtkTextureObject* texture)
{
  vtkInternals& internals = *this->Internals;
  const std::vector<Sphere>& spheres = internals.Spheres;
  const double uploadStart = vtkTimerLog::GetUniversalTime();
  vtkParticleComputeProgram* programs[4] = { internals.Weights, internals.Deposit, internals.Mip,
    internals.Store };
  if (!this->BuildGPUPrograms(context))
  {
    return false;
  }

  // per sphere: centre and radius, emission and extinction (float, voxel units: the grid
  // coordinates were formed in double, so the scene's distance from the origin does not
  // matter); per (sphere, slice) item: the pair
  const size_t n = spheres.size();
  const int nz = this->Dimensions[2];
  std::vector<float> geometry;
  std::vector<float> material;
  std::vector<std::uint64_t> itemStart;
  PackSpheres(spheres, this->AmbientEmission, nz, geometry, material, itemStart);
  const std::uint64_t items = itemStart[n];
  std::string why;
  if (items > 0xffffffffull / 64 ||
    !vtkParticleMemory::CanAllocate(static_cast<double>(items) * 8.0, why))
  {
    vtkErrorMacro(<< "The " << items << " sphere slices of the GPU voxelisation "
                  << (why.empty() ? std::string("are too many") : why) << ".");
    return false;
  }
  std::vector<std::uint32_t> itemData(2 * items);
  PackItems(spheres, nz, itemStart, itemData);

  // the pyramid's levels in one float buffer
  std::vector<std::array<int, 3>> dims;
  std::vector<size_t> offsets;
  PyramidLayout(this->Dimensions, this->NumberOfLevels, dims, offsets);
  if (offsets.back() > 0xffffffffull)
  {
    vtkErrorMacro(<< "The ambient volume is too large for the GPU voxelisation.");
    return false;
  }
  const size_t level0Bytes = offsets[1] * sizeof(float);
  if (!vtkParticleComputeProgram::AllocateStorage(internals.Geometry, geometry.size() * 4) ||
    !vtkParticleComputeProgram::AllocateStorage(internals.Material, material.size() * 4) ||
    !vtkParticleComputeProgram::AllocateStorage(internals.Items, itemData.size() * 4) ||
    !vtkParticleComputeProgram::AllocateStorage(internals.Sums, 2 * n * 4) ||
    (internals.AccumulatorFloats < offsets.back() &&
      !vtkParticleComputeProgram::AllocateStorage(
        internals.Accumulator, offsets.back() * sizeof(float))))
  {
    vtkErrorMacro(<< "Cannot allocate the GPU buffers of the ambient volume ("
                  << vtkParticleMemory::FormatBytes(offsets.back() * sizeof(float))
                  << " for its float pyramid).");
    internals.AccumulatorFloats = 0;
    return false;
  }
  internals.AccumulatorFloats = std::max(internals.AccumulatorFloats, offsets.back());
  internals.Offsets = offsets;
  vtkParticleComputeProgram::UploadStorage(
    internals.Geometry, 0, geometry.size() * 4, geometry.data());
  vtkParticleComputeProgram::UploadStorage(
    internals.Material, 0, material.size() * 4, material.data());
  vtkParticleComputeProgram::UploadStorage(
    internals.Items, 0, itemData.size() * 4, itemData.data());
  vtkParticleComputeProgram::ClearStorage(internals.Sums, 2 * n * 4, 0);
  vtkParticleComputeProgram::ClearStorage(internals.Accumulator, level0Bytes, 0);
  glFinish();
  const double voxeliseStart = vtkTimerLog::GetUniversalTime();
  this->LastUploadSeconds = voxeliseStart - uploadStart;

  // level 0: the sums of the weights per sphere, then the deposit
  vtkParticleComputeProgram::BindStorage(0, internals.Geometry);
  vtkParticleComputeProgram::BindStorage(1, internals.Material);
  vtkParticleComputeProgram::BindStorage(2, internals.Items);
  vtkParticleComputeProgram::BindStorage(3, internals.Sums);
  vtkParticleComputeProgram::BindStorage(4, internals.Accumulator);
  const unsigned int groups = static_cast<unsigned int>((items + 63) / 64);
  for (int p = 0; p < 2; ++p)
  {
    programs[p]->Use();
    programs[p]->SetUniformui("count", static_cast<unsigned int>(items));
    glUniform3i(programs[p]->GetUniformLocation("dimensions"), this->Dimensions[0],
      this->Dimensions[1], this->Dimensions[2]);
    programs[p]->SetUniformi("subGrid", this->SubGridSamples);
    programs[p]->Dispatch(groups);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  glFinish();
  const double mipStart = vtkTimerLog::GetUniversalTime();
  this->LastVoxeliseSeconds += mipStart - voxeliseStart;

  // the mips, in float
  vtkParticleComputeProgram* mip = internals.Mip;
  mip->Use();
  for (int level = 1; level < this->NumberOfLevels; ++level)
  {
    const size_t voxels = (offsets[level + 1] - offsets[level]) / 4;
    mip->SetUniformui("count", static_cast<unsigned int>(voxels));
    mip->SetUniformui("fineOffset", static_cast<unsigned int>(offsets[level - 1]));
    mip->SetUniformui("coarseOffset", static_cast<unsigned int>(offsets[level]));
    glUniform3i(mip->GetUniformLocation("fineDimensions"), dims[level - 1][0], dims[level - 1][1],
      dims[level - 1][2]);
    glUniform3i(
      mip->GetUniformLocation("coarseDimensions"), dims[level][0], dims[level][1], dims[level][2]);
    mip->Dispatch(static_cast<unsigned int>((voxels + 255) / 256));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }

  // every level into the half-float texture
  bool ok = this->AllocateTexture(context, texture);
  if (ok)
  {
    vtkParticleComputeProgram* store = internals.Store;
    store->Use();
    for (int level = 0; level < this->NumberOfLevels; ++level)
    {
      const size_t voxels = (offsets[level + 1] - offsets[level]) / 4;
      glBindImageTexture(0, texture->GetHandle(), level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
      store->SetUniformui("count", static_cast<unsigned int>(voxels));
      store->SetUniformui("levelOffset", static_cast<unsigned int>(offsets[level]));
      glUniform3i(store->GetUniformLocation("levelDimensions"), dims[level][0], dims[level][1],
        dims[level][2]);
      store->Dispatch(static_cast<unsigned int>((voxels + 255) / 256));
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    texture->Deactivate();
  }
  for (unsigned int binding = 0; binding < 5; ++binding)
  {
    vtkParticleComputeProgram::BindStorage(binding, nullptr);
  }
  vtkParticleComputeProgram::UseNone();
  glFinish();
  this->LastMipSeconds = vtkTimerLog::GetUniversalTime() - mipStart;
  this->LastBuildOnGPU = ok;
  return ok;
}

//------------------------------------------------------------------------------
bool vtkParticleAmbientVolume::ReadLevels(vtkOpenGLRenderWindow* context)
{
  vtkInternals& internals = *this->Internals;
  if (!this->LastBuildOnGPU || !context || context != internals.Context ||
    internals.Accumulator->GetHandle() == 0 || internals.Offsets.size() < 2)
  {
    return internals.LevelsValid; // the CPU's, or nothing
  }
  context->MakeCurrent();
  std::vector<float> all(internals.Offsets.back());
  if (!vtkParticleComputeProgram::DownloadStorage(
        internals.Accumulator, 0, all.size() * sizeof(float), all.data()))
  {
    return false;
  }
  internals.Levels.resize(internals.Offsets.size() - 1);
  for (size_t level = 0; level + 1 < internals.Offsets.size(); ++level)
  {
    internals.Levels[level].assign(
      all.begin() + internals.Offsets[level], all.begin() + internals.Offsets[level + 1]);
  }
  internals.LevelsValid = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleAmbientVolume::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkInternals& internals = *this->Internals;
  for (vtkParticleComputeProgram* program : { internals.Weights.Get(), internals.Deposit.Get(),
         internals.Mip.Get(), internals.Store.Get() })
  {
    program->ReleaseGraphicsResources(window);
  }
  const bool current =
    internals.Context && vtkParticleComputeProgram::MakeCurrentForRelease(internals.Context);
  for (auto* buffer : { &internals.Geometry, &internals.Material, &internals.Items, &internals.Sums,
         &internals.Accumulator })
  {
    if ((*buffer)->GetHandle() != 0)
    {
      vtkParticleComputeProgram::ReleaseStorage(*buffer, current);
    }
  }
  internals.Context = nullptr;
  internals.AccumulatorFloats = 0;
  internals.Offsets.clear();
  internals.TextureHandle = 0; // the pass releases the texture with us
}

//------------------------------------------------------------------------------
unsigned short vtkParticleAmbientVolume::FloatToHalf(float value)
{
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  const std::uint32_t sign = (bits >> 16) & 0x8000u;
  bits &= 0x7fffffffu;
  if (bits > 0x7f800000u)
  {
    return 0; // NaN: no extinction, no emission
  }
  if (bits >= 0x477ff000u)
  {
    return static_cast<unsigned short>(sign | 0x7bffu); // the largest half, 65504 (also Inf)
  }
  if (bits >= 0x38800000u)
  {
    // normal: rebias the exponent, round the mantissa to nearest even (a carry into the
    // exponent is right)
    return static_cast<unsigned short>(
      sign | ((bits - 0x38000000u + 0xfffu + ((bits >> 13) & 1u)) >> 13));
  }
  if (bits < 0x33000000u)
  {
    return static_cast<unsigned short>(sign); // below half the smallest subnormal: 0
  }
  // subnormal: the 24-bit mantissa m of m 2^(E - 150) is h 2^-24 with h = m / 2^(126 - E)
  const std::uint32_t exponent = bits >> 23;
  const std::uint32_t mantissa = (bits & 0x7fffffu) | 0x800000u;
  const std::uint32_t shift = 126u - exponent;
  const std::uint32_t rounded =
    (mantissa + (1u << (shift - 1u)) - 1u + ((mantissa >> shift) & 1u)) >> shift;
  return static_cast<unsigned short>(sign | rounded);
}

//------------------------------------------------------------------------------
void vtkParticleAmbientVolume::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "MaximumResolution: " << this->MaximumResolution << "\n";
  os << indent << "SubGridSamples: " << this->SubGridSamples << "\n";
  os << indent << "AmbientEmission: " << this->AmbientEmission << "\n";
  os << indent << "MaximumMemory: " << this->MaximumMemory << " MiB\n";
  os << indent << "GPUVoxelisation: " << this->GPUVoxelisation << "\n";
  os << indent << "LastBuildOnGPU: " << this->LastBuildOnGPU << "\n";
  os << indent << "Dimensions: " << this->Dimensions[0] << " " << this->Dimensions[1] << " "
     << this->Dimensions[2] << "\n";
  os << indent << "VoxelSize: " << this->VoxelSize << "\n";
  os << indent << "NumberOfLevels: " << this->NumberOfLevels << "\n";
  os << indent << "LastGatherSeconds: " << this->LastGatherSeconds << "\n";
  os << indent << "LastVoxeliseSeconds: " << this->LastVoxeliseSeconds << "\n";
  os << indent << "LastMipSeconds: " << this->LastMipSeconds << "\n";
  os << indent << "LastUploadSeconds: " << this->LastUploadSeconds << "\n";
}
