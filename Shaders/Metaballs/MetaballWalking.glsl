//=========================================================================
// MetaballWalking.glsl -- fragment stage of vtkMetaballMapper's "walking depth
// plane" method (Mueller, Grottel, Ertl 2007, Sec. 3.2): what one particle's
// influence sphere contributes to each pass of vtkMetaballWalkingPlane, and the
// final draw that shades the surface the walk found.
//
// lambda is the view depth of a point measured from the depth of an anchor
// near the data (the centre of the particles' bounds): for a point rel relative
// to the drawn centre, whose view depth from the anchor is centerZ (formed in
// the vertex stage from the small difference of the centre and the anchor),
//   lambda = -(centerZ + rel.z).
// Every quantity in it is of the size of the data, not of the camera distance
// or of the coordinates: float precision holds with the camera far away or the
// data far from the origin. Field (Eq. 2 with influence factor k): D_j = c (1 - r^2/K_j^2)^2.
//=========================================================================
uniform int prWalkingPass;            // 0 final draw, 1 plane, 2 density, 3 gradient, 4 colour
uniform sampler2D prWalkingPlaneTexture;     // (lambda, -lambda_max, finished, 0)
uniform sampler2D prWalkingGradientTexture;  // (grad D, D) at lambda
uniform sampler2D prWalkingColorTexture;     // (sum D_j rgb_j, sum D_j) at lambda
uniform ivec2 prWalkingOrigin;        // viewport origin in the drawing framebuffer
uniform float prWalkingNear;          // lambda of the near plane
uniform float prWalkingStepMax;       // the largest step (the third density sample's offset)
uniform float prWalkingTolerance;     // on D / t
uniform float prKernelScale;          // c
uniform float prIsoValue;             // t

float prWalkingLambda(float centerOffsetZ, vec3 rel)
{
  return -(centerOffsetZ + rel.z);
}

// the ray parameter (ray s + p d relative to the centre) of the point at depth lambda
float prWalkingParameter(float lambda, float centerOffsetZ, vec3 s, vec3 d)
{
  return (-lambda - centerOffsetZ - s.z) / d.z;
}

float prWalkingKernel(vec3 rel, float influence2)
{
  float a = 1.0 - dot(rel, rel) / influence2;
  return a > 0.0 ? prKernelScale * a * a : 0.0;
}

vec3 prWalkingKernelGradient(vec3 rel, float influence2)
{
  float a = 1.0 - dot(rel, rel) / influence2;
  return a > 0.0 ? (-4.0 * prKernelScale * a / influence2) * rel : vec3(0.0);
}

// the pixel of the walk's buffers under this fragment
ivec2 prWalkingPixel()
{
  return ivec2(gl_FragCoord.xy) - prWalkingOrigin;
}

// a splat pass (prWalkingPass 1-4): this particle's contribution to the pixel; false: none
bool prWalkingSplat(vec3 s, vec3 d, float t0, float t1, float centerOffsetZ, float influence,
  vec4 ownColor, out vec4 result)
{
  result = vec4(0.0);
  if (prWalkingPass == 1)
  {
    // the front (not before the near plane) and the back of the influence sphere, MIN-blended
    result = vec4(max(prWalkingLambda(centerOffsetZ, s + t0 * d), prWalkingNear),
      -prWalkingLambda(centerOffsetZ, s + t1 * d), 0.0, 0.0);
    return true;
  }
  vec4 plane = texelFetch(prWalkingPlaneTexture, prWalkingPixel(), 0);
  bool covered = plane.x <= -plane.y;
  if (!covered || (prWalkingPass == 2 && plane.z > 0.5))
  {
    return false;
  }
  float influence2 = influence * influence;
  vec3 rel = s + prWalkingParameter(plane.x, centerOffsetZ, s, d) * d;
  if (prWalkingPass == 2)
  {
    // D, its derivative along lambda (ds/dlambda = -1/d.z) and D one largest step deeper
    vec3 rel2 = s + prWalkingParameter(plane.x + prWalkingStepMax, centerOffsetZ, s, d) * d;
    float slope = -dot(prWalkingKernelGradient(rel, influence2), d) / d.z;
    result = vec4(prWalkingKernel(rel, influence2), slope, prWalkingKernel(rel2, influence2), 1.0);
  }
  else if (prWalkingPass == 3)
  {
    result = vec4(prWalkingKernelGradient(rel, influence2), prWalkingKernel(rel, influence2));
  }
  else
  {
    float w = prWalkingKernel(rel, influence2);
    result = vec4(w * ownColor.rgb, w);
  }
  return true;
}

// the final draw: the surface point on this fragment's ray when this particle's influence
// sphere holds it (the walk finished there, or stopped just behind the surface)
bool prWalkingSurface(vec3 s, vec3 d, float t0, float t1, float centerOffsetZ, out float t)
{
  ivec2 pixel = prWalkingPixel();
  vec4 plane = texelFetch(prWalkingPlaneTexture, pixel, 0);
  float value = texelFetch(prWalkingGradientTexture, pixel, 0).w;
  t = prWalkingParameter(plane.x, centerOffsetZ, s, d);
  bool found = plane.x <= -plane.y &&
    (plane.z > 0.5 || value >= prIsoValue * (1.0 - prWalkingTolerance));
  return found && t >= t0 && t <= t1;
}

// the surface normal (view coordinates, facing the ray's origin) from the field's gradient
vec3 prWalkingNormal(vec3 d, vec3 fallback)
{
  vec3 g = texelFetch(prWalkingGradientTexture, prWalkingPixel(), 0).xyz;
  if (!(dot(g, g) > 0.0))
  {
    return fallback;
  }
  vec3 n = normalize(-g);
  return dot(n, d) > 0.0 ? -n : n;
}

// the colour blended by the particles' field contributions
vec4 prWalkingColor(vec4 ownColor)
{
  vec4 sum = texelFetch(prWalkingColorTexture, prWalkingPixel(), 0);
  return sum.w > 0.0 ? vec4(sum.rgb / sum.w, ownColor.a) : ownColor;
}
