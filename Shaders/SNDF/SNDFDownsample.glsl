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
// counts, the nearest depth the nearest of the children. The shaded bin sums
// ([1].rgb, [2].rgb) are the children's, averaged like the rest: they differ
// from the sums a re-light forms from the averaged bins (SNDFRebake.glsl) by
// the covariance, within a bin, of the children's mean colours and mean bin
// positions only (shading the averaged bins here instead tripled the time of
// a zoom on llvmpipe). A texel with a child that is not in the cache
// or holds no sample stays empty (the pass samples it).
//
// Two phases, so that each dispatch binds one part of the pool (one bin and
// one sum buffer, SNDFTiles.glsl): prPhase 0, once per part that holds
// children, adds the children in that part to a per-texel record in
// prPartial (prFirst: the first such dispatch starts the records); prPhase
// 1, with the destination's part bound, writes the texels from the records.
// A record (uvec4s): [0] the children's weighted colour sums, [1] (weighted
// shaded diffuse sums, nearest 1 - depth), [2] weighted (shaded specular
// sums, Nc), [3] (weighted AO sum, sum N, children found, 0) as float bits,
// then the occupancy bits of the record's bins (prMaskVec4s uvec4s), then
// one uvec4 per bin: its weighted count (float bits) and the running
// weighted means of its colour and of its bin coordinates, packed as a bin's
// words are (SNDFBins.glsl); with prMoments a second run of one uvec4 per
// bin follows, its colour coordinates' moments (SNDFBins.glsl, in .xy)
// averaged with the same weights. A bin's entry is written when the
// record first meets it and only read where the occupancy bits say so: the
// records are never cleared, and phase 1 visits the occupied bins only.
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
uniform int prMoments;

//PR::Include SNDFBins
//PR::Include SNDFTiles

layout(std430, binding = 1) buffer prPartialBuffer
{
  uvec4 prPartial[];
};

vec4 prLoad(uint i)
{
  return uintBitsToFloat(prPartial[i]);
}

void prStore(uint i, vec4 v)
{
  prPartial[i] = floatBitsToUint(v);
}

// a bin entry: weighted count w (float bits), then the mean colour c and mean bin coordinates u
// packed as a bin stores them (SNDFBins.glsl; the count field of the first word unused)
uvec4 prPackEntry(float w, vec3 c, vec2 u)
{
  uint w0;
  uint w1;
  prSNDFPackMean(0u, c, w0, w1);
  return uvec4(floatBitsToUint(w), w0, w1, prSNDFPackOffset(u));
}

void prUnpackEntry(uvec4 e, out float w, out vec3 c, out vec2 u)
{
  w = uintBitsToFloat(e.x);
  c = prSNDFUnpackMean(e.y, e.z);
  u = prSNDFUnpackOffset(e.w);
}

void main()
{
  ivec2 d = ivec2(gl_GlobalInvocationID.xy);
  int binCount = prBins * prBins;
  int maskWords = prSNDFMaskWords(prBins);
  uint maskVec4s = uint((maskWords + 3) / 4);
  uint runs = prMoments != 0 ? 2u : 1u;
  uint record = uint(d.y * prTileSize + d.x) * (4u + maskVec4s + runs * uint(binCount));
  uint entries = record + 4u + maskVec4s;
  uint momentEntries = entries + uint(binCount);
  uint binWords = prSNDFMaskWord(prBins);

  if (prPhase == 0)
  {
    vec4 head[4];
    uint masks[8];
    for (int k = 0; k < 4; ++k)
    {
      head[k] = prFirst != 0 ? vec4(0.0) : prLoad(record + uint(k));
    }
    for (int m = 0; m < maskWords; ++m)
    {
      masks[m] = prFirst != 0 ? 0u : prPartial[record + 4u + uint(m / 4)][m % 4];
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
      vec4 s1 = prSumAt(sums, 1u);
      head[1] = vec4(head[1].rgb + weight * s1.rgb, max(head[1].w, s1.w));
      head[2] += weight * prSumAt(sums, 2u);
      head[3] += vec4(weight * s3.x, s3.y, 1.0, 0.0);
      uint bins = prBinWordAddress(texel);
      int m = -1;
      uint mask = 0u;
      int next;
      while (prSNDFNextBin(bins, prBins, m, mask, next))
      {
        uint bin = uint(next);
        uint bit = 1u << (bin & 31u);
        uint base = prSNDFWordsPerBin * bin;
        uint w0 = prBinWordAt(bins, base);
        float share = weight * float(w0 & 0xFFFFu);
        vec3 mean = prSNDFUnpackMean(w0, prBinWordAt(bins, base + 1u));
        vec2 u = prSNDFUnpackOffset(prBinWordAt(bins, base + 2u));
        vec4 moments = prMoments != 0 ? prSNDFLoadMoments(bins, prBins, bin) : vec4(0.0);
        if ((masks[m] & bit) != 0u)
        {
          float w;
          vec3 c0;
          vec2 u0;
          prUnpackEntry(prPartial[entries + bin], w, c0, u0);
          float t = share / max(w + share, 1.0e-30);
          mean = mix(c0, mean, t);
          u = mix(u0, u, t);
          if (prMoments != 0)
          {
            uvec4 e = prPartial[momentEntries + bin];
            moments = mix(prSNDFUnpackMoments(e.x, e.y), moments, t);
          }
          share += w;
        }
        masks[m] |= bit;
        prPartial[entries + bin] = prPackEntry(share, mean, u);
        if (prMoments != 0)
        {
          uint m0;
          uint m1;
          prSNDFPackMoments(moments, m0, m1);
          prPartial[momentEntries + bin] = uvec4(m0, m1, 0u, 0u);
        }
      }
    }
    for (int k = 0; k < 4; ++k)
    {
      prStore(record + uint(k), head[k]);
    }
    for (int m = 0; m < maskWords; ++m)
    {
      prPartial[record + 4u + uint(m / 4)][m % 4] = masks[m];
    }
    return;
  }

  // phase 1: the destination texel, when every child was found
  vec4 h3 = prLoad(record + 3u);
  int count = prFactor * prFactor;
  if (int(h3.z + 0.5) < count)
  {
    return;
  }
  float samples = min(h3.y, prMaxSamples);
  float scale = samples / float(count);
  uint dest = uint(prDestSlot) * prTileTexels + uint(d.y * prTileSize + d.x);
  uint destSums = prSumAddress(dest);
  vec4 h1 = prLoad(record + 1u);
  prSetSumAt(destSums, 0u, scale * prLoad(record));
  prSetSumAt(destSums, 1u, vec4(scale * h1.rgb, h1.w));
  prSetSumAt(destSums, 2u, scale * prLoad(record + 2u));
  prSetSumAt(destSums, 3u, vec4(scale * h3.x, samples, 0.0, 0.0));
  uint destBins = prBinWordAddress(dest);
  for (int m = 0; m < maskWords; ++m)
  {
    uint mask = prPartial[record + 4u + uint(m / 4)][m % 4];
    uint occupied = 0u;
    while (mask != 0u)
    {
      int bit = prSNDFTakeBit(mask);
      uint bin = uint(32 * m + bit);
      float w;
      vec3 mean;
      vec2 u;
      prUnpackEntry(prPartial[entries + bin], w, mean, u);
      uint q = min(uint(scale * w + 0.5), 0xFFFFu);
      if (q > 0u)
      {
        uint w0;
        uint w1;
        prSNDFPackMean(q, mean, w0, w1);
        uint base = prSNDFWordsPerBin * bin;
        prSetBinWordAt(destBins, base, w0);
        prSetBinWordAt(destBins, base + 1u, w1);
        prSetBinWordAt(destBins, base + 2u, prSNDFPackOffset(u));
        if (prMoments != 0)
        {
          uvec4 e = prPartial[momentEntries + bin];
          prSNDFStoreMoments(destBins, prBins, bin, prSNDFUnpackMoments(e.x, e.y));
        }
        occupied |= 1u << uint(bit);
      }
    }
    prSetBinWordAt(destBins, binWords + uint(m), occupied);
  }
}
