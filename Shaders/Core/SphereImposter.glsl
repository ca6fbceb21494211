//=========================================================================
// SphereImposter.glsl -- geometry-stage set-up of one camera-facing triangle per
// sphere or ellipsoid (corner 0..2; ellipsoids: prEllipsoidBillboard at the end).
// One triangle, not a quad: half the vertices and half the triangle set-ups per
// sphere, for 30% more (cheaply discarded) fragments; with millions of few-pixel
// spheres the per-triangle cost dominates.
//
// Perspective: the triangle is the equilateral triangle circumscribing the
// sphere's silhouette circle (where the tangent cone from the eye touches the
// sphere), in that circle's plane at distance r^2/d in front of the centre; the
// circle's radius is r*sqrt(1-(r/d)^2). The projected triangle therefore covers
// the projected sphere exactly, also far off-axis, where a billboard through
// the centre clips the silhouette. Parallel: circumscribing a circle of radius
// r through the centre. Eye inside the sphere or within 0.2 radii of its
// surface: a triangle covering the whole viewport, its points on the near plane
// (grazing views of so near a sphere are also more precise from there).
// The clip-space z is set to 0: coverage does not depend on it and the
// fragment stage writes the real depth, so the near plane never cuts it.
//
// Outputs: clip position, the triangle point relative to the sphere centre in
// view coordinates (interpolated perspective-correctly, it is a point of the
// fragment's ray relative to the centre -- see RaySphere.glsl) and the same
// point relative to the eye (its direction is the fragment's ray direction).
//=========================================================================
bool prSphereIsDrawable(vec3 centerVC, float radiusVC)
{
  return radiusVC > 0.0 && !isinf(radiusVC) && !any(isnan(centerVC)) && !any(isinf(centerVC));
}

// corners of the equilateral triangle circumscribing the unit circle
const vec2 prTriangleCorners[3] = vec2[3](vec2(0.0, 2.0), vec2(-1.7320508, -1.0), vec2(1.7320508, -1.0));
// corners of a triangle covering the viewport [-1,1]^2
const vec2 prViewportCorners[3] = vec2[3](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));

// An orthonormal pair u, v perpendicular to the unit vector dir.
void prBasisAround(vec3 dir, out vec3 u, out vec3 v)
{
  vec3 helper = abs(dir.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  u = normalize(cross(dir, helper));
  v = cross(u, dir);
}

// Perspective: the corner c (of prTriangleCorners) of the triangle circumscribing the silhouette
// circle of a sphere of radius r whose centre is at `center` (distance dist > r) from the eye,
// relative to the centre.
vec3 prSilhouetteTriangleOffset(vec3 center, float dist, float r, vec2 c)
{
  vec3 dir = center / dist;
  vec3 u;
  vec3 v;
  prBasisAround(dir, u, v);
  float rr = r / dist;
  float silhouetteRadius = r * sqrt(max(0.0, 1.0 - rr * rr));
  return -dir * (r * rr) + silhouetteRadius * (c.x * u + c.y * v);
}

// Eye inside or at the surface of a particle: the corner of a triangle covering the viewport,
// its point on the near plane (see prSphereBillboard).
void prViewportBillboard(vec3 centerVC, int corner, mat4 dcvc, out vec4 positionDC,
  out vec3 offsetVC, out vec3 rayVC)
{
  vec2 v = prViewportCorners[corner];
  vec4 nearVC = dcvc * vec4(v, -1.0, 1.0);
  // the ray direction from the near-plane point itself: centerVC + offsetVC would cancel
  // (the eye is within a radius of the centre, the near plane much closer to the eye)
  rayVC = nearVC.xyz / nearVC.w;
  offsetVC = rayVC - centerVC;
  positionDC = vec4(v, 0.0, 1.0);
}

void prSphereBillboard(vec3 centerVC, float radiusVC, int corner, bool parallel, mat4 vcdc,
  mat4 dcvc, out vec4 positionDC, out vec3 offsetVC, out vec3 rayVC)
{
  // 1.0001: a margin of 1e-4 radii against rounding at the silhouette
  vec2 c = 1.0001 * prTriangleCorners[corner];
  if (parallel)
  {
    offsetVC = vec3(radiusVC * c, 0.0);
    positionDC = vcdc * vec4(centerVC + offsetVC, 1.0);
  }
  else
  {
    float dist = length(centerVC);
    if (dist <= 1.2 * radiusVC)
    {
      // eye inside or at the surface: cover the viewport, rays start at the near plane
      prViewportBillboard(centerVC, corner, dcvc, positionDC, offsetVC, rayVC);
      return;
    }
    offsetVC = prSilhouetteTriangleOffset(centerVC, dist, radiusVC, c);
    positionDC = vcdc * vec4(centerVC + offsetVC, 1.0);
  }
  // a point of the ray seen from the eye (the direction is all that is used)
  rayVC = centerVC + offsetVC;
  positionDC.z = 0.0;
}

// The ellipsoid x = centre + A u (|u| <= 1; toVC = A, toUnit = A^-1, view coordinates): the
// sphere's triangle set up for the unit sphere in the ellipsoid's own frame, its corners mapped
// back by A. An affine map takes the rays from the eye (or the parallel rays) to rays, the
// unit sphere's silhouette circle to the ellipsoid's silhouette ellipse and the circumscribing
// triangle to a triangle circumscribing that ellipse, so the projected triangle covers the
// projected ellipsoid exactly with the sphere's fragment overhead, whatever the axis ratio.
// Parallel: the unit frame's rays run along toUnit * (0, 0, -1); the triangle lies in the plane
// through the centre perpendicular to them. Eye within 1.2 (in the unit frame) of the centre:
// the viewport triangle, as for spheres.
void prEllipsoidBillboard(vec3 centerVC, mat3 toVC, mat3 toUnit, int corner, bool parallel,
  mat4 vcdc, mat4 dcvc, out vec4 positionDC, out vec3 offsetVC, out vec3 rayVC)
{
  vec2 c = 1.0001 * prTriangleCorners[corner];
  vec3 offsetU;
  if (parallel)
  {
    vec3 u;
    vec3 v;
    prBasisAround(normalize(toUnit * vec3(0.0, 0.0, -1.0)), u, v);
    offsetU = c.x * u + c.y * v;
  }
  else
  {
    vec3 centerU = toUnit * centerVC; // the centre relative to the eye, in the unit frame
    float dist = length(centerU);
    if (dist <= 1.2)
    {
      prViewportBillboard(centerVC, corner, dcvc, positionDC, offsetVC, rayVC);
      return;
    }
    offsetU = prSilhouetteTriangleOffset(centerU, dist, 1.0, c);
  }
  offsetVC = toVC * offsetU;
  positionDC = vcdc * vec4(centerVC + offsetVC, 1.0);
  rayVC = centerVC + offsetVC;
  positionDC.z = 0.0;
}
