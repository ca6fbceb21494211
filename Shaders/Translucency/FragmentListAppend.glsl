//=========================================================================
// FragmentListAppend.glsl -- the fragment stage of vtkTransparentSphereMapper
// with exact overlaps: instead of a colour, each translucent fragment appends
// its sphere's visible segment (prTranslucentSegment) to its pixel's list.
//=========================================================================
//PR::Include FragmentListBuffers

// seg: the visible segment (its tau = 0 point seg.closest relative to the centre, one unit of tau
// seg.scale long: the closest approach and the radius for a sphere); rayD: the fragment's ray
// direction; centerOffsetVC: the centre without the MC->VC translation, so that the key below is
// common to all spheres of the pixel and small (no camera-distance digits in it).
void prAppendSegment(prSegment seg, vec3 rayD, vec3 centerOffsetVC, float maximumIntegral)
{
  // the closest approach point's position along the pixel ray: z / d_z is the ray parameter
  // up to one constant of the pixel (all spheres share the ray and the translation)
  float key = (centerOffsetVC.z + seg.closest.z) / rayD.z;
  float lambda = seg.kappa < 0.0 ? 1e30 : seg.kappa / maximumIntegral;
  uint index = atomicAdd(prListCounters[0], 1u);
  if (index >= uint(prListCapacity))
  {
    return; // counted: the caller draws again with more room, or in bands
  }
  uint base = index * uint(PR_LIST_NODE_UINTS);
  prListNodes[base + 0u] = floatBitsToUint(key);
  prListNodes[base + 1u] = floatBitsToUint(seg.scale);
  prListNodes[base + 2u] = floatBitsToUint(seg.tn);
  prListNodes[base + 3u] = floatBitsToUint(seg.tf);
  prListNodes[base + 4u] = floatBitsToUint(seg.b2);
  prListNodes[base + 5u] = floatBitsToUint(lambda);
  prListNodes[base + 6u] = floatBitsToUint(seg.radiance.r);
  prListNodes[base + 7u] = floatBitsToUint(seg.radiance.g);
  prListNodes[base + 8u] = floatBitsToUint(seg.radiance.b);
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  uint head = atomicExchange(prListHeads[pixel.y * prListWidth + pixel.x], index);
  prListNodes[base + 9u] = head;
}
