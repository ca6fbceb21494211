// vtkTransparentSphereMapper against the double-precision reference (vtkParticleReferenceRenderer
// in its transparent mode: every hit sphere per pixel, numerically integrated density, exact
// front-to-back composite) on a real LAMMPS scene (two Lennard-Jones droplets and their vapour,
// 11033 atoms, radius 0.45 x the smallest pair distance so that no spheres intersect), with the
// opacity from the atoms' speed (the fastest ones fully opaque). Five scenes cover both density
// models, solid and hollow, perspective and parallel projection, the headlight and a light kit,
// dual depth peeling and VTK's order-independent pass, an opaque box cutting through the cloud
// (the reference gets the GPU's opaque image as its opaque layer), an actor opacity < 1, and
// the opacity of a column of 6 particles (COLUMN_OPACITY).
// Required: RGB error <= 2/255 on every pixel farther than 1.5 pixels from the silhouettes of
// the opaque particles and the box's edges (translucent silhouettes are continuous and not
// excluded); the float accumulation is free of NaN/Inf. The reference's radii, colours and
// maximum opacities are computed by the test from the raw arrays (prTest::RawAttributes), not
// read back from the mapper; every read-back and comparison is checked, and at least half of the
// pixels must be compared.
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkLightKit.h"
#include "vtkLookupTable.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkParticleFrontToBackTarget.h"
#include "vtkParticleImageComparison.h"
#include "vtkParticleReferenceRenderer.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"
#include "vtkTransparentSphereMapper.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>

namespace
{
const int Size = 360;

double SmallestPairDistance(vtkPolyData* points)
{
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(points);
  locator->BuildLocator();
  vtkNew<vtkIdList> ids;
  double smallest = VTK_DOUBLE_MAX;
  double p[3];
  double q[3];
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->GetPoint(i, p);
    locator->FindClosestNPoints(2, p, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      if (ids->GetId(k) != i)
      {
        points->GetPoint(ids->GetId(k), q);
        smallest = std::min(smallest, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
      }
    }
  }
  return smallest;
}

// Mark pixels within 1.5 pixels of the silhouette of an opaque particle (exactly, with the
// reference's double-precision pixel rays), where a pixel's colour jumps and so legitimately
// depends on sub-pixel rounding. Translucent glyphs need no mask: their opacity goes continuously
// to 0 at the silhouette (the chord vanishes), so a pixel ray that grazes one differently on the
// GPU (float) and in the reference (double) changes the colour by a negligible amount.
void MarkSilhouettes(vtkParticleReferenceRenderer* reference, vtkRenderer* renderer,
  vtkActor* actor, vtkPolyData* input, const prTest::ParticleAttributes& attributes,
  vtkUnsignedCharArray* mask)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkMatrix4x4* view = camera->GetModelViewTransformMatrix();
  vtkDoubleArray* radii = attributes.Radii;
  const double scale =
    actor->GetIsIdentity() ? 1.0 : std::cbrt(std::abs(actor->GetMatrix()->Determinant()));
  const double tanHalf = std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0);
  const bool parallel = camera->GetParallelProjection() != 0;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    const double r = radii->GetValue(i) * scale;
    if (!(r > 0.0) || attributes.Opacities->GetValue(i) < 1.0 ||
      actor->GetProperty()->GetOpacity() < 1.0)
    {
      continue;
    }
    double w[4] = { 0, 0, 0, 1 };
    input->GetPoint(i, w);
    actor->GetMatrix()->MultiplyPoint(w, w);
    double c[4];
    view->MultiplyPoint(w, c);
    renderer->SetWorldPoint(w);
    renderer->WorldToDisplay();
    double display[3];
    renderer->GetDisplayPoint(display);
    const double depth = std::max(-c[2], 1e-12);
    const double footprint =
      parallel ? 2.0 * camera->GetParallelScale() / Size : 2.0 * tanHalf * depth / Size;
    const double radiusPx = r / footprint * 1.2 + 3.0;
    const int x0 = std::max(0, static_cast<int>(display[0] - radiusPx));
    const int x1 = std::min(Size - 1, static_cast<int>(display[0] + radiusPx));
    const int y0 = std::max(0, static_cast<int>(display[1] - radiusPx));
    const int y1 = std::min(Size - 1, static_cast<int>(display[1] + radiusPx));
    for (int y = y0; y <= y1; ++y)
    {
      for (int x = x0; x <= x1; ++x)
      {
        double o[3];
        double d[3];
        reference->GetPixelRay(x + 0.5, y + 0.5, o, d);
        const double co[3] = { c[0] - o[0], c[1] - o[1], c[2] - o[2] };
        const double t = vtkMath::Dot(co, d);
        const double q[3] = { co[0] - t * d[0], co[1] - t * d[1], co[2] - t * d[2] };
        const double b = vtkMath::Norm(q);
        const double local = parallel ? footprint : 2.0 * tanHalf * t / Size;
        if (std::abs(b - r) < 1.5 * local)
        {
          mask->SetValue(y * Size + x, 1);
        }
      }
    }
  }
}

struct Scene
{
  std::string Name;
  bool Peeling;
  bool Box;
  std::function<void(vtkRenderer*, vtkActor*, vtkTransparentSphereMapper*)> Setup;
};

bool RunScene(const Scene& scene, vtkPolyData* particles, double radius, double speedRange[2],
  vtkLookupTable* lut, const std::string& tempDir)
{
  bool ok = true;
  vtkNew<vtkTransparentSphereMapper> mapper;
  mapper->SetInputData(particles);
  mapper->SetRadius(radius);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("type");
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(1, 2);
  mapper->SetOpacityArrayName("speed");
  const double opacityRange[2] = { speedRange[0],
    speedRange[0] + 0.7 * (speedRange[1] - speedRange[0]) };
  mapper->SetOpacityRange(opacityRange);
  mapper->GetFrontToBackTarget()->SetKeepAccumulation(true);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.15);
  renderer->AddActor(actor);
  renderer->SetUseDepthPeeling(scene.Peeling ? 1 : 0);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Size, Size);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);

  vtkNew<vtkActor> boxActor;
  if (scene.Box)
  {
    double bounds[6];
    particles->GetBounds(bounds);
    vtkNew<vtkCubeSource> box;
    box->SetCenter(
      0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
    box->SetXLength(0.1 * (bounds[1] - bounds[0]));
    box->SetYLength(0.8 * (bounds[3] - bounds[2]));
    box->SetZLength(0.1 * (bounds[5] - bounds[4]));
    vtkNew<vtkPolyDataMapper> boxMapper;
    boxMapper->SetInputConnection(box->GetOutputPort());
    boxActor->SetMapper(boxMapper);
    boxActor->GetProperty()->SetColor(0.85, 0.85, 0.8);
    renderer->AddActor(boxActor);
  }
  renderer->ResetCamera();
  scene.Setup(renderer, actor, mapper);
  renderer->ResetCameraClippingRange();

  // the opaque image alone (for the reference's opaque layer)
  vtkNew<vtkImageData> opaqueColor;
  vtkNew<vtkImageData> opaqueDepth;
  if (scene.Box)
  {
    actor->VisibilityOff();
    window->Render();
    ok &= prTest::Check(vtkParticleImageComparison::GrabColorBuffer(window, opaqueColor) &&
        vtkParticleImageComparison::GrabDepthBuffer(window, opaqueDepth),
      scene.Name + ": opaque layer read back");
    actor->VisibilityOn();
  }
  window->Render();
  vtkNew<vtkImageData> gpu;
  ok &= prTest::Check(
    vtkParticleImageComparison::GrabColorBuffer(window, gpu), scene.Name + ": image read back");
  ok &= vtkParticleImageComparison::TestRepeatable(
    window, ("TestTransparentSphereAccuracy_" + scene.Name).c_str());
  if (!ok)
  {
    return false;
  }

  std::vector<float> accumulation;
  mapper->GetFrontToBackTarget()->GetAccumulation(accumulation);
  bool finite = !accumulation.empty();
  for (float v : accumulation)
  {
    finite &= std::isfinite(v);
  }
  ok &= prTest::Check(finite, scene.Name + ": float accumulation read back, no NaN/Inf");

  vtkNew<vtkParticleReferenceRenderer> reference;
  reference->SetRenderer(renderer);
  reference->SetActor(actor);
  // the reference's radii, colours and maximum opacities come from the raw arrays
  const double typeRange[2] = { 1, 2 };
  const prTest::ParticleAttributes attributes = prTest::RawAttributes(
    particles, std::string(), radius, "type", lut, typeRange, "speed", opacityRange);
  reference->SetParticleAttributes(attributes.Radii, attributes.Colors, attributes.Opacities);
  if (scene.Box)
  {
    reference->SetOpaqueLayer(
      opaqueColor->GetPointData()->GetScalars(), opaqueDepth->GetPointData()->GetScalars());
  }
  if (!prTest::Check(reference->Render(), scene.Name + ": reference renders"))
  {
    return false;
  }

  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetNumberOfValues(Size * Size);
  mask->Fill(0);
  MarkSilhouettes(reference, renderer, actor, particles, attributes, mask);
  if (scene.Box)
  {
    vtkNew<vtkUnsignedCharArray> edges;
    vtkParticleImageComparison::MakeEdgeMask(opaqueColor, nullptr, 1, 0.01, edges);
    for (vtkIdType i = 0; i < mask->GetNumberOfValues(); ++i)
    {
      mask->SetValue(i, mask->GetValue(i) | edges->GetValue(i));
    }
  }
  vtkSmartPointer<vtkImageData> gpuRGB = vtkParticleImageComparison::ExtractRGB(gpu);
  vtkSmartPointer<vtkImageData> refRGB =
    vtkParticleImageComparison::ExtractRGB(reference->GetColorImage());
  vtkParticleImageComparison::Result result;
  ok &=
    prTest::Check(vtkParticleImageComparison::Compare(gpuRGB, refRGB, mask, 2.0 / 255.0, result),
      scene.Name + ": the images can be compared");
  // how much of the image is translucent particles (where the comparison is meaningful)
  vtkDataArray* alpha = reference->GetTranslucentAlphaImage()->GetPointData()->GetScalars();
  long long covered = 0;
  for (vtkIdType i = 0; i < alpha->GetNumberOfTuples(); ++i)
  {
    covered += (alpha->GetComponent(i, 0) > 0.01 && mask->GetValue(i) == 0) ? 1 : 0;
  }
  std::cout << scene.Name << ": compared " << result.NumberOfComparedPixels << " pixels ("
            << covered << " with particle opacity > 0.01), excluded "
            << result.NumberOfExcludedPixels
            << "; max |GPU - reference| = " << result.MaxAbsError * 255.0 << "/255 at ("
            << result.MaxErrorPixel[0] << ", " << result.MaxErrorPixel[1] << "), RMSE "
            << result.RMSE * 255.0
            << "/255, pixels over 2/255: " << result.NumberOfPixelsOverTolerance << "; reference "
            << reference->GetLastRenderSeconds() << " s\n";
  if (result.MaxAbsError > 2.0 / 255.0)
  {
    const vtkIdType p = result.MaxErrorPixel[1] * Size + result.MaxErrorPixel[0];
    const vtkIdType id = reference->GetIdImage()->GetValue(p);
    std::cout << "  worst pixel: reference id " << id << " depth "
              << reference->GetDepthImage()->GetPointData()->GetScalars()->GetComponent(p, 0)
              << " inside " << int(reference->GetInsideImage()->GetValue(p));
    if (id >= 0)
    {
      double x[3];
      particles->GetPoint(id, x);
      std::cout << " radius " << attributes.Radii->GetValue(id) << " theta_a "
                << attributes.Opacities->GetValue(id) << " at " << x[0] << " " << x[1] << " "
                << x[2];
    }
    std::cout << "\n";
  }
  vtkParticleImageComparison::WriteErrorMap(gpuRGB, refRGB, mask,
    (tempDir + "/TestTransparentSphereAccuracy_" + scene.Name + "_error.png").c_str(), 255.0 / 4);
  vtkParticleImageComparison::WritePNG(
    gpuRGB, (tempDir + "/TestTransparentSphereAccuracy_" + scene.Name + "_gpu.png").c_str());
  vtkParticleImageComparison::WritePNG(
    refRGB, (tempDir + "/TestTransparentSphereAccuracy_" + scene.Name + "_reference.png").c_str());
  ok &= prTest::Check(result.MaxAbsError <= 2.0 / 255.0, scene.Name + ": error <= 2/255");
  ok &= prTest::Check(result.NumberOfComparedPixels > Size * Size / 2,
    scene.Name + ": at least half of the pixels compared");
  ok &= prTest::Check(covered > Size * Size / 10, scene.Name + ": enough particle pixels");
  return ok;
}
}

int TestTransparentSphereAccuracy(int argc, char* argv[])
{
  if (std::string(vtkSMPTools::GetBackend()) == "Sequential")
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  vtkSmartPointer<vtkPolyData> particles =
    prTest::ReadPolyData(prTest::DataFile(argc, argv, "lj_droplets.vtp"));
  if (!particles)
  {
    return EXIT_FAILURE;
  }
  const std::string tempDir = prTest::TempDirectory(argc, argv);
  const double radius = 0.45 * SmallestPairDistance(particles);
  std::cout << "radius " << radius << " (0.45 x the smallest pair distance)\n";
  double speedRange[2];
  particles->GetPointData()->GetArray("speed")->GetRange(speedRange);

  vtkNew<vtkLookupTable> lut;
  lut->SetNumberOfTableValues(2);
  lut->SetTableValue(0, 0.95, 0.55, 0.2, 1.0);
  lut->SetTableValue(1, 0.25, 0.55, 0.95, 1.0);
  lut->Build();

  auto zoom = [](vtkRenderer* renderer, double factor)
  {
    renderer->GetActiveCamera()->Azimuth(25);
    renderer->GetActiveCamera()->Elevation(15);
    renderer->GetActiveCamera()->Zoom(factor);
  };
  std::vector<Scene> scenes;
  scenes.push_back({ "a_constant_peeling", true, false,
    [&](vtkRenderer* renderer, vtkActor* actor, vtkTransparentSphereMapper* mapper)
    {
      mapper->SetDensityModelToConstant();
      mapper->SetVolumeMix(0.5);
      actor->GetProperty()->SetSpecular(0.3);
      actor->GetProperty()->SetSpecularPower(20);
      zoom(renderer, 2.0);
    } });
  scenes.push_back({ "b_squared_hollow_oit", false, false,
    [&](vtkRenderer* renderer, vtkActor*, vtkTransparentSphereMapper* mapper)
    {
      mapper->SetDensityModelToSquaredDistance();
      mapper->SetHollowFraction(0.5);
      mapper->SetVolumeMix(0.3);
      zoom(renderer, 2.5);
    } });
  scenes.push_back({ "c_constant_hollow_parallel_lightkit", true, false,
    [&](vtkRenderer* renderer, vtkActor* actor, vtkTransparentSphereMapper* mapper)
    {
      mapper->SetDensityModelToConstant();
      mapper->SetHollowFraction(0.8);
      mapper->SetVolumeMix(0.0);
      vtkNew<vtkLightKit> kit;
      kit->AddLightsToRenderer(renderer);
      actor->GetProperty()->SetSpecular(0.4);
      actor->GetProperty()->SetSpecularPower(30);
      renderer->GetActiveCamera()->ParallelProjectionOn();
      zoom(renderer, 2.0);
    } });
  scenes.push_back({ "d_squared_box_opacity", true, true,
    [&](vtkRenderer* renderer, vtkActor* actor, vtkTransparentSphereMapper* mapper)
    {
      mapper->SetDensityModelToSquaredDistance();
      mapper->SetVolumeMix(0.7);
      actor->GetProperty()->SetOpacity(0.8);
      zoom(renderer, 1.6);
    } });
  // Theta_i as the opacity of a column of 6 particles (the ParaView default mode, with a set
  // layer count so that the reference does not depend on the mapper's estimate)
  scenes.push_back({ "e_constant_column", true, false,
    [&](vtkRenderer* renderer, vtkActor*, vtkTransparentSphereMapper* mapper)
    {
      mapper->SetDensityModelToConstant();
      mapper->SetOpacityReference(vtkTransparentSphereMapper::COLUMN_OPACITY);
      mapper->SetColumnLayers(6.0);
      zoom(renderer, 2.0);
    } });

  bool ok = true;
  for (const Scene& scene : scenes)
  {
    ok &= RunScene(scene, particles, radius, speedRange, lut, tempDir);
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
