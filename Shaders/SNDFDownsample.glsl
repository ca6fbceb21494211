#version 430
//=========================================================================
// SNDFDownsample.glsl -- vtkSNDFRenderPass: a tile of a coarser S-MIP level
// from the finer level in the cache (Ibrahim et al. 2017, Sec. 6.1.2,
// Fig. 10): each texel averages the prFactor x prFactor texels it covers
// (prFactor 2 for the next level, 4 for the one after; a box filter).
//
// Averaging is over the normalised S-NDFs, P(D_i) = c_i / N of Eq. 5, so
// children with different sample counts N weigh the same; the texel then
// holds N' = min(sum N, prMaxSamples) samples, its bin counts and sums are
// N' / prFactor^2 * sum over the children of (count or sum) / N (exact
// integers where the children hold equal counts), each bin's mean colour is
// the children's mean weighted by their normalised counts, the nearest depth
// the nearest of the children. A texel with a child that is not in the cache
// or holds no sample stays empty (the pass samples it).
//
// The destination slot was cleared. The page table of SNDFTiles.glsl maps
// the children's tile rectangle; child (i, j) of texel d is position
// d * prFactor + (i, j) there. Dispatch: (4, 4) groups of 16 x 16.
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;

uniform int prDestSlot;
uniform int prFactor;
uniform int prBins;
uniform float prMaxSamples;

//PR::Include SNDFBins
//PR::Include SNDFTiles


void main()
{
  ivec2 d = ivec2(gl_GlobalInvocationID.xy);
  uint dest = uint(prDestSlot) * prTileTexels + uint(d.y * prTileSize + d.x);
  uvec2 children[16];
  uvec2 childSums[16];
  float weight[16];
  int count = prFactor * prFactor;
  float total = 0.0;
  for (int c = 0; c < count; ++c)
  {
    uint texel;
    if (!prSNDFFindTexel(d * prFactor + ivec2(c % prFactor, c / prFactor), texel))
    {
      return;
    }
    childSums[c] = prSumAddress(texel);
    float n = prSumAt(childSums[c], 3u).y;
    if (!(n > 0.0))
    {
      return;
    }
    children[c] = prBinWordAddress(texel);
    weight[c] = 1.0 / n;
    total += n;
  }
  float samples = min(total, prMaxSamples);
  float scale = samples / float(count);

  vec4 colours = vec4(0.0);
  vec4 s1 = vec4(0.0);
  vec4 s2 = vec4(0.0);
  float ao = 0.0;
  for (int c = 0; c < count; ++c)
  {
    uvec2 t = childSums[c];
    colours += weight[c] * prSumAt(t, 0u);
    vec4 v1 = prSumAt(t, 1u);
    s1.rgb += weight[c] * v1.rgb;
    s1.w = max(s1.w, v1.w);
    s2 += weight[c] * prSumAt(t, 2u);
    ao += weight[c] * prSumAt(t, 3u).x;
  }
  uvec2 destSums = prSumAddress(dest);
  prSetSumAt(destSums, 0u, scale * colours);
  prSetSumAt(destSums, 1u, vec4(scale * s1.rgb, s1.w));
  prSetSumAt(destSums, 2u, scale * s2);
  prSetSumAt(destSums, 3u, vec4(scale * ao, samples, 0.0, 0.0));
  uvec2 destBins = prBinWordAddress(dest);

  uint binWords = uint(2 * prBins * prBins);
  int maskWords = max(1, prBins * prBins / 32);
  for (int m = 0; m < maskWords; ++m)
  {
    uint mask = 0u;
    for (int c = 0; c < count; ++c)
    {
      mask |= prBinWordAt(children[c], binWords + uint(m));
    }
    uint occupied = 0u;
    while (mask != 0u)
    {
      int bit = findLSB(mask);
      mask &= mask - 1u;
      uint bin = uint(32 * m + bit);
      float share = 0.0;
      vec3 mean = vec3(0.0);
      for (int c = 0; c < count; ++c)
      {
        uint w0 = prBinWordAt(children[c], 2u * bin);
        float k = weight[c] * float(w0 & 0xFFFFu);
        share += k;
        mean += k * prSNDFUnpackMean(w0, prBinWordAt(children[c], 2u * bin + 1u));
      }
      uint q = min(uint(scale * share + 0.5), 0xFFFFu);
      if (q > 0u)
      {
        uint w0;
        uint w1;
        prSNDFPackMean(q, mean / share, w0, w1);
        prSetBinWordAt(destBins, 2u * bin, w0);
        prSetBinWordAt(destBins, 2u * bin + 1u, w1);
        occupied |= 1u << uint(bit);
      }
    }
    prSetBinWordAt(destBins, binWords + uint(m), occupied);
  }
}
