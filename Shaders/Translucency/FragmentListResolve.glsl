#version 430
//=========================================================================
// FragmentListResolve.glsl -- compute pass of vtkParticleFragmentLists:
// composites each pixel's list of translucent sphere segments exactly,
// overlaps included, into the front-to-back accumulation image (one
// invocation per pixel of the band being resolved). A compute pass rather
// than a full-screen quad: no rasterisation masks (Mesa's llvmpipe loses
// shader-storage loads in the 4x4 blocks a quad's diagonal cuts).
//
// Along the ray the extinction is the sum of the spheres' densities,
// sigma = sum_j lambda_j rho_j, and the emission sum_j lambda_j rho_j L_j
// (L_j the colour of sphere j, Eq. 2 of Staib et al. 2015 per sphere). Between
// consecutive boundaries (segment starts and ends, hollow-core boundaries) the
// set of spheres is fixed; such an interval adds T (1 - exp(-D)) sum_j w_j L_j
// and multiplies T by exp(-D), D = sum_j D_j the exact optical depths
// (EmissionAbsorption.glsl). The weights are w_j = D_j / D for constant
// densities (exact: the integrands are proportional) and
// w_j = int sigma_j T / int sigma T for squared-distance densities (sigma_j
// quadratic along the interval: three moments of T by 4-point Gauss-Legendre
// quadrature on pieces of optical depth <= 1) (normalised, so
// the opacity stays exact and only the colour mix is approximated). Where
// nothing overlaps this is the sorted compositing of the glyph path.
//
// Two passes: the first composites every pixel whose list fits into the
// PR_LIST_LOCAL segments held and appends the others to prListDeferred; the
// second (PR_LIST_DEFERRED, the rounds below) runs over those pixels only.
//
// Bounded work space: PR_LIST_LOCAL segments are held at a time. The list is
// processed in rounds by increasing start: each round loads the next segments
// that fit, composites up to the start of the first one not loaded, and keeps
// the segments still open there. Exact as long as fewer than PR_LIST_LOCAL
// segments overlap at one point of the ray; otherwise the segments that found
// no room are skipped and the pixel is counted (prListCounters[1]).
//=========================================================================
#ifdef PR_LIST_DEFERRED
// the second pass: one invocation per pixel of the deferred list
layout(local_size_x = 64) in;
uniform int prDeferredCount;
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif
//PR::Include FragmentListBuffers
//PR::Include EmissionAbsorption
uniform float prHollowFraction2;
// the band being resolved: first pixel and size
uniform ivec2 prBandOrigin;
uniform ivec2 prBandSize;
// the front-to-back accumulation (premultiplied RGBA, cleared to 0)
layout(rgba32f, binding = 0) uniform writeonly image2D prAccumulation;

#ifndef PR_LIST_LOCAL
#define PR_LIST_LOCAL 16
#endif
#define PR_HUGE 3.0e38

float lKey[PR_LIST_LOCAL];
float lRadius[PR_LIST_LOCAL];
float lTn[PR_LIST_LOCAL];
float lTf[PR_LIST_LOCAL];
float lB2[PR_LIST_LOCAL];
float lLambda[PR_LIST_LOCAL];
vec3 lRadiance[PR_LIST_LOCAL];
float lStart[PR_LIST_LOCAL];
float lEnd[PR_LIST_LOCAL];
float lDepth[PR_LIST_LOCAL];

float prNodeFloat(uint node, uint word)
{
  return uintBitsToFloat(prListNodes[node * uint(PR_LIST_NODE_UINTS) + word]);
}

// where a segment starts along the pixel ray (the selection and the loading use this one
// expression, so that equal starts compare equal)
float prNodeStart(uint node)
{
  return prNodeFloat(node, 0u) + prNodeFloat(node, 2u) * prNodeFloat(node, 1u);
}

void prLoad(int slot, uint node, float start)
{
  lKey[slot] = prNodeFloat(node, 0u);
  lRadius[slot] = prNodeFloat(node, 1u);
  lTn[slot] = prNodeFloat(node, 2u);
  lTf[slot] = prNodeFloat(node, 3u);
  lB2[slot] = prNodeFloat(node, 4u);
  lLambda[slot] = prNodeFloat(node, 5u);
  lRadiance[slot] = vec3(prNodeFloat(node, 6u), prNodeFloat(node, 7u), prNodeFloat(node, 8u));
  lStart[slot] = start;
  lEnd[slot] = lKey[slot] + lTf[slot] * lRadius[slot];
}

void prCopy(int to, int from)
{
  lKey[to] = lKey[from];
  lRadius[to] = lRadius[from];
  lTn[to] = lTn[from];
  lTf[to] = lTf[from];
  lB2[to] = lB2[from];
  lLambda[to] = lLambda[from];
  lRadiance[to] = lRadiance[from];
  lStart[to] = lStart[from];
  lEnd[to] = lEnd[from];
}

// half length of the hollow core's chord in radii (0: the ray misses the core)
float prCoreHalf(int j)
{
  return lB2[j] < prHollowFraction2 ? sqrt(prHollowFraction2 - lB2[j]) : 0.0;
}

// the segment's own parameter (radii from its closest approach) at the ray position x: its own
// values where x is one of its boundaries, so that a sphere alone is integrated exactly as the
// glyph path does
float prTauAt(int j, float x)
{
  if (x == lStart[j])
  {
    return lTn[j];
  }
  if (x == lEnd[j])
  {
    return lTf[j];
  }
  float hs = prCoreHalf(j);
  if (hs > 0.0)
  {
    if (x == lKey[j] - hs * lRadius[j])
    {
      return -hs;
    }
    if (x == lKey[j] + hs * lRadius[j])
    {
      return hs;
    }
  }
  return clamp((x - lKey[j]) / lRadius[j], lTn[j], lTf[j]);
}

// density integral of segment j from its parameter tau0 to tau1 (no core boundary inside)
float prDensityBetween(int j, float tau0, float tau1)
{
  float mid = 0.5 * (tau0 + tau1);
  if (lB2[j] + mid * mid < prHollowFraction2)
  {
    return 0.0; // inside the empty core
  }
  return prPieceIntegral(lB2[j], tau0, tau1, tau1 - tau0);
}

// Segment j's extinction over [x0, x1] (no boundary inside) per unit of v, v = 0 at x0 and 1 at
// x1: lambda_j delta_j (b2_j + (tau0_j + v delta_j)^2) with delta_j = tau_j(x1) - tau_j(x0), as
// the coefficients of 1, v, v^2 (squared-distance density; its integral over v is the segment's
// optical depth there)
vec3 prExtinctionPolynomial(int j, float x0, float x1)
{
  float tau0 = prTauAt(j, x0);
  float delta = prTauAt(j, x1) - tau0;
  return (lLambda[j] * delta) * vec3(lB2[j] + tau0 * tau0, 2.0 * tau0 * delta, delta * delta);
}

// Composite the n segments held from `position` up to `limit` (no segment not held starts
// before it), over the elementary intervals between their boundaries; position ends at the limit
// or where nothing follows.
void prSweep(
  inout float position, float limit, int n, inout vec3 color, inout float transmittance)
{
  for (int step = 0; step < 4 * PR_LIST_LOCAL + 4 && position < limit && transmittance > 1e-6;
       ++step)
  {
    float x0 = position;
    float x1 = limit;
    for (int j = 0; j < n; ++j)
    {
      if (lStart[j] > x0)
      {
        x1 = min(x1, lStart[j]);
      }
      if (lEnd[j] > x0)
      {
        x1 = min(x1, lEnd[j]);
      }
      float hs = prCoreHalf(j);
      if (hs > 0.0)
      {
        float c0 = lKey[j] - hs * lRadius[j];
        float c1 = lKey[j] + hs * lRadius[j];
        if (c0 > x0)
        {
          x1 = min(x1, c0);
        }
        if (c1 > x0)
        {
          x1 = min(x1, c1);
        }
      }
    }
    if (!(x1 < PR_HUGE))
    {
      position = limit;
      break; // nothing further along this ray
    }
    // the interval [x0, x1]: exact optical depths of the segments spanning it
    float total = 0.0;
    int contributing = 0;
    int only = 0;
    for (int j = 0; j < n; ++j)
    {
      lDepth[j] = 0.0;
      if (lStart[j] <= x0 && lEnd[j] >= x1 && x0 > -PR_HUGE)
      {
        float integral = prDensityBetween(j, prTauAt(j, x0), prTauAt(j, x1));
        lDepth[j] = lLambda[j] * integral;
        if (lDepth[j] > 0.0)
        {
          total += lDepth[j];
          ++contributing;
          only = j;
        }
      }
    }
    if (total > 0.0)
    {
      float opacity = prOneMinusExpNeg(total);
      vec3 radiance = lRadiance[only];
      if (contributing > 1)
      {
#if PR_DENSITY_MODEL == 1
        // v in [0, 1] across the interval: segment j's extinction per unit v is the quadratic
        // p_j(v) (prExtinctionPolynomial), the optical depth from x0 S(v) the integral of their
        // sum p = a + b v + c v^2, and w_j = int p_j exp(-S) dv = p_j . (M0, M1, M2) with the
        // moments M_k = int v^k exp(-S(v)) dv, by 4-point Gauss-Legendre quadrature on pieces of
        // optical depth <= 1 (one loop over the segments before and one after, none per node)
        vec3 sum = vec3(0.0);
        for (int j = 0; j < n; ++j)
        {
          if (lDepth[j] > 0.0)
          {
            sum += prExtinctionPolynomial(j, x0, x1);
          }
        }
        int pieces = int(clamp(ceil(total), 1.0, 8.0));
        const float gaussNode[4] = float[4](-0.86113631, -0.33998104, 0.33998104, 0.86113631);
        const float gaussWeight[4] = float[4](0.34785485, 0.65214515, 0.65214515, 0.34785485);
        float width = 1.0 / float(pieces);
        vec3 moments = vec3(0.0);
        for (int p = 0; p < pieces; ++p)
        {
          for (int g = 0; g < 4; ++g)
          {
            float v = (float(p) + 0.5 + 0.5 * gaussNode[g]) * width;
            float depth = v * (sum.x + v * (0.5 * sum.y + v * (sum.z / 3.0)));
            moments += (0.5 * width * gaussWeight[g] * exp(-depth)) * vec3(1.0, v, v * v);
          }
        }
        vec3 weighted = vec3(0.0);
        float weightSum = 0.0;
        for (int j = 0; j < n; ++j)
        {
          if (lDepth[j] > 0.0)
          {
            float w = max(dot(prExtinctionPolynomial(j, x0, x1), moments), 0.0);
            weighted += w * lRadiance[j];
            weightSum += w;
          }
        }
        if (weightSum > 0.0)
        {
          radiance = weighted / weightSum;
        }
        else
        {
          radiance = vec3(0.0);
          for (int j = 0; j < n; ++j)
          {
            radiance += (lDepth[j] / total) * lRadiance[j];
          }
        }
#else
        radiance = vec3(0.0);
        for (int j = 0; j < n; ++j)
        {
          radiance += (lDepth[j] / total) * lRadiance[j];
        }
#endif
      }
      color += transmittance * opacity * radiance;
      transmittance *= exp(-total);
    }
    position = x1;
  }
}

// Write the pixel's premultiplied colour and opacity (nothing when empty or not finite: the
// accumulation is cleared to 0).
void prStore(ivec2 pixel, vec3 color, float transmittance)
{
  float alpha = 1.0 - transmittance;
  if (!(alpha > 0.0) || any(isnan(color)) || any(isinf(color)) || isnan(alpha))
  {
    return;
  }
  imageStore(prAccumulation, pixel, vec4(color, alpha));
}

void main()
{
#ifdef PR_LIST_DEFERRED
  int index = int(gl_GlobalInvocationID.x);
  if (index >= prDeferredCount)
  {
    return;
  }
  uint deferred = prListDeferred[index];
  ivec2 pixel = ivec2(int(deferred % uint(prListWidth)), int(deferred / uint(prListWidth)));
#else
  ivec2 offset = ivec2(gl_GlobalInvocationID.xy);
  if (offset.x >= prBandSize.x || offset.y >= prBandSize.y)
  {
    return;
  }
  ivec2 pixel = prBandOrigin + offset;
#endif
  uint head = prListHeads[pixel.y * prListWidth + pixel.x];
  if (head == PR_LIST_END)
  {
    return;
  }
  vec3 color = vec3(0.0);
  float transmittance = 1.0;

  // short lists (the usual case): all segments held at once, one walk, one sweep
  int n = 0;
  uint node = head;
  for (; node != PR_LIST_END && n < PR_LIST_LOCAL; ++n)
  {
    prLoad(n, node, prNodeStart(node));
    node = prListNodes[node * uint(PR_LIST_NODE_UINTS) + 9u];
  }
  if (node == PR_LIST_END)
  {
    float position = -PR_HUGE;
    prSweep(position, PR_HUGE, n, color, transmittance);
    prStore(pixel, color, transmittance);
    return;
  }

#ifndef PR_LIST_DEFERRED
  // a longer list: left to the second pass, which works in rounds (a program with that code
  // costs more for every pixel on some implementations, llvmpipe among them)
  uint slot = atomicAdd(prListCounters[2], 1u);
  prListDeferred[slot] = uint(pixel.y * prListWidth + pixel.x);
}
#else
  // longer lists: in rounds by increasing start
  n = 0;                 // segments held
  float lastStart = -PR_HUGE; // the last segment loaded or skipped, by (start, node)
  uint lastNode = 0u;
  bool first = true;
  float position = -PR_HUGE; // composited up to here
  bool truncated = false;
  int guard = max(prListCapacity, 1);
  for (int round = 0; round < guard && transmittance > 1e-6; ++round)
  {
    // the next segments by (start, node), one more than there is room for
    int room = PR_LIST_LOCAL - n;
    float bStart[PR_LIST_LOCAL + 1];
    uint bNode[PR_LIST_LOCAL + 1];
    int count = 0;
    node = head;
    for (int walk = 0; walk < guard && node != PR_LIST_END; ++walk)
    {
      float s = prNodeStart(node);
      bool later = first || s > lastStart || (s == lastStart && node > lastNode);
      if (later && (count <= room ||
                     s < bStart[count - 1] || (s == bStart[count - 1] && node < bNode[count - 1])))
      {
        // insertion into the sorted batch, dropping the last when full
        int k = min(count, room);
        if (count <= room)
        {
          ++count;
        }
        while (k > 0 && (bStart[k - 1] > s || (bStart[k - 1] == s && bNode[k - 1] > node)))
        {
          bStart[k] = bStart[k - 1];
          bNode[k] = bNode[k - 1];
          --k;
        }
        bStart[k] = s;
        bNode[k] = node;
      }
      node = prListNodes[node * uint(PR_LIST_NODE_UINTS) + 9u];
    }
    if (count == 0 && n == 0)
    {
      break;
    }
    // composite up to the first segment that is not loaded (all starts before it are)
    float limit = PR_HUGE;
    int loads = count;
    if (count > room)
    {
      limit = bStart[room];
      loads = room;
    }
    if (room == 0)
    {
      // no room: the next segment is skipped (the pixel is counted as incomplete)
      truncated = true;
      lastStart = bStart[0];
      lastNode = bNode[0];
      first = false;
      limit = bStart[0];
    }
    for (int k = 0; k < loads; ++k)
    {
      prLoad(n + k, bNode[k], bStart[k]);
    }
    if (loads > 0)
    {
      lastStart = bStart[loads - 1];
      lastNode = bNode[loads - 1];
      first = false;
    }
    n += loads;

    prSweep(position, limit, n, color, transmittance);
    position = max(position, limit);
    // keep the segments still open at the limit
    int kept = 0;
    for (int j = 0; j < n; ++j)
    {
      if (lEnd[j] > limit)
      {
        if (kept != j)
        {
          prCopy(kept, j);
        }
        ++kept;
      }
    }
    n = kept;
    if (limit >= PR_HUGE)
    {
      break;
    }
  }
  if (truncated)
  {
    atomicAdd(prListCounters[1], 1u);
  }
  prStore(pixel, color, transmittance);
}
#endif
