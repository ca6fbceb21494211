// vtkParticleDensityVolume (Grottel et al. 2012, Eq. 5): the automatic grid (cubic voxels of four
// mean radii, degenerate boxes), the CPU volume against a direct evaluation of Eq. 5 (nearest
// voxel, the paper's splat, and the cloud-in-cell splat written out as tent weights), and the GPU
// volume against the CPU one (equal up to the GPU's fixed point, 2^-20 voxel volumes per
// particle) on the LAMMPS droplets, a user resolution, all particles in a plane, at one point
// (saturated voxel, no overflow), NaN/Inf positions, one particle and none.
#include "prTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticleComputeProgram.h"
#include "vtkParticleDensityVolume.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

namespace
{
bool Compare(vtkOpenGLRenderWindow* ctx, vtkParticleDensityVolume* volume, vtkDataArray* points,
  vtkFloatArray* radii, const std::string& what, int expectDims[3] = nullptr)
{
  bool ok = true;
  double bounds[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  double meanRadius = 0.0;
  const vtkIdType n = points->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    points->GetTuple(i, p);
    for (int k = 0; k < 3 && std::isfinite(p[0] + p[1] + p[2]); ++k)
    {
      bounds[2 * k] = std::min(bounds[2 * k], p[k]);
      bounds[2 * k + 1] = std::max(bounds[2 * k + 1], p[k]);
    }
    meanRadius += radii->GetValue(i) / n;
  }
  if (n == 0)
  {
    const double unit[6] = { 0, 1, 0, 1, 0, 1 };
    std::copy(unit, unit + 6, bounds);
    meanRadius = 0.5;
  }
  ok &= prTest::Check(volume->SetUpGrid(bounds, meanRadius), what + ": grid");
  int* dims = volume->GetDimensions();
  if (expectDims)
  {
    ok &= prTest::Check(
      dims[0] == expectDims[0] && dims[1] == expectDims[1] && dims[2] == expectDims[2],
      what + ": dimensions " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
        std::to_string(dims[2]));
  }
  ok &= prTest::Check(volume->ComputeOnCPU(points, radii), what + ": CPU volume");
  std::vector<float> cpu = volume->GetVolume();

  // Eq. 5 directly, one particle at a time, in double
  std::vector<double> direct(cpu.size(), 0.0);
  const double edge = volume->GetVoxelSize();
  const double* origin = volume->GetOrigin();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    points->GetTuple(i, p);
    if (!std::isfinite(p[0] + p[1] + p[2]))
    {
      continue; // skipped, like the mappers skip them
    }
    const double r = radii->GetValue(i);
    const double amount = 4.0 / 3.0 * vtkMath::Pi() * r * r * r / (edge * edge * edge);
    if (volume->GetSplatMode() == vtkParticleDensityVolume::NEAREST_VOXEL_SPLAT)
    {
      int v[3];
      for (int k = 0; k < 3; ++k)
      {
        v[k] = std::min(
          dims[k] - 1, std::max(0, static_cast<int>(std::floor((p[k] - origin[k]) / edge))));
      }
      direct[v[0] + dims[0] * (v[1] + dims[1] * v[2])] += amount;
      continue;
    }
    // cloud in cell, written out: the tent weight max(0, 1 - |c - t|) of every voxel centre c
    // near the particle (t: its position in voxel-centre units, clamped into the grid, which
    // folds the outside onto the boundary voxels)
    double t[3];
    int from[3];
    int to[3];
    for (int k = 0; k < 3; ++k)
    {
      t[k] = std::min(dims[k] - 1.0, std::max(0.0, (p[k] - origin[k]) / edge - 0.5));
      from[k] = std::max(0, static_cast<int>(t[k]) - 2);
      to[k] = std::min(dims[k] - 1, static_cast<int>(t[k]) + 2);
    }
    for (int z = from[2]; z <= to[2]; ++z)
    {
      for (int y = from[1]; y <= to[1]; ++y)
      {
        for (int x = from[0]; x <= to[0]; ++x)
        {
          const double w = std::max(0.0, 1.0 - std::abs(t[0] - x)) *
            std::max(0.0, 1.0 - std::abs(t[1] - y)) * std::max(0.0, 1.0 - std::abs(t[2] - z));
          direct[x + dims[0] * (y + dims[1] * z)] += amount * w;
        }
      }
    }
  }
  double worstDirect = 0.0;
  for (size_t j = 0; j < cpu.size(); ++j)
  {
    worstDirect = std::max(
      worstDirect, std::abs(cpu[j] - std::min(1.0, volume->GetDensityFactor() * direct[j])));
  }

  // the GPU from plain buffers of float positions and radii
  std::vector<float> xyz(3 * n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    points->GetTuple(i, p);
    for (int k = 0; k < 3; ++k)
    {
      xyz[3 * i + k] = static_cast<float>(p[k]);
    }
  }
  // the positions and radii as buffer objects, as a mapper's vertex buffers are
  vtkNew<vtkOpenGLBufferObject> positionBuffer;
  vtkNew<vtkOpenGLBufferObject> radiusBuffer;
  xyz.resize(std::max<size_t>(1, xyz.size()));
  std::vector<float> r(radii->GetPointer(0), radii->GetPointer(0) + n);
  r.resize(std::max<size_t>(1, r.size()));
  positionBuffer->Upload(xyz, vtkOpenGLBufferObject::ArrayBuffer);
  radiusBuffer->Upload(r, vtkOpenGLBufferObject::ArrayBuffer);
  const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  ok &= prTest::Check(volume->ComputeOnGPU(ctx, positionBuffer, 3, identity, radiusBuffer, 1.0, n),
    what + ": GPU volume");
  ok &= prTest::Check(volume->ReadVolumeBuffer(), what + ": GPU volume read back");
  positionBuffer->ReleaseGraphicsResources();
  radiusBuffer->ReleaseGraphicsResources();
  const std::vector<float>& gpu = volume->GetVolume();
  // Equal up to the fixed point, except where a particle's centre lies within float rounding
  // (~1e-6 voxels) of a voxel face and lands in the neighbour voxel on one side: such voxels
  // differ by about one particle's volume. The total must agree in any case.
  double worstGPU = 0.0;
  long long flipped = 0;
  double sumCPU = 0.0;
  double sumGPU = 0.0;
  for (size_t j = 0; j < cpu.size() && j < gpu.size(); ++j)
  {
    const double d = std::abs(cpu[j] - gpu[j]);
    if (d > 2e-4)
    {
      ++flipped;
    }
    else
    {
      worstGPU = std::max(worstGPU, d);
    }
    sumCPU += cpu[j];
    sumGPU += gpu[j];
  }
  std::cout << what << ": " << dims[0] << "x" << dims[1] << "x" << dims[2] << " voxels of " << edge
            << ", mean density " << sumCPU / cpu.size() << ", max |CPU - Eq. 5| " << worstDirect
            << ", max |GPU - CPU| " << worstGPU << " (" << flipped
            << " voxels with a particle on a face assigned differently), total " << sumCPU << " vs "
            << sumGPU << "\n";
  ok &= prTest::Check(gpu.size() == cpu.size(), what + ": GPU volume size");
  ok &= prTest::Check(worstDirect <= 1e-5, what + ": CPU volume is Eq. 5");
  // fixed point: each particle's contribution rounded to 2^-21 of a voxel volume
  ok &= prTest::Check(worstGPU <= 2e-4, what + ": GPU volume equals the CPU volume");
  ok &= prTest::Check(flipped <= std::max<long long>(4, static_cast<long long>(cpu.size() / 1000)),
    what + ": few face-straddling particles");
  const bool saturated = *std::max_element(cpu.begin(), cpu.end()) >= 1.0f;
  ok &= prTest::Check(
    saturated || std::abs(sumCPU - sumGPU) <= 1e-6 * n + 1e-3 * std::abs(sumCPU) * 0.01,
    what + ": same total density");
  return ok;
}

vtkSmartPointer<vtkFloatArray> Radii(vtkIdType n, float r)
{
  auto radii = vtkSmartPointer<vtkFloatArray>::New();
  radii->SetNumberOfTuples(n);
  radii->Fill(r);
  return radii;
}

bool Cases(int argc, char* argv[], vtkOpenGLRenderWindow* ctx, vtkParticleDensityVolume* volume,
  const std::string& prefix)
{
  bool ok = true;

  vtkSmartPointer<vtkPolyData> droplets =
    prTest::ReadPolyData(prTest::DataFile(argc, argv, "lj_droplets.vtp"));
  if (!droplets)
  {
    return false;
  }
  vtkDataArray* points = droplets->GetPoints()->GetData();
  const vtkIdType n = droplets->GetNumberOfPoints();
  // LAMMPS droplets, automatic grid: voxels of 4 mean radii = 2.0 over a ~80 sigma box
  int automatic[3] = { 40, 40, 40 };
  ok &= Compare(ctx, volume, points, Radii(n, 0.5), prefix + "droplets, automatic", automatic);
  volume->SetDensityFactor(1.0 / 0.74);
  ok &= Compare(ctx, volume, points, Radii(n, 0.5), prefix + "droplets, g = 1/0.74");
  volume->SetDensityFactor(1.0);
  volume->SetResolution(16);
  int user[3] = { 16, 16, 16 };
  ok &= Compare(ctx, volume, points, Radii(n, 0.5), prefix + "droplets, resolution 16", user);
  volume->SetResolution(0);

  // all particles in the plane z = 3: one voxel across z
  vtkNew<vtkDoubleArray> plane;
  plane->SetNumberOfComponents(3);
  for (int i = 0; i < 30; ++i)
  {
    for (int j = 0; j < 20; ++j)
    {
      plane->InsertNextTuple3(i * 1.1, j * 1.1, 3.0);
    }
  }
  int flat[3] = { 16, 11, 1 };
  ok &= Compare(ctx, volume, plane, Radii(600, 0.5), prefix + "plane", flat);
  // NaN and Inf positions are skipped
  plane->InsertNextTuple3(std::nan(""), 1.0, 3.0);
  plane->InsertNextTuple3(1.0, HUGE_VAL, 3.0);
  ok &= Compare(ctx, volume, plane, Radii(602, 0.5), prefix + "plane with NaN and Inf", flat);

  // all at one point: one voxel, saturated, no integer overflow on the GPU
  vtkNew<vtkDoubleArray> point;
  point->SetNumberOfComponents(3);
  for (int i = 0; i < 5000; ++i)
  {
    point->InsertNextTuple3(1.0, 2.0, 3.0);
  }
  int single[3] = { 1, 1, 1 };
  ok &= Compare(ctx, volume, point, Radii(5000, 0.5), prefix + "one point", single);
  ok &= prTest::Check(volume->GetVolume()[0] == 1.0f, prefix + "one point: saturated at 1");

  // one particle, and none
  vtkNew<vtkDoubleArray> one;
  one->SetNumberOfComponents(3);
  one->InsertNextTuple3(0.0, 0.0, 0.0);
  ok &= Compare(ctx, volume, one, Radii(1, 0.5), prefix + "one particle", single);
  vtkNew<vtkDoubleArray> none;
  none->SetNumberOfComponents(3);
  ok &= Compare(ctx, volume, none, Radii(0, 0.5), prefix + "no particle");

  return ok;
}
}

int TestParticleDensityVolume(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(32, 32);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  vtkOpenGLRenderWindow* ctx = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!prTest::Check(vtkParticleComputeProgram::IsSupported(ctx, nullptr), "OpenGL 4.3"))
  {
    return EXIT_FAILURE;
  }
  bool ok = true;
  vtkNew<vtkParticleDensityVolume> volume;
  for (int mode :
    { vtkParticleDensityVolume::NEAREST_VOXEL_SPLAT, vtkParticleDensityVolume::TRILINEAR_SPLAT })
  {
    volume->SetSplatMode(mode);
    ok &= Cases(argc, argv, ctx, volume,
      mode == vtkParticleDensityVolume::TRILINEAR_SPLAT ? "trilinear, " : "nearest, ");
  }

  // invalid input to SetUpGrid: an error, no grid
  const double bad[6] = { 0, 1, 0, 1, 0, 1 };
  volume->GlobalWarningDisplayOff();
  ok &= prTest::Check(!volume->SetUpGrid(bad, 0.0), "mean radius 0 refused");
  const double infinite[6] = { 0, 1, 0, HUGE_VAL, 0, 1 };
  ok &= prTest::Check(!volume->SetUpGrid(infinite, 0.5), "infinite bounds refused");
  volume->ReleaseGraphicsResources(window);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
