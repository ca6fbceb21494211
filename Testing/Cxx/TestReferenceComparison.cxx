// GPU vtkParticleSphereMapper vs. the double-precision CPU reference (vtkParticleReferenceRenderer)
// at 512x512, pixel by pixel. Every scene is rendered on the GPU (no MSAA), read back (colour and
// z-buffer), rendered by the reference, and compared at every pixel that is not within 1 pixel of
// a change of visible surface in the reference (particle id: silhouettes, occlusion edges,
// intersection curves; outer/inner side: where the near plane cuts a sphere):
//   colour: every channel within 2/255;
//   depth:  relative error of the view distance <= 1e-5, the GPU's view distance being
//           reconstructed in double from its z-buffer through the inverse projection (so the
//           tolerance has the same meaning at any distance and clipping range; a window-depth
//           tolerance would have to be scaled by the local slope of the depth mapping, which
//           varies by orders of magnitude between the scenes). At grazing incidence the depth
//           is ill-conditioned: a ray moved sideways by e (float rounding of the GPU's ray) moves
//           the hit by e / cos(incidence). Where cos(incidence) < 0.1 (hits within 6 degrees of
//           grazing, which outside the masked outlines only happen on spheres seen from very
//           close) the bound is 1e-5 * 0.1 / cos(incidence), i.e. the same sideways ray error;
//   coverage: at least 90% of the sphere pixels of the reference are compared;
//   the GPU's lighting complexity and light count equal the reference's.
// The reference's particles (radii, colours) are computed by the test from the raw arrays and the
// lookup table (prTest::RawAttributes), not read back from the mapper under test.
// Scenes: a headlight, b light kit + specular, c parallel projection, d positional spot lights,
// h double-precision data 1e6 units from the origin,
// e LAMMPS FCC block (Testing/Data/fcc_block.vtp; a missing file fails), f eye inside a big
// sphere, g camera 1e7 radii away, t 1e5 spheres (also times the reference).
// Outputs in the -T directory: <test>_<scene>_{gpu,ref,error}.png (error map: |gpu - ref| x 64,
// excluded pixels grey).
#include "prTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderer.h"
#include "vtkParticleImageComparison.h"
#include "vtkParticleReferenceRenderer.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRendererCollection.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
const int ImageSize = 512;
const double ColorTolerance = 2.0 / 255.0;
const double DepthTolerance = 1e-5;
const double GrazingCosine = 0.1;

struct Scene
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Input;
  std::function<void(vtkRenderer*, vtkActor*, vtkParticleSphereMapper*)> Setup;
  double MinimumComparedFraction = 0.9;
  // what the reference draws, computed by the test from the raw arrays (not read back from the
  // mapper): radii from RadiusArray (Radius when empty), colours from ColorArray through the
  // lookup table over ColorRange (none when empty)
  std::string RadiusArray = "radius";
  double Radius = 0.0;
  std::string ColorArray = "value";
  double ColorRange[2] = { 0.0, 21.0 };
};

void LatticeColors(vtkParticleSphereMapper* mapper, vtkLookupTable* lut)
{
  mapper->SetRadiusArrayName("radius");
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(0, 21);
}

// An oblique view of the whole input, zoomed in by zoom: spheres must be large enough on screen
// (about 60 pixels) for the 1-pixel bands around their outlines to leave 90% of their pixels.
void ObliqueCamera(vtkRenderer* renderer, double zoom)
{
  renderer->ResetCamera();
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->Azimuth(30);
  camera->Elevation(25);
  camera->OrthogonalizeViewUp();
  camera->Zoom(zoom);
  renderer->ResetCameraClippingRange();
}

// Run one scene; returns false when a check fails.
bool RunScene(
  const Scene& scene, vtkRenderWindow* window, vtkLookupTable* lut, const std::string& tempDir)
{
  // a fresh renderer (camera, lights) in the shared window
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.15);
  window->AddRenderer(renderer);
  vtkNew<vtkParticleSphereMapper> mapper;
  mapper->SetInputData(scene.Input);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  scene.Setup(renderer, actor, mapper);
  window->Render();

  vtkNew<vtkImageData> gpuColor;
  vtkNew<vtkImageData> gpuDepth;
  bool ok = prTest::Check(vtkParticleImageComparison::GrabColorBuffer(window, gpuColor, renderer),
    scene.Name + ": cannot read the colour buffer");
  ok &= prTest::Check(vtkParticleImageComparison::GrabDepthBuffer(window, gpuDepth, renderer),
    scene.Name + ": cannot read the depth buffer");
  ok &= vtkParticleImageComparison::TestRepeatable(
    window, ("TestReferenceComparison_" + scene.Name).c_str(), renderer);

  vtkNew<vtkParticleReferenceRenderer> reference;
  reference->SetRenderer(renderer);
  reference->SetActor(actor);
  const prTest::ParticleAttributes attributes = prTest::RawAttributes(
    scene.Input, scene.RadiusArray, scene.Radius, scene.ColorArray, lut, scene.ColorRange);
  reference->SetParticleAttributes(attributes.Radii, attributes.Colors, nullptr);
  ok &= prTest::Check(reference->Render(), scene.Name + ": reference render failed");
  if (!ok)
  {
    return false;
  }
  vtkOpenGLRenderer* glRenderer = vtkOpenGLRenderer::SafeDownCast(renderer);
  ok &= prTest::Check(glRenderer &&
      glRenderer->GetLightingComplexity() == reference->GetLightingComplexity() &&
      glRenderer->GetLightingCount() == reference->GetLightingCount(),
    scene.Name + ": lighting complexity/count GPU " +
      std::to_string(glRenderer ? glRenderer->GetLightingComplexity() : -1) + "/" +
      std::to_string(glRenderer ? glRenderer->GetLightingCount() : -1) + " vs. reference " +
      std::to_string(reference->GetLightingComplexity()) + "/" +
      std::to_string(reference->GetLightingCount()));

  // pixels within 1 pixel of a change of the visible surface (particle id, or outer/inner side
  // where the near plane cuts a sphere) are not compared
  vtkIdTypeArray* ids = reference->GetIdImage();
  vtkNew<vtkIdTypeArray> surfaceIds;
  reference->GetSurfaceIdImage(surfaceIds);
  vtkNew<vtkUnsignedCharArray> mask;
  vtkParticleImageComparison::MakeSilhouetteMask(surfaceIds, ImageSize, ImageSize, 1, mask);

  vtkParticleImageComparison::Result color;
  ok &= prTest::Check(vtkParticleImageComparison::Compare(
                        gpuColor, reference->GetColorImage(), mask, ColorTolerance, color),
    scene.Name + ": colour comparison impossible");

  // depth: view distances along the reference's pixel rays
  vtkNew<vtkImageData> gpuViewDepth;
  ok &= prTest::Check(reference->WindowDepthToViewDepth(gpuDepth, gpuViewDepth),
    scene.Name + ": depth conversion failed");
  const double* gpuT =
    vtkDoubleArray::SafeDownCast(gpuViewDepth->GetPointData()->GetScalars())->GetPointer(0);
  const double* refT =
    vtkDoubleArray::SafeDownCast(reference->GetViewDepthImage()->GetPointData()->GetScalars())
      ->GetPointer(0);
  const double* gpuZ =
    vtkDoubleArray::SafeDownCast(gpuDepth->GetPointData()->GetScalars())->GetPointer(0);
  const vtkIdType pixels = static_cast<vtkIdType>(ImageSize) * ImageSize;
  const double* normals =
    vtkDoubleArray::SafeDownCast(reference->GetNormalImage()->GetPointData()->GetScalars())
      ->GetPointer(0);
  vtkIdType spherePixels = 0;
  vtkIdType comparedSpherePixels = 0;
  vtkIdType grazingPixels = 0;
  vtkIdType depthMismatch = 0;    // sphere in one image, background in the other
  double maxRelDepth = 0.0;       // relative view-distance error
  double maxRelDepthScaled = 0.0; // the same, scaled by min(1, cos(incidence) / 0.1)
  vtkIdType maxRelDepthPixel = -1;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    const bool refSphere = ids->GetValue(p) >= 0;
    spherePixels += refSphere ? 1 : 0;
    if (mask->GetValue(p))
    {
      continue;
    }
    if (!refSphere)
    {
      depthMismatch += gpuZ[p] < 1.0 ? 1 : 0;
      continue;
    }
    ++comparedSpherePixels;
    if (!(gpuT[p] > 0.0))
    {
      ++depthMismatch;
      continue;
    }
    double o[3];
    double d[3];
    reference->GetPixelRay(p % ImageSize + 0.5, p / ImageSize + 0.5, o, d);
    const double* n = normals + 3 * p;
    const double cosIncidence = std::abs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]);
    grazingPixels += cosIncidence < GrazingCosine ? 1 : 0;
    double rel = std::abs(gpuT[p] - refT[p]) / refT[p];
    rel = std::isfinite(rel) ? rel : 1e300;
    maxRelDepth = std::max(maxRelDepth, rel);
    const double scaled = rel * std::min(1.0, cosIncidence / GrazingCosine);
    if (!(scaled <= maxRelDepthScaled))
    {
      maxRelDepthScaled = scaled;
      maxRelDepthPixel = p;
    }
  }
  const double fraction =
    spherePixels > 0 ? static_cast<double>(comparedSpherePixels) / spherePixels : 0.0;

  std::cout << std::setprecision(4) << "scene " << scene.Name << ": spheres "
            << reference->GetNumberOfSpheres() << ", lighting complexity "
            << reference->GetLightingComplexity() << " (" << reference->GetLightingCount()
            << " lights), compared pixels " << color.NumberOfComparedPixels << " (sphere pixels "
            << comparedSpherePixels << " of " << spherePixels << ", " << 100.0 * fraction
            << "%), max colour error x255 " << 255.0 * color.MaxAbsError << " at ("
            << color.MaxErrorPixel[0] << "," << color.MaxErrorPixel[1] << "), pixels over "
            << 255.0 * ColorTolerance << "/255 " << color.NumberOfPixelsOverTolerance
            << ", RMSE x255 " << 255.0 * color.RMSE << ", max rel. depth error " << maxRelDepth
            << " (grazing-scaled " << maxRelDepthScaled;
  if (maxRelDepthPixel >= 0)
  {
    std::cout << " at (" << maxRelDepthPixel % ImageSize << "," << maxRelDepthPixel / ImageSize
              << ")";
  }
  std::cout << "; " << grazingPixels << " grazing pixels)";
  std::cout << ", depth coverage mismatches " << depthMismatch << ", reference "
            << reference->GetLastRenderSeconds() << " s (grid " << reference->GetGridResolution()[0]
            << "x" << reference->GetGridResolution()[1] << "x" << reference->GetGridResolution()[2]
            << ", " << reference->GetNumberOfGridReferences() << " references, "
            << reference->GetNumberOfLargeSpheres() << " large, built in "
            << reference->GetLastGridBuildSeconds() << " s)\n";

  if (color.MaxAbsError > ColorTolerance)
  {
    // what the worst pixel sees in both images
    const vtkIdType p =
      static_cast<vtkIdType>(color.MaxErrorPixel[1]) * ImageSize + color.MaxErrorPixel[0];
    double g[4];
    double r[4];
    gpuColor->GetPointData()->GetScalars()->GetTuple(p, g);
    reference->GetColorImage()->GetPointData()->GetScalars()->GetTuple(p, r);
    std::cout << std::setprecision(9) << "  worst pixel: reference id " << ids->GetValue(p)
              << " rgba " << r[0] << " " << r[1] << " " << r[2] << " " << r[3] << " view depth "
              << refT[p] << "; GPU rgba " << g[0] << " " << g[1] << " " << g[2] << " " << g[3]
              << " view depth " << gpuT[p] << "\n";
  }
  if (maxRelDepthScaled > DepthTolerance)
  {
    const vtkIdType p = maxRelDepthPixel;
    std::cout << std::setprecision(9) << "  worst depth pixel: reference id " << ids->GetValue(p)
              << " inside " << int(reference->GetInsideImage()->GetValue(p)) << " view depth "
              << refT[p] << " window depth "
              << reference->GetDepthImage()->GetPointData()->GetScalars()->GetComponent(p, 0)
              << "; GPU view depth " << gpuT[p] << " window depth " << gpuZ[p] << "\n";
  }
  const std::string prefix = tempDir + "/TestReferenceComparison_" + scene.Name;
  vtkParticleImageComparison::WritePNG(gpuColor, (prefix + "_gpu.png").c_str());
  vtkParticleImageComparison::WritePNG(reference->GetColorImage(), (prefix + "_ref.png").c_str());
  vtkParticleImageComparison::WriteErrorMap(
    gpuColor, reference->GetColorImage(), mask, (prefix + "_error.png").c_str(), 64.0);

  ok &= prTest::Check(spherePixels > 0, scene.Name + ": the reference drew nothing");
  ok &= prTest::Check(color.MaxAbsError <= ColorTolerance,
    scene.Name + ": colour error " + std::to_string(255.0 * color.MaxAbsError) + "/255 > 2/255");
  ok &= prTest::Check(maxRelDepthScaled <= DepthTolerance,
    scene.Name + ": relative depth error " + std::to_string(maxRelDepthScaled) +
      " > 1e-5 (scaled at grazing incidence)");
  ok &= prTest::Check(depthMismatch == 0,
    scene.Name + ": " + std::to_string(depthMismatch) +
      " compared pixels are covered in one image and background in the other");
  ok &= prTest::Check(fraction >= scene.MinimumComparedFraction,
    scene.Name + ": only " + std::to_string(100.0 * fraction) + "% of the sphere pixels compared");
  return ok;
}
}

int TestReferenceComparison(int argc, char* argv[])
{
  const std::string tempDir = prTest::TempDirectory(argc, argv);
  // Debian's VTK defaults to the Sequential SMP backend; the reference renders rows in parallel
  if (std::string(vtkSMPTools::GetBackend()) == "Sequential")
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  std::cout << "SMP backend " << vtkSMPTools::GetBackend() << ", "
            << vtkSMPTools::GetEstimatedNumberOfThreads() << " threads\n";

  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();
  vtkSmartPointer<vtkPolyData> lattice = prTest::MakeLattice(8, 1.0, 3);

  std::vector<Scene> scenes;
  // (a) headlight (the renderer's automatic light), perspective
  scenes.push_back({ "a_headlight", lattice,
    [&](vtkRenderer* renderer, vtkActor*, vtkParticleSphereMapper* mapper)
    {
      LatticeColors(mapper, lut);
      ObliqueCamera(renderer, 2.2);
    } });
  // (b) light kit (complexity 2), specular
  scenes.push_back({ "b_lightkit", lattice,
    [&](vtkRenderer* renderer, vtkActor* actor, vtkParticleSphereMapper* mapper)
    {
      LatticeColors(mapper, lut);
      vtkNew<vtkLightKit> kit;
      kit->AddLightsToRenderer(renderer);
      actor->GetProperty()->SetSpecular(0.5);
      actor->GetProperty()->SetSpecularPower(20);
      ObliqueCamera(renderer, 2.2);
    } });
  // (c) parallel projection, light kit and specular (VTK's view vector normalize(-p) also here)
  scenes.push_back({ "c_parallel", lattice,
    [&](vtkRenderer* renderer, vtkActor* actor, vtkParticleSphereMapper* mapper)
    {
      LatticeColors(mapper, lut);
      vtkNew<vtkLightKit> kit;
      kit->AddLightsToRenderer(renderer);
      actor->GetProperty()->SetSpecular(0.5);
      actor->GetProperty()->SetSpecularPower(20);
      renderer->GetActiveCamera()->ParallelProjectionOn();
      ObliqueCamera(renderer, 2.4);
    } });
  // (d) positional lights (complexity 3): a spot light and an attenuated point light, plus an
  // actor transform (rotation, translation, uniform scale) and a coloured material
  scenes.push_back({ "d_spotlight", lattice,
    [&](vtkRenderer* renderer, vtkActor* actor, vtkParticleSphereMapper* mapper)
    {
      mapper->SetRadiusArrayName("radius");
      mapper->ScalarVisibilityOff();
      vtkProperty* property = actor->GetProperty();
      property->SetColor(0.9, 0.7, 0.3);
      property->SetAmbient(0.1);
      property->SetAmbientColor(0.2, 0.3, 1.0);
      property->SetDiffuse(0.8);
      property->SetSpecular(0.4);
      property->SetSpecularColor(1.0, 0.9, 0.8);
      property->SetSpecularPower(30);
      actor->SetOrientation(10, 20, 30);
      actor->SetPosition(1, -2, 0.5);
      actor->SetScale(1.2);
      ObliqueCamera(renderer, 3.6);
      double center[3];
      std::copy(actor->GetCenter(), actor->GetCenter() + 3, center);
      // a narrow spot from just above the eye (its cone edge crosses the view) and a bluish
      // attenuated point light to the right of the view
      vtkCamera* camera = renderer->GetActiveCamera();
      double eye[3];
      double up[3];
      double right[3];
      double forward[3];
      camera->GetPosition(eye);
      camera->GetViewUp(up);
      camera->GetDirectionOfProjection(forward);
      vtkMath::Cross(forward, up, right);
      vtkNew<vtkLight> spot;
      spot->SetLightTypeToSceneLight();
      spot->SetPositional(true);
      spot->SetPosition(eye[0] + 2 * up[0], eye[1] + 2 * up[1], eye[2] + 2 * up[2]);
      spot->SetFocalPoint(center);
      spot->SetConeAngle(5);
      spot->SetExponent(3);
      spot->SetColor(1.0, 0.95, 0.9);
      spot->SetIntensity(1.2);
      renderer->AddLight(spot);
      vtkNew<vtkLight> point;
      point->SetLightTypeToSceneLight();
      point->SetPositional(true);
      point->SetConeAngle(180);
      point->SetPosition(center[0] + 8 * right[0] + 3 * up[0] - 4 * forward[0],
        center[1] + 8 * right[1] + 3 * up[1] - 4 * forward[1],
        center[2] + 8 * right[2] + 3 * up[2] - 4 * forward[2]);
      point->SetFocalPoint(center);
      point->SetAttenuationValues(0.5, 0.05, 0.002);
      point->SetColor(0.4, 0.6, 1.0);
      renderer->AddLight(point);
    } });
  scenes.back().ColorArray.clear(); // scalar visibility off
  // (e) LAMMPS FCC block (the data file is part of the repository: missing is a failure)
  vtkSmartPointer<vtkPolyData> fcc =
    prTest::ReadPolyData(prTest::DataFile(argc, argv, "fcc_block.vtp"));
  if (!fcc)
  {
    return EXIT_FAILURE;
  }
  scenes.push_back({ "e_fcc_block", fcc,
    [&](vtkRenderer* renderer, vtkActor* actor, vtkParticleSphereMapper* mapper)
    {
      mapper->SetRadiusArrayName("radius");
      mapper->SetScalarModeToUsePointFieldData();
      mapper->SelectColorArray("type");
      mapper->SetScalarRange(1, 2);
      mapper->SetLookupTable(lut);
      vtkNew<vtkLightKit> kit;
      kit->AddLightsToRenderer(renderer);
      actor->GetProperty()->SetSpecular(0.3);
      actor->GetProperty()->SetSpecularPower(40);
      ObliqueCamera(renderer, 7.0);
    } });
  scenes.back().ColorArray = "type";
  scenes.back().ColorRange[0] = 1;
  scenes.back().ColorRange[1] = 2;
  // (f) the eye inside a big sphere: its back surface seen from inside, neighbours cut by the
  // near plane. The eye is placed where no other particle's centre is closer than 2 of its radii
  // (min 2.03): from a point just outside a sphere (e.g. the Extremes test's eye, 1.057 radii
  // from particle 57) its whole visible surface is seen at grazing incidence.
  vtkSmartPointer<vtkPolyData> inside = prTest::MakeLattice(5, 1.0, 11);
  vtkFloatArray::SafeDownCast(inside->GetPointData()->GetArray("radius"))->SetValue(62, 2.5);
  scenes.push_back({ "f_inside", inside,
    [&](vtkRenderer* renderer, vtkActor* actor, vtkParticleSphereMapper* mapper)
    {
      LatticeColors(mapper, lut);
      mapper->SetScalarRange(0, 12);
      vtkNew<vtkLightKit> kit;
      kit->AddLightsToRenderer(renderer);
      actor->GetProperty()->SetSpecular(0.3);
      actor->GetProperty()->SetSpecularPower(10);
      double c[3];
      inside->GetPoint(62, c);
      vtkCamera* camera = renderer->GetActiveCamera();
      camera->SetPosition(c[0] - 0.4, c[1] + 0.1, c[2] - 0.2);
      camera->SetFocalPoint(c[0] + 3, c[1] + 1, c[2] + 0.5);
      camera->SetViewUp(0, 0, 1);
      camera->SetViewAngle(80);
      camera->SetClippingRange(0.5, 20);
    } });
  scenes.back().ColorRange[1] = 12;
  // (g) the camera 1e7 radii away: radius 1, a 10^3 lattice of spacing 2.5, a view angle that
  // spans 13 units (6.5 sphere diameters; with 10 diameters the spheres are too small on screen
  // for 90% of their pixels to lie outside the masked outlines)
  vtkSmartPointer<vtkPolyData> far = prTest::MakeLattice(10, 2.5, 7);
  scenes.push_back({ "g_far", far,
    [&](vtkRenderer* renderer, vtkActor*, vtkParticleSphereMapper* mapper)
    {
      mapper->SetRadius(1.0);
      mapper->SetLookupTable(lut);
      mapper->SetScalarRange(0, 27);
      vtkCamera* camera = renderer->GetActiveCamera();
      const double d = 1e7;
      const double c[3] = { 11.25, 11.25, 11.25 };
      double dir[3] = { 7, -6, 6 };
      const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
      camera->SetFocalPoint(c[0], c[1], c[2]);
      camera->SetPosition(c[0] + d * dir[0] / n, c[1] + d * dir[1] / n, c[2] + d * dir[2] / n);
      camera->SetViewUp(0, 0, 1);
      camera->SetViewAngle(2.0 * std::atan(6.5 / d) * 180.0 / 3.14159265358979323846);
      renderer->ResetCameraClippingRange();
    } });
  scenes.back().RadiusArray.clear();
  scenes.back().Radius = 1.0;
  scenes.back().ColorRange[1] = 27;
  // (h) far from the origin: the lattice in double precision translated by 1e6 (float positions
  // would be off by 1/16 unit there), with one invalid particle so that the mapper's sanitised
  // copy of the positions is used. The VBO shift must keep the full precision either way.
  vtkSmartPointer<vtkPolyData> offset = vtkSmartPointer<vtkPolyData>::New();
  offset->DeepCopy(lattice);
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(lattice->GetNumberOfPoints());
    for (vtkIdType i = 0; i < lattice->GetNumberOfPoints(); ++i)
    {
      double p[3];
      lattice->GetPoint(i, p);
      points->SetPoint(i, p[0] + 1e6, p[1] - 1e6, p[2] + 1e6);
    }
    offset->SetPoints(points);
    vtkFloatArray::SafeDownCast(offset->GetPointData()->GetArray("radius"))->SetValue(0, -1.0f);
  }
  scenes.push_back({ "h_offset", offset,
    [&](vtkRenderer* renderer, vtkActor*, vtkParticleSphereMapper* mapper)
    {
      LatticeColors(mapper, lut);
      ObliqueCamera(renderer, 2.2);
    } });
  // (t) 1e5 spheres (47^3) in full view, light kit: accuracy at scale and the reference's speed.
  // The spheres are about 10 pixels wide here, so most of their pixels are outline bands: no
  // minimum compared fraction.
  vtkSmartPointer<vtkPolyData> big = prTest::MakeLattice(47, 1.0, 5);
  scenes.push_back({ "t_1e5", big,
    [&](vtkRenderer* renderer, vtkActor*, vtkParticleSphereMapper* mapper)
    {
      LatticeColors(mapper, lut);
      mapper->SetScalarRange(0, 138);
      vtkNew<vtkLightKit> kit;
      kit->AddLightsToRenderer(renderer);
      ObliqueCamera(renderer, 1.3);
    },
    0.0 });
  scenes.back().ColorRange[1] = 138;

  vtkNew<vtkRenderWindow> window;
  window->SetSize(ImageSize, ImageSize);
  window->SetMultiSamples(0);
  bool ok = true;
  for (const Scene& scene : scenes)
  {
    ok &= RunScene(scene, window, lut, tempDir);
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
