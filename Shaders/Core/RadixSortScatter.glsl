#version 430
//=========================================================================
// RadixSortScatter.glsl -- step 3 of a pass: stable scatter of a 1024-key
// tile. Invocation t holds the 4 consecutive keys 4t..4t+3 of the tile, so
// tile order is (invocation, item) order.
//
// Local ranks (rank of a key among the tile's keys of the same digit):
//   1. every invocation counts its keys per digit in registers (4-bit
//      counters) and knows, per key, its earlier keys of the same digit;
//      it stores the counts in shared memory as [8 digit pairs][256], two
//      16-bit counts per word (digit 2p low, 2p+1 high);
//   2. an exclusive scan along the invocations of every digit pair (both
//      halves at once: no half exceeds 1024) in two levels: 256 invocations
//      scan 8 words each, 8 invocations scan the 32 chunk sums of a pair.
// Output position = scanned global count of (digit, tile) + local rank.
// PR_LOCAL_REORDER (default 1; vtkParticleDepthSort::CoalescedWrites): the
// keys are first placed in tile order in shared memory (Harris et al.'s local
// sort), so that consecutive invocations write consecutive addresses of one
// digit run (coalesced writes on GPUs). 0 writes every key straight from its
// invocation (16 partial runs per tile), which is 20 % faster on llvmpipe.
// Shared memory: 9 KB counts + 1 KB chunk sums (+ 8 KB for the reorder).
//=========================================================================
//PR::Include RadixSortCommon
layout(local_size_x = 256) in;

#ifndef PR_LOCAL_REORDER
#define PR_LOCAL_REORDER 1
#endif

uniform uint prShift;          // bit position of the digit
uniform uint prReadB;          // 1: read side B, write side A; 0: the reverse
uniform uint prFlipInput;      // 1: side A still holds the caller's floats
uniform uint prIotaValues;     // 1: first pass, the value of key i is i (not read)
uniform uint prUnflipOutput;   // 1: last pass, write float keys
uniform uint prCountsOffset;   // scanned digit-major counts in prKeysB

shared uint prCounts[2304];    // [pair][t], padded by one word per 8 (prPad)
shared uint prChunks[8 * 33];  // [pair][chunk of 8 invocations], [pair][32]: pair total
shared uint prDigitBase[16];   // global start of each digit of the tile (minus its tile start)
#if PR_LOCAL_REORDER
shared uint prTileStart[16];
shared uint prTileKeys[PR_TILE];
shared uint prTileValues[PR_TILE];
#endif

uint prPad(uint i)
{
  return i + (i >> 3u);
}

void prStore(uint destination, uint key, uint value)
{
  uint outKey = prUnflipOutput != 0u ? prKeyToFloat(key) : key;
  if (prReadB != 0u)
  {
    prKeysA[destination] = outKey;
    prValuesA[destination] = value;
  }
  else
  {
    prKeysB[destination] = outKey;
    prValuesB[destination] = value;
  }
}

void main()
{
  uint t = gl_LocalInvocationIndex;
  uint g = prLinearGroupID();
  bool live = g < prNumGroups;
  uint first = g * PR_TILE + t * 4u;

  if (t < PR_BUCKETS)
  {
    prDigitBase[t] = live ? prKeysB[prCountsOffset + t * prNumGroups + g] : 0u;
  }

  uint key[4];
  uint value[4];
  uint digit[4]; // 16: no key
  uint before[4];
  uint low = 0u;  // 4-bit counters of digits 0-7
  uint high = 0u; // 4-bit counters of digits 8-15
  for (uint j = 0u; j < 4u; ++j)
  {
    uint i = first + j;
    digit[j] = 16u;
    key[j] = 0u;
    value[j] = 0u;
    before[j] = 0u;
    if (live && i < prCount)
    {
      uint k = prReadB != 0u ? prKeysB[i] : prKeysA[i];
      key[j] = prFlipInput != 0u ? prFloatToKey(k) : k;
      value[j] = prIotaValues != 0u ? i : (prReadB != 0u ? prValuesB[i] : prValuesA[i]);
      uint d = (key[j] >> prShift) & 15u;
      digit[j] = d;
      uint nibble = 4u * (d & 7u);
      if (d < 8u)
      {
        before[j] = (low >> nibble) & 15u;
        low += 1u << nibble;
      }
      else
      {
        before[j] = (high >> nibble) & 15u;
        high += 1u << nibble;
      }
    }
  }
  // 1. counts of digit pairs (2p, 2p+1) as 16-bit halves
  for (uint p = 0u; p < 8u; ++p)
  {
    uint counters = p < 4u ? low : high;
    uint shift = 8u * (p & 3u);
    prCounts[prPad(p * PR_THREADS + t)] =
      ((counters >> shift) & 15u) | (((counters >> (shift + 4u)) & 15u) << 16u);
  }
  PR_BARRIER;

  // 2a. invocation t scans the 8 words of chunk (t & 31) of pair (t >> 5)
  {
    uint p = t >> 5u;
    uint c = t & 31u;
    uint sum = 0u;
    for (uint k = 0u; k < 8u; ++k)
    {
      uint slot = prPad(p * PR_THREADS + c * 8u + k);
      uint x = prCounts[slot];
      prCounts[slot] = sum;
      sum += x;
    }
    prChunks[p * 33u + c] = sum;
  }
  PR_BARRIER;
  // 2b. invocation p < 8 scans the 32 chunk sums of pair p
  if (t < 8u)
  {
    uint sum = 0u;
    for (uint c = 0u; c < 32u; ++c)
    {
      uint x = prChunks[t * 33u + c];
      prChunks[t * 33u + c] = sum;
      sum += x;
    }
    prChunks[t * 33u + 32u] = sum;
  }
  PR_BARRIER;

  uint rank[4];
  for (uint j = 0u; j < 4u; ++j)
  {
    rank[j] = 0u;
    if (digit[j] < 16u)
    {
      uint p = digit[j] >> 1u;
      uint word = prCounts[prPad(p * PR_THREADS + t)] + prChunks[p * 33u + (t >> 3u)];
      rank[j] = ((word >> (16u * (digit[j] & 1u))) & 0xFFFFu) + before[j];
    }
  }

#if PR_LOCAL_REORDER
  // tile start of every digit; the keys in tile order in shared memory
  if (t < PR_BUCKETS)
  {
    uint start = 0u;
    for (uint d = 0u; d < t; ++d)
    {
      start += (prChunks[(d >> 1u) * 33u + 32u] >> (16u * (d & 1u))) & 0xFFFFu;
    }
    prTileStart[t] = start;
  }
  PR_BARRIER;
  for (uint j = 0u; j < 4u; ++j)
  {
    if (digit[j] < 16u)
    {
      uint slot = prTileStart[digit[j]] + rank[j];
      prTileKeys[slot] = key[j];
      prTileValues[slot] = value[j];
    }
  }
  PR_BARRIER;
  uint tileCount = live ? min(PR_TILE, prCount - g * PR_TILE) : 0u;
  for (uint j = 0u; j < 4u; ++j)
  {
    uint slot = j * PR_THREADS + t;
    if (slot < tileCount)
    {
      uint k = prTileKeys[slot];
      uint d = (k >> prShift) & 15u;
      prStore(prDigitBase[d] + slot - prTileStart[d], k, prTileValues[slot]);
    }
  }
#else
  for (uint j = 0u; j < 4u; ++j)
  {
    if (digit[j] < 16u)
    {
      prStore(prDigitBase[digit[j]] + rank[j], key[j], value[j]);
    }
  }
#endif
}
