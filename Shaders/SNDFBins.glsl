//=========================================================================
// SNDFBins.glsl -- the "projected normals" binning of vtkSNDFRenderPass
// (Ibrahim et al. 2017, Sec. 4): a unit normal n facing the viewer is
// represented by its view-space (x, y) in the unit disk, and the square
// [-1, 1]^2 around the disk is cut into prBins x prBins equal bins; bin
// (i, j) is number j * prBins + i. The accumulation bins samples with
// prSNDFBin; the lighting table integrates over bin ∩ disk with
// prSNDFBinPoint (Eqs. 12-14).
//=========================================================================

uint prSNDFBin(vec2 nxy, int bins)
{
  ivec2 cell = clamp(ivec2(floor((nxy + 1.0) * 0.5 * float(bins))), ivec2(0), ivec2(bins - 1));
  return uint(cell.y * bins + cell.x);
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
