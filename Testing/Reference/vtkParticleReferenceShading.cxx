#include "vtkParticleReferenceShading.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkParticleReferenceAmbientOcclusion.h"
#include "vtkParticleReferenceFrame.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace prReference
{
//------------------------------------------------------------------------------
int SetUpLights(vtkRenderer* renderer, vtkCamera* camera, const double viewMatrix[16],
  const double viewInverse[16], vtkProperty* property, vtkPolyData* input,
  std::vector<LightVC>& lights)
{
  int complexity = 0;
  {
    vtkLightCollection* collection = renderer->GetLights();
    vtkLight* first = nullptr;
    int count = 0;
    vtkCollectionSimpleIterator it;
    collection->InitTraversal(it);
    while (vtkLight* light = collection->GetNextLight(it))
    {
      first = first ? first : light;
      if (light->GetSwitch())
      {
        ++count;
        complexity = std::max(complexity, 1);
      }
      if (complexity == 1 && (count > 1 || light->GetLightType() != VTK_LIGHT_TYPE_HEADLIGHT))
      {
        complexity = 2;
      }
      if (complexity < 3 && light->GetPositional())
      {
        complexity = 3;
      }
    }
    const bool followCamera = renderer->GetLightFollowCamera() != 0;
    vtkMatrix4x4* cameraLightMatrix = camera->GetCameraLightTransformMatrix();
    auto addLight = [&](vtkLight* light, bool isCreatedHeadlight)
    {
      LightVC l;
      double color[3] = { 1, 1, 1 };
      double intensity = 1.0;
      if (light)
      {
        light->GetDiffuseColor(color);
        intensity = light->GetIntensity();
      }
      for (int k = 0; k < 3; ++k)
      {
        l.Color[k] = color[k] * intensity;
      }
      // transformed position and focal point at render time
      double pos[4] = { 0, 0, 0, 1 };
      double focal[4] = { 0, 0, -1, 1 };
      const bool headlight = isCreatedHeadlight || light->LightTypeIsHeadlight();
      vtkMatrix4x4* lightMatrix = light ? light->GetTransformMatrix() : nullptr;
      if (followCamera && headlight)
      {
        camera->GetPosition(pos);
        camera->GetFocalPoint(focal);
      }
      else if (light)
      {
        light->GetPosition(pos);
        light->GetFocalPoint(focal);
      }
      if (followCamera && light && light->LightTypeIsCameraLight())
      {
        lightMatrix = cameraLightMatrix;
      }
      if (lightMatrix)
      {
        double tp[4];
        double tf[4];
        lightMatrix->MultiplyPoint(pos, tp);
        lightMatrix->MultiplyPoint(focal, tf);
        for (int k = 0; k < 3; ++k)
        {
          pos[k] = tp[k] / tp[3];
          focal[k] = tf[k] / tf[3];
        }
      }
      double dir[3] = { focal[0] - pos[0], focal[1] - pos[1], focal[2] - pos[2] };
      NormalizeInPlace(dir);
      // normal transform: inverse transpose of the view matrix
      for (int i = 0; i < 3; ++i)
      {
        l.Direction[i] =
          viewInverse[i] * dir[0] + viewInverse[4 + i] * dir[1] + viewInverse[8 + i] * dir[2];
      }
      NormalizeInPlace(l.Direction);
      double posVC[4];
      MultiplyPoint(viewMatrix, pos, posVC);
      for (int k = 0; k < 3; ++k)
      {
        l.Position[k] = posVC[k] / posVC[3];
      }
      if (light)
      {
        l.Positional = light->GetPositional() != 0;
        light->GetAttenuationValues(l.Attenuation);
        l.ConeAngle = light->GetConeAngle();
        l.Exponent = light->GetExponent();
      }
      lights.push_back(l);
    };
    if (count == 0 && renderer->GetAutomaticLightCreation())
    {
      // the renderer creates a headlight and adds it at the end of the collection
      complexity = (!first || first->LightTypeIsHeadlight()) ? 1 : 2;
      addLight(nullptr, true);
    }
    else
    {
      collection->InitTraversal(it);
      while (vtkLight* light = collection->GetNextLight(it))
      {
        if (light->GetSwitch())
        {
          addLight(light, false);
        }
      }
    }
  }
  // lighting off, or the representation of unlit points (vtkOpenGLPolyDataMapper's rules)
  bool needLighting = true;
  if (property->GetRepresentation() == VTK_POINTS)
  {
    const bool haveNormals = input && input->GetPointData()->GetNormals() != nullptr;
    needLighting = (property->GetInterpolation() != VTK_FLAT && haveNormals) ||
      property->GetRenderPointsAsSpheres();
  }
  if (!property->GetLighting() || !needLighting || lights.empty())
  {
    complexity = 0;
  }
  return complexity;
}

//------------------------------------------------------------------------------
void Frame::Material(vtkIdType pid, double amb[3], double dif[3], double& alpha) const
{
  const unsigned char* rgba = this->RGBA;
  const double opacity = this->Opacity;
  const double ambientK = this->AmbientK;
  const double diffuseK = this->DiffuseK;
  const double* ambientColor = this->AmbientColor;
  const double* diffuseColor = this->DiffuseColor;
  {
    alpha = opacity;
    if (rgba)
    {
      const unsigned char* c = rgba + 4 * pid;
      for (int k = 0; k < 3; ++k)
      {
        amb[k] = ambientK * (c[k] / 255.0);
        dif[k] = diffuseK * (c[k] / 255.0);
      }
      alpha *= c[3] / 255.0;
    }
    else
    {
      for (int k = 0; k < 3; ++k)
      {
        amb[k] = ambientK * ambientColor[k];
        dif[k] = diffuseK * diffuseColor[k];
      }
    }
  }
}

//------------------------------------------------------------------------------
std::uint32_t Frame::Shade(const double n[3], const double p[3], const double amb[3],
  const double dif[3], double color[3]) const
{
  const int complexity = this->Complexity;
  const std::vector<LightVC>& lights = this->Lights;
  const double specularPower = this->SpecularPower;
  const double* specularColor = this->SpecularColor;
  {
    std::uint32_t cones = 0;
    if (complexity == 0)
    {
      for (int k = 0; k < 3; ++k)
      {
        color[k] = amb[k] + dif[k];
      }
      return cones;
    }
    double diffuse[3] = { 0, 0, 0 };
    double specular[3] = { 0, 0, 0 };
    unsigned int bit = 0;
    for (const LightVC& light : lights)
    {
      if (complexity == 1)
      {
        // Lighting.glsl, prHeadlight
        const double df = std::max(0.000001, n[2]);
        const double sf = std::pow(df, specularPower);
        for (int k = 0; k < 3; ++k)
        {
          diffuse[k] += df * light.Color[k];
          specular[k] += sf * light.Color[k];
        }
      }
      else
      {
        const bool inCone =
          SceneLight(n, p, light, complexity == 3, specularPower, diffuse, specular);
        if (complexity == 3 && light.Positional && light.ConeAngle < 90.0 && bit < MaximumConeBits)
        {
          cones |= (inCone ? 1u : 0u) << bit++;
        }
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      color[k] = amb[k] + diffuse[k] * dif[k] + specular[k] * specularColor[k];
    }
    return cones;
  }
}

//------------------------------------------------------------------------------
std::uint32_t Frame::ShadeHit(
  const Hit& hit, double n[3], double p[3], double color[3], double& alpha) const
{
  HitGeometry(hit, this->Spheres[hit.Index], n, p);
  double amb[3];
  double dif[3];
  this->Material(this->Ids[hit.Index], amb, dif, alpha);
  return this->Shade(n, p, amb, dif, color);
}

//------------------------------------------------------------------------------
void RenderOpaque(const Frame& frame)
{
  const RayCamera& cam = *frame.Camera;
  const std::vector<SphereVC>& spheres = frame.Spheres;
  const std::vector<vtkIdType>& ids = frame.Ids;
  const int aoSamples = frame.AmbientOcclusionSamples;
  double* colorOut = frame.ColorOut;
  double* aoOut = frame.AmbientOcclusionOut;
  ForEachPixelRay<AmbientScratch>(frame,
    [&](int x, int y, std::size_t pixel, const double o[3], const double d[3], double tNear,
      double tFar, AmbientScratch& scratch)
    {
      Hit hit;
      const double tMin = tNear - 1e-9 * std::abs(tNear) - 1e-300;
      const double tMax = tFar + 1e-9 * std::abs(tFar) + 1e-300;
      frame.Grid->Trace(cam, spheres, o, d, tMin, tMax, hit);

      double rgbaOut[4] = { frame.Background[0], frame.Background[1], frame.Background[2],
        frame.BackgroundAlpha };
      double depth = 1.0;
      double viewDepth = -1.0;
      vtkIdType id = -1;
      unsigned char inside = 0;
      std::uint32_t cones = 0;
      double normal[3] = { 0, 0, 0 };
      if (hit.Index >= 0)
      {
        const vtkIdType pid = ids[hit.Index];
        double n[3];
        double p[3];
        double color[3];
        double alpha;
        cones = frame.ShadeHit(hit, n, p, color, alpha);
        double occlusion = 1.0;
        double light[3] = { 0, 0, 0 };
        if (aoSamples > 0)
        {
          occlusion = AmbientTerms(frame, p, n, hit.Index, x, y, scratch, light);
          if (frame.ApplyAmbientOcclusion)
          {
            // Eq. 7: L_E = A_O L_R + alpha_A L_A
            for (int k = 0; k < 3; ++k)
            {
              color[k] = occlusion * color[k] + frame.AmbientIllumination * light[k];
            }
          }
        }
        const bool finite = std::isfinite(color[0]) && std::isfinite(color[1]) &&
          std::isfinite(color[2]) && std::isfinite(alpha);
        if (finite && alpha > 0.0) // otherwise the GPU discards the fragment
        {
          aoOut[pixel] = occlusion;
          std::copy(light, light + 3, frame.AmbientLightOut + 3 * pixel);
          for (int k = 0; k < 3; ++k)
          {
            rgbaOut[k] = std::min(1.0, std::max(0.0, color[k]));
          }
          rgbaOut[3] = std::min(1.0, std::max(0.0, alpha));
          depth = hit.Depth;
          viewDepth = hit.T;
          id = pid;
          inside = hit.Inside ? 1 : 0;
          std::copy(n, n + 3, normal);
        }
      }
      std::copy(rgbaOut, rgbaOut + 4, colorOut + 4 * pixel);
      frame.WriteSurface(
        pixel, depth, viewDepth, id, inside != 0, cones, normal, id >= 0 ? 1.0 : 0.0);
    });
}
} // namespace prReference
