#version 430
//=========================================================================
// RadixSortScanAdd.glsl -- end of a scan level: adds the scanned sum of
// every 1024-entry tile, prKeysB[prSumsOffset + group], to its entries.
//=========================================================================
//PR::Include RadixSortCommon
layout(local_size_x = 256) in;

uniform uint prOffset;
uniform uint prLength;
uniform uint prSumsOffset;

void main()
{
  uint g = prLinearGroupID();
  if (g < prNumGroups)
  {
    uint add = prKeysB[prSumsOffset + g];
    for (uint j = 0u; j < 4u; ++j)
    {
      uint i = g * PR_TILE + j * PR_THREADS + gl_LocalInvocationIndex;
      if (i < prLength)
      {
        prKeysB[prOffset + i] += add;
      }
    }
  }
}
