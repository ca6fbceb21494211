#include "vtkParticleReferenceEmissionAbsorption.h"

#include "vtkParticleReferenceAmbientOcclusion.h"
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
// a composited segment with what the overlap sweep needs
struct Emitter
{
  const Segment* Seg;
  double Radius;
  double Impact;
  double Lambda;      // kappa_i / I_max: optical depth per unit density integral
  double Radiance[3]; // L_RV / Theta: the colour the segment emits
  double Start;       // visible part [Start, End] in the ray parameter
  double End;
};

struct Event
{
  double T;
  int Emitter; // index into the emitters
  bool Start;
};

struct TranslucentScratch
{
  std::vector<std::uint32_t> Candidates;
  std::vector<Segment> Segments;
  std::vector<Emitter> Emitters;
  std::vector<Event> Events;
  std::vector<int> Active;
  std::vector<double> Depths;
  AmbientScratch Ambient;
};

// Density integral of a piece [tau0, tau1] (relative to the closest approach, no core inside
// it) in closed form: only for the weight integrand below, where the adaptive rule evaluates it
// many times; the optical depths themselves use IntegrateDensityImpl.
inline double PieceIntegral(int model, double b2, double tau0, double tau1)
{
  if (model == vtkTransparentSphereMapper::SQUARED_DISTANCE_DENSITY)
  {
    return (tau1 - tau0) * b2 + (tau1 * tau1 * tau1 - tau0 * tau0 * tau0) / 3.0;
  }
  return tau1 - tau0;
}

/**
 * Exact compositing of possibly overlapping segments (vtkTransparentSphereMapper's
 * EXACT_OVERLAP): along the ray the extinction is the sum sigma = sum_j lambda_j rho_j and the
 * emission sum_j lambda_j rho_j L_j, with L_j the segment's colour (Eq. 2 per sphere), so the
 * radiance is sum_j L_j int lambda_j rho_j(t) T(t) dt. Between consecutive boundaries (segment
 * starts and ends, hollow-core boundaries) the set of segments is fixed: the interval's optical
 * depths D_j are exact (IntegrateDensityImpl) and the interval adds T (1 - exp(-D)) sum_j w_j L_j
 * with weights w_j = D_j / D for constant densities (exact: the integrands are proportional) and
 * w_j = int sigma_j T / int sigma T by adaptive Gauss-Kronrod quadrature otherwise. Where no
 * segments overlap this is the sorted compositing term by term.
 */
void CompositeExactly(TranslucentScratch& scratch, int model, double hollowFraction,
  double accumulated[3], double& transmittance)
{
  std::vector<Emitter>& emitters = scratch.Emitters;
  std::vector<Event>& events = scratch.Events;
  std::vector<int>& active = scratch.Active;
  std::vector<double>& depths = scratch.Depths;
  events.clear();
  for (int j = 0; j < static_cast<int>(emitters.size()); ++j)
  {
    const Emitter& e = emitters[j];
    if (e.End > e.Start)
    {
      events.push_back({ e.Start, j, true });
      events.push_back({ e.End, j, false });
    }
  }
  // ends before starts at equal t: touching spheres do not overlap
  std::sort(events.begin(), events.end(),
    [](const Event& a, const Event& b)
    { return a.T < b.T || (a.T == b.T && !a.Start && b.Start); });
  active.clear();
  const double rs = std::min(std::max(hollowFraction, 0.0), 1.0);
  for (std::size_t k = 0; k < events.size(); ++k)
  {
    const Event& ev = events[k];
    if (ev.Start)
    {
      active.push_back(ev.Emitter);
    }
    else
    {
      active.erase(std::find(active.begin(), active.end(), ev.Emitter));
    }
    if (active.empty() || k + 1 == events.size())
    {
      continue;
    }
    // the interval up to the next event, split at the hollow cores' boundaries inside it
    const double x0 = ev.T;
    const double x1 = events[k + 1].T;
    if (!(x1 > x0))
    {
      continue;
    }
    double cuts[64];
    int numCuts = 0;
    cuts[numCuts++] = x0;
    if (rs > 0.0)
    {
      for (int j : active)
      {
        const Emitter& e = emitters[j];
        const double core = rs * e.Radius;
        if (e.Impact < core && numCuts < 62)
        {
          const double hs = std::sqrt((core - e.Impact) * (core + e.Impact));
          for (double c : { e.Seg->Tc - hs, e.Seg->Tc + hs })
          {
            if (c > x0 && c < x1)
            {
              cuts[numCuts++] = c;
            }
          }
        }
      }
      std::sort(cuts + 1, cuts + numCuts);
    }
    cuts[numCuts++] = x1;
    for (int c = 0; c + 1 < numCuts && transmittance > 0.0; ++c)
    {
      const double u0 = cuts[c];
      const double u1 = cuts[c + 1];
      if (!(u1 > u0))
      {
        continue;
      }
      depths.assign(active.size(), 0.0);
      double total = 0.0;
      int contributing = 0;
      for (std::size_t a = 0; a < active.size(); ++a)
      {
        const Emitter& e = emitters[active[a]];
        // a piece inside the hollow core (pieces end at its boundaries) has no density: decided
        // at the piece's middle, so that rounding at the boundaries adds no sliver to it
        const double mid = 0.5 * (u0 + u1) - e.Seg->Tc;
        const double core = rs * e.Radius;
        if (e.Impact * e.Impact + mid * mid < core * core)
        {
          continue;
        }
        const double integral = IntegrateDensityImpl(
          model, hollowFraction, e.Radius, e.Impact, u0 - e.Seg->Tc, u1 - e.Seg->Tc);
        depths[a] = e.Lambda * integral;
        total += depths[a];
        contributing += depths[a] > 0.0 ? 1 : 0;
      }
      if (!(total > 0.0) || !std::isfinite(total))
      {
        continue;
      }
      const double opacity = -std::expm1(-total);
      if (contributing > 1 && model == vtkTransparentSphereMapper::SQUARED_DISTANCE_DENSITY)
      {
        // w_j proportional to int lambda_j rho_j(t) exp(-S(t)) dt, S the optical depth from u0
        const double piece[1][2] = { { u0, u1 } };
        auto extinctionFrom = [&](double t)
        {
          double s = 0.0;
          for (std::size_t a = 0; a < active.size(); ++a)
          {
            if (depths[a] > 0.0)
            {
              const Emitter& e = emitters[active[a]];
              s +=
                e.Lambda * PieceIntegral(model, e.Impact * e.Impact, u0 - e.Seg->Tc, t - e.Seg->Tc);
            }
          }
          return s;
        };
        double weights[64];
        double weightSum = 0.0;
        const std::size_t n = std::min<std::size_t>(active.size(), 64);
        for (std::size_t a = 0; a < n; ++a)
        {
          weights[a] = 0.0;
          if (depths[a] > 0.0)
          {
            const Emitter& e = emitters[active[a]];
            const double b2 = e.Impact * e.Impact;
            weights[a] = AdaptiveIntegrate(
              [&](double t)
              {
                const double tau = t - e.Seg->Tc;
                return e.Lambda * (b2 + tau * tau) * std::exp(-extinctionFrom(t));
              },
              piece, 1, IntegrationTolerance);
            weightSum += weights[a];
          }
        }
        for (std::size_t a = 0; a < n && weightSum > 0.0; ++a)
        {
          const Emitter& e = emitters[active[a]];
          for (int q = 0; q < 3; ++q)
          {
            accumulated[q] += transmittance * opacity * (weights[a] / weightSum) * e.Radiance[q];
          }
        }
      }
      else
      {
        for (std::size_t a = 0; a < active.size(); ++a)
        {
          const Emitter& e = emitters[active[a]];
          for (int q = 0; q < 3; ++q)
          {
            accumulated[q] += transmittance * opacity * (depths[a] / total) * e.Radiance[q];
          }
        }
      }
      transmittance *= std::exp(-total);
    }
    if (transmittance == 0.0)
    {
      return;
    }
  }
}
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
  const bool exactOverlaps = frame.ExactOverlaps;
  const double inf = std::numeric_limits<double>::infinity();
  const bool haveLayer = !layerDepths.empty();
  const int densityPower = densityModel == 1 ? 3 : 1; // I_max ~ r or r^3
  ForEachPixelRay<TranslucentScratch>(frame,
    [&](int x, int y, std::size_t pixel, const double o[3], const double d[3], double tNear,
      double tFar, TranslucentScratch& scratch)
    {
      std::vector<std::uint32_t>& candidates = scratch.Candidates;
      std::vector<Segment>& segments = scratch.Segments;
      std::vector<Emitter>& emitters = scratch.Emitters;
      emitters.clear();

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
          if (MakeSegment(cam, o, d, spheres[i], tNear, tFar, i, seg, densityPower))
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
      double occlusionFront = 1.0;
      double lightFront[3] = { 0, 0, 0 };
      double tOpaqueFront = inf;
      // Eq. 5-7 at a surface point: A_O and L_A into occlusion and light; the radiance becomes
      // A_O radiance + alpha_A L_A when they are applied
      const bool ambient = frame.AmbientOcclusionSamples > 0;
      auto applyAmbient = [&](const double p[3], const double n[3], std::uint32_t own,
                            double radiance[3], double& occlusion, double light[3])
      {
        occlusion = AmbientTerms(frame, p, n, own, x, y, scratch.Ambient, light);
        if (frame.ApplyAmbientOcclusion)
        {
          for (int k = 0; k < 3; ++k)
          {
            radiance[k] = occlusion * radiance[k] + frame.AmbientIllumination * light[k];
          }
        }
      };
      if (opaqueHit.Index >= 0)
      {
        const vtkIdType pid = ids[opaqueHit.Index];
        double n[3];
        double p[3];
        double color[3];
        double alpha;
        const std::uint32_t cones = frame.ShadeHit(opaqueHit, n, p, color, alpha);
        double occlusion = 1.0;
        double light[3] = { 0, 0, 0 };
        if (ambient)
        {
          applyAmbient(p, n, static_cast<std::uint32_t>(opaqueHit.Index), color, occlusion, light);
        }
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
          occlusionFront = occlusion;
          std::copy(light, light + 3, lightFront);
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
        const double impact = seg.Impact;
        const double maximum = sphereMaximum[seg.Index] * seg.MaximumScale;
        const double integral = IntegrateDensityImpl(
          densityModel, hollowFraction, seg.Radius, impact, seg.Tau0, seg.Tau1);
        const double opticalDepth = sphereKappa[seg.Index] * (integral / maximum);
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
        double radiance[3];
        std::uint32_t cones = 0;
        double n[3] = { 0, 0, 0 };
        double depth = 0.0;
        double occlusion = 1.0;
        double light[3] = { 0, 0, 0 };
        if (seg.Entry)
        {
          double rel[3];
          double p[3];
          for (int k = 0; k < 3; ++k)
          {
            rel[k] = seg.Q[k] - seg.H * d[k];
          }
          Hit entry;
          std::copy(rel, rel + 3, entry.Rel);
          HitGeometry(entry, s, n, p);
          double surface[3];
          cones = frame.Shade(n, p, amb, dif, surface);
          if (!std::isfinite(surface[0]) || !std::isfinite(surface[1]) ||
            !std::isfinite(surface[2]))
          {
            continue; // discarded
          }
          for (int k = 0; k < 3; ++k)
          {
            radiance[k] = (1.0 - volumeMix) * surface[k] + volumeMix * dif[k];
          }
          // a segment without entry surface (the eye or the near plane inside the sphere) has
          // no front hit x_0: no ambient terms; without ApplyAmbientOcclusion only the front
          // surface's terms are used (the images)
          if (ambient && (frame.ApplyAmbientOcclusion || !haveFront))
          {
            applyAmbient(p, n, seg.Index, radiance, occlusion, light);
          }
          cam.Depth(p, depth);
        }
        else
        {
          for (int k = 0; k < 3; ++k)
          {
            radiance[k] = dif[k];
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
          occlusionFront = occlusion;
          std::copy(light, light + 3, lightFront);
        }
        if (exactOverlaps)
        {
          // composited below, with the other segments
          Emitter e;
          e.Seg = &seg;
          e.Radius = seg.Radius;
          e.Impact = impact;
          e.Lambda = sphereKappa[seg.Index] / maximum;
          for (int k = 0; k < 3; ++k)
          {
            e.Radiance[k] = radiance[k];
          }
          e.Start = seg.Tc + std::max(seg.Tau0, -seg.H);
          e.End = seg.Tc + std::min(seg.Tau1, seg.H);
          emitters.push_back(e);
          continue;
        }
        for (int k = 0; k < 3; ++k)
        {
          accumulated[k] += transmittance * theta * radiance[k];
        }
        transmittance *= std::exp(-opticalDepth);
        if (transmittance == 0.0)
        {
          break;
        }
      }
      if (exactOverlaps)
      {
        CompositeExactly(scratch, densityModel, hollowFraction, accumulated, transmittance);
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
      if (idFront >= 0)
      {
        frame.AmbientOcclusionOut[pixel] = occlusionFront;
        std::copy(lightFront, lightFront + 3, frame.AmbientLightOut + 3 * pixel);
      }
    });
}
} // namespace prReference
