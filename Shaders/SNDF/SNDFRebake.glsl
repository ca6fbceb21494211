#version 430
//=========================================================================
// SNDFRebake.glsl -- vtkSNDFRenderPass: after a change of the lighting
// table (re-lighting, Ibrahim et al. 2017, Eqs. 12-14), sum the shaded bin
// sums of every texel of the listed S-MIP tiles again over its occupied bins:
//
//   prSums[1].rgb = sum_b c_b mean_b(AO diffuse) D(b)
//   prSums[2].rgb = sum_b c_b S(b)
// (D and S with the table's slopes at the bin's mean position: SNDFBins.glsl)
//
// (see SNDFAccumulate.glsl for the storage). No sample is taken again.
// Dispatch: (4, 4, number of tiles) groups of 16 x 16; group z rebakes the
// tile in slot prPageTable[z] (SNDFTiles.glsl: the page table holds the list).
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;

uniform sampler2D prTable;
uniform int prBins;

//PR::Include SNDFBins
//PR::Include SNDFTiles

void main()
{
  uint texel = prSNDFListedTexel();
  uint sums = prSumAddress(texel);
  vec4 s2 = prSumAt(sums, 2u);
  if (s2.a <= 0.0)
  {
    return; // no particle sample: both sums are zero
  }
  vec3 diffuse = vec3(0.0);
  vec3 specular = vec3(0.0);
  uint words = prBinWordAddress(texel);
  int m = -1;
  uint mask = 0u;
  int bin;
  while (prSNDFNextBin(words, prBins, m, mask, bin))
  {
    uint base = prSNDFWordsPerBin * uint(bin);
    vec3 d;
    vec3 s;
    prSNDFBinShadeWords(prTable, bin, prBinWordAt(words, base), prBinWordAt(words, base + 1u),
      prBinWordAt(words, base + 2u), d, s);
    diffuse += d;
    specular += s;
  }
  prSetSumAt(sums, 1u, vec4(diffuse, prSumAt(sums, 1u).w));
  prSetSumAt(sums, 2u, vec4(specular, s2.w));
}
