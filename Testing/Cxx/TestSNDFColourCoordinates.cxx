// TestSNDFColourCoordinates: the arithmetic of vtkSNDFColourCoordinates alone (no OpenGL):
//   a) Normalise: each particle's t in [0, 1] over the finite range, one component or the
//      magnitude, 0 for a range of one value, rejected with a non-finite value;
//   b) Place: actor a of K at t' = offset + scale t, with the margin between actors;
//   c) NearestCategory and FindCategories: the nearest distinct value (the greater half way), at
//      most 4096 of them;
//   d) MakeRamp: the stored colour at the ramp's ends through the table and the diffuse scale,
//      a solid actor's colour and alpha 1, an indexed table's colours only those of the values
//      the particles have, empty where the sizes disagree.
#include "prTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkSNDFColourCoordinates.h"
#include "vtkVariant.h"

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

bool Near(double a, double b, double tolerance = 1e-6)
{
  return std::abs(a - b) <= tolerance;
}

// an actor coloured through a table: its array and the range of its values
void TableActor(vtkSNDFColourCoordinates::Actor& actor, vtkDataArray* array, double lo, double hi)
{
  actor.Array = array;
  actor.Range[0] = lo;
  actor.Range[1] = hi;
}

// the colour the ramp's entry should hold: scale * the table's colour of v, the table's alpha
bool Entry(
  const std::vector<float>& ramp, std::size_t i, vtkScalarsToColors* table, double v, double scale)
{
  const unsigned char* rgba = table->MapValue(v);
  for (int j = 0; j < 3; ++j)
  {
    if (!Near(ramp[4 * i + j], scale * rgba[j] / 255.0))
    {
      return false;
    }
  }
  return Near(ramp[4 * i + 3], rgba[3] / 255.0);
}
}

int TestSNDFColourCoordinates(int, char*[])
{
  using Coordinates = vtkSNDFColourCoordinates;
  // a) one component, the magnitude, one value, not finite
  vtkNew<vtkDoubleArray> values;
  for (double v : { 2.0, 4.0, 6.0, 3.0 })
  {
    values->InsertNextValue(v);
  }
  double range[2] = { 0.0, 0.0 };
  std::vector<float> t;
  Check(Coordinates::Normalise(values, 0, range, t), "finite values are normalised");
  Check(range[0] == 2.0 && range[1] == 6.0, "the range is the values' range");
  Check(t.size() == 4 && t[0] == 0.0f && t[1] == 0.5f && t[2] == 1.0f && t[3] == 0.25f,
    "t is the value's place in the range");
  vtkNew<vtkDoubleArray> vectors;
  vectors->SetNumberOfComponents(3);
  vectors->InsertNextTuple3(3.0, 4.0, 0.0);  // |v| 5
  vectors->InsertNextTuple3(0.0, 0.0, 1.0);  // |v| 1
  vectors->InsertNextTuple3(0.0, -3.0, 0.0); // |v| 3
  Check(Coordinates::Normalise(vectors, -1, range, t), "magnitudes are normalised");
  Check(range[0] == 1.0 && range[1] == 5.0 && t[0] == 1.0f && t[1] == 0.0f && t[2] == 0.5f,
    "component -1 is the magnitude");
  Check(Coordinates::Normalise(vectors, 1, range, t) && range[0] == -3.0 && range[1] == 4.0 &&
      Near(t[0], 1.0) && Near(t[1], 3.0 / 7.0) && t[2] == 0.0f,
    "component 1 is that component");
  vtkNew<vtkDoubleArray> constant;
  constant->InsertNextValue(7.0);
  constant->InsertNextValue(7.0);
  Check(Coordinates::Normalise(constant, 0, range, t) && t[0] == 0.0f && t[1] == 0.0f,
    "one value: t = 0");
  values->SetValue(1, std::numeric_limits<double>::quiet_NaN());
  range[0] = range[1] = -1.0;
  Check(!Coordinates::Normalise(values, 0, range, t), "a NaN is rejected");
  Check(range[0] == -1.0 && range[1] == -1.0, "a rejected array leaves the range");
  values->SetValue(1, std::numeric_limits<double>::infinity());
  Check(!Coordinates::Normalise(values, 0, range, t), "an Inf is rejected");
  values->SetValue(1, 4.0);

  // b) placement in [0, 1]
  float offset = -1.0f;
  float scale = -1.0f;
  Coordinates::Place(0, 1, offset, scale);
  Check(offset == 0.0f && scale == 1.0f, "one actor: t' = t");
  Coordinates::Place(0, 2, offset, scale);
  Check(Near(offset, 0.01) && Near(scale, 0.48), "actor 0 of 2: [0.01, 0.49]");
  Coordinates::Place(1, 2, offset, scale);
  Check(Near(offset, 0.51) && Near(scale, 0.48), "actor 1 of 2: [0.51, 0.99]");
  Coordinates::Place(3, 4, offset, scale);
  Check(Near(offset, 0.755) && Near(scale, 0.24), "actor 3 of 4: [0.755, 0.995]");

  // c) categories
  const std::vector<double> categories = { 1.0, 2.0, 5.0 };
  Check(Coordinates::NearestCategory(categories, -3.0) == 1.0, "below all: the first");
  Check(Coordinates::NearestCategory(categories, 1.4) == 1.0, "nearer the lower");
  Check(Coordinates::NearestCategory(categories, 3.4) == 2.0, "nearer the lower (2)");
  Check(Coordinates::NearestCategory(categories, 1.5) == 2.0, "half way: the greater");
  Check(Coordinates::NearestCategory(categories, 3.6) == 5.0, "nearer the upper");
  Check(Coordinates::NearestCategory(categories, 5.0) == 5.0, "on a value");
  Check(Coordinates::NearestCategory(categories, 9.0) == 5.0, "above all: the last");
  vtkNew<vtkDoubleArray> types;
  for (double v : { 5.0, 1.0, 2.0, 5.0, 1.0 })
  {
    types->InsertNextValue(v);
  }
  Coordinates::Actor typed;
  TableActor(typed, types, 1.0, 5.0);
  Check(Coordinates::FindCategories(typed) && typed.Categories == categories,
    "the distinct values, sorted");
  vtkNew<vtkDoubleArray> many;
  for (int i = 0; i < 5000; ++i)
  {
    many->InsertNextValue(i);
  }
  Coordinates::Actor continuous;
  continuous.Array = many;
  Check(!Coordinates::FindCategories(continuous), "more than 4096 values: no categories");

  // d) the ramp: a table-coloured actor and a solid one
  vtkNew<vtkLookupTable> table;
  table->SetTableRange(2.0, 6.0);
  table->SetHueRange(0.667, 0.0);
  table->SetAlphaRange(0.5, 1.0);
  table->Build();
  Coordinates coordinates;
  coordinates.Actors.resize(2);
  TableActor(coordinates.Actors[0], values, 2.0, 6.0);
  coordinates.Actors[1].Solid = true;
  std::vector<Coordinates::SampledColours> stored(2);
  stored[0].Scale = 0.8;
  stored[1].Solid[0] = 0.25;
  stored[1].Solid[1] = 0.5;
  stored[1].Solid[2] = 0.75;
  std::vector<float> ramp = coordinates.MakeRamp({ table, nullptr }, stored);
  const std::size_t size = 2 * Coordinates::RampPerActor;
  Check(ramp.size() == 4 * size, "RampPerActor RGBA entries per actor");
  if (ramp.size() == 4 * size)
  {
    // actor 0 covers t' in [0, 0.5): t = 0 up to the margin, t = 1 from its end on
    Check(Entry(ramp, 0, table, 2.0, 0.8), "the first entry is the table's lowest, scaled");
    Check(Entry(ramp, size / 2 - 1, table, 6.0, 0.8), "actor 0's last entry is its highest");
    Check(!Entry(ramp, size / 4, table, 2.0, 0.8) && !Entry(ramp, size / 4, table, 6.0, 0.8),
      "actor 0's middle lies between");
    bool solid = true;
    for (std::size_t i = size / 2; i < size; ++i)
    {
      solid = solid && ramp[4 * i] == 0.25f && ramp[4 * i + 1] == 0.5f &&
        ramp[4 * i + 2] == 0.75f && ramp[4 * i + 3] == 1.0f;
    }
    Check(solid, "actor 1's entries are its solid colour, alpha 1");
  }
  // an indexed table: every entry is one of the particles' values' colours
  vtkNew<vtkLookupTable> indexed;
  indexed->SetNumberOfTableValues(3);
  indexed->SetTableValue(0, 1.0, 0.0, 0.0, 1.0);
  indexed->SetTableValue(1, 0.0, 1.0, 0.0, 1.0);
  indexed->SetTableValue(2, 0.0, 0.0, 1.0, 1.0);
  indexed->SetAnnotation(vtkVariant(1.0), "one");
  indexed->SetAnnotation(vtkVariant(2.0), "two");
  indexed->SetAnnotation(vtkVariant(5.0), "five");
  indexed->IndexedLookupOn();
  Coordinates categorical;
  categorical.Actors.resize(1);
  TableActor(categorical.Actors[0], types, 1.0, 5.0);
  ramp = categorical.MakeRamp({ indexed }, std::vector<Coordinates::SampledColours>(1));
  Check(ramp.size() == 4 * static_cast<std::size_t>(Coordinates::RampPerActor), "an indexed ramp");
  bool onValues = !ramp.empty();
  for (std::size_t i = 0; i < ramp.size() / 4; ++i)
  {
    onValues = onValues &&
      (Entry(ramp, i, indexed, 1.0, 1.0) || Entry(ramp, i, indexed, 2.0, 1.0) ||
        Entry(ramp, i, indexed, 5.0, 1.0));
  }
  Check(onValues, "an indexed table's entries are its values' colours");
  Check(!ramp.empty() && Entry(ramp, 0, indexed, 1.0, 1.0) &&
      Entry(ramp, ramp.size() / 4 - 1, indexed, 5.0, 1.0) &&
      Entry(ramp, ramp.size() / 8, indexed, 2.0, 1.0),
    "t = 0, 1/2, 1 take the nearest values 1, 2 (3 is nearer 2 than 5) and 5");
  categorical.Actors[0].Array = many;
  categorical.Actors[0].HaveCategories = false;
  categorical.Actors[0].Categories.clear();
  Check(categorical.MakeRamp({ indexed }, std::vector<Coordinates::SampledColours>(1)).empty(),
    "an indexed table over more than 4096 values: no ramp");
  Check(coordinates.MakeRamp({ table }, stored).empty(), "sizes that disagree: no ramp");
  Check(Coordinates()
          .MakeRamp(std::vector<vtkScalarsToColors*>(), std::vector<Coordinates::SampledColours>())
          .empty(),
    "no actors: no ramp");

  if (Failures > 0)
  {
    std::cerr << Failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
