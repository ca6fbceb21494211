//=========================================================================
// OcclusionCull.glsl -- per-sphere occlusion test of the geometry stage
// (vtkParticleOcclusionCuller). prOcclusionMap holds, per block of
// prOcclusionBlock x prOcclusionBlock pixels of the viewport, the largest depth
// already in the depth buffer. A sphere is hidden when the nearest depth of the
// sphere (its point of largest view z, centre + r) lies behind every block its
// billboard covers by more than prOcclusionMargin: then every fragment it could
// write fails the depth test. Conservative everywhere else: billboard corners at
// or behind the eye plane, more than 4x4 blocks, the front beyond the near plane.
// The nearest depth is formed from the MC->VC translation and the small rest of
// the point separately (prClipZWOfSplitPointVC), so it stays exact with the
// camera far away.
//=========================================================================
uniform int prOcclusionCull;
uniform sampler2D prOcclusionMap;
uniform vec2 prOcclusionViewport;
uniform float prOcclusionBlock;
uniform float prOcclusionMargin;

bool prSphereIsOccluded(vec4 cornersDC[3], vec3 centerOffsetVC, float radiusVC, vec2 clipZW0,
  mat4 vcdc)
{
  if (prOcclusionCull == 0)
  {
    return false;
  }
  vec2 zw = prClipZWOfSplitPointVC(clipZW0, centerOffsetVC + vec3(0.0, 0.0, radiusVC), vcdc);
  if (!(zw.y > 0.0))
  {
    return false;
  }
  float nearest = 0.5 * (max(zw.x / zw.y, -1.0) + 1.0);
  vec2 lo = vec2(1e30);
  vec2 hi = vec2(-1e30);
  for (int i = 0; i < 3; ++i)
  {
    if (!(cornersDC[i].w > 0.0))
    {
      return false;
    }
    vec2 ndc = cornersDC[i].xy / cornersDC[i].w;
    lo = min(lo, ndc);
    hi = max(hi, ndc);
  }
  // pixels of the viewport, grown by one, as blocks
  vec2 blocks = vec2(textureSize(prOcclusionMap, 0));
  vec2 b0 = floor(((lo + 1.0) * 0.5 * prOcclusionViewport - 1.0) / prOcclusionBlock);
  vec2 b1 = floor(((hi + 1.0) * 0.5 * prOcclusionViewport + 1.0) / prOcclusionBlock);
  b0 = max(b0, vec2(0.0));
  b1 = min(b1, blocks - 1.0);
  if (any(greaterThan(b0, b1)))
  {
    return true; // entirely outside the viewport
  }
  if (any(greaterThan(b1 - b0, vec2(3.0))))
  {
    return false;
  }
  float limit = nearest - prOcclusionMargin;
  ivec2 i0 = ivec2(b0);
  ivec2 i1 = ivec2(b1);
  for (int y = i0.y; y <= i1.y; ++y)
  {
    for (int x = i0.x; x <= i1.x; ++x)
    {
      if (!(texelFetch(prOcclusionMap, ivec2(x, y), 0).r < limit))
      {
        return false;
      }
    }
  }
  return true;
}
