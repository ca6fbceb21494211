#include "vtkParticleReferenceMetaballPass.h"

#include "vtkParticleReferenceMetaballs.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace prReference
{
void RenderMetaballs(const Frame& frame, const vtkParticleReferenceMetaballs* surface)
{
  const RayCamera& cam = *frame.Camera;
  using Contributions = std::vector<vtkParticleReferenceMetaballs::Contribution>;
  ForEachPixelRay<Contributions>(frame,
    [&](int, int, std::size_t pixel, const double o[3], const double d[3], double tNear,
      double tFar, Contributions& contributions)
    {
      double rgbaOut[4] = { frame.Background[0], frame.Background[1], frame.Background[2],
        frame.BackgroundAlpha };
      double depth = 1.0;
      double viewDepth = -1.0;
      vtkIdType id = -1;
      bool inside = false;
      std::uint32_t cones = 0;
      double normal[3] = { 0, 0, 0 };
      const double tMin = tNear - 1e-9 * std::abs(tNear) - 1e-300;
      const double tMax = tFar + 1e-9 * std::abs(tFar) + 1e-300;
      double t = 0.0;
      double n[3];
      vtkIdType candidates = 0;
      double p[3];
      if (surface->IntersectRay(o, d, tMin, tMax, t, n, inside, &contributions, candidates))
      {
        for (int k = 0; k < 3; ++k)
        {
          p[k] = o[k] + t * d[k];
        }
        double hitDepth = 1.0;
        if (!inside && cam.Depth(p, hitDepth) && !contributions.empty())
        {
          // the colour blended by the field shares (8-bit RGBA as uploaded), as the GPU does
          double rgba[4] = { 0, 0, 0, 0 };
          double weights = 0.0;
          double strongest = -1.0;
          for (const auto& c : contributions)
          {
            const vtkIdType sphere = c.Particle;
            const vtkIdType pid = frame.Ids[sphere];
            if (frame.RGBA)
            {
              const unsigned char* value = frame.RGBA + 4 * pid;
              for (int k = 0; k < 4; ++k)
              {
                rgba[k] += c.Weight * (value[k] / 255.0);
              }
            }
            weights += c.Weight;
            if (c.Weight > strongest)
            {
              strongest = c.Weight;
              id = pid;
            }
          }
          double amb[3];
          double dif[3];
          double alpha = frame.Opacity;
          for (int k = 0; k < 3; ++k)
          {
            const double scalar = frame.RGBA ? rgba[k] / weights : 1.0;
            amb[k] = frame.AmbientK * (frame.RGBA ? scalar : frame.AmbientColor[k]);
            dif[k] = frame.DiffuseK * (frame.RGBA ? scalar : frame.DiffuseColor[k]);
          }
          if (frame.RGBA)
          {
            alpha *= rgba[3] / weights;
          }
          double color[3];
          cones = frame.Shade(n, p, amb, dif, color);
          const bool finite = std::isfinite(color[0]) && std::isfinite(color[1]) &&
            std::isfinite(color[2]) && std::isfinite(alpha);
          if (finite && alpha > 0.0)
          {
            for (int k = 0; k < 3; ++k)
            {
              rgbaOut[k] = std::min(1.0, std::max(0.0, color[k]));
            }
            rgbaOut[3] = std::min(1.0, std::max(0.0, alpha));
            depth = hitDepth;
            viewDepth = t;
            std::copy(n, n + 3, normal);
          }
          else
          {
            id = -1;
          }
        }
        else if (inside)
        {
          id = -1;
          viewDepth = -1.0;
        }
      }
      std::copy(rgbaOut, rgbaOut + 4, frame.ColorOut + 4 * pixel);
      frame.WriteSurface(pixel, depth, viewDepth, id, inside, cones, normal, id >= 0 ? 1.0 : 0.0);
    });
}
} // namespace prReference
