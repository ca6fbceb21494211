#version 430
//=========================================================================
// SNDFResolve.glsl -- vtkSNDFRenderPass: shade every window pixel from its
// S-NDF and the pre-integrated lighting table (Ibrahim et al. 2017,
// Eqs. 12-14):
//
//   L(x) = ( sum_k colour_k + prAmbientTerm * sum_i AO_i
//          + prDiffuseScale * sum_b c_b mean_b(AO diffuse) * D(b)
//          + specularColour (sum_i AO_i / Nc) * sum_b c_b S(b) ) / N
//
// N samples of the texel (prSums[3].y), Nc of them on particles, colour_k
// what sample k drew without its normal (a particle's AO * ambient colour
// and ambient light, other geometry's and the background's colour), c_b the
// count of bin b and mean_b its samples' mean diffuse colour, D(b) and S(b)
// the lights' diffuse and specular terms averaged over the normals of bin b
// (table rows 0 and 1). Where the samples hold the particles' colours without
// their material (vtkSNDFRenderPass: one particle actor) prDiffuseScale is
// the diffuse coefficient (times the property's diffuse colour where the
// samples stored white) and prAmbientTerm the ambient coefficient times the
// ambient colour (the samples then left the particle's ambient term out);
// otherwise 1 and 0. Writes the colour and the nearest depth seen.
//
// The two bin sums are linear in the samples for a fixed table and kept up
// to date per sample (SNDFAccumulate.glsl) or summed again after a table
// change (SNDFRebake.glsl), so the shade costs O(1) per pixel whatever the
// bin count. One tile-list dispatch per part of the pool the view's tiles
// lie in (SNDFTiles.glsl), one invocation per texel.
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;

uniform ivec2 prSize;
uniform vec3 prSpecularColour;
uniform vec3 prDiffuseScale;
uniform vec3 prAmbientTerm;

//PR::Include SNDFBins
//PR::Include SNDFTiles

layout(rgba32f, binding = 0) uniform writeonly image2D prImage;
layout(r32f, binding = 1) uniform writeonly image2D prDepthImage;

void main()
{
  ivec2 p;
  uint texel;
  if (!prSNDFTileInvocation(prSize, p, texel))
  {
    return;
  }
  vec4 colours = prSum(texel, 0u);
  vec4 s1 = prSum(texel, 1u);
  vec4 s2 = prSum(texel, 2u);
  vec2 s3 = prSum(texel, 3u).xy;
  vec3 particles = prDiffuseScale * s1.rgb + prAmbientTerm * s3.x;
  if (s2.a > 0.0)
  {
    particles += prSpecularColour * (s3.x / s2.a) * s2.rgb;
  }
  vec4 colour = vec4(particles + colours.rgb, colours.a) / max(1.0, s3.y);
  float depth = s1.w > 0.0 ? 1.0 - s1.w : 1.0;
  if (any(isnan(colour)) || any(isinf(colour)))
  {
    colour = vec4(0.0, 0.0, 0.0, 1.0);
  }
  imageStore(prImage, p, colour);
  imageStore(prDepthImage, p, vec4(depth));
}
