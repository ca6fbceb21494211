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
//
// prMode 1: any new colour map of the colour coordinate t (the particles'
// scalar within its range, SNDFBins.glsl) where the pool keeps t's moments:
// prRamps holds the stored colour as a function of t, prRampSize entries
// over [0, 1], for the old map (row 0) and the new one (row 1). A bin's
// samples have the AO-weighted moments A, A mu_1..3 of t; its mean colour
// m = mean(AO c(t)) becomes A Q_new + R (m - A Q_old), Q the two-node Gauss
// quadrature of the ramp under the bin's distribution of t
// (prSNDFQuadrature), R = prColourMatrix the least-squares linear map from
// the old ramp's colours to the new one's (it carries the old map's known
// quadrature error over). Exact where a bin's samples show at most two
// distinct values of t (a pixel split between two particles) and for any
// map quadratic in t. With several particle actors t is the placed
// coordinate t' of vtkSNDFRenderPass (each actor a part of [0, 1]).
// Dispatch: (4, 4, number of tiles) groups of 16 x 16; group z recolours the
// tile in slot prPageTable[z] (SNDFTiles.glsl: the page table holds the list).
//=========================================================================
layout(local_size_x = 16, local_size_y = 16) in;

uniform mat3 prColourMatrix;
uniform int prBins;
uniform int prMode;
uniform sampler2D prRamps;
uniform int prRampSize;

//PR::Include SNDFBins
//PR::Include SNDFTiles

// ramp `row` at t (linear between its entries)
vec3 prRamp(int row, float t)
{
  float x = clamp(t, 0.0, 1.0) * float(prRampSize - 1);
  int i = min(int(x), prRampSize - 2);
  return mix(texelFetch(prRamps, ivec2(i, row), 0).rgb, texelFetch(prRamps, ivec2(i + 1, row), 0).rgb,
    x - float(i));
}

// The mean of ramp `row` under a distribution of t with moments mu = (E t, E t^2, E t^3):
// two-node Gauss quadrature (nodes: the roots of x^2 + a x + b, orthogonal to 1 and x). Where the
// variance is too small for the 16-bit moments to place two nodes (below 1e-3: a t spread of
// 0.03) the nodes mu_1 -/+ sigma with equal weights, which meet the first two moments; below
// 2.5e-5 (the moments' rounding) one node.
vec3 prSNDFQuadrature(int row, vec3 mu)
{
  float variance = mu.y - mu.x * mu.x;
  if (variance < 2.5e-5)
  {
    return prRamp(row, mu.x);
  }
  if (variance >= 1.0e-3)
  {
    float a = (mu.x * mu.y - mu.z) / variance;
    float b = -mu.y - a * mu.x;
    float root = sqrt(max(a * a - 4.0 * b, 0.0));
    float x1 = 0.5 * (-a - root);
    float x2 = 0.5 * (-a + root);
    float w1 = (x2 - mu.x) / max(x2 - x1, 1.0e-6);
    if (x2 - x1 > 1.0e-3 && w1 >= 0.0 && w1 <= 1.0 && x1 >= -0.05 && x2 <= 1.05)
    {
      return w1 * prRamp(row, x1) + (1.0 - w1) * prRamp(row, x2);
    }
  }
  float sigma = sqrt(variance);
  return 0.5 * (prRamp(row, mu.x - sigma) + prRamp(row, mu.x + sigma));
}

void main()
{
  uint texel = prSNDFListedTexel();
  if (prSumAt(prSumAddress(texel), 2u).a <= 0.0)
  {
    return; // no particle sample: no occupied bin
  }
  uint words = prBinWordAddress(texel);
  int m = -1;
  uint mask = 0u;
  int bin;
  while (prSNDFNextBin(words, prBins, m, mask, bin))
  {
    uint base = prSNDFWordsPerBin * uint(bin);
    uint w0 = prBinWordAt(words, base);
    uint w1 = prBinWordAt(words, base + 1u);
    vec3 mean = prSNDFUnpackMean(w0, w1);
    if (prMode == 0)
    {
      mean = prColourMatrix * mean;
    }
    else
    {
      vec4 moments = prSNDFLoadMoments(words, prBins, uint(bin));
      if (moments.x > 0.0)
      {
        vec3 mu = moments.yzw / moments.x;
        vec3 residual = mean - moments.x * prSNDFQuadrature(0, mu);
        mean = moments.x * prSNDFQuadrature(1, mu) + prColourMatrix * residual;
      }
    }
    prSNDFPackMean(w0 & 0xFFFFu, mean, w0, w1);
    prSetBinWordAt(words, base, w0);
    prSetBinWordAt(words, base + 1u, w1);
  }
}
