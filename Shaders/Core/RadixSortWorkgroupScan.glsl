//=========================================================================
// RadixSortWorkgroupScan.glsl -- exclusive prefix sum over the 256
// invocations of a work group. Three barriers (16 invocations scan 16 values
// each, one invocation scans the 16 sums), no subgroup operations. Must be
// called by every invocation of the group (uniform control flow).
//=========================================================================
shared uint prScanData[256];
shared uint prScanSums[17];

uint prWorkgroupExclusiveScan(uint value, out uint total)
{
  uint t = gl_LocalInvocationIndex;
  prScanData[t] = value;
  PR_BARRIER;
  if (t < 16u)
  {
    uint sum = 0u;
    for (uint k = 0u; k < 16u; ++k)
    {
      uint x = prScanData[t * 16u + k];
      prScanData[t * 16u + k] = sum;
      sum += x;
    }
    prScanSums[t] = sum;
  }
  PR_BARRIER;
  if (t == 0u)
  {
    uint sum = 0u;
    for (uint k = 0u; k < 16u; ++k)
    {
      uint x = prScanSums[k];
      prScanSums[k] = sum;
      sum += x;
    }
    prScanSums[16] = sum;
  }
  PR_BARRIER;
  uint result = prScanData[t] + prScanSums[t >> 4u];
  total = prScanSums[16];
  PR_BARRIER; // the scratch arrays may be reused after the return
  return result;
}
