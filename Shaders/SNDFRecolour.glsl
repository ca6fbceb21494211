#version 430
//=========================================================================
// SNDFRecolour.glsl -- vtkSNDFRenderPass: a colour-map change whose new
// particle colours are a linear function of the old ones (c' = M c for every
// colour the particles had: up to three linearly independent colours, e.g.
// colour by type with up to three types) applied to the samples already
// taken: every occupied bin of every texel of the listed S-MIP tiles gets
// the mean colour M m instead of m (m is the mean of AO * colour over the
// bin's samples, so M m is exactly the mean the samples would have under
// the new colours). Counts and bin positions stay; the shaded sums are
// formed again afterwards by SNDFRebake.glsl (vtkSNDFTileCache marks the
// tiles stale). No sample is taken again.
// Dispatch: (4, 4, number of tiles) groups of 16 x 16; group z recolours the
// tile in slot prPageTable[z] (SNDFTiles.glsl: the page table holds the list).
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;

uniform mat3 prColourMatrix;
uniform int prBins;

//PR::Include SNDFBins
//PR::Include SNDFTiles

void main()
{
  uint texel = prSNDFListedTexel();
  if (prSumAt(prSumAddress(texel), 2u).a <= 0.0)
  {
    return; // no particle sample: no occupied bin
  }
  uint words = prBinWordAddress(texel);
  uint masks = prSNDFMaskWord(prBins);
  int maskWords = prSNDFMaskWords(prBins);
  for (int m = 0; m < maskWords; ++m)
  {
    uint mask = prBinWordAt(words, masks + uint(m));
    while (mask != 0u)
    {
      int bit = prSNDFTakeBit(mask);
      uint base = prSNDFWordsPerBin * uint(32 * m + bit);
      uint w0 = prBinWordAt(words, base);
      uint w1 = prBinWordAt(words, base + 1u);
      vec3 mean = prColourMatrix * prSNDFUnpackMean(w0, w1);
      prSNDFPackMean(w0 & 0xFFFFu, mean, w0, w1);
      prSetBinWordAt(words, base, w0);
      prSetBinWordAt(words, base + 1u, w1);
    }
  }
}
