#version 430
//=========================================================================
// SNDFResolve.glsl -- vtkSNDFRenderPass: shade every pixel from its S-NDF
// and the pre-integrated lighting table (Ibrahim et al. 2017, Eqs. 12-14):
//
//   L(x) = ( sum_k colour_k
//          + sum_b c_b mean_b(AO diffuse) * D(b)
//          + specularColour (sum_i AO_i / Nc) * sum_b c_b S(b) ) / N
//
// N samples of the pixel (prSums[3].y), Nc of them on particles, colour_k what sample k drew
// without its normal (a particle's AO * ambient colour and ambient light,
// other geometry's and the background's colour), c_b the count of bin b and
// mean_b its samples' mean diffuse colour, D(b) and S(b) the lights' diffuse
// and specular terms averaged over the normals of bin b (table rows 0 and
// 1). Writes the colour and the nearest depth seen.
//
// The two bin sums are linear in the samples for a fixed table, so
// SNDFAccumulate.glsl keeps them up to date per sample (prSums[1].rgb and
// prSums[2].rgb). With prRebake set (the table changed: re-lighting) they are
// summed again over the occupied bins and stored; otherwise they are read,
// and the shade costs O(1) per pixel whatever the bin count.
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;

uniform sampler2D prTable;
uniform ivec2 prSize;
uniform int prBins;
uniform int prWordsPerPixel;
uniform int prRebake;
uniform vec3 prSpecularColour;

//PR::Include SNDFBins

layout(std430, binding = 0) readonly buffer prBinBuffer
{
  uint prBinWords[];
};
layout(std430, binding = 1) buffer prSumBuffer
{
  vec4 prSums[];
};
layout(rgba32f, binding = 0) uniform writeonly image2D prImage;
layout(r32f, binding = 1) uniform writeonly image2D prDepthImage;

void main()
{
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= prSize.x || p.y >= prSize.y)
  {
    return;
  }
  uint pixel = uint(p.y) * uint(prSize.x) + uint(p.x);
  vec4 colours = prSums[4u * pixel];
  vec4 s1 = prSums[4u * pixel + 1u];
  vec4 s2 = prSums[4u * pixel + 2u];
  vec2 s3 = prSums[4u * pixel + 3u].xy;
  float aoSum = s3.x;
  if (prRebake != 0 && s2.a > 0.0)
  {
    vec3 diffuse = vec3(0.0);
    vec3 specular = vec3(0.0);
    uint first = pixel * uint(prWordsPerPixel);
    uint masks = first + uint(2 * prBins * prBins);
    int maskWords = max(1, prBins * prBins / 32);
    for (int m = 0; m < maskWords; ++m)
    {
      uint mask = prBinWords[masks + uint(m)];
      while (mask != 0u)
      {
        int bit = findLSB(mask);
        mask &= mask - 1u;
        int bin = 32 * m + bit;
        uint w0 = prBinWords[first + 2u * uint(bin)];
        float count = float(w0 & 0xFFFFu);
        vec3 mean = prSNDFUnpackMean(w0, prBinWords[first + 2u * uint(bin) + 1u]);
        diffuse += count * mean * texelFetch(prTable, ivec2(bin, 0), 0).rgb;
        specular += count * texelFetch(prTable, ivec2(bin, 1), 0).rgb;
      }
    }
    s1.rgb = diffuse;
    s2.rgb = specular;
    prSums[4u * pixel + 1u] = s1;
    prSums[4u * pixel + 2u] = s2;
  }
  vec3 particles = s1.rgb;
  if (s2.a > 0.0)
  {
    particles += prSpecularColour * (aoSum / s2.a) * s2.rgb;
  }
  vec4 colour = vec4(particles + colours.rgb, colours.a) / max(1.0, s3.y);
  if (any(isnan(colour)) || any(isinf(colour)))
  {
    colour = vec4(0.0, 0.0, 0.0, 1.0);
  }
  imageStore(prImage, p, colour);
  imageStore(prDepthImage, p, vec4(s1.w > 0.0 ? 1.0 - s1.w : 1.0));
}
