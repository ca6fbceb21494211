// Private header of ParticleRendering::Reference (vtkParticleReferenceRenderer): ray-traced
// ambient occlusion A_O and ambient illumination L_A (Staib et al. 2015, Eq. 5 and 6) --
// cosine-distributed rays from a visible point (Hammersley points with a per-pixel
// Cranley-Patterson rotation) through the real spheres (all of them, the visible one excepted)
// up to the distance: an opaque sphere stops the ray, a translucent one attenuates it by its
// exact emission-absorption transmittance and emits e_A c_j; the reference of every AO technique.
#ifndef vtkParticleReferenceAmbientOcclusion_h
#define vtkParticleReferenceAmbientOcclusion_h

#include "vtkType.h"

#include <cstdint>
#include <vector>

namespace prReference
{
struct Frame;

// per-thread work space of the ambient rays
struct AmbientScratch
{
  // a sphere's part of an ambient ray
  struct Piece
  {
    double Start;
    double End;
    std::uint32_t Index;
    // the (equivalent, for an ellipsoid) sphere along this ray: see MakeSegment
    double Tc = 0.0;
    double Radius = 0.0;
    double Impact = 0.0;
    double MaximumScale = 1.0;
  };
  std::vector<std::uint32_t> Candidates;
  std::vector<Piece> Pieces;
};

/**
 * A_O (Eq. 5): the mean transmittance of frame.AmbientOcclusionSamples rays from p (view
 * coordinates) around the unit normal n within frame.AmbientOcclusionDistance, cosine
 * distributed; light receives L_A (Eq. 6), the mean radiance e_A c_j the spheres emit into the
 * rays, composited front to back. Spheres with frame.SphereTheta >= 1 (or all, when it is empty:
 * the opaque mode) are opaque: the transmittance is 0 from their first point on the ray (binary
 * visibility, Eq. 3). Translucent spheres attenuate by exp(-kappa_j I / I_max) with I the
 * density integral of their part of the ray (exact for overlaps too: optical depths add); their
 * emission is composited in the order of their entry along the ray (exact where they do not
 * overlap). own is the sphere the point lies on, (px, py) the pixel (it rotates the pattern).
 */
double AmbientTerms(const Frame& frame, const double p[3], const double n[3], vtkIdType own, int px,
  int py, AmbientScratch& scratch, double light[3]);
} // namespace prReference

#endif
