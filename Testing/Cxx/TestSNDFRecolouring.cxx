// TestSNDFRecolouring: the fits and the colour pairs of vtkSNDFRecolouring alone (no OpenGL):
//   a) FitColourMatrix recovers a known 3 x 3 map exactly from (old, new) colour pairs, also
//      where the old colours span fewer than three dimensions (minimum norm);
//   b) it rejects pairs that are not a linear function within the tolerance and maps with
//      entries beyond 16;
//   c) AddPairs makes the distinct (old, new) pairs of mapped colours in the units of the stored
//      colour, and rejects what no map can carry: a changed opacity, one old colour with two new
//      ones, the same array mapped anew, a changed colour with an ambient term or a coloured
//      light; a solid colour is one pair;
//   d) RampResidual is the map between two ramps' centred colours.
#include "prTestUtilities.h"

#include "vtkNew.h"
#include "vtkSNDFRecolouring.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  Failures += prTest::Check(condition, what) ? 0 : 1;
}

using Pair = vtkSNDFRecolouring::Pair;

// (o, M o)
Pair Mapped(const double m[3][3], double r, double g, double b)
{
  Pair pair = { r, g, b, 0.0, 0.0, 0.0 };
  for (int row = 0; row < 3; ++row)
  {
    pair[3 + row] = m[row][0] * r + m[row][1] * g + m[row][2] * b;
  }
  return pair;
}

bool SameMatrix(const double a[3][3], const double b[3][3], double tolerance)
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (!(std::abs(a[i][j] - b[i][j]) <= tolerance))
      {
        return false;
      }
    }
  }
  return true;
}

bool NearPair(const Pair& a, const Pair& b)
{
  for (int i = 0; i < 6; ++i)
  {
    if (!(std::abs(a[i] - b[i]) <= 1e-12))
    {
      return false;
    }
  }
  return true;
}

// RGBA colours, opaque unless given
vtkSmartPointer<vtkUnsignedCharArray> Colours(
  const std::vector<std::vector<unsigned char>>& colours)
{
  auto array = vtkSmartPointer<vtkUnsignedCharArray>::New();
  array->SetNumberOfComponents(4);
  for (const auto& c : colours)
  {
    array->InsertNextTypedTuple(std::vector<unsigned char>{
      c[0], c[1], c[2], static_cast<unsigned char>(c.size() > 3 ? c[3] : 255) }
                                  .data());
  }
  return array;
}

vtkSNDFRecolouring::SampledColours Sampled(vtkUnsignedCharArray* colours, double scale)
{
  vtkSNDFRecolouring::SampledColours s;
  s.Colours = colours;
  s.Time = colours ? colours->GetMTime() : 0;
  s.Scale = scale;
  return s;
}
}

int TestSNDFRecolouring(int, char*[])
{
  // a) exact recovery
  const double known[3][3] = { { 0.5, 0.25, 0.0 }, { -0.125, 1.0, 0.375 }, { 0.0, 0.75, 2.0 } };
  std::vector<Pair> pairs = { Mapped(known, 1.0, 0.0, 0.0), Mapped(known, 0.2, 0.9, 0.1),
    Mapped(known, 0.3, 0.3, 0.8), Mapped(known, 0.6, 0.1, 0.4) };
  double m[3][3];
  Check(vtkSNDFRecolouring::FitColourMatrix(pairs, m, 1e-12), "a linear map is fitted");
  Check(SameMatrix(m, known, 1e-12), "the fitted map is the known one");
  // two old colours (a plane of colours): the minimum-norm map that carries them
  const double gray[3][3] = { { 2.0, 0.0, 0.0 }, { 0.0, 2.0, 0.0 }, { 0.0, 0.0, 2.0 } };
  std::vector<Pair> plane = { Mapped(gray, 0.1, 0.1, 0.1), Mapped(gray, 0.4, 0.4, 0.4) };
  Check(vtkSNDFRecolouring::FitColourMatrix(plane, m, 1e-12), "one direction of colours");
  const double minimum[3][3] = { { 2.0 / 3, 2.0 / 3, 2.0 / 3 }, { 2.0 / 3, 2.0 / 3, 2.0 / 3 },
    { 2.0 / 3, 2.0 / 3, 2.0 / 3 } };
  Check(SameMatrix(m, minimum, 1e-12), "its minimum-norm map");

  // b) rejections: not linear (a square), within a tolerance that the square exceeds
  std::vector<Pair> square;
  for (double v : { 0.1, 0.3, 0.5, 0.7, 0.9 })
  {
    square.push_back({ v, 0.5 * v, 0.2, v * v, 0.5 * v, 0.2 });
  }
  Check(
    !vtkSNDFRecolouring::FitColourMatrix(square, m, 0.05 / 255.0), "a square is not a linear map");
  Check(vtkSNDFRecolouring::FitColourMatrix(square, m, std::numeric_limits<double>::infinity()),
    "with no tolerance it is fitted");
  std::vector<Pair> perturbed = pairs;
  perturbed[3][4] += 1.0 / 255.0;
  Check(!vtkSNDFRecolouring::FitColourMatrix(perturbed, m, 0.05 / 255.0),
    "one pair off by 1/255 is rejected");
  Check(vtkSNDFRecolouring::FitColourMatrix(perturbed, m, 1.0 / 255.0),
    "within a tolerance of 1/255 it is not");
  std::vector<Pair> steep = { { 0.01, 0.0, 0.0, 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0, 0.0, 1.0, 0.0 },
    { 0.0, 0.0, 1.0, 0.0, 0.0, 1.0 } };
  Check(!vtkSNDFRecolouring::FitColourMatrix(steep, m, 1.0), "an entry of 100 is rejected");

  // c) pairs of mapped colours: red -> blue, green kept, at scales 0.8 -> 0.5
  auto old = Colours({ { 255, 0, 0 }, { 0, 255, 0 }, { 255, 0, 0 } });
  auto now = Colours({ { 0, 0, 255 }, { 0, 255, 0 }, { 0, 0, 255 } });
  bool changed = false;
  pairs.clear();
  Check(
    vtkSNDFRecolouring::AddPairs(Sampled(old, 0.8), Sampled(now, 0.5), 0.0, false, changed, pairs),
    "a new map of two colours gives pairs");
  Check(changed && pairs.size() == 2, "two distinct pairs, changed");
  bool red = false;
  bool green = false;
  for (const Pair& p : pairs)
  {
    red = red || NearPair(p, Pair{ 0.8, 0.0, 0.0, 0.0, 0.0, 0.5 });
    green = green || NearPair(p, Pair{ 0.0, 0.8, 0.0, 0.0, 0.5, 0.0 });
  }
  Check(red && green, "the pairs are the stored colours, old and new");
  Check(vtkSNDFRecolouring::FitColourMatrix(pairs, m, 0.05 / 255.0), "which are linear");
  changed = false;
  pairs.clear();
  Check(
    vtkSNDFRecolouring::AddPairs(Sampled(old, 0.8), Sampled(old, 0.8), 0.5, true, changed, pairs) &&
      !changed && pairs.size() == 2,
    "unchanged colours give pairs (an ambient term and a coloured light do not matter)");
  changed = false;
  Check(
    !vtkSNDFRecolouring::AddPairs(Sampled(old, 0.8), Sampled(now, 0.8), 0.1, false, changed, pairs),
    "changed colours with an ambient term are rejected");
  Check(
    !vtkSNDFRecolouring::AddPairs(Sampled(old, 0.8), Sampled(now, 0.8), 0.0, true, changed, pairs),
    "changed colours with a coloured light are rejected");
  auto translucent = Colours({ { 0, 0, 255, 128 }, { 0, 255, 0 }, { 0, 0, 255 } });
  Check(!vtkSNDFRecolouring::AddPairs(
          Sampled(old, 0.8), Sampled(translucent, 0.8), 0.0, false, changed, pairs),
    "a changed opacity is rejected");
  auto split = Colours({ { 0, 0, 255 }, { 0, 255, 0 }, { 0, 255, 255 } });
  Check(!vtkSNDFRecolouring::AddPairs(
          Sampled(old, 0.8), Sampled(split, 0.8), 0.0, false, changed, pairs),
    "one old colour with two new ones is rejected");
  auto shorter = Colours({ { 0, 0, 255 } });
  Check(!vtkSNDFRecolouring::AddPairs(
          Sampled(old, 0.8), Sampled(shorter, 0.8), 0.0, false, changed, pairs),
    "another number of particles is rejected");
  auto then = Sampled(old, 0.8);
  old->Modified();
  Check(!vtkSNDFRecolouring::AddPairs(then, Sampled(old, 0.8), 0.0, false, changed, pairs),
    "the same array mapped anew is rejected");
  Check(!vtkSNDFRecolouring::AddPairs(
          Sampled(old, 0.8), Sampled(nullptr, 0.8), 0.0, false, changed, pairs),
    "scalars to a solid colour are rejected");
  // solid colours: one pair
  auto solidThen = Sampled(nullptr, 1.0);
  auto solidNow = Sampled(nullptr, 1.0);
  solidThen.Solid[0] = 0.5;
  solidNow.Solid[2] = 0.25;
  changed = false;
  pairs.clear();
  Check(vtkSNDFRecolouring::AddPairs(solidThen, solidNow, 0.3, false, changed, pairs) && changed &&
      pairs.size() == 1 && pairs[0] == (Pair{ 0.5, 0.0, 0.0, 0.0, 0.0, 0.25 }),
    "a new solid colour is one pair (its ambient term is the ambient colour's)");
  Check(!vtkSNDFRecolouring::AddPairs(solidThen, solidNow, 0.0, true, changed, pairs),
    "a new solid colour with a coloured light is rejected");

  // d) the residual map between two ramps: new = known * old + a constant
  std::vector<float> oldRamp;
  std::vector<float> newRamp;
  for (int i = 0; i < 64; ++i)
  {
    const double c[3] = { (i % 4) / 4.0, (i / 4 % 4) / 4.0, (i / 16) / 4.0 };
    for (int row = 0; row < 3; ++row)
    {
      oldRamp.push_back(static_cast<float>(c[row]));
      newRamp.push_back(static_cast<float>(
        0.1 + known[row][0] * c[0] + known[row][1] * c[1] + known[row][2] * c[2]));
    }
    oldRamp.push_back(1.0f);
    newRamp.push_back(1.0f);
  }
  double residual[3][3];
  vtkSNDFRecolouring::RampResidual(oldRamp, newRamp, residual);
  Check(SameMatrix(residual, known, 1e-5), "the ramps' residual map is the known one");

  if (Failures > 0)
  {
    std::cerr << Failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
