#version 430
//=========================================================================
// RadixSortBits.glsl -- bitwise AND and OR of all mapped keys (read as floats
// from prKeysA) into prKeysB[prBitsOffset + 0/1]. A 4-bit digit where AND
// and OR agree is the same in every key: its pass is skipped. 4096 keys per
// work group; the host initialises AND to ~0 and OR to 0.
//=========================================================================
//PR::Include RadixSortCommon
layout(local_size_x = 256) in;

uniform uint prBitsOffset;

shared uint prAnd;
shared uint prOr;

void main()
{
  uint t = gl_LocalInvocationIndex;
  uint g = prLinearGroupID();
  if (t == 0u)
  {
    prAnd = 0xFFFFFFFFu;
    prOr = 0u;
  }
  PR_BARRIER;
  uint a = 0xFFFFFFFFu;
  uint o = 0u;
  if (g < prNumGroups)
  {
    for (uint j = 0u; j < 16u; ++j)
    {
      uint i = g * 4096u + j * PR_THREADS + t;
      if (i < prCount)
      {
        uint key = prFloatToKey(prKeysA[i]);
        a &= key;
        o |= key;
      }
    }
  }
  atomicAnd(prAnd, a);
  atomicOr(prOr, o);
  PR_BARRIER;
  if (t == 0u && g < prNumGroups)
  {
    atomicAnd(prKeysB[prBitsOffset], prAnd);
    atomicOr(prKeysB[prBitsOffset + 1u], prOr);
  }
}
