//=========================================================================
// VoxelConeTrace.glsl -- ambient occlusion A_O (Eq. 5) and ambient
// illumination L_A (Eq. 6) of Staib, Grottel, Gumhold 2015 by voxel cone
// tracing (Sec. 5.2) through vtkParticleAmbientVolume's mip pyramid.
//
// Coordinates are voxel units of level 0 (cubic voxels, so directions stay
// unit length). A voxel's alpha is its extinction per voxel edge, its RGB the
// emission times that extinction (see vtkParticleAmbientVolume). A cone of
// half-angle tan prConeTanHalf starts prConeStart voxels from the surface
// point; each step samples the middle of the step at the level one finer than
// the cone diameter d (a level's trilinear filter reaches 1.5 of its voxels from
// the sample: at the diameter's own level it reaches back below the surface the
// cone leaves, and flat dense surfaces darken themselves), composites front to
// back with the step's opacity 1 - exp(-sigma d) and advances one diameter, until prConeLength voxels or a
// transmittance below 1/256. Cones: prCones[k].xyz in the frame (u, v, n) of
// the normal, .w the cone's weight (cosine-weighted, summing to 1).
//
// Result: rgb = L_A (emitted radiance that reaches the point, weighted over the
// cones), a = A_O (the weighted transmittance along the cones).
//=========================================================================
uniform sampler3D prAmbientVolume;
uniform vec3 prAmbientDimensions;
uniform mat4 prViewToVoxel;
uniform float prConeTanHalf;
uniform float prConeStart;
uniform float prConeLength;
uniform int prConeCount;
uniform vec4 prCones[16];
uniform float prAmbientScale;

vec4 prTraceCone(vec3 p, vec3 dir)
{
  float t = prConeStart;
  float transmittance = 1.0;
  vec3 radiance = vec3(0.0);
  // at most 32 steps: the diameter grows geometrically with the distance
  for (int i = 0; i < 32; ++i)
  {
    if (t >= prConeLength || transmittance < 0.00390625)
    {
      break;
    }
    float d = max(1.0, 2.0 * (t + 0.5) * prConeTanHalf);
    vec4 s = textureLod(prAmbientVolume, (p + (t + 0.5 * d) * dir) / prAmbientDimensions,
      max(0.0, log2(d) - 1.0));
    float sigma = max(s.a, 0.0);
    float alpha = 1.0 - exp(-sigma * d);
    vec3 color = sigma > 0.0 ? max(s.rgb, vec3(0.0)) / sigma : vec3(0.0);
    radiance += transmittance * alpha * color;
    transmittance *= 1.0 - alpha;
    t += d;
  }
  return vec4(radiance, transmittance);
}

// p, n: a surface point and its unit normal in voxel units
vec4 prTraceConesVoxel(vec3 p, vec3 n)
{
  vec3 helper = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 u = normalize(cross(n, helper));
  vec3 v = cross(n, u);
  vec4 sum = vec4(0.0);
  for (int k = 0; k < 16; ++k)
  {
    if (k >= prConeCount)
    {
      break;
    }
    vec4 cone = prCones[k];
    sum += cone.w * prTraceCone(p, normalize(cone.x * u + cone.y * v + cone.z * n));
  }
  return sum;
}

// pointVC, normalVC: the visible point and its unit normal in view coordinates
vec4 prTraceCones(vec3 pointVC, vec3 normalVC)
{
  return prTraceConesVoxel((prViewToVoxel * vec4(pointVC, 1.0)).xyz,
    normalize(mat3(prViewToVoxel) * normalVC));
}

// Per sphere (vertex stage): the cones of the sphere's six extreme points along the world axes,
// +x, -x, +y, -y, +z, -z, each around its axis (the grid is aligned with the world axes).
void prTraceSphereCones(vec3 centerVC, float radiusVC, out vec4 cones[6])
{
  vec3 c = (prViewToVoxel * vec4(centerVC, 1.0)).xyz;
  float r = radiusVC * length(prViewToVoxel[0].xyz);
  for (int k = 0; k < 6; ++k)
  {
    vec3 axis = vec3(0.0);
    axis[k / 2] = (k % 2 == 0) ? 1.0 : -1.0;
    cones[k] = prTraceConesVoxel(c + r * axis, axis);
  }
}

#ifdef PR_ELLIPSOID
// Per ellipsoid (x = c + A u, toVC = A in view coordinates): the same six cones from the
// ellipsoid's extreme points along the world axes, c + A A^T e / |A^T e| (voxel coordinates).
void prTraceEllipsoidCones(vec3 centerVC, mat3 toVC, out vec4 cones[6])
{
  vec3 c = (prViewToVoxel * vec4(centerVC, 1.0)).xyz;
  mat3 a = mat3(prViewToVoxel) * toVC;
  for (int k = 0; k < 6; ++k)
  {
    vec3 axis = vec3(0.0);
    axis[k / 2] = (k % 2 == 0) ? 1.0 : -1.0;
    vec3 support = transpose(a) * axis;
    cones[k] = prTraceConesVoxel(c + a * (support / length(support)), axis);
  }
}
#endif

// Per fragment: the six axis results blended by the squared components of the world normal
// (they sum to 1), the side chosen by each component's sign.
vec4 prBlendSphereCones(vec3 normalWC, vec4 plusX, vec4 minusX, vec4 plusY, vec4 minusY,
  vec4 plusZ, vec4 minusZ)
{
  vec3 w = normalWC * normalWC;
  return w.x * (normalWC.x >= 0.0 ? plusX : minusX) + w.y * (normalWC.y >= 0.0 ? plusY : minusY) +
    w.z * (normalWC.z >= 0.0 ? plusZ : minusZ);
}
