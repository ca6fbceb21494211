// TestParticleOverlapError: vtkParticleOverlapError, the bound of the sorted spheres' error in the
// lens of two penetrating translucent spheres and the pixels such lenses cover (no OpenGL):
//   a) the bound a_i a_j (|c_i - c_j| + S) of two unit spheres one radius apart against its
//      closed form in double; touching spheres give 0; a sphere inside another has the smaller
//      sphere as its lens; equal colours and no shading give 0 (the order does not matter);
//   b) Build keeps the pairs over the tolerance and deeper than the floor, and reports the
//      largest bound of all;
//   c) EstimatePixels: a lens of radius r at distance D covers pi (r P / D)^2 pixels (P pixels
//      per unit at distance 1), nothing behind the eye or wholly beside the view frustum (its
//      side planes, the viewport's aspect), at most the viewport; parallel views use P as is.
#include "prTestUtilities.h"

#include "vtkParticleOverlapError.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  Failures += prTest::Check(condition, what) ? 0 : 1;
}

vtkParticleOverlapError::Sphere MakeSphere(
  double x, double y, double z, double r, double theta, double red, double green, double blue)
{
  vtkParticleOverlapError::Sphere s;
  s.Centre[0] = x;
  s.Centre[1] = y;
  s.Centre[2] = z;
  s.Radius = r;
  s.OpticalDepth = -std::log1p(-theta);
  s.Colour[0] = red;
  s.Colour[1] = green;
  s.Colour[2] = blue;
  return s;
}
}

int TestParticleOverlapError(int, char*[])
{
  using E = vtkParticleOverlapError;
  const double pi = 3.14159265358979323846;
  // a) one radius apart: lens width 1, circle radius sqrt(3)/2, longest chord sqrt(3)
  const E::Sphere a = MakeSphere(0, 0, 0, 1, 0.9, 255, 40, 40);
  const E::Sphere b = MakeSphere(1, 0, 0, 1, 0.9, 40, 80, 255);
  double lensRadius = 0.0;
  double lensCentre[3] = { 0, 0, 0 };
  const double bound = E::Amplitude(a, b, 2.0, 10.0, &lensRadius, lensCentre);
  const double lensOpacity = 1.0 - std::pow(0.1, std::sqrt(3.0) / 2.0);
  const double expected = lensOpacity * lensOpacity * (215.0 + 10.0);
  std::cout << "bound " << bound << " expected " << expected << "\n";
  Check(std::abs(bound - expected) < 1e-12 * expected, "a_i a_j (|dc| + S) in closed form");
  Check(std::abs(lensRadius - std::sqrt(3.0) / 2.0) < 1e-14 &&
      std::abs(lensCentre[0] - 0.5) < 1e-14 && lensCentre[1] == 0.0,
    "the lens circle: radius sqrt(3)/2 at x = 0.5");
  Check(E::Amplitude(a, MakeSphere(2, 0, 0, 1, 0.9, 0, 0, 255), 2.0, 10.0) == 0.0,
    "touching spheres: 0");
  const E::Sphere inner = MakeSphere(0.2, 0, 0, 0.3, 0.5, 0, 0, 0);
  const double contained = E::Amplitude(a, inner, 2.0, 0.0, &lensRadius);
  const double expectedContained = (1.0 - std::pow(0.1, 0.6 / 2.0)) * 0.5 * 255.0;
  Check(std::abs(contained - expectedContained) < 1e-12 * expectedContained &&
      std::abs(lensRadius - 0.3) < 1e-15,
    "a sphere inside another: the lens is the smaller sphere");
  const E::Sphere same = MakeSphere(1, 0, 0, 1, 0.9, 255, 40, 40);
  Check(E::Amplitude(a, same, 2.0, 0.0) == 0.0, "equal colours, no shading: 0");

  // b) Build: the deep contrasting pair is kept, a shallow one (0.1 radius) is under the floor,
  // a faint deep pair is under the tolerance
  std::vector<E::Sphere> spheres = { a, b, MakeSphere(10, 0, 0, 1, 0.9, 255, 0, 0),
    MakeSphere(11.9, 0, 0, 1, 0.9, 0, 0, 255), MakeSphere(20, 0, 0, 1, 0.01, 255, 0, 0),
    MakeSphere(21, 0, 0, 1, 0.01, 0, 0, 255) };
  E error;
  error.Build(spheres, 2.0, 0.0, 2.0, 0.25);
  Check(error.GetNumberOfPairs() == 1,
    "one pair over the tolerance and the floor (" + std::to_string(error.GetNumberOfPairs()) + ")");
  Check(std::abs(error.GetLargestAmplitude() - lensOpacity * lensOpacity * 215.0) < 1e-9,
    "the largest bound");
  error.Build(spheres, 2.0, 0.0, 2.0, 0.0);
  Check(error.GetNumberOfPairs() == 2, "floor 0: the shallow pair counts too");
  error.Build(spheres, 2.0, 0.0, 255.0, 0.0);
  Check(error.GetNumberOfPairs() == 0, "tolerance 255: nothing can exceed it");
  E none;
  none.Build({}, 2.0, 0.0, 2.0, 0.25);
  Check(none.GetNumberOfPairs() == 0 && none.EstimatePixels(nullptr) == 0.0, "no spheres: 0");

  // c) pixels
  E one;
  one.Build({ a, b }, 2.0, 0.0, 2.0, 0.25);
  const double eye[3] = { 0.5, 0, 10 };
  const double down[3] = { 0, 0, -1 };
  const double r = std::sqrt(3.0) / 2.0;
  const double north[3] = { 0, 1, 0 }; // the view-up
  const double pixels = one.EstimatePixels(eye, down, north, 500.0, false, 1000, 1000);
  const double expectedPixels = pi * std::pow(r * 500.0 / 10.0, 2);
  Check(std::abs(pixels - expectedPixels) < 1e-9 * expectedPixels,
    "a lens covers pi (r P / D)^2 pixels");
  const double up[3] = { 0, 0, 1 };
  Check(
    one.EstimatePixels(eye, up, north, 500.0, false, 1000, 1000) == 0.0, "behind the eye: nothing");
  Check(
    one.EstimatePixels(eye, down, north, 5e4, false, 1000, 1000) == 1e6, "at most the viewport");
  Check(std::abs(one.EstimatePixels(eye, up, north, 50.0, true, 1000, 1000) -
          pi * std::pow(r * 50.0, 2)) < 1e-6,
    "parallel projection: P pixels per unit at any depth");

  // beside the view: 1000 x 1000 pixels, P 500 (a 90 degree frustum, side planes x = +-D at
  // depth D): the lens at depth 10 is outside where its centre lies more than r sqrt(2) beyond
  // the plane, i.e. at a sideways offset of 10 + r sqrt(2)
  const double edge = 10.0 + r * std::sqrt(2.0);
  for (int axis = 0; axis < 2; ++axis)
  {
    for (double sign : { -1.0, 1.0 })
    {
      double inside[3] = { eye[0], eye[1], eye[2] };
      double outside[3] = { eye[0], eye[1], eye[2] };
      inside[axis] -= sign * (edge - 0.01);
      outside[axis] -= sign * (edge + 0.01);
      Check(std::abs(one.EstimatePixels(inside, down, north, 500.0, false, 1000, 1000) -
              expectedPixels) < 1e-9 * expectedPixels,
        "a lens reaching into the view from beside it counts");
      Check(one.EstimatePixels(outside, down, north, 500.0, false, 1000, 1000) == 0.0,
        "a lens wholly beside the view counts nothing");
    }
  }
  // the viewport's aspect: 10 pixels wide, the side planes at x = +-D / 100
  double aside[3] = { eye[0] + 0.1 + r * std::sqrt(1.0 + 1e-4) + 0.01, eye[1], eye[2] };
  Check(one.EstimatePixels(aside, down, north, 500.0, false, 10, 1000) == 0.0 &&
      one.EstimatePixels(aside, down, north, 500.0, false, 1000, 1000) > 0.0,
    "the frustum's width follows the viewport's");
  // parallel: 1000 pixels at 50 per unit, the view +-10 units wide
  double beside[3] = { eye[0] + 10.0 + r + 0.01, eye[1], eye[2] };
  Check(one.EstimatePixels(beside, down, north, 50.0, true, 1000, 1000) == 0.0,
    "parallel projection: a lens beside the view counts nothing");
  beside[0] -= 0.02;
  Check(one.EstimatePixels(beside, down, north, 50.0, true, 1000, 1000) > 0.0,
    "parallel projection: a lens reaching into the view counts");
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
