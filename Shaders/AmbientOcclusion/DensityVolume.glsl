#version 430
//=========================================================================
// DensityVolume.glsl -- compute stages of vtkParticleDensityVolume (Grottel et
// al. 2012, Eq. 5). PR_DENSITY_SPLAT: one invocation per particle adds the
// sphere's volume, in fixed point (2^-20 voxel volumes), to the voxel of its
// centre (nearest voxel, the paper's rule) or, with trilinear, to the 8 voxels
// whose centres surround it with tent weights (cloud in cell; corners beyond the
// grid fold onto its boundary voxels), with integer atomicAdds (float atomics
// are not core OpenGL).
// Otherwise: one invocation per voxel converts to the density, scaled by g and
// clamped to [0, 1].
//=========================================================================
layout(local_size_x = 256) in;

//PR::Include ComputeCommon

layout(std430, binding = 2) buffer prCounts { uint counts[]; };

#ifdef PR_DENSITY_SPLAT
layout(std430, binding = 0) readonly buffer prPositions { float positions[]; };
layout(std430, binding = 1) readonly buffer prRadii { float radii[]; };

// this dispatch splats particles first ... count - 1 (blocks, for progress)
uniform uint first;
uniform uint count;
uniform uint positionStride;
// voxel coordinate of a buffer position p (affine, composed in double on the CPU)
uniform mat4 toVoxel;
uniform float radiusScale;
uniform int trilinear;
uniform ivec3 dimensions;
// fixed-point volume of a sphere of radius 1, relative to a voxel: 4/3 pi / edge^3 * 2^20
uniform float unitContribution;
// no voxel needs more than this (the density is clamped at 1 anyway): no overflow
const uint prCountCap = 1u << 26;

void prAddDensity(ivec3 voxel, float amount)
{
  uint index = uint(voxel.x + dimensions.x * (voxel.y + dimensions.y * voxel.z));
  if (counts[index] < prCountCap)
  {
    atomicAdd(counts[index], uint(min(amount, float(prCountCap)) + 0.5));
  }
}

void main()
{
  uint i = first + PR_INVOCATION_INDEX;
  if (i >= count)
  {
    return;
  }
  float r = radii[i] * radiusScale;
  if (!(r > 0.0))
  {
    return;
  }
  uint j = i * positionStride;
  vec3 v = (toVoxel * vec4(positions[j], positions[j + 1u], positions[j + 2u], 1.0)).xyz;
  if (any(isnan(v)) || any(isinf(v)))
  {
    return;
  }
  float contribution = r * r * r * unitContribution;
  if (trilinear == 0)
  {
    ivec3 voxel = clamp(ivec3(floor(v)), ivec3(0), dimensions - ivec3(1));
    prAddDensity(voxel, contribution);
    return;
  }
  vec3 corner = floor(v - 0.5);
  vec3 weight = clamp(v - 0.5 - corner, 0.0, 1.0);
  ivec3 lower = ivec3(clamp(corner, vec3(-1.0), vec3(dimensions)));
  for (int c = 0; c < 8; ++c)
  {
    ivec3 high = ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    vec3 w = mix(1.0 - weight, weight, vec3(high));
    prAddDensity(clamp(lower + high, ivec3(0), dimensions - ivec3(1)),
      contribution * w.x * w.y * w.z);
  }
}
#else
layout(std430, binding = 3) writeonly buffer prVolume { float volume[]; };

uniform uint voxelCount;
// g / 2^20
uniform float toDensity;

void main()
{
  uint i = PR_INVOCATION_INDEX;
  if (i >= voxelCount)
  {
    return;
  }
  volume[i] = min(1.0, float(counts[i]) * toDensity);
}
#endif
