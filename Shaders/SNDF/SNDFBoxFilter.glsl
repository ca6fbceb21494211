#version 430
//=========================================================================
// SNDFBoxFilter.glsl -- vtkSNDFRenderPass: a view between two levels of the
// S-MIP (a parallel zoom by a factor other than a power of two; Ibrahim et
// al. 2017, Sec. 6: "interpolating between two adjacent S-MIP levels"). The
// S-NDFs are sampled at the nearest level L and shaded per texel
// (SNDFResolve.glsl) into prTexels; each window pixel is the box filter of
// the texels under its footprint, weighted by the area they share with it.
// Shading is linear in the S-NDF, so this is the shade of the pixel's
// S-NDF: the average of the footprint's normal distributions (a
// pixel prScale texels wide, its lower-left corner at prOffset + p * prScale
// in texel units of prTexels), exactly the zoom's box-filtered image where
// the footprint covers whole texels, and otherwise that image convolved with
// the texel's own box (at most a texel of blur). Depth: the nearest texel of
// the footprint.
// Dispatch: one invocation per window pixel, 16 x 16 groups.
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;

uniform ivec2 prSize;       // the window
uniform ivec2 prTexelSize;  // prTexels
uniform float prScale;      // pixel width in texels
uniform vec2 prOffset;      // the window's lower-left corner in texels

layout(rgba32f, binding = 0) uniform readonly image2D prTexels;
layout(r32f, binding = 1) uniform readonly image2D prTexelDepth;
layout(rgba32f, binding = 2) uniform writeonly image2D prImage;
layout(r32f, binding = 3) uniform writeonly image2D prDepthImage;

void main()
{
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, prSize)))
  {
    return;
  }
  vec2 lo = prOffset + vec2(p) * prScale;
  vec2 hi = lo + vec2(prScale);
  ivec2 first = max(ivec2(floor(lo)), ivec2(0));
  ivec2 last = min(ivec2(ceil(hi)) - 1, prTexelSize - 1);
  vec4 colour = vec4(0.0);
  float weights = 0.0;
  float depth = 1.0;
  for (int y = first.y; y <= last.y; ++y)
  {
    float wy = min(hi.y, float(y + 1)) - max(lo.y, float(y));
    for (int x = first.x; x <= last.x; ++x)
    {
      float w = wy * (min(hi.x, float(x + 1)) - max(lo.x, float(x)));
      if (w > 0.0)
      {
        colour += w * imageLoad(prTexels, ivec2(x, y));
        weights += w;
        depth = min(depth, imageLoad(prTexelDepth, ivec2(x, y)).r);
      }
    }
  }
  colour = weights > 0.0 ? colour / weights : vec4(0.0, 0.0, 0.0, 1.0);
  imageStore(prImage, p, colour);
  imageStore(prDepthImage, p, vec4(depth));
}
