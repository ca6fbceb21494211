//=========================================================================
// RaySphere.glsl -- ray/sphere and ray/ellipsoid intersection shared by every particle mapper.
//
// The ray is described relative to the sphere centre: s is a point of the ray
// relative to the centre (|s| is of the order of the radius, never of the eye
// distance) and d is the unit ray direction. Working relative to the centre is
// what keeps a camera 1e7 radii away exact in single precision: the classic
// form |o - c|^2 - r^2 cancels catastrophically there.
//
// On a hit, t0 <= t1 are the entry and exit parameters along d measured from s,
// so the hit points relative to the centre are s + t0*d and s + t1*d.
//=========================================================================
bool prIntersectSphere(vec3 s, vec3 d, float r, out float t0, out float t1)
{
  float b = dot(s, d);
  // closest approach of the ray to the centre; |q| <= |s| so no cancellation
  vec3 q = s - b * d;
  float h2 = r * r - dot(q, q);
  t0 = 0.0;
  t1 = 0.0;
  if (!(h2 >= 0.0)) // also rejects NaN
  {
    return false;
  }
  float h = sqrt(h2);
  t0 = -b - h;
  t1 = -b + h;
  return true;
}

// Ray/ellipsoid intersection: the ellipsoid is the unit sphere under the affine map
// x = centre + A u; toUnit = A^-1 takes view-coordinate offsets from the centre to the unit
// sphere's frame. The map keeps the ray parameter, so the unit-frame ray (toUnit s, toUnit d) is
// intersected with the unit sphere in the centre-relative form above (its direction normalised,
// of length |toUnit d|) and the parameters are scaled back: t0 <= t1 are measured along d from
// s exactly as for a sphere. Equal axes r give toUnit = R^T / r and the sphere's hits.
bool prIntersectEllipsoid(vec3 s, vec3 d, mat3 toUnit, out float t0, out float t1)
{
  vec3 du = toUnit * d;
  float len = length(du);
  bool hit = prIntersectSphere(toUnit * s, du / len, 1.0, t0, t1);
  t0 /= len;
  t1 /= len;
  return hit && len > 0.0;
}

// Unit outward normal of the ellipsoid at the view-coordinate offset rel from its centre: the
// gradient of |toUnit x|^2, toUnit^T toUnit rel.
vec3 prEllipsoidNormal(vec3 rel, mat3 toUnit)
{
  return normalize(transpose(toUnit) * (toUnit * rel));
}

// Depth-buffer value and visibility of the view-coordinate point T + offsetVC. A point is
// visible when it lies in front of the eye and between the near and far planes. The sum is never
// formed in single precision.
// T is the translation of the MC->VC matrix (the same for every sphere) and offsetVC the rest of
// the point (MC->VC rotation of the centre plus the hit point relative to it); clipZW0 holds the
// clip-space z and w of T, computed once per frame on the CPU in double. With the camera 1e7
// radii away |T.z| ~ 1e7, where a float resolves whole radii: the summed point, and so the depth,
// would be rounded by up to half a radius, differently for every sphere, and the depth test would
// pick the wrong one of two overlapping spheres. Split, the large terms are one common constant
// (their rounding is a common offset of all spheres) and only the small offset varies, so depths
// stay ordered to about 1e-7 of the sphere distances.
// Clip-space z and w of the view-coordinate point T + offsetVC (see prDepthOfSplitPointVC).
vec2 prClipZWOfSplitPointVC(vec2 clipZW0, vec3 offsetVC, mat4 vcdc)
{
  return vec2(clipZW0.x + (vcdc[0][2] * offsetVC.x + vcdc[1][2] * offsetVC.y + vcdc[2][2] * offsetVC.z),
    clipZW0.y + (vcdc[0][3] * offsetVC.x + vcdc[1][3] * offsetVC.y + vcdc[2][3] * offsetVC.z));
}

bool prDepthOfSplitPointVC(vec2 clipZW0, vec3 offsetVC, mat4 vcdc, out float depth)
{
  vec2 zw = prClipZWOfSplitPointVC(clipZW0, offsetVC, vcdc);
  depth = 0.0;
  if (!(zw.y > 0.0))
  {
    return false;
  }
  float ndcZ = zw.x / zw.y;
  if (!(ndcZ >= -1.0 && ndcZ <= 1.0))
  {
    return false;
  }
  depth = (gl_DepthRange.diff * ndcZ + gl_DepthRange.near + gl_DepthRange.far) * 0.5;
  return true;
}
