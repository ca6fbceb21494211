// vtkDensityVolumeAOPass with bad or degenerate input: no delegate, an empty renderer, no
// particle props (only an ordinary polydata actor), one particle, all particles in a plane or at
// one point, NaN/Inf positions, and requested resolutions beyond MaximumVoxelCount and the GPU's
// largest 3D texture. Each gets a clear warning where something is refused and a sane image:
// finite, the particles drawn, the background untouched, AO never brightening.
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkDensityVolumeAOPass.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkParticleDensityVolume.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderStepsPass> Steps;
  vtkNew<vtkDensityVolumeAOPass> AO;
  vtkNew<prTest::MessageCounter> Messages;
  Scene()
  {
    this->Window->SetSize(120, 100);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0.1, 0.2, 0.3);
    this->AO->SetDelegatePass(this->Steps);
    this->Messages->Observe(this->AO);
    this->Messages->Observe(this->AO->GetDensityVolume());
  }
  std::vector<int> Render(bool withAO)
  {
    this->Renderer->SetPass(withAO ? static_cast<vtkRenderPass*>(this->AO) : nullptr);
    this->Window->Render();
    vtkNew<vtkUnsignedCharArray> rgba;
    this->Window->GetRGBACharPixelData(0, 0, 119, 99, 0, rgba);
    std::vector<int> values(rgba->GetNumberOfValues());
    for (vtkIdType i = 0; i < rgba->GetNumberOfValues(); ++i)
    {
      values[i] = rgba->GetValue(i);
    }
    return values;
  }
};

vtkSmartPointer<vtkActor> Particles(vtkPoints* points, double radius)
{
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  vtkNew<vtkParticleSphereMapper> mapper;
  mapper->SetInputData(data);
  mapper->SetRadius(radius);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.85, 0.8);
  return actor;
}

// AO on vs off: the background identical, the particles drawn, never brighter; returns the
// number of darker pixels
long long CompareOnOff(Scene& scene, const std::string& what, bool& ok, int* darkest = nullptr)
{
  const std::vector<int> plain = scene.Render(false);
  const std::vector<int> occluded = scene.Render(true);
  long long background = 0;
  long long brighter = 0;
  long long darker = 0;
  long long changedBackground = 0;
  int maxDarkening = 0;
  for (size_t i = 0; i + 3 < plain.size(); i += 4)
  {
    // the scenes leave the corner pixel (0, 0) to the background
    const bool isBackground =
      plain[i] == plain[0] && plain[i + 1] == plain[1] && plain[i + 2] == plain[2];
    background += isBackground ? 1 : 0;
    const int a = plain[i] + plain[i + 1] + plain[i + 2];
    const int b = occluded[i] + occluded[i + 1] + occluded[i + 2];
    changedBackground += isBackground && a != b ? 1 : 0;
    brighter += b > a + 3 ? 1 : 0;
    darker += b < a - 3 ? 1 : 0;
    maxDarkening = std::max(maxDarkening, a - b);
  }
  if (darkest)
  {
    *darkest = maxDarkening;
  }
  std::cout << what << ": " << plain.size() / 4 - background << " particle pixels, " << darker
            << " darker with AO (by up to " << maxDarkening << "/765), " << brighter
            << " brighter, " << changedBackground << " background pixels changed; "
            << scene.Messages->Warnings << " warning(s), " << scene.Messages->Errors << " error(s)"
            << (scene.Messages->All.empty() ? "" : "; " + scene.Messages->All) << "\n";
  ok &= prTest::Check(changedBackground == 0, what + ": background untouched");
  ok &= prTest::Check(brighter == 0, what + ": AO never brightens");
  ok &= prTest::Check(background > 1000 && background < static_cast<long long>(plain.size() / 4),
    what + ": particles and background in view");
  return darker;
}
}

int TestDensityVolumeAOPassBadInput(int, char*[])
{
  bool ok = true;

  // no delegate: a warning, nothing drawn, no crash
  {
    Scene scene;
    scene.AO->SetDelegatePass(nullptr);
    scene.Renderer->SetPass(scene.AO);
    scene.Window->Render();
    ok &= prTest::Check(scene.Messages->Warnings >= 1, "no delegate: warning");
  }

  // empty renderer: one warning (not one per frame), the background
  {
    Scene scene;
    scene.Render(true);
    scene.Render(true);
    ok &= prTest::Check(scene.Messages->Warnings == 1 && scene.Messages->Errors == 0,
      "empty renderer: exactly one warning over two frames");
    ok &= prTest::Check(scene.AO->GetNumberOfVolumeBuilds() == 0, "empty renderer: no volume");
  }

  // only an ordinary polydata actor: the image is exactly the one without the pass
  {
    Scene scene;
    vtkNew<vtkCubeSource> cube;
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(cube->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    scene.Renderer->AddActor(actor);
    scene.Renderer->ResetCamera();
    const std::vector<int> plain = scene.Render(false);
    const std::vector<int> withPass = scene.Render(true);
    ok &= prTest::Check(plain == withPass, "no particle props: same image as without the pass");
    ok &= prTest::Check(scene.Messages->Warnings == 1, "no particle props: a warning");
  }

  // one particle: a lone sphere only occludes itself through its own density, at most the
  // density of one sphere of radius 0.5 in its voxel of edge 2 (4/3 pi / 64 = 0.065)
  {
    Scene scene;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(1.0, 2.0, 3.0);
    scene.Renderer->AddActor(Particles(points, 0.5));
    scene.Renderer->ResetCamera();
    int darkest = 0;
    CompareOnOff(scene, "one particle", ok, &darkest);
    ok &= prTest::Check(darkest <= std::ceil(0.0655 * (0.9 + 0.85 + 0.8) * 255.0) + 3,
      "one particle: darkened by at most its own density");
    ok &= prTest::Check(scene.AO->GetNumberOfVolumeBuilds() == 1, "one particle: one volume");
    const int* dims = scene.AO->GetDensityVolume()->GetDimensions();
    ok &= prTest::Check(dims[0] == 1 && dims[1] == 1 && dims[2] == 1, "one particle: 1 voxel");
  }

  // all particles in a plane, seen obliquely: one voxel across the plane, AO darkens
  {
    Scene scene;
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 40; ++i)
    {
      for (int j = 0; j < 40; ++j)
      {
        points->InsertNextPoint(i * 0.9, j * 0.9, 0.0);
      }
    }
    scene.Renderer->AddActor(Particles(points, 0.5));
    scene.Renderer->ResetCamera();
    scene.Renderer->GetActiveCamera()->Elevation(-50);
    scene.Renderer->ResetCameraClippingRange();
    const long long darker = CompareOnOff(scene, "plane", ok);
    const int* dims = scene.AO->GetDensityVolume()->GetDimensions();
    ok &= prTest::Check(dims[2] == 1, "plane: one voxel across it");
    ok &= prTest::Check(darker > 500, "plane: the packed layer occludes itself");
  }

  // all particles at one point: one saturated voxel, still a sane image
  {
    Scene scene;
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 1000; ++i)
    {
      points->InsertNextPoint(-4.0, 5.0, 6.0);
    }
    scene.Renderer->AddActor(Particles(points, 0.5));
    scene.Renderer->ResetCamera();
    CompareOnOff(scene, "one point", ok);
    ok &=
      prTest::Check(scene.AO->GetDensityVolume()->GetDimensions()[0] == 1, "one point: 1 voxel");
  }

  // NaN and Inf positions among valid ones: skipped by the volume (finite grid), so the picture
  // with AO is exactly that of the finite particles alone -- an upper and a lower bound on the
  // darkening (pixels blackened by a NaN would differ)
  {
    Scene scene;
    Scene finite;
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 10; ++i)
    {
      for (int j = 0; j < 10; ++j)
      {
        for (int k = 0; k < 10; ++k)
        {
          points->InsertNextPoint(i, j, k);
        }
      }
    }
    vtkNew<vtkPoints> finitePoints;
    finitePoints->DeepCopy(points);
    finite.Renderer->AddActor(Particles(finitePoints, 0.5));
    finite.Renderer->ResetCamera(0, 9, 0, 9, 0, 9);
    const std::vector<int> expected = finite.Render(true);
    points->InsertNextPoint(std::nan(""), 0.0, 0.0);
    points->InsertNextPoint(0.0, HUGE_VAL, 0.0);
    points->InsertNextPoint(0.0, 0.0, -HUGE_VAL);
    scene.Renderer->AddActor(Particles(points, 0.5));
    scene.Renderer->ResetCamera(0, 9, 0, 9, 0, 9);
    scene.Messages->Reset();
    const long long darker = CompareOnOff(scene, "NaN and Inf positions", ok);
    ok &= prTest::Check(std::isfinite(scene.AO->GetDensityVolume()->GetVoxelSize()) &&
        scene.AO->GetDensityVolume()->GetDimensions()[0] == 5,
      "NaN and Inf positions: the grid of the finite particles (5 voxels of 2 per axis)");
    ok &= prTest::Check(darker > 100, "NaN and Inf positions: AO on the finite particles");
    const std::vector<int> image = scene.Render(true);
    int worst = 0;
    for (size_t i = 0; i < image.size(); ++i)
    {
      worst = std::max(worst, std::abs(image[i] - expected[i]));
    }
    std::cout << "NaN and Inf positions: max |image - image of the finite particles| " << worst
              << "/255\n";
    ok &= prTest::Check(
      worst <= 1, "NaN and Inf positions: the same picture as the finite particles alone");
  }

  // huge resolutions: beyond MaximumVoxelCount, then beyond the GPU's largest 3D texture
  {
    Scene scene;
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 20; ++i)
    {
      for (int j = 0; j < 20; ++j)
      {
        for (int k = 0; k < 5; ++k)
        {
          points->InsertNextPoint(i * 0.9, j * 0.9, k * 0.9);
        }
      }
    }
    scene.Renderer->AddActor(Particles(points, 0.5));
    scene.Renderer->ResetCamera();
    vtkParticleDensityVolume* volume = scene.AO->GetDensityVolume();
    volume->SetMaximumResolution(4096);
    volume->SetResolution(4096);
    volume->SetMaximumVoxelCount(1 << 16);
    scene.Messages->Reset();
    CompareOnOff(scene, "resolution 4096, at most 2^16 voxels", ok);
    const int* dims = volume->GetDimensions();
    const double voxels = static_cast<double>(dims[0]) * dims[1] * dims[2];
    ok &= prTest::Check(voxels <= (1 << 16) && voxels > (1 << 14),
      "voxel budget: " + std::to_string(voxels) + " voxels, within 2^16 and not far below");
    ok &= prTest::Check(
      scene.Messages->Warnings >= 1 && scene.Messages->Errors == 0, "voxel budget: a warning");

    // the default budget (2^26 voxels) still applies: 4096 per axis would be 4096^2 x 1200
    GLint maxTexture3D = 0;
    vtkOpenGLRenderWindow::SafeDownCast(scene.Window)->MakeCurrent();
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxTexture3D);
    volume->SetMaximumVoxelCount(vtkIdType(1) << 26);
    scene.Messages->Reset();
    CompareOnOff(
      scene, "resolution 4096, GL_MAX_3D_TEXTURE_SIZE " + std::to_string(maxTexture3D), ok);
    ok &= prTest::Check(
      volume->GetDimensions()[0] <= maxTexture3D, "at most GL_MAX_3D_TEXTURE_SIZE voxels per axis");
    if (maxTexture3D < 4096)
    {
      ok &= prTest::Check(scene.Messages->All.find("3D texture") != std::string::npos,
        "GPU limit: a warning that names it");
    }
    ok &= prTest::Check(scene.Messages->Errors == 0, "GPU limit and budget: no error");
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
