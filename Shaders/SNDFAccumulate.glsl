#version 430
//=========================================================================
// SNDFAccumulate.glsl -- vtkSNDFRenderPass: enter one sample per pixel into
// the pixel's S-NDF (Ibrahim et al. 2017, Sec. 4, "Computing probabilities")
// and into its colour sums. One invocation per pixel, so no atomics.
//
// The G-buffer of one jittered sample pass:
//   prColour   what the scene drew: the shaded colour of other geometry or the
//              background; for a particle, the radiance its AO source adds
//   prNormal   particles: (n.x, n.y, ambient visibility, 1); else 0
//   prAmbient  particles: the ambient colour (VTK's ambientColor)
//   prDiffuse  particles: the diffuse colour (VTK's diffuseColor)
//   prDepth    window depth
// Per pixel (prSums, 3 vec4):
//   [0] = (sum AO * ambientColor, sum AO)   [1] = (unused, max(1 - depth))
//   [2] = sum prColour (rgba)
// and per bin two words (prBinWords): its sample count (low 16 bits) and the
// running mean of AO * diffuseColor of its samples, 16-bit fixed point over
// [0, 2] per channel (R in the high half of word 0, G and B in word 1): the
// colour is kept per bin because colour and normal are correlated where
// about one particle covers a pixel (two species split it along their
// silhouettes).
//=========================================================================
layout(local_size_x = 8, local_size_y = 8) in;

//PR::Include SNDFBins

uniform sampler2D prColour;
uniform sampler2D prNormal;
uniform sampler2D prAmbient;
uniform sampler2D prDiffuse;
uniform sampler2D prDepth;
uniform ivec2 prSize;
uniform int prBins;
uniform int prWordsPerPixel;

layout(std430, binding = 0) buffer prBinBuffer
{
  uint prBinWords[];
};
layout(std430, binding = 1) buffer prSumBuffer
{
  vec4 prSums[];
};

vec4 prFinite(vec4 v)
{
  return (any(isnan(v)) || any(isinf(v))) ? vec4(0.0) : v;
}

void main()
{
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= prSize.x || p.y >= prSize.y)
  {
    return;
  }
  uint pixel = uint(p.y) * uint(prSize.x) + uint(p.x);
  vec4 normal = texelFetch(prNormal, p, 0);
  vec4 s0 = prSums[3u * pixel];
  vec4 s1 = prSums[3u * pixel + 1u];
  float depth = texelFetch(prDepth, p, 0).r;
  if (normal.w > 0.5 && !any(isnan(normal.xy)))
  {
    float ao = clamp(normal.z, 0.0, 1.0);
    s0 += prFinite(vec4(ao * texelFetch(prAmbient, p, 0).rgb, ao));
    vec3 diffuse = clamp(prFinite(vec4(ao * texelFetch(prDiffuse, p, 0).rgb, 0.0)).rgb, 0.0, 2.0);
    uint word = pixel * uint(prWordsPerPixel) + 2u * prSNDFBin(normal.xy, prBins);
    uint w0 = prBinWords[word];
    uint w1 = prBinWords[word + 1u];
    uint count = (w0 & 0xFFFFu) + 1u;
    vec3 mean = prSNDFUnpackMean(w0, w1);
    mean += (diffuse - mean) / float(count);
    prSNDFPackMean(count, mean, w0, w1);
    prBinWords[word] = w0;
    prBinWords[word + 1u] = w1;
  }
  s1.w = max(s1.w, 1.0 - depth);
  prSums[3u * pixel] = s0;
  prSums[3u * pixel + 1u] = s1;
  prSums[3u * pixel + 2u] += prFinite(texelFetch(prColour, p, 0));
}
