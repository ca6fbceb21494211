// Private header of ParticleRendering::Reference (vtkParticleReferenceRenderer): ray-traced
// ambient occlusion -- cosine-distributed rays from a visible point (Hammersley points with a
// per-pixel Cranley-Patterson rotation), binary visibility against the real spheres (all of
// them, the visible one excepted) up to the distance; the reference of every AO technique.
#ifndef vtkParticleReferenceAmbientOcclusion_h
#define vtkParticleReferenceAmbientOcclusion_h

#include "vtkType.h"

#include <cstdint>
#include <vector>

namespace prReference
{
struct Frame;

/**
 * Unoccluded fraction of frame.AmbientOcclusionSamples rays from p (view coordinates) around the
 * unit normal n within frame.AmbientOcclusionDistance; own is the sphere the point lies on,
 * (px, py) the pixel (it rotates the sample pattern); candidates is scratch space.
 */
double AmbientOcclusion(const Frame& frame, const double p[3], const double n[3], vtkIdType own,
  int px, int py, std::vector<std::uint32_t>& candidates);
} // namespace prReference

#endif
