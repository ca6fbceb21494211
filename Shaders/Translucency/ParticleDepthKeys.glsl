#version 430
//=========================================================================
// ParticleDepthKeys.glsl -- compute stage of vtkTransparentSphereMapper: the
// front-to-back sort key of every particle, read straight from the mapper's
// vertex buffers (positions after VTK's shift/scale, radii).
//
// Perspective: the power of the eye with respect to the sphere, |c - e|^2 - r^2,
// an exact visibility order for spheres that do not intersect. In view
// coordinates c = o + T with o = M3 p (p the VBO position, M3 the linear part of
// the MC->VC matrix) and T its translation (large when the camera is far away);
// the constant |T|^2 is dropped, so the key o.o + 2 T.o - r^2 keeps the small
// differences between particles. Parallel projection: the centre depth -o.z.
//=========================================================================
layout(local_size_x = 256) in;

//PR::Include ComputeCommon

layout(std430, binding = 0) readonly buffer prPositions { float positions[]; };
layout(std430, binding = 1) readonly buffer prRadii { float radii[]; };
layout(std430, binding = 2) writeonly buffer prKeys { float keys[]; };

uniform uint count;
uniform uint positionStride; // floats per position tuple in the VBO
uniform mat4 matrixMCVC; // only its linear part is used
uniform vec3 translationVC;
uniform float radiusScale;
uniform int parallelProjection;

void main()
{
  uint i = PR_INVOCATION_INDEX;
  if (i >= count)
  {
    return;
  }
  uint j = i * positionStride;
  vec3 o = mat3(matrixMCVC) * vec3(positions[j], positions[j + 1u], positions[j + 2u]);
  if (parallelProjection != 0)
  {
    keys[i] = -o.z;
    return;
  }
  float r = radii[i] * radiusScale;
  keys[i] = dot(o, o) + 2.0 * dot(translationVC, o) - r * r;
}
