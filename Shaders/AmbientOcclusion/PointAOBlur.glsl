//=========================================================================
// PointAOBlur.glsl -- the depth-aware blur of vtkPointAOPass: one direction
// of a separable 9-tap Gaussian (sigma 2.5 px) over the occlusion, each tap
// weighted by 1 / (1 + (dz / prDepthTolerance)^2), dz its view depth difference
// to the centre pixel, so that occlusion does not leak across silhouettes.
// prOcclusion holds (occlusion, view depth -z, 0 or 1 for background or
// geometry); background taps are left out, background pixels pass through.
//=========================================================================

uniform sampler2D prOcclusion;
uniform ivec2 prDirection;       // (1, 0) or (0, 1)
uniform float prDepthTolerance;  // view units

vec4 prBlurOcclusion(ivec2 pixel)
{
  ivec2 size = textureSize(prOcclusion, 0);
  vec4 centre = texelFetch(prOcclusion, pixel, 0);
  if (centre.z < 0.5)
  {
    return centre;
  }
  float sum = centre.x;
  float weights = 1.0;
  const float gauss[4] = float[4](0.9231163, 0.7261490, 0.4867523, 0.2780373);
  for (int k = 1; k <= 4; ++k)
  {
    float g = gauss[k - 1]; // exp(-k^2 / (2 * 2.5^2))
    for (int side = -1; side <= 1; side += 2)
    {
      ivec2 q = clamp(pixel + side * k * prDirection, ivec2(0), size - 1);
      vec4 tap = texelFetch(prOcclusion, q, 0);
      float dz = (tap.y - centre.y) / prDepthTolerance;
      float w = tap.z * g / (1.0 + dz * dz);
      sum += w * tap.x;
      weights += w;
    }
  }
  return vec4(sum / weights, centre.yzw);
}
