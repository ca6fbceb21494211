#version 430
//=========================================================================
// RadixSortIota.glsl -- prValuesA[i] = i: the result when every pass is
// skipped (all keys equal).
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
      prValuesA[i] = i;
    }
  }
}
