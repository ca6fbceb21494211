//=========================================================================
// EmissionAbsorption.glsl -- the emission-absorption glyph model of
// vtkTransparentSphereMapper (Staib et al. 2015, Sec. 4, Eq. 8-19).
//
// Everything along a ray is measured in units of the sphere radius and
// relative to the ray's closest approach to the centre: b2 is the squared
// impact parameter, the sphere spans tau in [-h, h] with h = sqrt(1 - b2), and
// rho(tau) = 1 (constant model) or b2 + tau^2 (squared distance, Eq. 16 without
// the eye position, whose |e|^2 term cancels every digit with a far camera).
//
// The opacity of a segment is Theta = 1 - exp(-kappa I / I_max) (Eq. 12 with
// lambda from Eq. 15/19 or the hollow maximum), where kappa = -ln(1 - Theta_i)
// is the particle's optical depth along its most opaque ray and I the density
// integral of the segment. log1p and 1 - exp(-a) are evaluated with series
// near 0 and explicit range reduction, not with the builtin log/exp near 1
// (whose absolute error GLSL allows to be 2^-21), so Theta keeps ~1e-7 relative
// precision from Theta_i = 1e-6 to 1 - 1e-7 and for grazing rays.
//=========================================================================

// 2 atanh(z) = ln((1 + z) / (1 - z)) for |z| <= 0.18, relative error < 1e-9 before rounding.
float prTwoAtanhSeries(float z)
{
  float z2 = z * z;
  float s = 1.0 / 13.0;
  s = s * z2 + 1.0 / 11.0;
  s = s * z2 + 1.0 / 9.0;
  s = s * z2 + 1.0 / 7.0;
  s = s * z2 + 1.0 / 5.0;
  s = s * z2 + 1.0 / 3.0;
  s = s * z2 + 1.0;
  return 2.0 * z * s;
}

// ln(u) for u > 0 (finite).
float prLogOfPositive(float u)
{
  // u = m 2^e with m in [0.707, 1.414), by exact scalings (no frexp before GLSL 4.0; the
  // fragment stage is compiled as VTK's GLSL 1.50)
  float m = u;
  float e = 0.0;
  for (int k = 0; k < 160 && m < 0.70710678; ++k)
  {
    m *= 2.0;
    e -= 1.0;
  }
  for (int k = 0; k < 160 && m >= 1.41421356; ++k)
  {
    m *= 0.5;
    e += 1.0;
  }
  // m - 1 is exact, |z| < 0.172
  return e * 0.69314718 + prTwoAtanhSeries((m - 1.0) / (m + 1.0));
}

// ln(1 + x) for x > -1.
float prLog1p(float x)
{
  if (abs(x) < 0.25)
  {
    // 1 + x = (1 + z) / (1 - z) with z = x / (2 + x), |z| < 0.143; 2 + x has no cancellation
    return prTwoAtanhSeries(x / (2.0 + x));
  }
  return prLogOfPositive(1.0 + x);
}

// Optical depth -ln(1 - Theta) of the product Theta = thetaA * thetaO of two opacities, each
// also given as its transmittance (tauA = 1 - thetaA, tauO = 1 - thetaO, so that neither end
// loses digits: 1 - 1e-6 and 1e-7 are both exact enough this way and not as one float), without
// cancellation: 1 - Theta = tauA + thetaA * tauO is a sum of non-negative terms. -1 (infinite)
// when both are opaque.
float prCombinedOpticalDepth(float thetaA, float tauA, float thetaO, float tauO)
{
  float theta = thetaA * thetaO;
  float tau = tauA + thetaA * tauO;
  if (!(tau > 0.0))
  {
    return -1.0;
  }
  return theta < 0.5 ? -prLog1p(-theta) : -prLogOfPositive(tau);
}

// 1 - exp(-a) for a >= 0.
float prOneMinusExpNeg(float a)
{
  if (a < 0.5)
  {
    // a - a^2/2! + a^3/3! - ... (Horner, 11 terms: truncation < 1e-11)
    float s = 1.0;
    for (int k = 11; k >= 2; --k)
    {
      s = 1.0 - s * a / float(k);
    }
    return a * s;
  }
  // exp(-a) <= 0.61: no cancellation, the builtin's relative error is enough
  return 1.0 - exp(-a);
}

// Density integral over the piece [t0, t1] of the ray (length len given separately so that the
// caller can pass a cancellation-free form).
float prPieceIntegral(float b2, float t0, float t1, float len)
{
#if PR_DENSITY_MODEL == 1
  // integral of b2 + tau^2 = len * (b2 + (t0^2 + t0 t1 + t1^2) / 3)
  return len * (b2 + (t0 * t0 + t0 * t1 + t1 * t1) / 3.0);
#else
  return len;
#endif
}

// Density integral of the segment [tn, tf] within [-h, h] (units of the radius) of a sphere whose
// empty core has the squared radius f2 (0: solid). clipN / clipF say whether tn / tf are the
// sphere's own entry / exit (-h / h) or were moved by clipping; unclipped ends use the exact
// chord lengths. f2 is passed squared (rounded once, on the CPU) so that f2 - b2 is exact near
// the core's tangent rays.
float prSegmentIntegral(float b2, float h, float tn, float tf, bool clipN, bool clipF, float f2)
{
  if (f2 <= b2)
  {
    // the ray misses the core
    float len = (clipN || clipF) ? tf - tn : 2.0 * h;
    return prPieceIntegral(b2, tn, tf, len);
  }
  float hs = sqrt(f2 - b2);
  // h - hs = (h^2 - hs^2) / (h + hs) = (1 - f^2) / (h + hs), no cancellation
  float shell = (1.0 - f2) / (h + hs);
  float integral = 0.0;
  if (tn < -hs)
  {
    float end = min(tf, -hs);
    float len = (!clipN && tf >= -hs) ? shell : end - tn;
    integral += prPieceIntegral(b2, tn, end, len);
  }
  if (tf > hs)
  {
    float start = max(tn, hs);
    float len = (!clipF && tn <= hs) ? shell : tf - start;
    integral += prPieceIntegral(b2, start, tf, len);
  }
  return integral;
}

// Theta of a segment for a particle of optical depth kappa (see the file comment).
float prSegmentOpacity(float kappa, float integral, float maximumIntegral)
{
  return prOneMinusExpNeg(kappa * (integral / maximumIntegral));
}
