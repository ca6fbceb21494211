#version 430
//=========================================================================
// RadixSortFlipCopy.glsl -- prKeysB[i] = mapped key of the float prKeysA[i].
// Used when an odd number of passes runs, so that the first pass starts on
// side B and the last one ends on side A.
//=========================================================================
//PR::Include RadixSortCommon
layout(local_size_x = 256) in;

void main()
{
  uint g = prLinearGroupID();
  for (uint j = 0u; j < 4u; ++j)
  {
    uint i = g * PR_TILE + j * PR_THREADS + gl_LocalInvocationIndex;
    if (g < prNumGroups && i < prCount)
    {
      prKeysB[i] = prFloatToKey(prKeysA[i]);
    }
  }
}
