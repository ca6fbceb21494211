// Private header of ParticleRendering::Reference (vtkParticleReferenceRenderer): shading -- the
// lights as the fragment shader sees them (Lighting.glsl in double), VTK's light set-up, and the
// lit opaque surface pass.
#ifndef vtkParticleReferenceShading_h
#define vtkParticleReferenceShading_h

#include "vtkMath.h"
#include "vtkParticleReferenceRays.h"

#include <algorithm>
#include <cmath>
#include <vector>

class vtkCamera;
class vtkPolyData;
class vtkProperty;
class vtkRenderer;

namespace prReference
{
struct Frame;

//------------------------------------------------------------------------------
// spot lights whose cones take part in the surface ids
const unsigned int MaximumConeBits = 16;

// A light as the fragment shader sees it (uniform values in double).
struct LightVC
{
  double Color[3] = { 0, 0, 0 };
  double Direction[3] = { 0, 0, -1 };
  bool Positional = false;
  double Position[3] = { 0, 0, 0 };
  double Attenuation[3] = { 1, 0, 0 };
  double ConeAngle = 180.0;
  double Exponent = 1.0;
};

// Lighting.glsl, prSceneLight (VTK's view vector normalize(-p), in either projection, and its
// 1e-5 floor of the specular base). Returns true when the point is inside the light's spot cone
// (or the light is not a spot).
inline bool SceneLight(const double n[3], const double p[3], const LightVC& light,
  bool usePositional, double specularPower, double diffuse[3], double specular[3])
{
  bool inCone = true;
  double attenuation = 1.0;
  double l[3] = { light.Direction[0], light.Direction[1], light.Direction[2] };
  if (usePositional && light.Positional)
  {
    for (int k = 0; k < 3; ++k)
    {
      l[k] = p[k] - light.Position[k];
    }
    const double distance = std::sqrt(Dot(l, l));
    for (double& c : l)
    {
      c /= distance;
    }
    attenuation = 1.0 /
      (light.Attenuation[0] + light.Attenuation[1] * distance +
        light.Attenuation[2] * distance * distance);
    if (light.ConeAngle < 90.0)
    {
      const double coneDot = Dot(l, light.Direction);
      inCone = coneDot >= std::cos(vtkMath::RadiansFromDegrees(light.ConeAngle));
      attenuation = inCone ? attenuation * std::pow(coneDot, light.Exponent) : 0.0;
    }
  }
  const double minusL[3] = { -l[0], -l[1], -l[2] };
  const double df = std::max(0.0, attenuation * Dot(n, minusL));
  const double nl = Dot(n, l);
  const double r[3] = { l[0] - 2.0 * nl * n[0], l[1] - 2.0 * nl * n[1], l[2] - 2.0 * nl * n[2] };
  const double signDf = df > 0.0 ? 1.0 : (df < 0.0 ? -1.0 : 0.0);
  double v[3] = { -p[0], -p[1], -p[2] };
  NormalizeInPlace(v);
  const double sf = signDf * attenuation * std::pow(std::max(1e-5, Dot(r, v)), specularPower);
  for (int k = 0; k < 3; ++k)
  {
    diffuse[k] += df * light.Color[k];
    specular[k] += sf * light.Color[k];
  }
  return inCone;
}

/**
 * The renderer's lights in view coordinates, as vtkOpenGLRenderer::UpdateLights /
 * UpdateLightingUniforms (the automatic headlight included), and the lighting complexity the
 * mapper's shader would use (0 when lighting is off or not needed).
 */
int SetUpLights(vtkRenderer* renderer, vtkCamera* camera, const double viewMatrix[16],
  const double viewInverse[16], vtkProperty* property, vtkPolyData* input,
  std::vector<LightVC>& lights);

/**
 * The opaque mode's per-pixel pass: the first visible sphere along each pixel's ray, lit, with
 * ray-traced ambient occlusion when asked for; writes every output of the frame.
 */
void RenderOpaque(const Frame& frame);
} // namespace prReference

#endif
