// Private header of ParticleRendering::Reference (vtkParticleReferenceRenderer): the state one
// Render() hands from its set-up (camera, spheres, lights, material) to its per-pixel stages
// (RenderOpaque with AmbientOcclusion, RenderTranslucent), and the images they write.
#ifndef vtkParticleReferenceFrame_h
#define vtkParticleReferenceFrame_h

#include "vtkParticleReferenceRays.h"
#include "vtkParticleReferenceShading.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace prReference
{
struct Frame
{
  // image size and the camera as the rays see it
  int Width = 0;
  int Height = 0;
  const RayCamera* Camera = nullptr;
  // visible spheres in view coordinates, their particle ids, the grid over them
  std::vector<SphereVC> Spheres;
  std::vector<vtkIdType> Ids;
  const SphereGrid* Grid = nullptr;

  // transparent mode: density model, Theta_i, kappa_i and I_max per sphere, the opaque layer
  int DensityModel = 0;
  double HollowFraction = 0.0;
  double VolumeMix = 0.0;
  // overlapping segments: the summed densities (true) or each sphere whole in order (false)
  bool ExactOverlaps = true;
  std::vector<double> SphereTheta;
  std::vector<double> SphereKappa;
  std::vector<double> SphereMaximum;
  std::vector<double> LayerColors; // RGBA per pixel, empty: none
  std::vector<double> LayerDepths; // window depth per pixel

  // lights (complexity as vtkOpenGLRenderer's: 0 unlit, 1 headlight, 2 directional, 3 positional)
  std::vector<LightVC> Lights;
  int Complexity = 0;
  // material: the actor's opacity, coefficients and colours; per-particle RGBA or nullptr
  double Opacity = 1.0;
  double AmbientK = 0.0;
  double DiffuseK = 1.0;
  double AmbientColor[3] = { 0, 0, 0 };
  double DiffuseColor[3] = { 1, 1, 1 };
  double SpecularColor[3] = { 0, 0, 0 }; // times the specular coefficient
  double SpecularPower = 1.0;
  const unsigned char* RGBA = nullptr;
  double Background[3] = { 0, 0, 0 };
  double BackgroundAlpha = 0.0;

  // ray-traced ambient occlusion: samples (0: none), distance, applied to colour; ambient
  // illumination: alpha_A of Eq. 7, e_A of Eq. 6, the property's colour (without scalars)
  int AmbientOcclusionSamples = 0;
  double AmbientOcclusionDistance = 0.0;
  bool ApplyAmbientOcclusion = false;
  double AmbientIllumination = 0.0;
  double AmbientEmission = 1.0;
  double PropertyColor[3] = { 1, 1, 1 };
  double* AmbientLightOut = nullptr; // L_A, 3 per pixel

  // outputs, Width x Height, row-major from the bottom row
  double* ColorOut = nullptr;     // RGBA
  double* DepthOut = nullptr;     // window depth
  double* ViewDepthOut = nullptr; // ray parameter of the visible point, -1 for background
  double* NormalOut = nullptr;    // view-coordinate normal
  vtkIdType* IdOut = nullptr;     // particle id, -1 for background
  unsigned char* InsideOut = nullptr;
  std::uint32_t* ConeOut = nullptr; // spot cones containing the visible point
  double* AmbientOcclusionOut = nullptr;
  double* TranslucentAlphaOut = nullptr;

  /**
   * Write what a pixel shows besides its colour: window and view depth, particle id, whether the
   * ray starts inside it, its spot cones (0 without a particle), normal, translucent alpha.
   */
  void WriteSurface(std::size_t pixel, double depth, double viewDepth, vtkIdType id, bool inside,
    std::uint32_t cones, const double normal[3], double translucentAlpha) const
  {
    this->DepthOut[pixel] = depth;
    this->ViewDepthOut[pixel] = viewDepth;
    this->IdOut[pixel] = id;
    this->InsideOut[pixel] = inside ? 1 : 0;
    this->ConeOut[pixel] = id >= 0 ? cones : 0;
    std::copy(normal, normal + 3, this->NormalOut + 3 * pixel);
    this->TranslucentAlphaOut[pixel] = translucentAlpha;
  }

  /**
   * The lit colour (not clamped) and fragment opacity of a hit, with its unit normal n and
   * view-coordinate point p; returns the bits of the spot cones containing p.
   * (vtkParticleReferenceShading.cxx)
   */
  std::uint32_t ShadeHit(
    const Hit& hit, double n[3], double p[3], double color[3], double& alpha) const;

  /**
   * The colour c_j sphere j (an index into Spheres) emits into ambient rays (Eq. 6), as
   * vtkParticleAmbientVolume voxelises it: the scalar colour, or the property's colour.
   */
  void EmissionColor(std::uint32_t j, double c[3]) const
  {
    if (this->RGBA)
    {
      const unsigned char* rgba = this->RGBA + 4 * this->Ids[j];
      for (int k = 0; k < 3; ++k)
      {
        c[k] = rgba[k] / 255.0;
      }
    }
    else
    {
      std::copy(this->PropertyColor, this->PropertyColor + 3, c);
    }
  }

  /**
   * Material of a particle as vtkOpenGLPolyDataMapper: ambient and diffuse colours (with their
   * coefficients) and the fragment opacity. (vtkParticleReferenceShading.cxx)
   */
  void Material(vtkIdType pid, double amb[3], double dif[3], double& alpha) const;

  /**
   * VTK's lit colour (not clamped) at the surface point p (view coordinates) with unit normal n;
   * returns the bits of the spot cones containing p. (vtkParticleReferenceShading.cxx)
   */
  std::uint32_t Shade(const double n[3], const double p[3], const double amb[3],
    const double dif[3], double color[3]) const;
};
/**
 * Call perPixel(x, y, pixel, o, d, tNear, tFar, scratch) for every pixel's centre ray (origin o,
 * unit direction d, the near and far planes at tNear and tFar), rows in parallel (vtkSMPTools);
 * Scratch is default-constructed once per block of rows (per-thread work space).
 */
template <class Scratch, class PerPixel>
void ForEachPixelRay(const Frame& frame, PerPixel perPixel)
{
  const int width = frame.Width;
  const RayCamera& cam = *frame.Camera;
  vtkSMPTools::For(0, frame.Height,
    [&](vtkIdType rowBegin, vtkIdType rowEnd)
    {
      Scratch scratch;
      for (vtkIdType y = rowBegin; y < rowEnd; ++y)
      {
        for (int x = 0; x < width; ++x)
        {
          const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
          double o[3];
          double d[3];
          double tNear;
          double tFar;
          cam.PixelRay(x + 0.5, y + 0.5, o, d, tNear, tFar);
          perPixel(x, static_cast<int>(y), pixel, o, d, tNear, tFar, scratch);
        }
      }
    });
}
} // namespace prReference

#endif
