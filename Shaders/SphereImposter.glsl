//=========================================================================
// SphereImposter.glsl -- vertex-stage set-up of one camera-facing quad per
// sphere; corner 0..3 is (-1,-1), (1,-1), (-1,1), (1,1) in the quad's frame.
//
// Perspective: the quad lies in the plane of the sphere's silhouette circle
// (the circle where the tangent cone from the eye touches the sphere), at
// distance r^2/d in front of the centre, with half-size r*sqrt(1-(r/d)^2): the
// circle is inscribed in the quad, so the projected quad covers the projected
// sphere exactly (no clipped silhouettes off-axis, unlike a quad through the
// centre). Parallel: a quad of half-size r through the centre.
// Eye inside (or within 1% of) the sphere: a full-viewport quad whose corners
// are the near-plane corners.
// The quad's clip-space z is set to 0: coverage does not depend on it and the
// fragment stage writes the real depth, so the near plane never cuts a quad.
//
// Outputs: clip position, and the quad point relative to the sphere centre in
// view coordinates (interpolated perspective-correctly, it is a point of the
// fragment's ray relative to the centre -- see RaySphere.glsl).
//=========================================================================
bool prSphereIsDrawable(vec3 centerVC, float radiusVC)
{
  return radiusVC > 0.0 && !isinf(radiusVC) && !any(isnan(centerVC)) && !any(isinf(centerVC));
}

void prSphereQuad(vec3 centerVC, float radiusVC, int corner, bool parallel, mat4 vcdc,
  mat4 dcvc, out vec4 positionDC, out vec3 offsetVC)
{
  vec2 c = vec2((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0);
  if (parallel)
  {
    offsetVC = vec3(radiusVC * c, 0.0);
    positionDC = vcdc * vec4(centerVC + offsetVC, 1.0);
  }
  else
  {
    float dist = length(centerVC);
    if (dist <= 1.01 * radiusVC)
    {
      // eye inside or at the surface: cover the viewport, rays start at the near plane
      vec4 nearVC = dcvc * vec4(c, -1.0, 1.0);
      offsetVC = nearVC.xyz / nearVC.w - centerVC;
      positionDC = vec4(c, 0.0, 1.0);
      return;
    }
    vec3 dir = centerVC / dist;
    vec3 helper = abs(dir.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    vec3 u = normalize(cross(dir, helper));
    vec3 v = cross(u, dir);
    float rr = radiusVC / dist;
    float halfSize = radiusVC * sqrt(max(0.0, 1.0 - rr * rr));
    offsetVC = -dir * (radiusVC * rr) + halfSize * (c.x * u + c.y * v);
    positionDC = vcdc * vec4(centerVC + offsetVC, 1.0);
  }
  positionDC.z = 0.0;
}
