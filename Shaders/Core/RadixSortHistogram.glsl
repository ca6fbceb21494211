#version 430
//=========================================================================
// RadixSortHistogram.glsl -- step 1 of a pass: the digit histogram of every
// 1024-key tile, written digit-major to
// prKeysB[prCountsOffset + digit * prNumGroups + tile], so that an exclusive
// scan of that array gives every (digit, tile) its first output position.
//=========================================================================
//PR::Include RadixSortCommon
layout(local_size_x = 256) in;

uniform uint prShift;        // bit position of the digit
uniform uint prReadB;        // 1: keys are read from side B, 0: from side A
uniform uint prFlipInput;    // 1: side A still holds the caller's floats
uniform uint prCountsOffset; // in prKeysB

shared uint prHistogram[PR_BUCKETS];

void main()
{
  uint t = gl_LocalInvocationIndex;
  uint g = prLinearGroupID();
  if (t < PR_BUCKETS)
  {
    prHistogram[t] = 0u;
  }
  PR_BARRIER;
  if (g < prNumGroups)
  {
    for (uint j = 0u; j < 4u; ++j)
    {
      uint i = g * PR_TILE + j * PR_THREADS + t;
      if (i < prCount)
      {
        uint key = prReadB != 0u ? prKeysB[i] : prKeysA[i];
        if (prFlipInput != 0u)
        {
          key = prFloatToKey(key);
        }
        atomicAdd(prHistogram[(key >> prShift) & 15u], 1u);
      }
    }
  }
  PR_BARRIER;
  if (t < PR_BUCKETS && g < prNumGroups)
  {
    prKeysB[prCountsOffset + t * prNumGroups + g] = prHistogram[t];
  }
}
