#include "vtkParticleReferenceAmbientOcclusion.h"

#include "vtkMath.h"
#include "vtkParticleReferenceEmissionAbsorption.h"
#include "vtkParticleReferenceFrame.h"

#include <algorithm>
#include <cmath>

namespace prReference
{
namespace
{
// the k-th of n Hammersley points (k / n, radical inverse of k), rotated by (rotU, rotV)
void Hammersley(int k, int n, double rotU, double rotV, double& u, double& w)
{
  std::uint32_t bits = static_cast<std::uint32_t>(k);
  bits = (bits << 16u) | (bits >> 16u);
  bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
  bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
  bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
  bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
  u = (k + 0.5) / n + rotU;
  w = bits * 2.3283064365386963e-10 + rotV;
  u -= std::floor(u);
  w -= std::floor(w);
}
}

//------------------------------------------------------------------------------
double AmbientTerms(const Frame& frame, const double p[3], const double n[3], vtkIdType own, int px,
  int py, AmbientScratch& scratch, double light[3])
{
  const int aoSamples = frame.AmbientOcclusionSamples;
  const double aoDistance = frame.AmbientOcclusionDistance;
  const SphereGrid& grid = *frame.Grid;
  const std::vector<SphereVC>& spheres = frame.Spheres;
  const bool allOpaque = frame.SphereTheta.empty();
  light[0] = light[1] = light[2] = 0.0;
  if (aoSamples <= 0)
  {
    return 1.0;
  }
  // orthonormal basis around n
  double t1[3];
  const double helper[3] = { std::abs(n[0]) < 0.9 ? 1.0 : 0.0, std::abs(n[0]) < 0.9 ? 0.0 : 1.0,
    0.0 };
  vtkMath::Cross(n, helper, t1);
  vtkMath::Normalize(t1);
  double t2[3];
  vtkMath::Cross(n, t1, t2);
  // per-pixel Cranley-Patterson rotation from a hash of the pixel
  std::uint32_t h =
    static_cast<std::uint32_t>(px) * 73856093u ^ static_cast<std::uint32_t>(py) * 19349663u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  const double rotU = (h & 0xffffu) / 65536.0;
  const double rotV = (h >> 16) / 65536.0;
  double transmittanceSum = 0.0;
  std::vector<std::uint32_t>& candidates = scratch.Candidates;
  std::vector<AmbientScratch::Piece>& pieces = scratch.Pieces;
  for (int k = 0; k < aoSamples; ++k)
  {
    double u;
    double w;
    Hammersley(k, aoSamples, rotU, rotV, u, w);
    // cosine-weighted direction
    const double sinTheta = std::sqrt(u);
    const double cosTheta = std::sqrt(std::max(0.0, 1.0 - u));
    const double phi = 2.0 * vtkMath::Pi() * w;
    double dir[3];
    for (int c = 0; c < 3; ++c)
    {
      dir[c] = sinTheta * (std::cos(phi) * t1[c] + std::sin(phi) * t2[c]) + cosTheta * n[c];
    }
    candidates.clear();
    grid.Collect(p, dir, 0.0, aoDistance, candidates);
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    // the spheres' parts of [0, distance]; the first opaque point ends the ray
    double tOpaque = aoDistance;
    std::uint32_t opaqueIndex = 0;
    bool blocked = false;
    pieces.clear();
    for (std::uint32_t j : candidates)
    {
      if (static_cast<vtkIdType>(j) == own)
      {
        continue;
      }
      const SphereVC& sv = spheres[j];
      Chord chord;
      if (!ChordOf(p, dir, sv, frame.DensityModel == 1 ? 3 : 1, chord))
      {
        continue;
      }
      const double tIn = chord.Tc - chord.H;
      const double tOut = chord.Tc + chord.H;
      // (the piece of the ray through the sphere along it that has the particle's profile)
      AmbientScratch::Piece piece;
      piece.Tc = chord.Tc;
      piece.Radius = chord.Radius;
      piece.Impact = chord.Impact;
      piece.MaximumScale = chord.MaximumScale;
      if (!(tOut > 1e-9 * sv.R && tIn < aoDistance))
      {
        continue;
      }
      const double start = std::max(tIn, 0.0);
      if (allOpaque || frame.SphereTheta[j] >= 1.0)
      {
        if (!blocked || start < tOpaque || (start == tOpaque && j < opaqueIndex))
        {
          blocked = true;
          tOpaque = start;
          opaqueIndex = j;
        }
        continue;
      }
      piece.Start = start;
      piece.End = std::min(tOut, aoDistance);
      piece.Index = j;
      pieces.push_back(piece);
    }
    if (allOpaque)
    {
      if (blocked)
      {
        double c[3];
        frame.EmissionColor(opaqueIndex, c);
        for (int m = 0; m < 3; ++m)
        {
          light[m] += frame.AmbientEmission * c[m];
        }
      }
      else
      {
        transmittanceSum += 1.0;
      }
      continue;
    }
    std::sort(pieces.begin(), pieces.end(),
      [](const AmbientScratch::Piece& a, const AmbientScratch::Piece& b)
      { return a.Start < b.Start || (a.Start == b.Start && a.Index < b.Index); });
    double transmittance = 1.0;
    for (const AmbientScratch::Piece& piece : pieces)
    {
      if (!(piece.Start < tOpaque))
      {
        break;
      }
      const double tc = piece.Tc;
      const double integral = IntegrateDensityImpl(frame.DensityModel, frame.HollowFraction,
        piece.Radius, piece.Impact, piece.Start - tc, std::min(piece.End, tOpaque) - tc);
      const double opticalDepth = frame.SphereKappa[piece.Index] *
        (integral / (frame.SphereMaximum[piece.Index] * piece.MaximumScale));
      if (!(opticalDepth > 0.0) || !std::isfinite(opticalDepth))
      {
        continue;
      }
      double c[3];
      frame.EmissionColor(piece.Index, c);
      const double theta = OpacityFromOpticalDepth(opticalDepth);
      for (int m = 0; m < 3; ++m)
      {
        light[m] += transmittance * theta * frame.AmbientEmission * c[m];
      }
      transmittance *= std::exp(-opticalDepth);
    }
    if (blocked)
    {
      double c[3];
      frame.EmissionColor(opaqueIndex, c);
      for (int m = 0; m < 3; ++m)
      {
        light[m] += transmittance * frame.AmbientEmission * c[m];
      }
      transmittance = 0.0;
    }
    transmittanceSum += transmittance;
  }
  for (int m = 0; m < 3; ++m)
  {
    light[m] /= aoSamples;
  }
  return transmittanceSum / aoSamples;
}
} // namespace prReference
