//=========================================================================
// SNDFBins.glsl -- the "projected normals" binning of vtkSNDFRenderPass
// (Ibrahim et al. 2017, Sec. 4): a unit normal n facing the viewer is
// represented by its view-space (x, y) in the unit disk, and the square
// [-1, 1]^2 around the disk is cut into prBins x prBins equal bins; bin
// (i, j) is number j * prBins + i. The accumulation bins samples with
// prSNDFBin; the lighting table integrates over bin ∩ disk with
// prSNDFBinPoint (Eqs. 12-14).
//
// Storage of a bin (SNDFAccumulate.glsl): three words -- its sample count and
// the running mean of its samples' AO * diffuse colour (word 0: count, R;
// word 1: G, B), and the running mean of where in the bin its samples fell
// (word 2: the sample's bin coordinates u in [0, 1]^2, prSNDFBinCoordinates).
// After the bins, prSNDFMaskWord(bins) is the first of the words that mark the
// occupied bins.
//
// Colour coordinates (vtkSNDFRenderPass, "Colour"). Where the pass keeps them
// (prMoments), the words of the occupancy bits are followed by two words per
// bin: the running means over its samples of AO * t^k, k = 0..3, where t in
// [0, 1] is the sampled particle's scalar within its array's range, placed in
// its actor's part of [0, 1] where there are several particle actors (16-bit
// fixed point: AO and AO t in word 0, AO t^2 and AO t^3 in word 1; accessors
// prSNDFLoadMoments and prSNDFStoreMoments in SNDFTiles.glsl). A new colour
// map re-shades from them (SNDFRecolour.glsl, prSNDFQuadrature).
//
// Shading a bin (prSNDFBinShade). The lighting table (vtkSNDFRenderPass,
// SNDFLightingTable.glsl) has seven rows per bin b:
//   0: D(b)  mean diffuse light sum over bin ∩ disk  (Eq. 13's L~(D_i))
//   1: S(b)  mean specular light sum
//   2, 3: d D / d u.x, d D / d u.y   least-squares slopes over bin ∩ disk
//   4, 5: d S / d u.x, d S / d u.y
//   6: (u.x, u.y) of the centroid of bin ∩ disk
// A bin with c samples, mean colour m and mean bin coordinates u adds
//   diffuse   c m (D + dD/du . (u - centroid))
//   specular  c (S + dS/du . (u - centroid))
// For samples spread uniformly over the bin u is its centroid and this is the
// paper's pre-integrated bin value; where the samples crowd into part of the
// bin (a particle several pixels wide: each pixel sees a small patch of one
// sphere) the slope moves the value towards the light at that patch, so the
// shading is not quantised into facets.
//=========================================================================

const uint prSNDFWordsPerBin = 3u;

uint prSNDFMaskWord(int bins)
{
  return prSNDFWordsPerBin * uint(bins * bins);
}

// How many words mark the occupied bins (after prSNDFMaskWord(bins)).
int prSNDFMaskWords(int bins)
{
  return max(1, bins * bins / 32);
}

// The first word of the colour coordinates' moments (after the occupancy words).
uint prSNDFMomentWord(int bins)
{
  return prSNDFMaskWord(bins) + uint(prSNDFMaskWords(bins));
}

vec4 prSNDFUnpackMoments(uint m0, uint m1)
{
  return vec4(float(m0 & 0xFFFFu), float(m0 >> 16u), float(m1 & 0xFFFFu), float(m1 >> 16u)) *
    (1.0 / 65535.0);
}

void prSNDFPackMoments(vec4 moments, out uint m0, out uint m1)
{
  uvec4 q = uvec4(clamp(moments, 0.0, 1.0) * 65535.0 + 0.5);
  m0 = q.x | (q.y << 16u);
  m1 = q.z | (q.w << 16u);
}

// The bin square of a projected normal, in bin units: its cell and the position f of the normal.
vec2 prSNDFCell(vec2 nxy, int bins, out vec2 f)
{
  f = (nxy + 1.0) * 0.5 * float(bins);
  return clamp(floor(f), vec2(0.0), vec2(float(bins - 1)));
}

uint prSNDFBin(vec2 nxy, int bins)
{
  vec2 f;
  ivec2 cell = ivec2(prSNDFCell(nxy, bins, f));
  return uint(cell.y * bins + cell.x);
}

// Where in its bin's square the projected normal lies: [0, 1]^2.
vec2 prSNDFBinCoordinates(vec2 nxy, int bins)
{
  vec2 f;
  vec2 cell = prSNDFCell(nxy, bins, f);
  return clamp(f - cell, 0.0, 1.0);
}

// The normal at the sub-sample (u, v) in [0, 1]^2 of bin `bin`; false outside the unit disk.
bool prSNDFBinPoint(int bin, int bins, vec2 uv, out vec3 n)
{
  vec2 cell = vec2(float(bin % bins), float(bin / bins));
  vec2 xy = (cell + uv) * (2.0 / float(bins)) - 1.0;
  float r2 = dot(xy, xy);
  n = vec3(xy, sqrt(max(0.0, 1.0 - r2)));
  return r2 <= 1.0;
}

// A bin's sample count and mean colour in two words (see SNDFAccumulate.glsl).
vec3 prSNDFUnpackMean(uint w0, uint w1)
{
  return vec3(float(w0 >> 16u), float(w1 & 0xFFFFu), float(w1 >> 16u)) * (2.0 / 65535.0);
}

void prSNDFPackMean(uint count, vec3 mean, out uint w0, out uint w1)
{
  uvec3 q = uvec3(clamp(mean, 0.0, 2.0) * (65535.0 / 2.0) + 0.5);
  w0 = min(count, 0xFFFFu) | (q.r << 16u);
  w1 = q.g | (q.b << 16u);
}

// A bin's mean bin coordinates in one word (16-bit fixed point per axis).
vec2 prSNDFUnpackOffset(uint w2)
{
  return vec2(float(w2 & 0xFFFFu), float(w2 >> 16u)) * (1.0 / 65535.0);
}

uint prSNDFPackOffset(vec2 u)
{
  uvec2 q = uvec2(clamp(u, 0.0, 1.0) * 65535.0 + 0.5);
  return q.x | (q.y << 16u);
}

// A bin's seven rows of the lighting table (see above).
struct prSNDFBinLight
{
  vec3 D;
  vec3 S;
  vec3 DX;
  vec3 DY;
  vec3 SX;
  vec3 SY;
  vec2 Centroid;
};

// `table` is a sampler2D (GLSL takes samplers as arguments).
prSNDFBinLight prSNDFTableRows(sampler2D table, int bin)
{
  prSNDFBinLight light;
  light.D = texelFetch(table, ivec2(bin, 0), 0).rgb;
  light.S = texelFetch(table, ivec2(bin, 1), 0).rgb;
  light.DX = texelFetch(table, ivec2(bin, 2), 0).rgb;
  light.DY = texelFetch(table, ivec2(bin, 3), 0).rgb;
  light.SX = texelFetch(table, ivec2(bin, 4), 0).rgb;
  light.SY = texelFetch(table, ivec2(bin, 5), 0).rgb;
  light.Centroid = texelFetch(table, ivec2(bin, 6), 0).xy;
  return light;
}

// The diffuse and specular sums a bin with `count` samples, mean colour `mean` and mean bin
// coordinates `u` adds to its texel (see above), from its three stored words.
void prSNDFBinShade(prSNDFBinLight light, uint w0, uint w1, uint w2,
  out vec3 diffuse, out vec3 specular)
{
  float count = float(w0 & 0xFFFFu);
  vec2 du = prSNDFUnpackOffset(w2) - light.Centroid;
  diffuse = count * prSNDFUnpackMean(w0, w1) * (light.D + du.x * light.DX + du.y * light.DY);
  specular = count * (light.S + du.x * light.SX + du.y * light.SY);
}

void prSNDFBinShadeWords(sampler2D table, int bin, uint w0, uint w1, uint w2,
  out vec3 diffuse, out vec3 specular)
{
  prSNDFBinShade(prSNDFTableRows(table, bin), w0, w1, w2, diffuse, specular);
}
