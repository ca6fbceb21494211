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
// integers where the children hold equal counts), each bin's mean colour and
// mean bin coordinates are the children's means weighted by their normalised
// counts, the nearest depth the nearest of the children; the shaded bin sums
// ([1].rgb, [2].rgb) are summed from the averaged bins with the table prTable
// (as SNDFRebake.glsl does, so that a later re-light changes nothing but the
// light). A texel with a child that is not in the cache
// or holds no sample stays empty (the pass samples it).
//
// Two phases, so that each dispatch binds one part of the pool (one bin and
// one sum buffer, SNDFTiles.glsl): prPhase 0, once per part that holds
// children, adds the children in that part to a per-texel record in
// prPartial (prFirst: the first such dispatch starts the records from
// zero); prPhase 1, with the destination's part bound, writes the texels
// from the records. A record: [0] the children's weighted colour sums,
// [1].w the nearest 1 - depth, [2].w the weighted Nc,
// [3] (weighted AO sum, sum N, children found, 0), then per bin two:
// (weighted count, weighted count * mean colour), (weighted count * mean bin
// coordinates, 0, 0).
//
// The page table of SNDFTiles.glsl maps the children's tile rectangle;
// child (i, j) of texel d is position d * prFactor + (i, j) there. The
// destination slot was cleared. Dispatch: (4, 4) groups of 16 x 16.
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;

uniform int prPhase;
uniform int prFirst;
uniform int prDestSlot;
uniform int prFactor;
uniform int prBins;
uniform float prMaxSamples;
uniform sampler2D prTable;

//PR::Include SNDFBins
//PR::Include SNDFTiles

layout(std430, binding = 1) buffer prPartialBuffer
{
  vec4 prPartial[];
};

void main()
{
  ivec2 d = ivec2(gl_GlobalInvocationID.xy);
  int binCount = prBins * prBins;
  uint record = uint((d.y * prTileSize + d.x) * (4 + 2 * binCount));
  uint binWords = prSNDFMaskWord(prBins);
  int maskWords = max(1, binCount / 32);

  if (prPhase == 0)
  {
    vec4 head[4];
    for (int k = 0; k < 4; ++k)
    {
      head[k] = prFirst != 0 ? vec4(0.0) : prPartial[record + uint(k)];
    }
    if (prFirst != 0)
    {
      for (int b = 0; b < 2 * binCount; ++b)
      {
        prPartial[record + 4u + uint(b)] = vec4(0.0);
      }
    }
    for (int c = 0; c < prFactor * prFactor; ++c)
    {
      uint texel;
      if (!prSNDFFindTexel(d * prFactor + ivec2(c % prFactor, c / prFactor), texel) ||
        !prSNDFInPart(texel))
      {
        continue;
      }
      uint sums = prSumAddress(texel);
      vec4 s3 = prSumAt(sums, 3u);
      if (!(s3.y > 0.0))
      {
        continue;
      }
      float weight = 1.0 / s3.y;
      head[0] += weight * prSumAt(sums, 0u);
      head[1].w = max(head[1].w, prSumAt(sums, 1u).w);
      head[2].w += weight * prSumAt(sums, 2u).w;
      head[3] += vec4(weight * s3.x, s3.y, 1.0, 0.0);
      uint bins = prBinWordAddress(texel);
      for (int m = 0; m < maskWords; ++m)
      {
        uint mask = prBinWordAt(bins, binWords + uint(m));
        while (mask != 0u)
        {
          int bit = findLSB(mask);
          mask &= mask - 1u;
          uint bin = uint(32 * m + bit);
          uint base = prSNDFWordsPerBin * bin;
          uint w0 = prBinWordAt(bins, base);
          float share = weight * float(w0 & 0xFFFFu);
          vec3 mean = prSNDFUnpackMean(w0, prBinWordAt(bins, base + 1u));
          vec2 u = prSNDFUnpackOffset(prBinWordAt(bins, base + 2u));
          prPartial[record + 4u + 2u * bin] += vec4(share, share * mean);
          prPartial[record + 5u + 2u * bin] += vec4(share * u, 0.0, 0.0);
        }
      }
    }
    for (int k = 0; k < 4; ++k)
    {
      prPartial[record + uint(k)] = head[k];
    }
    return;
  }

  // phase 1: the destination texel, when every child was found
  vec4 h3 = prPartial[record + 3u];
  int count = prFactor * prFactor;
  if (int(h3.z + 0.5) < count)
  {
    return;
  }
  float samples = min(h3.y, prMaxSamples);
  float scale = samples / float(count);
  uint dest = uint(prDestSlot) * prTileTexels + uint(d.y * prTileSize + d.x);
  uint destSums = prSumAddress(dest);
  vec4 h1 = prPartial[record + 1u];
  prSetSumAt(destSums, 0u, scale * prPartial[record]);
  uint destBins = prBinWordAddress(dest);
  vec3 diffuse = vec3(0.0);
  vec3 specular = vec3(0.0);
  for (int m = 0; m < maskWords; ++m)
  {
    uint occupied = 0u;
    for (int bit = 0; bit < 32 && 32 * m + bit < binCount; ++bit)
    {
      uint bin = uint(32 * m + bit);
      vec4 entry = prPartial[record + 4u + 2u * bin];
      uint q = min(uint(scale * entry.x + 0.5), 0xFFFFu);
      if (entry.x > 0.0 && q > 0u)
      {
        uint w0;
        uint w1;
        prSNDFPackMean(q, entry.yzw / entry.x, w0, w1);
        uint w2 = prSNDFPackOffset(prPartial[record + 5u + 2u * bin].xy / entry.x);
        uint base = prSNDFWordsPerBin * bin;
        prSetBinWordAt(destBins, base, w0);
        prSetBinWordAt(destBins, base + 1u, w1);
        prSetBinWordAt(destBins, base + 2u, w2);
        occupied |= 1u << uint(bit);
        vec3 d;
        vec3 s;
        prSNDFBinShadeWords(prTable, int(bin), w0, w1, w2, d, s);
        diffuse += d;
        specular += s;
      }
    }
    prSetBinWordAt(destBins, binWords + uint(m), occupied);
  }
  prSetSumAt(destSums, 1u, vec4(diffuse, h1.w));
  prSetSumAt(destSums, 2u, vec4(specular, scale * prPartial[record + 2u].w));
  prSetSumAt(destSums, 3u, vec4(scale * h3.x, samples, 0.0, 0.0));
}
