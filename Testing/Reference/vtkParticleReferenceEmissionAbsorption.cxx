#include "vtkParticleReferenceEmissionAbsorption.h"

#include "vtkParticleReferenceFrame.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace prReference
{
namespace
{
// per-thread work space of the transparent pass
struct TranslucentScratch
{
  std::vector<std::uint32_t> Candidates;
  std::vector<Segment> Segments;
};
}

//------------------------------------------------------------------------------
void RenderTranslucent(const Frame& frame)
{
  const RayCamera& cam = *frame.Camera;
  const SphereGrid& grid = *frame.Grid;
  const std::vector<SphereVC>& spheres = frame.Spheres;
  const std::vector<vtkIdType>& ids = frame.Ids;
  const double* background = frame.Background;
  const double backgroundAlpha = frame.BackgroundAlpha;
  double* colorOut = frame.ColorOut;
  const std::vector<double>& sphereTheta = frame.SphereTheta;
  const std::vector<double>& sphereKappa = frame.SphereKappa;
  const std::vector<double>& sphereMaximum = frame.SphereMaximum;
  const std::vector<double>& layerColors = frame.LayerColors;
  const std::vector<double>& layerDepths = frame.LayerDepths;
  const int densityModel = frame.DensityModel;
  const double hollowFraction = frame.HollowFraction;
  const double volumeMix = frame.VolumeMix;
  const double inf = std::numeric_limits<double>::infinity();
  const bool haveLayer = !layerDepths.empty();
  ForEachPixelRay<TranslucentScratch>(frame,
    [&](int x, int y, std::size_t pixel, const double o[3], const double d[3], double tNear,
      double tFar, TranslucentScratch& scratch)
    {
      std::vector<std::uint32_t>& candidates = scratch.Candidates;
      std::vector<Segment>& segments = scratch.Segments;

      // what lies behind the particles: background, opaque layer or opaque particle
      double back[4] = { background[0], background[1], background[2], backgroundAlpha };
      double tStop = inf;
      if (haveLayer)
      {
        const double depth = layerDepths[pixel];
        if (depth >= 0.0 && depth < 1.0)
        {
          const double t = cam.WindowDepthToT(x + 0.5, y + 0.5, depth, o, d);
          if (std::isfinite(t))
          {
            tStop = t;
            std::copy(&layerColors[4 * pixel], &layerColors[4 * pixel] + 4, back);
          }
        }
      }
      const double tMin = tNear - 1e-9 * std::abs(tNear) - 1e-300;
      double tMax = tFar + 1e-9 * std::abs(tFar) + 1e-300;
      if (tStop < inf)
      {
        tMax = std::min(tMax, tStop + 1e-9 * std::abs(tStop) + 1e-300);
      }
      candidates.clear();
      grid.Collect(o, d, tMin, tMax, candidates);
      std::sort(candidates.begin(), candidates.end());
      candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

      // opaque particles: the opaque mode's visible surface; translucent ones: segments
      Hit opaqueHit;
      segments.clear();
      for (std::uint32_t i : candidates)
      {
        if (sphereTheta[i] >= 1.0)
        {
          IntersectSphere(cam, o, d, spheres[i], i, opaqueHit);
        }
        else
        {
          Segment seg;
          if (MakeSegment(cam, o, d, spheres[i], tNear, tFar, i, seg))
          {
            segments.push_back(seg);
          }
        }
      }

      // front-most composited particle, for the depth/id/normal images
      double depthFront = 1.0;
      double viewDepthFront = -1.0;
      vtkIdType idFront = -1;
      unsigned char insideFront = 0;
      std::uint32_t conesFront = 0;
      double normalFront[3] = { 0, 0, 0 };
      double tOpaqueFront = inf;
      if (opaqueHit.Index >= 0)
      {
        const vtkIdType pid = ids[opaqueHit.Index];
        double n[3];
        double p[3];
        double color[3];
        double alpha;
        const std::uint32_t cones = frame.ShadeHit(opaqueHit, n, p, color, alpha);
        const bool finite = std::isfinite(color[0]) && std::isfinite(color[1]) &&
                            std::isfinite(color[2]) && std::isfinite(alpha);
        // otherwise the GPU discards the fragment; at a tie the particle (drawn later,
        // GL_LEQUAL) wins over the opaque layer
        if (finite && alpha > 0.0 && opaqueHit.T <= tStop)
        {
          tStop = opaqueHit.T;
          for (int k = 0; k < 3; ++k)
          {
            back[k] = std::min(1.0, std::max(0.0, color[k]));
          }
          back[3] = std::min(1.0, std::max(0.0, alpha));
          tOpaqueFront = opaqueHit.T;
          depthFront = opaqueHit.Depth;
          viewDepthFront = opaqueHit.T;
          idFront = pid;
          insideFront = opaqueHit.Inside ? 1 : 0;
          conesFront = cones;
          std::copy(n, n + 3, normalFront);
        }
      }

      // cut the segments at the opaque depth, order them by their start
      size_t kept = 0;
      for (Segment& seg : segments)
      {
        if (seg.Key < tStop)
        {
          seg.Tau1 = std::min(seg.Tau1, tStop - seg.Tc);
          segments[kept++] = seg;
        }
      }
      segments.resize(kept);
      std::sort(segments.begin(), segments.end(),
        [&](const Segment& a, const Segment& b)
        { return a.Key < b.Key || (a.Key == b.Key && ids[a.Index] < ids[b.Index]); });

      // front-to-back compositing
      double accumulated[3] = { 0, 0, 0 };
      double transmittance = 1.0;
      bool haveFront = false;
      for (const Segment& seg : segments)
      {
        const SphereVC& s = spheres[seg.Index];
        const double impact = std::sqrt(Dot(seg.Q, seg.Q));
        const double integral =
          IntegrateDensityImpl(densityModel, hollowFraction, s.R, impact, seg.Tau0, seg.Tau1);
        const double opticalDepth = sphereKappa[seg.Index] * (integral / sphereMaximum[seg.Index]);
        const double theta = OpacityFromOpticalDepth(opticalDepth);
        if (!(theta > 0.0) || !std::isfinite(opticalDepth))
        {
          continue;
        }
        const vtkIdType pid = ids[seg.Index];
        double amb[3];
        double dif[3];
        double alpha;
        frame.Material(pid, amb, dif, alpha);
        double emitted[3];
        std::uint32_t cones = 0;
        double n[3] = { 0, 0, 0 };
        double depth = 0.0;
        if (seg.Entry)
        {
          double rel[3];
          double p[3];
          for (int k = 0; k < 3; ++k)
          {
            rel[k] = seg.Q[k] - seg.H * d[k];
            n[k] = rel[k] / s.R;
            p[k] = s.C[k] + rel[k];
          }
          double surface[3];
          cones = frame.Shade(n, p, amb, dif, surface);
          if (!std::isfinite(surface[0]) || !std::isfinite(surface[1]) ||
              !std::isfinite(surface[2]))
          {
            continue; // discarded
          }
          for (int k = 0; k < 3; ++k)
          {
            emitted[k] = theta * ((1.0 - volumeMix) * surface[k] + volumeMix * dif[k]);
          }
          cam.Depth(p, depth);
        }
        else
        {
          for (int k = 0; k < 3; ++k)
          {
            emitted[k] = theta * dif[k];
          }
          double p[3];
          for (int k = 0; k < 3; ++k)
          {
            p[k] = s.C[k] + seg.Q[k] + seg.Tau0 * d[k];
          }
          if (!cam.Depth(p, depth))
          {
            depth = 0.0; // the start is the near plane
          }
        }
        if (!haveFront)
        {
          haveFront = true;
          depthFront = depth;
          viewDepthFront = seg.Key;
          idFront = pid;
          insideFront = seg.Entry ? 0 : 1;
          conesFront = cones;
          std::copy(n, n + 3, normalFront);
        }
        for (int k = 0; k < 3; ++k)
        {
          accumulated[k] += transmittance * emitted[k];
        }
        transmittance *= std::exp(-opticalDepth);
        if (transmittance == 0.0)
        {
          break;
        }
      }
      if (!haveFront && tOpaqueFront == inf)
      {
        idFront = -1;
      }
      const double particleOpacity = tOpaqueFront < inf ? 1.0 : 1.0 - transmittance;

      double* out = colorOut + 4 * pixel;
      for (int k = 0; k < 3; ++k)
      {
        out[k] = std::min(1.0, std::max(0.0, accumulated[k] + transmittance * back[k]));
      }
      out[3] = std::min(1.0, std::max(0.0, 1.0 - transmittance * (1.0 - back[3])));
      frame.WriteSurface(pixel, depthFront, viewDepthFront, idFront, insideFront != 0, conesFront,
        normalFront, particleOpacity);
    });
}
} // namespace prReference
