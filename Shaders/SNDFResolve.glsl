#version 430
//=========================================================================
// SNDFResolve.glsl -- vtkSNDFRenderPass: shade every pixel from its S-NDF
// and the pre-integrated lighting table (Ibrahim et al. 2017, Eqs. 12-14):
//
//   L(x) = ( sum_i AO_i ambient_i
//          + sum_b c_b mean_b(AO diffuse) * D(b)
//          + specularColour (sum_i AO_i / Nc) * sum_b c_b S(b)
//          + sum_k colour_k ) / N
//
// N samples per pixel, Nc of them on particles, c_b the count of bin b and
// mean_b its samples' mean diffuse colour, D(b) and S(b) the lights' diffuse
// and specular terms averaged over the normals of bin b (table rows 0 and
// 1). Writes the colour and the nearest depth seen.
//=========================================================================
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler2D prTable;
uniform ivec2 prSize;
uniform int prBins;
uniform int prWordsPerPixel;
uniform float prInverseSamples;
uniform vec3 prSpecularColour;

//PR::Include SNDFBins

layout(std430, binding = 0) readonly buffer prBinBuffer
{
  uint prBinWords[];
};
layout(std430, binding = 1) readonly buffer prSumBuffer
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
  vec4 s0 = prSums[3u * pixel];
  vec4 s1 = prSums[3u * pixel + 1u];
  vec4 s2 = prSums[3u * pixel + 2u];
  vec3 diffuse = vec3(0.0);
  vec3 specular = vec3(0.0);
  float covered = 0.0;
  int bins = prBins * prBins;
  uint first = pixel * uint(prWordsPerPixel);
  for (int bin = 0; bin < bins; ++bin)
  {
    uint w0 = prBinWords[first + 2u * uint(bin)];
    if (w0 == 0u)
    {
      continue;
    }
    float count = float(w0 & 0xFFFFu);
    vec3 mean = prSNDFUnpackMean(w0, prBinWords[first + 2u * uint(bin) + 1u]);
    diffuse += count * mean * texelFetch(prTable, ivec2(bin, 0), 0).rgb;
    specular += count * texelFetch(prTable, ivec2(bin, 1), 0).rgb;
    covered += count;
  }
  vec3 particles = s0.rgb + diffuse;
  if (covered > 0.0)
  {
    particles += prSpecularColour * (s0.a / covered) * specular;
  }
  vec4 colour = vec4(particles + s2.rgb, s2.a) * prInverseSamples;
  if (any(isnan(colour)) || any(isinf(colour)))
  {
    colour = vec4(0.0, 0.0, 0.0, 1.0);
  }
  imageStore(prImage, p, colour);
  imageStore(prDepthImage, p, vec4(s1.w > 0.0 ? 1.0 - s1.w : 1.0));
}
