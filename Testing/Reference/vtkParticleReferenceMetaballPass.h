// Private header of ParticleRendering::Reference (vtkParticleReferenceRenderer): the metaball
// mode, the per-pixel stage for a vtkMetaballMapper's actor.
#ifndef vtkParticleReferenceMetaballPass_h
#define vtkParticleReferenceMetaballPass_h

#include "vtkParticleReferenceFrame.h"

class vtkParticleReferenceMetaballs;

namespace prReference
{
/**
 * The metaball surface of the frame's spheres (view coordinates, radius R) for every pixel ray
 * (surface prepared with the same particles in the same order, InfluenceFactor and IsoValue
 * set): the first crossing within the near and far planes, its window and view depth, the
 * gradient normal facing the viewer, the colour blended from the contributing particles' 8-bit
 * RGBA by their field share D_j (as vtkMetaballMapper) and lit as in the opaque mode. Id: the
 * particle with the largest share. Inside: the ray starts inside the surface (the near plane
 * cuts it; the GPU then shows the exit, the reference the near-plane point: mask these).
 */
void RenderMetaballs(const Frame& frame, const vtkParticleReferenceMetaballs* surface);
}

#endif
