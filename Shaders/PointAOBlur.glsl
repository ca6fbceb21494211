//=========================================================================
// PointAOBlur.glsl -- the depth-aware blur of vtkPointAOPass: one direction
// of a separable 9-tap Gaussian (sigma 2.5 px) over the occlusion, each tap
// weighted by exp(-(dz / prDepthTolerance)^2), dz its view-depth difference
// to the centre pixel, so that occlusion does not leak across silhouettes.
// Background taps and background pixels are left out.
//=========================================================================

uniform sampler2D prOcclusion;
uniform sampler2D prBlurDepth;
uniform mat4 prBlurInverseProjection;
uniform ivec2 prDirection;       // (1, 0) or (0, 1)
uniform float prDepthTolerance;  // view units

float prBlurViewDepth(ivec2 pixel, vec2 size)
{
  float d = texelFetch(prBlurDepth, pixel, 0).r;
  vec2 uv = (vec2(pixel) + 0.5) / size;
  vec4 v = prBlurInverseProjection * vec4(vec3(uv, d) * 2.0 - 1.0, 1.0);
  return d < 1.0 ? v.z / v.w : 1e30;
}

float prBlurOcclusion(ivec2 pixel)
{
  ivec2 size = textureSize(prOcclusion, 0);
  float centre = prBlurViewDepth(pixel, vec2(size));
  float value = texelFetch(prOcclusion, pixel, 0).r;
  if (centre > 1e29)
  {
    return value;
  }
  float sum = value;
  float weights = 1.0;
  for (int k = 1; k <= 4; ++k)
  {
    float g = exp(-float(k * k) / (2.0 * 2.5 * 2.5));
    for (int side = -1; side <= 1; side += 2)
    {
      ivec2 q = pixel + side * k * prDirection;
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)))
      {
        continue;
      }
      float dz = (prBlurViewDepth(q, vec2(size)) - centre) / prDepthTolerance;
      float w = g * exp(-dz * dz);
      sum += w * texelFetch(prOcclusion, q, 0).r;
      weights += w;
    }
  }
  return sum / weights;
}
