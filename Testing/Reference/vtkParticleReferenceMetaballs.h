/**
 * @class   vtkParticleReferenceMetaballs
 * @brief   the exact metaball surface of a set of particles, in double precision (the ground
 *          truth for vtkMetaballMapper; Mueller, Grottel, Ertl 2007)
 *
 * The field is the sum over the particles of the kernel of the paper's Eq. 2, generalised to an
 * influence radius of InfluenceFactor times the particle radius R (the paper: 2):
 *
 *   D_i(r) = c (1 - (r / (k R_i))^2)^2  for r <= k R_i, 0 beyond,  c = 1 / (1 - 1/k^2)^2,
 *
 * so that D_i(R_i) = 1 (k = 2: c = 16/9, Eq. 2), and the surface is the iso-surface
 * sum_i D_i = IsoValue (default 1): an isolated particle is exactly its sphere.
 *
 * Ray intersection (IntersectRay): along a ray each kernel is a polynomial of degree 4 in the ray
 * parameter inside its influence interval [a_i, b_i] (|x - c_i|^2 = (t - t_i)^2 + h_i^2, with the
 * closest approach t_i and impact parameter h_i formed relative to the centre, as
 * Shaders/Core/RaySphere.glsl does, so that a camera far away loses nothing). Between consecutive
 * interval ends the set of contributing particles is fixed and the field minus the iso-value is
 * one quartic P; its first root is isolated exactly: the roots of P' (a cubic, whose own
 * critical points come from a quadratic, solved the same way) split the interval into monotone
 * pieces, and the first piece whose end is not below zero holds the crossing, found by
 * bisection to the last bit of the double and no further (no root is missed: there are no
 * sampling steps). The polynomial is expanded about the interval's start, so its coefficients
 * hold only that interval's geometry. A ray that starts inside the surface (field >= iso at
 * tMin) returns tMin and reports it (inside).
 *
 * Normal: the unit vector against the analytic field gradient,
 *   grad D_i = -4 c (1 - r^2 / (k R_i)^2) (x - c_i) / (k R_i)^2,
 * evaluated with x - c_i formed from the hit's offset to that particle in double.
 *
 * Candidates along a ray come from a uniform grid of the influence spheres (the reference
 * renderer's), so a scene of 1e5 particles costs about as much per ray as its neighbourhood.
 * Particles with a radius <= 0 or a non-finite position or radius are skipped.
 *
 * @sa vtkParticleReferenceRenderer
 */
#ifndef vtkParticleReferenceMetaballs_h
#define vtkParticleReferenceMetaballs_h

#include "vtkObject.h"
#include "vtkParticleRenderingReferenceModule.h" // for export macro

#include <vector> // for std::vector

class vtkDataArray;
class vtkPoints;

class VTKPARTICLERENDERINGREFERENCE_EXPORT vtkParticleReferenceMetaballs : public vtkObject
{
public:
  static vtkParticleReferenceMetaballs* New();
  vtkTypeMacro(vtkParticleReferenceMetaballs, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The particles: centres and radii (one radius per point; nullptr: all of radius
   * DefaultRadius). Copied in double; changing them later needs another call.
   */
  void SetParticles(vtkPoints* centers, vtkDataArray* radii);

  ///@{
  /**
   * The radius of every particle when SetParticles() got no radii. Default 1.
   */
  vtkSetMacro(DefaultRadius, double);
  vtkGetMacro(DefaultRadius, double);
  ///@}

  ///@{
  /**
   * Influence radius over particle radius, k > 1 (the paper: 2). Default 2.
   */
  vtkSetClampMacro(InfluenceFactor, double, 1.000001, 1e3);
  vtkGetMacro(InfluenceFactor, double);
  ///@}

  ///@{
  /**
   * The iso-value of the surface (the paper's threshold t). Default 1.
   */
  vtkSetClampMacro(IsoValue, double, 1e-9, 1e9);
  vtkGetMacro(IsoValue, double);
  ///@}

  /**
   * The field sum_i D_i at a point, and its gradient.
   */
  double EvaluateField(const double point[3]);
  void EvaluateGradient(const double point[3], double gradient[3]);

  /**
   * The first point of the surface on the ray origin + t direction (direction need not be unit
   * length; t in its units) with tMin <= t <= tMax: true and t, the unit outward normal (against
   * the gradient) and whether the ray started inside the surface (then t = tMin and the normal
   * faces the ray's origin: -direction). False when the ray stays outside.
   */
  bool IntersectRay(const double origin[3], const double direction[3], double tMin, double tMax,
    double& t, double normal[3], bool& inside);

  /**
   * Build the search grid for the current particles and InfluenceFactor (IntersectRay() does
   * it when needed; call it before using the thread-safe form below from several threads).
   */
  void Prepare();

#ifndef __VTK_WRAP__
  /**
   * A particle's share of the field at a point: its index in SetParticles()' centres and D_i.
   */
  struct Contribution
  {
    vtkIdType Particle;
    double Weight;
  };

  /**
   * IntersectRay() for many threads at once (after Prepare(), without changing the particles or
   * settings meanwhile): also the particles contributing to the field at the hit with their
   * D_i (when `contributions` is given) and the number of influence intervals examined.
   */
  bool IntersectRay(const double origin[3], const double direction[3], double tMin, double tMax,
    double& t, double normal[3], bool& inside, std::vector<Contribution>* contributions,
    vtkIdType& candidates) const;
#endif

  /**
   * Number of particles kept (valid), and the number of influence intervals the last
   * IntersectRay() examined.
   */
  vtkIdType GetNumberOfParticles();
  vtkGetMacro(LastCandidates, vtkIdType);

  /**
   * The kernel's scale c = 1 / (1 - 1/k^2)^2 for influence factor k (16/9 for k = 2).
   */
  static double KernelScale(double influenceFactor);

  /**
   * The smallest root in [0, width] of p0 + p1 u + p2 u^2 + p3 u^3 + p4 u^4 (coefficients c[0..4])
   * where the polynomial changes from negative to non-negative (or touches zero from below);
   * -1 when it stays negative. Exposed for tests.
   */
  static double FirstNonNegative(const double c[5], double width);

protected:
  vtkParticleReferenceMetaballs();
  ~vtkParticleReferenceMetaballs() override;

  double DefaultRadius = 1.0;
  double InfluenceFactor = 2.0;
  double IsoValue = 1.0;
  vtkIdType LastCandidates = 0;

private:
  vtkParticleReferenceMetaballs(const vtkParticleReferenceMetaballs&) = delete;
  void operator=(const vtkParticleReferenceMetaballs&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
