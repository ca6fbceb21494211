//=========================================================================
// EllipsoidFrame.glsl -- the affine frame of an oriented ellipsoid particle, set up once per
// particle in the vertex stage of vtkParticleSphereMapper's ellipsoid variant (PR_ELLIPSOID).
//
// The ellipsoid is the unit sphere under x = centre + A u, |u| <= 1, with
//   A = axesToVC * R(q) * diag(a),
// a the semi-axes and q the unit quaternion (w, x, y, z) of the particle's body frame (LAMMPS's
// convention: a body-frame vector b is R(q) b in the model frame), axesToVC the linear part of
// the model -> view map times the radius scale factor. A^-1 = diag(1/a) R(q)^T vcToAxes, with
// vcToAxes = axesToVC^-1 computed on the CPU in double. The mapper checks the axes (finite,
// positive) and normalises the quaternions before they are uploaded.
//=========================================================================

// Rotation matrix of the unit quaternion q = (w, x, y, z), GLSL's column-major order.
mat3 prRotationOfQuaternion(vec4 q)
{
  float w = q.x;
  float x = q.y;
  float y = q.z;
  float z = q.w;
  return mat3(
    vec3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z), 2.0 * (x * z - w * y)),
    vec3(2.0 * (x * y - w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + w * x)),
    vec3(2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y)));
}

// A (toVC) and A^-1 (toUnit) of the ellipsoid, and the radius of a sphere about its centre that
// contains it: the square root of a Gershgorin bound of the largest eigenvalue of A^T A, which is
// the largest semi-axis (times the view scale) when A's columns are orthogonal (any rotation
// with a uniform actor scale) and an upper bound when an actor's non-uniform scale shears them.
void prEllipsoidFrame(vec3 axes, vec4 q, mat3 axesToVC, mat3 vcToAxes, out mat3 toVC,
  out mat3 toUnit, out float boundingRadius)
{
  mat3 r = prRotationOfQuaternion(q);
  toVC = axesToVC * mat3(r[0] * axes.x, r[1] * axes.y, r[2] * axes.z);
  mat3 rt = transpose(r);
  // diag(1/a) R^T: every column of R^T divided by a componentwise
  mat3 inverseBody = mat3(rt[0] / axes, rt[1] / axes, rt[2] / axes);
  toUnit = inverseBody * vcToAxes;
  mat3 g = transpose(toVC) * toVC;
  float bound = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    bound = max(bound, abs(g[i][0]) + abs(g[i][1]) + abs(g[i][2]));
  }
  boundingRadius = sqrt(bound);
}
