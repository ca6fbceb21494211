//=========================================================================
// RadixSortCommon.glsl -- buffers and key mapping of vtkParticleDepthSort.
//
// Four shader storage buffers, bound once per sort at binding points 0-3:
//   0 prKeysA    the caller's float keys on input, sorted keys on output;
//                between passes the mapped (uint) keys of the even sides
//   1 prValuesA  the sorted indices on output (the index buffer)
//   2 prKeysB    scratch keys, followed by the scratch area ("tail"): the
//                AND/OR of all mapped keys, the per-tile digit counts and
//                the levels of their scan (offsets are uniforms)
//   3 prValuesB  scratch indices
// A pass reads side A and writes side B, or the reverse (prReadB).
//
// Tiles: 256 invocations x 4 keys = 1024 keys per work group.
//=========================================================================
//PR::Include ComputeCommon

#define PR_THREADS 256u
#define PR_TILE 1024u
#define PR_BUCKETS 16u

layout(std430, binding = 0) buffer prKeysABlock { uint prKeysA[]; };
layout(std430, binding = 1) buffer prValuesABlock { uint prValuesA[]; };
layout(std430, binding = 2) buffer prKeysBBlock { uint prKeysB[]; };
layout(std430, binding = 3) buffer prValuesBBlock { uint prValuesB[]; };

uniform uint prCount;     // number of keys
uniform uint prNumGroups; // work groups that have work (the dispatch may hold more)

// float bits -> uint whose unsigned order is the float order: negatives
// inverted, positives with the sign bit set (so -0 < +0); every NaN -> the
// largest key, so NaNs sort last.
uint prFloatToKey(uint bits)
{
  if ((bits & 0x7FFFFFFFu) > 0x7F800000u)
  {
    return 0xFFFFFFFFu;
  }
  return (bits & 0x80000000u) != 0u ? ~bits : (bits | 0x80000000u);
}

// inverse of prFloatToKey (a NaN comes back as 0x7FFFFFFF, a quiet NaN)
uint prKeyToFloat(uint key)
{
  return (key & 0x80000000u) != 0u ? (key & 0x7FFFFFFFu) : ~key;
}
