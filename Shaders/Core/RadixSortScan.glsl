#version 430
//=========================================================================
// RadixSortScan.glsl -- step 2 of a pass, one level of a multi-level
// exclusive scan: every work group scans 1024 consecutive entries of
// prKeysB[prOffset, prOffset + prLength) in place and (prWriteSums) writes
// their total to prKeysB[prSumsOffset + group]. The host scans the sums the
// same way (one level per factor 1024, so 3 levels hold 1e9 entries) and
// RadixSortScanAdd.glsl adds them back.
//=========================================================================
//PR::Include RadixSortCommon
//PR::Include RadixSortWorkgroupScan
layout(local_size_x = 256) in;

uniform uint prOffset;
uniform uint prLength;
uniform uint prSumsOffset;
uniform uint prWriteSums;

void main()
{
  uint t = gl_LocalInvocationIndex;
  uint g = prLinearGroupID();
  uint first = g * PR_TILE + t * 4u;
  bool live = g < prNumGroups;
  uint v[4];
  uint sum = 0u;
  for (uint j = 0u; j < 4u; ++j)
  {
    v[j] = (live && first + j < prLength) ? prKeysB[prOffset + first + j] : 0u;
    sum += v[j];
  }
  uint total;
  uint prefix = prWorkgroupExclusiveScan(sum, total);
  for (uint j = 0u; j < 4u; ++j)
  {
    if (live && first + j < prLength)
    {
      prKeysB[prOffset + first + j] = prefix;
    }
    prefix += v[j];
  }
  if (t == 0u && live && prWriteSums != 0u)
  {
    prKeysB[prSumsOffset + g] = total;
  }
}
