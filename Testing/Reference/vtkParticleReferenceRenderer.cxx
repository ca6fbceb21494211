#include "vtkParticleReferenceRenderer.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMetaballMapper.h"
#include "vtkObjectFactory.h"
#include "vtkParticleMemory.h"
#include "vtkParticleReferenceEmissionAbsorption.h"
#include "vtkParticleReferenceFrame.h"
#include "vtkParticleReferenceMetaballPass.h"
#include "vtkParticleReferenceMetaballs.h"
#include "vtkParticleReferenceRays.h"
#include "vtkParticleReferenceShading.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkTransparentSphereMapper.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkParticleReferenceRenderer);
vtkCxxSetObjectMacro(vtkParticleReferenceRenderer, Renderer, vtkRenderer);
vtkCxxSetObjectMacro(vtkParticleReferenceRenderer, Actor, vtkActor);

namespace
{
using namespace prReference;

// new image data of the given size and components
vtkSmartPointer<vtkImageData> NewImage(int w, int h, int components, const char* name)
{
  vtkSmartPointer<vtkImageData> image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkDoubleArray> values;
  values->SetName(name);
  values->SetNumberOfComponents(components);
  values->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  image->GetPointData()->SetScalars(values);
  return image;
}
}

//------------------------------------------------------------------------------
class vtkParticleReferenceRenderer::vtkInternals
{
public:
  RayCamera Camera;
  bool HaveCamera = false;
  // per pixel, bit i: the hit is inside the cone of the i-th spot light
  std::vector<std::uint32_t> ConeBits;
  SphereGrid Grid;
};

//------------------------------------------------------------------------------
vtkParticleReferenceRenderer::vtkParticleReferenceRenderer()
  : Internals(new vtkInternals)
{
  this->ColorImage = NewImage(0, 0, 4, "Color");
  this->DepthImage = NewImage(0, 0, 1, "Depth");
  this->ViewDepthImage = NewImage(0, 0, 1, "ViewDepth");
  this->NormalImage = NewImage(0, 0, 3, "Normal");
  this->IdImage = vtkSmartPointer<vtkIdTypeArray>::New();
  this->IdImage->SetName("ParticleId");
  this->InsideImage = vtkSmartPointer<vtkUnsignedCharArray>::New();
  this->InsideImage->SetName("Inside");
  this->TranslucentAlphaImage = NewImage(0, 0, 1, "TranslucentAlpha");
  this->AmbientOcclusionImage = NewImage(0, 0, 1, "AmbientOcclusion");
  this->AmbientLightImage = NewImage(0, 0, 3, "AmbientLight");
}

//------------------------------------------------------------------------------
vtkParticleReferenceRenderer::~vtkParticleReferenceRenderer()
{
  this->SetRenderer(nullptr);
  this->SetActor(nullptr);
  delete this->Internals;
}

//------------------------------------------------------------------------------
vtkImageData* vtkParticleReferenceRenderer::GetColorImage()
{
  return this->ColorImage;
}

vtkImageData* vtkParticleReferenceRenderer::GetDepthImage()
{
  return this->DepthImage;
}

vtkImageData* vtkParticleReferenceRenderer::GetViewDepthImage()
{
  return this->ViewDepthImage;
}

vtkImageData* vtkParticleReferenceRenderer::GetNormalImage()
{
  return this->NormalImage;
}

vtkImageData* vtkParticleReferenceRenderer::GetAmbientOcclusionImage()
{
  return this->AmbientOcclusionImage;
}

vtkImageData* vtkParticleReferenceRenderer::GetAmbientLightImage()
{
  return this->AmbientLightImage;
}

//------------------------------------------------------------------------------
vtkImageData* vtkParticleReferenceRenderer::GetTranslucentAlphaImage()
{
  return this->TranslucentAlphaImage;
}

//------------------------------------------------------------------------------
void vtkParticleReferenceRenderer::SetParticleAttributes(
  vtkDataArray* radii, vtkUnsignedCharArray* colors, vtkDataArray* opacities)
{
  if (!radii)
  {
    colors = nullptr;
    opacities = nullptr;
  }
  if (this->ParticleRadii != radii || this->ParticleColors != colors ||
    this->ParticleOpacities != opacities)
  {
    this->ParticleRadii = radii;
    this->ParticleColors = colors;
    this->ParticleOpacities = opacities;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkParticleReferenceRenderer::SetOpaqueLayer(vtkDataArray* rgba, vtkDataArray* windowDepth)
{
  if (!rgba || !windowDepth)
  {
    rgba = nullptr;
    windowDepth = nullptr;
  }
  if (this->OpaqueLayerColors != rgba || this->OpaqueLayerDepth != windowDepth)
  {
    this->OpaqueLayerColors = rgba;
    this->OpaqueLayerDepth = windowDepth;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
double vtkParticleReferenceRenderer::IntegrateDensity(
  int model, double hollowFraction, double radius, double impact, double tau0, double tau1)
{
  return IntegrateDensityImpl(model, hollowFraction, radius, impact, tau0, tau1);
}

double vtkParticleReferenceRenderer::NumericalMaximumPathIntegral(int model, double hollowFraction)
{
  return NumericalMaximumPathIntegralImpl(model, hollowFraction);
}

double vtkParticleReferenceRenderer::SegmentOpacity(int model, double hollowFraction, double radius,
  double impact, double tau0, double tau1, double thetaMax)
{
  if (!(thetaMax > 0.0))
  {
    return 0.0;
  }
  const double integral = IntegrateDensityImpl(model, hollowFraction, radius, impact, tau0, tau1);
  if (!(integral > 0.0))
  {
    return 0.0;
  }
  if (thetaMax >= 1.0)
  {
    return 1.0;
  }
  const bool squared = model == vtkTransparentSphereMapper::SQUARED_DISTANCE_DENSITY;
  const double scale = squared ? radius * radius * radius : radius;
  const double maximum = NumericalMaximumPathIntegralImpl(model, hollowFraction) * scale;
  if (!(maximum > 0.0))
  {
    return 0.0;
  }
  return OpacityFromOpticalDepth(-std::log1p(-thetaMax) * (integral / maximum));
}

//------------------------------------------------------------------------------
bool vtkParticleReferenceRenderer::GetPixelRay(
  double x, double y, double origin[3], double direction[3])
{
  if (!this->Internals->HaveCamera)
  {
    return false;
  }
  double tNear;
  double tFar;
  this->Internals->Camera.PixelRay(x, y, origin, direction, tNear, tFar);
  return true;
}

//------------------------------------------------------------------------------
vtkIdTypeArray* vtkParticleReferenceRenderer::GetIdImage()
{
  return this->IdImage;
}

vtkUnsignedCharArray* vtkParticleReferenceRenderer::GetInsideImage()
{
  return this->InsideImage;
}

//------------------------------------------------------------------------------
void vtkParticleReferenceRenderer::GetSurfaceIdImage(vtkIdTypeArray* surfaceIds)
{
  if (!surfaceIds)
  {
    return;
  }
  const vtkIdType n = this->IdImage->GetNumberOfTuples();
  const std::vector<std::uint32_t>& cones = this->Internals->ConeBits;
  const bool haveCones = cones.size() == static_cast<size_t>(n);
  surfaceIds->SetNumberOfComponents(1);
  surfaceIds->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkIdType id = this->IdImage->GetValue(i);
    const vtkIdType surface = 2 * id + this->InsideImage->GetValue(i);
    const vtkIdType cone = haveCones ? static_cast<vtkIdType>(cones[i]) : 0;
    surfaceIds->SetValue(i, id < 0 ? -1 : (surface << MaximumConeBits) + cone);
  }
}

//------------------------------------------------------------------------------
namespace
{
// The ellipsoid x = C + A u of semi-axes a and unit quaternion q (w, x, y, z) under the linear
// map axesToView (vtkParticleSphereMapper::GetAxesToViewMatrix): A = axesToView R(q) diag(a),
// its inverse, and R the largest singular value of A (the radius of the smallest sphere about C
// that holds the ellipsoid), all in double. False for a degenerate A.
bool SetEllipsoid(
  prReference::SphereVC& s, const double axesToView[3][3], const float* a, const float* qf)
{
  const double w = qf[0];
  const double x = qf[1];
  const double y = qf[2];
  const double z = qf[3];
  const double rotation[3][3] = {
    { 1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y) },
    { 2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x) },
    { 2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y) },
  };
  double body[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      body[i][j] = rotation[i][j] * a[j];
    }
  }
  vtkMath::Multiply3x3(axesToView, body, s.ToVC);
  if (!(std::abs(vtkMath::Determinant3x3(s.ToVC)) > 0.0))
  {
    return false;
  }
  vtkMath::Invert3x3(s.ToVC, s.ToUnit);
  double gram[3][3];
  double transposed[3][3];
  vtkMath::Transpose3x3(s.ToVC, transposed);
  vtkMath::Multiply3x3(transposed, s.ToVC, gram);
  double eigenvalues[3];
  double eigenvectors[3][3];
  vtkMath::Diagonalize3x3(gram, eigenvalues, eigenvectors);
  const double largest = std::max({ eigenvalues[0], eigenvalues[1], eigenvalues[2] });
  // (a hair larger: the grid's cells must hold the whole ellipsoid)
  s.R = std::sqrt(std::max(largest, 0.0)) * (1.0 + 1e-12);
  s.Ellipsoid = true;
  return std::isfinite(s.R) && s.R > 0.0;
}
}

//------------------------------------------------------------------------------
bool vtkParticleReferenceRenderer::Render()
{
  const double startTime = vtkTimerLog::GetUniversalTime();
  vtkInternals& internals = *this->Internals;
  internals.HaveCamera = false;
  auto fail = [this](const char* why)
  {
    vtkErrorMacro(<< why);
    this->ColorImage = NewImage(0, 0, 4, "Color");
    this->DepthImage = NewImage(0, 0, 1, "Depth");
    this->ViewDepthImage = NewImage(0, 0, 1, "ViewDepth");
    this->NormalImage = NewImage(0, 0, 3, "Normal");
    this->IdImage->SetNumberOfTuples(0);
    this->InsideImage->SetNumberOfTuples(0);
    this->TranslucentAlphaImage = NewImage(0, 0, 1, "TranslucentAlpha");
    this->AmbientOcclusionImage = NewImage(0, 0, 1, "AmbientOcclusion");
    this->AmbientLightImage = NewImage(0, 0, 3, "AmbientLight");
    return false;
  };
  if (!this->Renderer)
  {
    return fail("No renderer.");
  }
  if (!this->Actor)
  {
    return fail("No actor.");
  }
  vtkParticleSphereMapper* mapper = vtkParticleSphereMapper::SafeDownCast(this->Actor->GetMapper());
  if (!mapper)
  {
    return fail("The actor's mapper is not a vtkParticleSphereMapper.");
  }
  vtkCamera* camera = this->Renderer->GetActiveCamera();

  // image size and aspect ratio, as vtkOpenGLCamera::GetKeyMatrices
  int width = this->ImageSize[0];
  int height = this->ImageSize[1];
  double aspect;
  if (width > 0 && height > 0)
  {
    aspect = static_cast<double>(width) / height;
  }
  else
  {
    int x0, y0;
    this->Renderer->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
    if (width <= 0 || height <= 0)
    {
      return fail("The renderer's viewport is empty (no render window?): set ImageSize.");
    }
    aspect = this->Renderer->GetTiledAspectRatio();
  }

  // matrices (VTK: row-major, column vectors)
  RayCamera& cam = internals.Camera;
  cam.Width = width;
  cam.Height = height;
  cam.Parallel = camera->GetParallelProjection() != 0;
  vtkMatrix4x4* projection = camera->GetProjectionTransformMatrix(aspect, -1, 1);
  vtkMatrix4x4::DeepCopy(cam.P, projection);
  vtkMatrix4x4::Invert(cam.P, cam.PInv);
  internals.HaveCamera = true;
  double viewMatrix[16];
  vtkMatrix4x4::DeepCopy(viewMatrix, camera->GetModelViewTransformMatrix());
  double mcvc[16];
  vtkMatrix4x4::Multiply4x4(viewMatrix, &this->Actor->GetMatrix()->Element[0][0], mcvc);
  // normal matrix of the view transform (inverse transpose of its 3x3 part)
  double viewInverse[16];
  vtkMatrix4x4::Invert(viewMatrix, viewInverse);

  // ---- spheres in view coordinates
  if (!mapper->GetStatic() && mapper->GetInputAlgorithm())
  {
    mapper->GetInputAlgorithm()->Update(); // as the mapper does before drawing
  }
  vtkPolyData* input = mapper->GetInput();
  const vtkIdType numPts =
    (input && input->GetPoints()) ? input->GetNumberOfPoints() : static_cast<vtkIdType>(0);
  const bool given = this->ParticleRadii != nullptr; // the caller's attributes
  vtkDataArray* radii = nullptr;
  double radiusScale = 1.0;
  vtkUnsignedCharArray* colors = nullptr;
  if (given)
  {
    radii = this->ParticleRadii;
    colors = this->ParticleColors;
    const vtkDataArray* opacities = this->ParticleOpacities;
    if (radii->GetNumberOfTuples() != numPts ||
      (colors && (colors->GetNumberOfTuples() != numPts || colors->GetNumberOfComponents() != 4)) ||
      (opacities && opacities->GetNumberOfTuples() != numPts))
    {
      return fail("The particle attributes do not have one tuple (RGBA colours) per point.");
    }
    radiusScale = this->Actor->GetIsIdentity()
      ? 1.0
      : std::cbrt(std::abs(this->Actor->GetMatrix()->Determinant()));
  }
  else
  {
    radii = mapper->GetParticleRadii(); // validates the input
    radiusScale = mapper->GetRadiusScaleVC(this->Actor);
    colors = numPts > 0 ? mapper->MapScalars(1.0) : nullptr;
    if (colors && (colors->GetNumberOfTuples() != numPts || colors->GetNumberOfComponents() != 4))
    {
      colors = nullptr; // cell scalars do not colour particles (as on the GPU)
    }
  }
  vtkProperty* property = this->Actor->GetProperty();
  const double opacity = property->GetOpacity();

  // ---- oriented ellipsoids (the mapper's semi-axes and unit quaternions, as uploaded)
  vtkFloatArray* ellipsoidAxes = numPts > 0 ? mapper->GetParticleAxes() : nullptr;
  vtkFloatArray* ellipsoidOrientations =
    ellipsoidAxes ? mapper->GetParticleOrientations() : nullptr;
  double axesToView[3][3];
  if (ellipsoidAxes)
  {
    if (given)
    {
      return fail("SetParticleAttributes() gives radii, but the mapper draws ellipsoids.");
    }
    if (mapper->IsA("vtkMetaballMapper"))
    {
      return fail("A vtkMetaballMapper draws no ellipsoids.");
    }
    mapper->GetAxesToViewMatrix(this->Renderer, this->Actor, axesToView);
  }

  // ---- transparent mode: the model's parameters and Theta_a
  vtkTransparentSphereMapper* transparentMapper = vtkTransparentSphereMapper::SafeDownCast(mapper);
  const bool transparent = transparentMapper != nullptr;
  int densityModel = vtkTransparentSphereMapper::CONSTANT_DENSITY;
  double hollowFraction = 0.0;
  double volumeMix = 0.0;
  bool exactOverlaps = true;
  double maximumPathIntegral = 0.0; // for radius 1
  vtkDataArray* opacityArray = nullptr;
  std::vector<double> layerColors;
  std::vector<double> layerDepths;
  if (transparent)
  {
    densityModel = transparentMapper->GetDensityModel();
    hollowFraction = transparentMapper->GetHollowFraction();
    volumeMix = transparentMapper->GetVolumeMix();
    exactOverlaps =
      transparentMapper->GetOverlapCompositing() != vtkTransparentSphereMapper::SORTED_SPHERES;
    // COLUMN_OPACITY: Theta_i is the opacity of a column of L particles, i.e. I_max x L
    maximumPathIntegral = NumericalMaximumPathIntegralImpl(densityModel, hollowFraction) *
      transparentMapper->GetEffectiveColumnLayers();
    if (given)
    {
      opacityArray = this->ParticleOpacities; // nullptr: Theta_a = 1
    }
    else if (numPts > 0)
    {
      transparentMapper->GetBounds(); // prepares the opacities (see GetParticleOpacities())
      opacityArray = transparentMapper->GetParticleOpacities();
      if (!opacityArray || opacityArray->GetNumberOfTuples() != numPts)
      {
        return fail("The mapper's particle opacities do not match its input.");
      }
    }
    if (this->OpaqueLayerColors && this->OpaqueLayerDepth)
    {
      const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
      if (this->OpaqueLayerColors->GetNumberOfComponents() != 4 ||
        this->OpaqueLayerColors->GetNumberOfTuples() != pixels ||
        this->OpaqueLayerDepth->GetNumberOfComponents() != 1 ||
        this->OpaqueLayerDepth->GetNumberOfTuples() != pixels)
      {
        return fail("The opaque layer is not a 4-component colour and a 1-component depth array "
                    "of the image's size.");
      }
      layerColors.resize(4 * static_cast<size_t>(pixels));
      layerDepths.resize(static_cast<size_t>(pixels));
      for (vtkIdType i = 0; i < pixels; ++i)
      {
        for (int k = 0; k < 4; ++k)
        {
          layerColors[4 * i + k] = this->OpaqueLayerColors->GetComponent(i, k);
        }
        layerDepths[i] = this->OpaqueLayerDepth->GetComponent(i, 0);
      }
    }
  }
  // per sphere (transparent mode): Theta_i, kappa_i = -ln(1 - Theta_i), I_max at its radius
  std::vector<double> sphereTheta;
  std::vector<double> sphereKappa;
  std::vector<double> sphereMaximum;

  std::vector<double> planes;
  for (int i = 0; i < mapper->GetNumberOfClippingPlanes(); ++i)
  {
    double eq[4];
    mapper->GetClippingPlaneInDataCoords(this->Actor->GetMatrix(), i, eq);
    planes.insert(planes.end(), eq, eq + 4);
  }

  std::vector<SphereVC> spheres;
  std::vector<vtkIdType> ids;
  if (numPts > 0 && radii && radii->GetNumberOfTuples() == numPts && opacity > 0.0)
  {
    spheres.reserve(numPts);
    ids.reserve(numPts);
    vtkPoints* points = input->GetPoints();
    for (vtkIdType i = 0; i < numPts; ++i)
    {
      const double r = radii->GetComponent(i, 0) * radiusScale;
      if (!(r > 0.0) || !std::isfinite(r))
      {
        continue; // skipped particle
      }
      if (colors && colors->GetValue(4 * i + 3) == 0)
      {
        continue; // opacity 0: every fragment is discarded
      }
      double p[4] = { 0, 0, 0, 1 };
      points->GetPoint(i, p);
      bool clipped = false;
      for (size_t k = 0; k < planes.size(); k += 4)
      {
        clipped |=
          planes[k] * p[0] + planes[k + 1] * p[1] + planes[k + 2] * p[2] + planes[k + 3] < 0.0;
      }
      if (clipped)
      {
        continue;
      }
      double c[4];
      MultiplyPoint(mcvc, p, c);
      SphereVC s;
      for (int k = 0; k < 3; ++k)
      {
        s.C[k] = c[k] / c[3];
      }
      s.R = r;
      if (ellipsoidAxes &&
        !SetEllipsoid(s, axesToView, ellipsoidAxes->GetPointer(3 * i),
          ellipsoidOrientations->GetPointer(4 * i)))
      {
        continue;
      }
      if (!std::isfinite(s.C[0]) || !std::isfinite(s.C[1]) || !std::isfinite(s.C[2]))
      {
        continue;
      }
      if (transparent)
      {
        double theta = (opacityArray ? opacityArray->GetComponent(i, 0) : 1.0) * opacity;
        if (colors)
        {
          theta *= colors->GetValue(4 * i + 3) / 255.0;
        }
        if (!(theta > 0.0))
        {
          continue; // not drawn at all
        }
        theta = std::min(theta, 1.0);
        sphereTheta.push_back(theta);
        sphereKappa.push_back(theta < 1.0 ? -std::log1p(-theta) : 0.0);
        // (an ellipsoid's largest semi-axis: s.R, see MakeSegment)
        sphereMaximum.push_back(maximumPathIntegral *
          (densityModel == vtkTransparentSphereMapper::SQUARED_DISTANCE_DENSITY ? s.R * s.R * s.R
                                                                                : s.R));
      }
      spheres.push_back(s);
      ids.push_back(i);
    }
  }
  if (spheres.size() > std::numeric_limits<std::uint32_t>::max())
  {
    return fail("Too many particles for the reference renderer.");
  }
  this->NumberOfSpheres = static_cast<vtkIdType>(spheres.size());

  const double gridStart = vtkTimerLog::GetUniversalTime();
  internals.Grid.Build(spheres);
  this->LastGridBuildSeconds = vtkTimerLog::GetUniversalTime() - gridStart;
  for (int k = 0; k < 3; ++k)
  {
    this->GridResolution[k] = internals.Grid.GetResolution()[k];
  }
  this->NumberOfGridReferences = static_cast<vtkIdType>(internals.Grid.GetNumberOfReferences());
  this->NumberOfLargeSpheres = static_cast<vtkIdType>(internals.Grid.GetNumberOfLarge());

  // ---- lights, as vtkOpenGLRenderer::UpdateLights / UpdateLightingUniforms
  std::vector<LightVC> lights;
  const int complexity =
    SetUpLights(this->Renderer, camera, viewMatrix, viewInverse, property, input, lights);
  this->LightingComplexity = complexity;
  this->LightingCount = complexity > 0 ? static_cast<int>(lights.size()) : 0;

  // ---- material
  double ambientK = property->GetAmbient();
  double diffuseK = property->GetDiffuse();
  double ambientColor[3];
  double diffuseColor[3];
  double specularColor[3];
  property->GetAmbientColor(ambientColor);
  property->GetDiffuseColor(diffuseColor);
  property->GetSpecularColor(specularColor);
  const double specularK = property->GetSpecular();
  for (double& c : specularColor)
  {
    c *= specularK;
  }
  const double specularPower = property->GetSpecularPower();
  double background[3];
  this->Renderer->GetBackground(background);
  const double backgroundAlpha = this->Renderer->GetBackgroundAlpha();

  // ---- outputs: 11 doubles, an id, a flag and the cone bits per pixel
  {
    const double bytes = static_cast<double>(width) * height *
      (11.0 * sizeof(double) + sizeof(vtkIdType) + 1.0 + sizeof(std::uint32_t));
    std::string why;
    if (!vtkParticleMemory::CanAllocate(bytes, why))
    {
      const std::string text = "The reference images of " + std::to_string(width) + " x " +
        std::to_string(height) + " pixels: " + why + ".";
      return fail(text.c_str());
    }
  }
  this->ColorImage = NewImage(width, height, 4, "Color");
  this->DepthImage = NewImage(width, height, 1, "Depth");
  this->ViewDepthImage = NewImage(width, height, 1, "ViewDepth");
  this->NormalImage = NewImage(width, height, 3, "Normal");
  this->IdImage->SetNumberOfComponents(1);
  this->IdImage->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  double* colorOut =
    vtkDoubleArray::SafeDownCast(this->ColorImage->GetPointData()->GetScalars())->GetPointer(0);
  double* depthOut =
    vtkDoubleArray::SafeDownCast(this->DepthImage->GetPointData()->GetScalars())->GetPointer(0);
  double* viewDepthOut =
    vtkDoubleArray::SafeDownCast(this->ViewDepthImage->GetPointData()->GetScalars())->GetPointer(0);
  double* normalOut =
    vtkDoubleArray::SafeDownCast(this->NormalImage->GetPointData()->GetScalars())->GetPointer(0);
  vtkIdType* idOut = this->IdImage->GetPointer(0);
  this->InsideImage->SetNumberOfComponents(1);
  this->InsideImage->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  unsigned char* insideOut = this->InsideImage->GetPointer(0);
  internals.ConeBits.assign(static_cast<size_t>(width) * height, 0);
  std::uint32_t* coneOut = internals.ConeBits.data();
  this->TranslucentAlphaImage = NewImage(width, height, 1, "TranslucentAlpha");
  this->AmbientOcclusionImage = NewImage(width, height, 1, "AmbientOcclusion");
  double* aoOut =
    vtkDoubleArray::SafeDownCast(this->AmbientOcclusionImage->GetPointData()->GetScalars())
      ->GetPointer(0);
  std::fill(aoOut, aoOut + static_cast<size_t>(width) * height, 1.0);
  this->AmbientLightImage = NewImage(width, height, 3, "AmbientLight");
  double* ambientLightOut =
    vtkDoubleArray::SafeDownCast(this->AmbientLightImage->GetPointData()->GetScalars())
      ->GetPointer(0);
  std::fill(ambientLightOut, ambientLightOut + 3 * static_cast<size_t>(width) * height, 0.0);
  double* translucentAlphaOut =
    vtkDoubleArray::SafeDownCast(this->TranslucentAlphaImage->GetPointData()->GetScalars())
      ->GetPointer(0);

  const SphereGrid& grid = internals.Grid;
  const unsigned char* rgba = colors ? colors->GetPointer(0) : nullptr;

  // everything the per-pixel stages need
  Frame frame;
  frame.Width = width;
  frame.Height = height;
  frame.Camera = &cam;
  frame.Grid = &grid;
  frame.Spheres = std::move(spheres);
  frame.Ids = std::move(ids);
  frame.DensityModel = densityModel;
  frame.HollowFraction = hollowFraction;
  frame.VolumeMix = volumeMix;
  frame.ExactOverlaps = exactOverlaps;
  frame.SphereTheta = std::move(sphereTheta);
  frame.SphereKappa = std::move(sphereKappa);
  frame.SphereMaximum = std::move(sphereMaximum);
  frame.LayerColors = std::move(layerColors);
  frame.LayerDepths = std::move(layerDepths);
  frame.Lights = std::move(lights);
  frame.Complexity = complexity;
  frame.Opacity = opacity;
  frame.AmbientK = ambientK;
  frame.DiffuseK = diffuseK;
  std::copy(ambientColor, ambientColor + 3, frame.AmbientColor);
  std::copy(diffuseColor, diffuseColor + 3, frame.DiffuseColor);
  std::copy(specularColor, specularColor + 3, frame.SpecularColor);
  frame.SpecularPower = specularPower;
  frame.RGBA = rgba;
  std::copy(background, background + 3, frame.Background);
  frame.BackgroundAlpha = backgroundAlpha;
  frame.ColorOut = colorOut;
  frame.DepthOut = depthOut;
  frame.ViewDepthOut = viewDepthOut;
  frame.NormalOut = normalOut;
  frame.IdOut = idOut;
  frame.InsideOut = insideOut;
  frame.ConeOut = coneOut;
  frame.AmbientOcclusionOut = aoOut;
  frame.AmbientLightOut = ambientLightOut;
  frame.TranslucentAlphaOut = translucentAlphaOut;

  // Ray-traced ambient occlusion and illumination (vtkParticleReferenceAmbientOcclusion): up to
  // the distance, four mean radii by default
  const int aoSamples = this->AmbientOcclusionSamples;
  double aoDistance = this->AmbientOcclusionDistance;
  if (aoSamples > 0 && !(aoDistance > 0.0))
  {
    double sum = 0.0;
    for (const SphereVC& sv : frame.Spheres)
    {
      // (an ellipsoid: the radius of the sphere of its volume, as the AO volumes' grids)
      sum += sv.Ellipsoid ? std::cbrt(std::abs(vtkMath::Determinant3x3(sv.ToVC))) : sv.R;
    }
    aoDistance = frame.Spheres.empty() ? 1.0 : 4.0 * sum / frame.Spheres.size();
  }
  frame.AmbientOcclusionSamples = aoSamples;
  frame.AmbientOcclusionDistance = aoDistance;
  frame.ApplyAmbientOcclusion = this->ApplyAmbientOcclusion;
  frame.AmbientIllumination = this->AmbientIllumination;
  frame.AmbientEmission = this->AmbientEmission;
  property->GetColor(frame.PropertyColor);

  if (auto* metaballMapper = vtkMetaballMapper::SafeDownCast(mapper))
  {
    // the exact metaball surface of the same spheres (vtkParticleReferenceMetaballs)
    vtkNew<vtkPoints> centers;
    centers->SetDataTypeToDouble();
    centers->SetNumberOfPoints(static_cast<vtkIdType>(frame.Spheres.size()));
    vtkNew<vtkDoubleArray> sphereRadii;
    sphereRadii->SetNumberOfTuples(static_cast<vtkIdType>(frame.Spheres.size()));
    for (size_t i = 0; i < frame.Spheres.size(); ++i)
    {
      centers->SetPoint(static_cast<vtkIdType>(i), frame.Spheres[i].C);
      sphereRadii->SetValue(static_cast<vtkIdType>(i), frame.Spheres[i].R);
    }
    vtkNew<vtkParticleReferenceMetaballs> surface;
    surface->SetInfluenceFactor(metaballMapper->GetInfluenceFactor());
    surface->SetIsoValue(metaballMapper->GetIsoValue());
    surface->SetParticles(centers, sphereRadii);
    surface->Prepare();
    RenderMetaballs(frame, surface);
    this->LastRenderSeconds = vtkTimerLog::GetUniversalTime() - startTime;
    this->Modified();
    return true;
  }

  if (transparent)
  {
    RenderTranslucent(frame);
    this->LastRenderSeconds = vtkTimerLog::GetUniversalTime() - startTime;
    this->Modified();
    return true;
  }

  RenderOpaque(frame);

  this->LastRenderSeconds = vtkTimerLog::GetUniversalTime() - startTime;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleReferenceRenderer::WindowDepthToViewDepth(
  vtkImageData* windowDepth, vtkImageData* viewDepth)
{
  const vtkInternals& internals = *this->Internals;
  if (!internals.HaveCamera || !windowDepth || !viewDepth)
  {
    vtkErrorMacro(<< "Nothing rendered yet, or no image.");
    return false;
  }
  const RayCamera& cam = internals.Camera;
  int dims[3];
  windowDepth->GetDimensions(dims);
  vtkDataArray* in = windowDepth->GetPointData()->GetScalars();
  if (dims[0] != cam.Width || dims[1] != cam.Height || !in || in->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro(<< "The depth image is not a one-component " << cam.Width << "x" << cam.Height
                  << " image.");
    return false;
  }
  vtkSmartPointer<vtkImageData> out = NewImage(cam.Width, cam.Height, 1, "ViewDepth");
  double* values = vtkDoubleArray::SafeDownCast(out->GetPointData()->GetScalars())->GetPointer(0);
  vtkSMPTools::For(0, cam.Height,
    [&](vtkIdType rowBegin, vtkIdType rowEnd)
    {
      for (vtkIdType y = rowBegin; y < rowEnd; ++y)
      {
        for (int x = 0; x < cam.Width; ++x)
        {
          const vtkIdType pixel = y * cam.Width + x;
          const double depth = in->GetComponent(pixel, 0);
          if (!(depth < 1.0) || !(depth >= 0.0))
          {
            values[pixel] = -1.0;
            continue;
          }
          double o[3];
          double d[3];
          double tNear;
          double tFar;
          cam.PixelRay(x + 0.5, y + 0.5, o, d, tNear, tFar);
          const double t = cam.WindowDepthToT(x + 0.5, y + 0.5, depth, o, d);
          values[pixel] = std::isfinite(t) ? t : -1.0;
        }
      }
    });
  viewDepth->ShallowCopy(out);
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "Actor: " << this->Actor << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " " << this->ImageSize[1] << "\n";
  os << indent << "ParticleAttributes: " << (this->ParticleRadii ? "given" : "the mapper's")
     << "\n";
  os << indent << "LightingComplexity: " << this->LightingComplexity << "\n";
  os << indent << "LightingCount: " << this->LightingCount << "\n";
  os << indent << "NumberOfSpheres: " << this->NumberOfSpheres << "\n";
  os << indent << "GridResolution: " << this->GridResolution[0] << " " << this->GridResolution[1]
     << " " << this->GridResolution[2] << "\n";
  os << indent << "NumberOfGridReferences: " << this->NumberOfGridReferences << "\n";
  os << indent << "NumberOfLargeSpheres: " << this->NumberOfLargeSpheres << "\n";
  os << indent << "LastRenderSeconds: " << this->LastRenderSeconds << "\n";
  os << indent << "LastGridBuildSeconds: " << this->LastGridBuildSeconds << "\n";
  os << indent << "OpaqueLayer: " << (this->OpaqueLayerColors ? "set" : "none") << "\n";
  os << indent << "AmbientOcclusionSamples: " << this->AmbientOcclusionSamples << "\n";
  os << indent << "AmbientOcclusionDistance: " << this->AmbientOcclusionDistance << "\n";
  os << indent << "ApplyAmbientOcclusion: " << this->ApplyAmbientOcclusion << "\n";
  os << indent << "AmbientIllumination: " << this->AmbientIllumination << "\n";
  os << indent << "AmbientEmission: " << this->AmbientEmission << "\n";
}
