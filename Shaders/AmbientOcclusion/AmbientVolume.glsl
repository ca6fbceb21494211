#version 430
//=========================================================================
// AmbientVolume.glsl -- compute stages of vtkParticleAmbientVolume's GPU
// voxelisation (Staib et al. 2015, Sec. 5.1), the same arithmetic as its CPU
// path (see the class description):
//
//  PR_AMBIENT_WEIGHTS  one invocation per item (sphere j, voxel slice z):
//                      the overlap weights of the sphere's voxels in the
//                      slice, summed into the sphere's (full, partial) pair;
//  PR_AMBIENT_DEPOSIT  one invocation per item: the partial weights rescaled
//                      so that the sphere deposits its volume exactly, times
//                      the sphere's (emission, extinction), added to level 0
//                      of the float accumulator;
//  PR_AMBIENT_MIP      one invocation per voxel of level l: the mean of its
//                      2x2x2 children in level l - 1 (float, like the CPU);
//  PR_AMBIENT_STORE    one invocation per voxel of level l: the accumulator's
//                      floats into level l of the RGBA16F texture (NaN -> 0,
//                      beyond the largest half -> 65504, as FloatToHalf).
//
// Float sums use a compare-and-swap loop on the float's bits (float atomics
// are not core OpenGL 4.3); the order of the additions varies, so the sums
// agree with the CPU's to float rounding, not bit for bit.
//=========================================================================
#if defined(PR_AMBIENT_WEIGHTS) || defined(PR_AMBIENT_DEPOSIT)
layout(local_size_x = 64) in; // per item: loops of varying length
#else
layout(local_size_x = 256) in; // per voxel: uniform and short
#endif

//PR::Include ComputeCommon

uniform uint count; // invocations that have work (items or voxels)

#if defined(PR_AMBIENT_WEIGHTS) || defined(PR_AMBIENT_DEPOSIT)
// per sphere: centre and radius in voxel units (grid origin at 0)
layout(std430, binding = 0) readonly buffer prGeometry { vec4 geometry[]; };
// per item: the sphere and the voxel slice z
layout(std430, binding = 2) readonly buffer prItems { uvec2 items[]; };
// per sphere: the summed weights of its whole voxels and of its partial ones
layout(std430, binding = 3) buffer prSums { uint sums[]; };
uniform ivec3 dimensions;
uniform int subGrid; // sub-grid samples per axis

const float prPi = 3.14159265358979;

// target += value for a float stored as bits in a buffer's uint (a macro: atomic functions need
// the buffer variable itself, not a function's copy)
#define PR_ATOMIC_ADD_FLOAT(target, value)                                                       \
  {                                                                                              \
    uint prExpected = target;                                                                    \
    for (;;)                                                                                     \
    {                                                                                            \
      uint prPrevious = atomicCompSwap(                                                          \
        target, prExpected, floatBitsToUint(uintBitsToFloat(prExpected) + (value)));             \
      if (prPrevious == prExpected)                                                              \
      {                                                                                          \
        break;                                                                                   \
      }                                                                                          \
      prExpected = prPrevious;                                                                   \
    }                                                                                            \
  }

// the overlap of sphere (c, r) with voxel v: 1 inside, V_sphere when the voxel holds it, the
// negated sub-grid hit fraction when partial, 0 outside
float prWeight(vec3 c, float r, ivec3 v)
{
  vec3 lo = vec3(v);
  vec3 nearest = max(max(lo - c, c - lo - 1.0), vec3(0.0));
  vec3 farthest = max(abs(c - lo), abs(c - lo - 1.0));
  float r2 = r * r;
  if (dot(nearest, nearest) > r2)
  {
    return 0.0;
  }
  if (dot(farthest, farthest) <= r2)
  {
    return 1.0;
  }
  if (all(greaterThanEqual(c - r, lo)) && all(lessThanEqual(c + r, lo + 1.0)))
  {
    return 4.0 / 3.0 * prPi * r2 * r;
  }
  int hits = 0;
  float inv = 1.0 / float(subGrid);
  for (int a = 0; a < subGrid; ++a)
  {
    float pz = lo.z + (float(a) + 0.5) * inv - c.z;
    for (int b = 0; b < subGrid; ++b)
    {
      float py = lo.y + (float(b) + 0.5) * inv - c.y;
      for (int d = 0; d < subGrid; ++d)
      {
        float px = lo.x + (float(d) + 0.5) * inv - c.x;
        hits += px * px + py * py + pz * pz <= r2 ? 1 : 0;
      }
    }
  }
  return -float(hits) / float(subGrid * subGrid * subGrid);
}
#endif

#ifdef PR_AMBIENT_DEPOSIT
// per sphere: emission (e_A c_i sigma_i, RGB) and extinction sigma_i of a whole voxel
layout(std430, binding = 1) readonly buffer prMaterial { vec4 material[]; };
// level 0 of the accumulator: RGBA floats (as bits), x fastest
layout(std430, binding = 4) buffer prAccumulator { uint accumulator[]; };

void prDeposit(ivec3 v, float w, vec4 m)
{
  uint index = 4u * (uint(v.x) + uint(dimensions.x) * (uint(v.y) + uint(dimensions.y) * uint(v.z)));
  for (uint k = 0u; k < 4u; ++k)
  {
    PR_ATOMIC_ADD_FLOAT(accumulator[index + k], w * m[k]);
  }
}
#endif

#ifdef PR_AMBIENT_MIP
layout(std430, binding = 4) buffer prAccumulator { float levels[]; };
uniform uint fineOffset;   // first float of level l - 1
uniform uint coarseOffset; // first float of level l
uniform ivec3 fineDimensions;
uniform ivec3 coarseDimensions;
#endif

#ifdef PR_AMBIENT_STORE
layout(std430, binding = 4) readonly buffer prAccumulator { float levels[]; };
layout(rgba16f, binding = 0) writeonly uniform image3D prLevel;
uniform uint levelOffset;
uniform ivec3 levelDimensions;
#endif

void main()
{
  uint t = PR_INVOCATION_INDEX;
  if (t >= count)
  {
    return;
  }
#if defined(PR_AMBIENT_WEIGHTS) || defined(PR_AMBIENT_DEPOSIT)
  uint j = items[t].x;
  int z = int(items[t].y);
  vec3 c = geometry[j].xyz;
  float r = geometry[j].w;
  ivec2 lo = max(ivec2(floor(c.xy - r)), ivec2(0));
  ivec2 hi = min(ivec2(floor(c.xy + r)), dimensions.xy - 1);
#endif
#ifdef PR_AMBIENT_WEIGHTS
  float full = 0.0;
  float partial = 0.0;
  for (int y = lo.y; y <= hi.y; ++y)
  {
    for (int x = lo.x; x <= hi.x; ++x)
    {
      float w = prWeight(c, r, ivec3(x, y, z));
      if (w < 0.0)
      {
        partial -= w;
      }
      else
      {
        full += w;
      }
    }
  }
  if (full > 0.0)
  {
    PR_ATOMIC_ADD_FLOAT(sums[2u * j], full);
  }
  if (partial > 0.0)
  {
    PR_ATOMIC_ADD_FLOAT(sums[2u * j + 1u], partial);
  }
#endif
#ifdef PR_AMBIENT_DEPOSIT
  vec4 m = material[j];
  float volume = 4.0 / 3.0 * prPi * r * r * r;
  float full = uintBitsToFloat(sums[2u * j]);
  float partial = uintBitsToFloat(sums[2u * j + 1u]);
  if (partial == 0.0 && full == 0.0)
  {
    // smaller than the sub-grid and between its samples: all into the voxel of its centre,
    // once (by the item of that slice)
    ivec3 v = clamp(ivec3(c), ivec3(0), dimensions - 1);
    if (v.z == z)
    {
      prDeposit(v, volume, m);
    }
    return;
  }
  float scale = partial > 0.0 ? max(0.0, volume - full) / partial : 1.0;
  for (int y = lo.y; y <= hi.y; ++y)
  {
    for (int x = lo.x; x <= hi.x; ++x)
    {
      float w = prWeight(c, r, ivec3(x, y, z));
      w = w < 0.0 ? -w * scale : w;
      if (w > 0.0)
      {
        prDeposit(ivec3(x, y, z), w, m);
      }
    }
  }
#endif
#ifdef PR_AMBIENT_MIP
  ivec3 v = ivec3(int(t) % coarseDimensions.x, (int(t) / coarseDimensions.x) % coarseDimensions.y,
    int(t) / (coarseDimensions.x * coarseDimensions.y));
  // children per axis: 2, or 1 where the finer level is already 1 voxel thick
  ivec3 s = ivec3(greaterThan(fineDimensions, ivec3(1))) + 1;
  vec4 sum = vec4(0.0);
  for (int cz = 0; cz < s.z; ++cz)
  {
    for (int cy = 0; cy < s.y; ++cy)
    {
      for (int cx = 0; cx < s.x; ++cx)
      {
        ivec3 f = s * v + ivec3(cx, cy, cz);
        uint index = fineOffset + 4u * uint(f.x + fineDimensions.x * (f.y + fineDimensions.y * f.z));
        sum += vec4(levels[index], levels[index + 1u], levels[index + 2u], levels[index + 3u]);
      }
    }
  }
  sum *= 1.0 / float(s.x * s.y * s.z);
  for (uint k = 0u; k < 4u; ++k)
  {
    levels[coarseOffset + 4u * t + k] = sum[k];
  }
#endif
#ifdef PR_AMBIENT_STORE
  uint index = levelOffset + 4u * t;
  vec4 value = vec4(levels[index], levels[index + 1u], levels[index + 2u], levels[index + 3u]);
  // as FloatToHalf: NaN gives 0, beyond the largest half 65504
  value = mix(value, vec4(0.0), isnan(value));
  value = clamp(value, vec4(-65504.0), vec4(65504.0));
  ivec3 v = ivec3(int(t) % levelDimensions.x, (int(t) / levelDimensions.x) % levelDimensions.y,
    int(t) / (levelDimensions.x * levelDimensions.y));
  imageStore(prLevel, v, value);
#endif
}
