//=========================================================================
// Metaballs.glsl -- fragment stage of vtkMetaballMapper: the first crossing of
// the metaball iso-surface along the fragment's ray inside the sphere the particle
// draws (the part of its influence sphere where it can hold a surface point's
// largest kernel; ended at the depth pre-pass's depth, see vtkMetaballMapper)
// (Mueller, Grottel, Ertl 2007, Sec. 3.1 "vicinity" method).
//
// Field (Eq. 2 with influence factor k): D_j(x) = c (1 - |x - c_j|^2 / K_j^2)^2
// for |x - c_j| <= K_j = k R_j, c = 1 / (1 - 1/k^2)^2, summed over the drawn
// particle and its neighbour list (the particles whose influence spheres
// overlap its own, built on the CPU, view-independent).
//
// Along the ray x = s + t d (s relative to the drawn centre, d unit) each kernel
// is c (a_j - (t - tc_j)^2 / K_j^2)^2 with the closest approach tc_j and
// a_j = 1 - h_j^2 / K_j^2 (h_j the impact parameter; formed in list coordinates,
// below). Only the kernels positive somewhere on the fragment's chord are
// gathered: the others are 0 on all of it. Each is unimodal in t, so its
// maximum over [t0, t1] is at clamp(tc_j, t0, t1) and its minimum at the end
// farther from tc_j. The sums of these are certified bounds of the field over
// an interval. The search subdivides the chord depth first, left half first:
// an interval whose bound stays on the start's side of the iso-value cannot
// hold a crossing and is passed whole; the others are halved down to the
// tolerance, where the field at the interval's end decides: across the
// iso-value -> the first crossing is in it (every interval before it was
// passed), bisected prRefinementSteps times and finished with a secant step;
// not across -> passed (a part of the surface thinner than the tolerance along
// the ray can be missed, nothing thicker). The loop is bounded by
// prIterationLimit.
//
// Needs GL_ARB_shader_storage_buffer_object (core in OpenGL 4.3), enabled after
// the #version line by the mapper; binding points are set from the CPU.
//=========================================================================
#ifndef PR_METABALL_KERNELS
#define PR_METABALL_KERNELS 65
#endif

// per drawn particle: the first entry of its list and the entry count
layout(std430) buffer prMetaballRangeBlock
{
  ivec2 prMetaballRanges[];
};
// per list entry: the neighbour's centre relative to the particle (model coordinates, formed in
// double on the CPU) and its radius (model coordinates, before radiusScaleVC)
layout(std430) buffer prMetaballEntryBlock
{
  vec4 prMetaballEntries[];
};
// per list entry: the neighbour's index among the drawn particles (its colour)
layout(std430) buffer prMetaballIdBlock
{
  int prMetaballIds[];
};
#ifdef PR_METABALL_COLORS
// per drawn particle: its RGBA8 colour (r in the low byte)
layout(std430) buffer prMetaballColorBlock
{
  uint prMetaballColors[];
};
#endif

uniform mat3 prViewToListLinear;   // view -> list coordinates, linear part (see below)
uniform float prInfluenceFactor;  // k
uniform float prKernelScale;      // c
uniform float prIsoValue;
uniform float prTolerance;        // leaf width of the search, in units of the particle radius
uniform int prIterationLimit;     // most intervals examined per fragment
uniform int prRefinementSteps;    // bisections of the bracket before the secant step
uniform float prListRadiusScale;  // list radius -> list coordinates (the mapper's radius scale)
uniform float prViewToListScale;  // view -> list lengths, 1 / sigma

// The kernels are gathered in list coordinates: the model coordinates relative to the drawn
// centre, with radii scaled by the mapper's radius scale, so the list entries are used as they
// are (no per-entry transform). The actor and camera map them to view coordinates by
// L = sigma Q (sigma the cube root of |det|, the core's radius scale): the ray (s, d), d unit in
// view coordinates, becomes (L^-1 s, L^-1 d) with |L^-1 d|^2 = e = 1/sigma^2, and the kernel of
// list radius K_j along it, c (1 - |x - o_j|^2 / K_j^2)^2, is c (a_j - (t - tc_j)^2 e / K_j^2)^2
// in the view ray parameter t. (An actor matrix that is not a similarity gives the affine image
// of the list-coordinate surface.)
// the kernels that reach the chord: (tc, a, e/K^2) along the ray, and the list entry (-1: the
// drawn particle itself)
vec3 prKernelRay[PR_METABALL_KERNELS];
int prKernelId[PR_METABALL_KERNELS];
int prKernelCount = 0;

void prAddKernel(vec3 rel, float influenceRadius, int id, vec3 d, float e, float t0, float t1)
{
  // rel: the ray start relative to the kernel's centre, d: the ray direction (list coordinates)
  float tc = -dot(rel, d) / e;
  vec3 q = rel + tc * d;
  float invK2 = 1.0 / (influenceRadius * influenceRadius);
  float a = 1.0 - dot(q, q) * invK2;
  float u = clamp(tc, t0, t1) - tc;
  float scale = e * invK2;
  // kept when the kernel is positive somewhere on the chord [t0, t1]
  if (a - u * u * scale > 0.0 && prKernelCount < PR_METABALL_KERNELS)
  {
    prKernelRay[prKernelCount] = vec3(tc, a, scale);
    prKernelId[prKernelCount] = id;
    ++prKernelCount;
  }
}

// the field along the ray, and certified upper and lower bounds of it over [t0, t1]
float prMetaballField(float t)
{
  float sum = 0.0;
  for (int j = 0; j < prKernelCount; ++j)
  {
    vec3 k = prKernelRay[j];
    float u = t - k.x;
    float q = max(k.y - u * u * k.z, 0.0);
    sum += q * q;
  }
  return prKernelScale * sum;
}

float prMetaballFieldMax(float t0, float t1)
{
  float sum = 0.0;
  for (int j = 0; j < prKernelCount; ++j)
  {
    vec3 k = prKernelRay[j];
    float u = clamp(k.x, t0, t1) - k.x;
    float q = max(k.y - u * u * k.z, 0.0);
    sum += q * q;
  }
  return prKernelScale * sum;
}

float prMetaballFieldMin(float t0, float t1)
{
  float sum = 0.0;
  for (int j = 0; j < prKernelCount; ++j)
  {
    vec3 k = prKernelRay[j];
    float u = max(abs(t0 - k.x), abs(t1 - k.x));
    float q = max(k.y - u * u * k.z, 0.0);
    sum += q * q;
  }
  return prKernelScale * sum;
}

// Gather the kernels of the drawn particle (its list `id`) that reach the chord [t0, t1] of the
// ray (s, d) (view coordinates relative to the drawn centre).
void prGatherKernels(int id, float radiusVC, vec3 s, vec3 d, float t0, float t1)
{
  prKernelCount = 0;
  vec3 sL = prViewToListLinear * s;
  vec3 dL = prViewToListLinear * d;
  float e = prViewToListScale * prViewToListScale;
  prAddKernel(sL, prInfluenceFactor * prViewToListScale * radiusVC, -1, dL, e, t0, t1);
  ivec2 range = prMetaballRanges[id];
  float k = prInfluenceFactor * prListRadiusScale;
  for (int n = range.x; n < range.x + range.y; ++n)
  {
    vec4 entry = prMetaballEntries[n];
    prAddKernel(sL - entry.xyz, k * entry.w, n, dL, e, t0, t1);
  }
}

// The centre (list coordinates) and squared influence radius of gathered kernel j.
vec4 prKernelCentre(int j, float radiusVC)
{
  int n = prKernelId[j];
  if (n < 0)
  {
    float K = prInfluenceFactor * prViewToListScale * radiusVC;
    return vec4(0.0, 0.0, 0.0, K * K);
  }
  vec4 entry = prMetaballEntries[n];
  float K = prInfluenceFactor * prListRadiusScale * entry.w;
  return vec4(entry.xyz, K * K);
}

// The first crossing of the iso-value in [tLo, tHi] from the side the field has at tLo:
// true and tHit; startsInside says the field was at or above the iso-value at tLo (the crossing
// is then an exit). A depth-first subdivision of the chord, left half first: the intervals are
// visited left to right, so only their right ends are stacked.
#define PR_METABALL_STACK 40
bool prMetaballSearch(float tLo, float tHi, float radiusVC, out float tHit, out bool startsInside)
{
  float iso = prIsoValue;
  float tol = max(prTolerance * radiusVC, 1e-6 * radiusVC);
  startsInside = prMetaballField(tLo) >= iso;
  float side = startsInside ? -1.0 : 1.0; // look for side * (D - iso) >= 0
  tHit = tLo;
  float ends[PR_METABALL_STACK];
  int top = 0;
  ends[0] = tHi;
  float a = tLo;
  int it = 0;
  for (; it < prIterationLimit && top >= 0; ++it)
  {
    float b = ends[top];
    bool certified = startsInside ? (prMetaballFieldMin(a, b) >= iso)
                                  : (prMetaballFieldMax(a, b) < iso);
    if (!certified && (b - a <= tol || top == PR_METABALL_STACK - 1))
    {
      float gb = side * (prMetaballField(b) - iso);
      if (gb >= 0.0)
      {
        // the bracket [a, b]: bisected prRefinementSteps times, then one secant step
        float ga = side * (prMetaballField(a) - iso);
        for (int r = 0; r < prRefinementSteps; ++r)
        {
          float m = 0.5 * (a + b);
          float gm = side * (prMetaballField(m) - iso);
          if (gm >= 0.0)
          {
            b = m;
            gb = gm;
          }
          else
          {
            a = m;
            ga = gm;
          }
        }
        float w = gb - ga;
        tHit = w > 0.0 ? a + (b - a) * clamp(-ga / w, 0.0, 1.0) : b;
        return true;
      }
      certified = true; // thinner than the tolerance (or a near miss): passed
    }
    if (certified)
    {
      a = b;
      --top;
      continue;
    }
    ++top;
    ends[top] = 0.5 * (a + b);
  }
  return false;
}

// The unit normal (view coordinates) at the point x (view coordinates relative to the drawn
// centre) against the field's gradient (pointing out of the surface), and the colour blended by
// each kernel's share of the field.
vec3 prMetaballNormal(vec3 x, float radiusVC)
{
  // -grad D / (4 c) in list coordinates: points out of the surface; to view coordinates by
  // L^-T (gradients are covectors)
  vec3 xL = prViewToListLinear * x;
  vec3 outward = vec3(0.0);
  for (int j = 0; j < prKernelCount; ++j)
  {
    vec4 c = prKernelCentre(j, radiusVC);
    vec3 rel = xL - c.xyz;
    float q = max(1.0 - dot(rel, rel) / c.w, 0.0);
    outward += (q / c.w) * rel;
  }
  outward = transpose(prViewToListLinear) * outward;
  float len = length(outward);
  return len > 0.0 ? outward / len : vec3(0.0, 0.0, 1.0);
}

#ifdef PR_METABALL_COLORS
vec4 prUnpackColor(uint c)
{
  return vec4(float(c & 0xffu), float((c >> 8u) & 0xffu), float((c >> 16u) & 0xffu),
           float((c >> 24u) & 0xffu)) / 255.0;
}

vec4 prMetaballColor(vec3 x, float radiusVC, vec4 ownColor)
{
  vec3 xL = prViewToListLinear * x;
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int j = 0; j < prKernelCount; ++j)
  {
    vec4 c = prKernelCentre(j, radiusVC);
    vec3 rel = xL - c.xyz;
    float q = max(1.0 - dot(rel, rel) / c.w, 0.0);
    float w = q * q;
    int id = prKernelId[j] < 0 ? -1 : prMetaballIds[prKernelId[j]];
    sum += w * (id < 0 ? ownColor : prUnpackColor(prMetaballColors[id]));
    weights += w;
  }
  return weights > 0.0 ? sum / weights : ownColor;
}
#endif
