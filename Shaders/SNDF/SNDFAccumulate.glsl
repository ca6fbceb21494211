#version 430
//=========================================================================
// SNDFAccumulate.glsl -- vtkSNDFRenderPass: enter one sample per pixel into
// the pixel's S-NDF (Ibrahim et al. 2017, Sec. 4, "Computing probabilities")
// and into its colour sums. One invocation per pixel, so no atomics.
//
// The G-buffer of one jittered sample pass:
//   prColour   what the scene drew: the shaded colour of other geometry or the
//              background; for a particle the part of its shading that needs
//              no normal: AO * ambientColor plus the radiance its AO source
//              adds
//   prNormal   particles: (n.x, n.y, 2 + ambient visibility AO, 1); other
//              geometry: (0, 0, -1, 1); the background: what the delegate's
//              clear left (components in [0, 1]), so a sample is a particle's
//              when its third component exceeds 1.5
//   prDiffuse  particles: the diffuse colour (VTK's diffuseColor)
//   prDepth    window depth
// The S-NDFs live in the S-MIP cache (SNDFTiles.glsl): one tile-list dispatch
// per part of the pool the view's tiles lie in, one invocation per texel. Texels that hold
// prTarget samples or more take no more (a zoomed-out level averaged from a
// finer one, tiles converged before a pan): they stay as they are.
// Per texel (prSums, 4 vec4):
//   [0] = sum prColour (rgba)
//   [1] = (sum AO * diffuseColor * D(bin), max(1 - depth))
//   [2] = (sum S(bin), number of particle samples Nc)
//   [3] = (sum AO, number of samples N, 0, 0)   (N per texel: after a pan the
//         texels it uncovered have fewer than the others)
// D(bin) and S(bin) stand for a bin's shaded contribution with the lighting
// table's slopes (prSNDFBinShade, SNDFBins.glsl). [1].rgb and [2].rgb are the
// sums over the bins of those contributions, kept up to date sample by
// sample (a sample changes one bin: its contribution is taken out and put
// back in): a refinement frame costs O(1) per pixel, not O(bins); only a new
// table (re-lighting) sums the bins again.
// Per bin three words (SNDFBins.glsl): its sample count (low 16 bits) and the
// running mean of AO * diffuseColor of its samples, 16-bit fixed point over
// [0, 2] per channel (R in the high half of word 0, G and B in word 1), and
// the running mean of the samples' bin coordinates (word 2): the colour is
// kept per bin because colour and normal are correlated where about one
// particle covers a pixel (two species split it along their silhouettes).
// After the bins, prBins^2 / 32 words (at least one) mark the occupied bins,
// so that re-lighting visits those only. With prMoments, two words per bin
// follow: the running means of AO * t^k (k = 0..3) of its samples, t the
// particle's colour coordinate that the sample pass writes into prDiffuse.a
// (SNDFBins.glsl; a new colour map re-shades from them).
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;
// (dispatch: (4, 4, tiles))

//PR::Include SNDFBins
//PR::Include SNDFTiles

uniform sampler2D prColour;
uniform sampler2D prNormal;
uniform sampler2D prDiffuse;
uniform sampler2D prDepth;
uniform sampler2D prTable;
uniform ivec2 prSize;
uniform int prBins;
uniform float prTarget;
uniform int prMoments;


vec4 prFinite(vec4 v)
{
  return (any(isnan(v)) || any(isinf(v))) ? vec4(0.0) : v;
}

void main()
{
  ivec2 p;
  uint texel;
  if (!prSNDFTileInvocation(prSize, p, texel))
  {
    return;
  }
  uint sums = prSumAddress(texel);
  vec4 s3 = prSumAt(sums, 3u);
  if (s3.y >= prTarget)
  {
    return;
  }
  vec4 normal = texelFetch(prNormal, p, 0);
  vec4 s1 = prSumAt(sums, 1u);
  float depth = texelFetch(prDepth, p, 0).r;
  if (normal.z > 1.5 && !any(isnan(normal.xy)))
  {
    float ao = clamp(normal.z - 2.0, 0.0, 1.0);
    vec3 diffuse = clamp(prFinite(vec4(ao * texelFetch(prDiffuse, p, 0).rgb, 0.0)).rgb, 0.0, 2.0);
    uint bin = prSNDFBin(normal.xy, prBins);
    uint bins = prBinWordAddress(texel);
    uint base = prSNDFWordsPerBin * bin;
    uint w0 = prBinWordAt(bins, base);
    uint w1 = prBinWordAt(bins, base + 1u);
    uint w2 = prBinWordAt(bins, base + 2u);
    prSNDFBinLight light = prSNDFTableRows(prTable, int(bin));
    vec3 oldDiffuse;
    vec3 oldSpecular;
    prSNDFBinShade(light, w0, w1, w2, oldDiffuse, oldSpecular);
    uint count = (w0 & 0xFFFFu) + 1u;
    vec3 mean = prSNDFUnpackMean(w0, w1);
    mean += (diffuse - mean) / float(count);
    vec2 u = prSNDFUnpackOffset(w2);
    u += (prSNDFBinCoordinates(normal.xy, prBins) - u) / float(count);
    prSNDFPackMean(count, mean, w0, w1);
    w2 = prSNDFPackOffset(u);
    prSetBinWordAt(bins, base, w0);
    prSetBinWordAt(bins, base + 1u, w1);
    prSetBinWordAt(bins, base + 2u, w2);
    if (prMoments != 0)
    {
      float t = texelFetch(prDiffuse, p, 0).a;
      t = isnan(t) ? 0.0 : clamp(t, 0.0, 1.0);
      vec4 moments = prSNDFLoadMoments(bins, prBins, bin);
      moments += (ao * vec4(1.0, t, t * t, t * t * t) - moments) / float(count);
      prSNDFStoreMoments(bins, prBins, bin, moments);
    }
    uint mask = prSNDFMaskWord(prBins) + (bin >> 5u);
    prSetBinWordAt(bins, mask, prBinWordAt(bins, mask) | (1u << (bin & 31u)));
    // the texel's shaded sums follow the bin's new contribution (SNDFBins.glsl), computed from
    // the stored words as SNDFRebake.glsl computes it
    vec3 newDiffuse;
    vec3 newSpecular;
    prSNDFBinShade(light, w0, w1, w2, newDiffuse, newSpecular);
    s1.rgb += newDiffuse - oldDiffuse;
    prSetSumAt(sums, 2u, prSumAt(sums, 2u) + vec4(newSpecular - oldSpecular, 1.0));
    s3.x += ao;
  }
  s3.y += 1.0;
  prSetSumAt(sums, 3u, s3);
  s1.w = max(s1.w, 1.0 - depth);
  prSetSumAt(sums, 1u, s1);
  prSetSumAt(sums, 0u, prSumAt(sums, 0u) + prFinite(texelFetch(prColour, p, 0)));
}
