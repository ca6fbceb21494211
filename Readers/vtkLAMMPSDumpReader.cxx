#include "vtkLAMMPSDumpReader.h"
#include "vtkParticleReaderInternals.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLAMMPSDumpReader);

namespace
{
using namespace prReader;

struct Snapshot
{
  int File = 0;
  long long Timestep = 0;
  long long NumberOfAtoms = 0;
  std::uint64_t AtomsOffset = 0; // first byte of the first atom line
  std::uint64_t EndOffset = 0;   // first byte after the last atom line
  long long AtomsLine = 0;       // line number of the first atom line
  Box SimulationBox;
  std::vector<std::string> Columns;
};

//------------------------------------------------------------------------------
// Where a column goes.
enum class Kind
{
  Point,  // a component of the points (double)
  Float,  // a component of a float array
  Int,    // a component of an int array
  IdType, // vtkIdType array (id)
  String, // a string array
};

struct ColumnPlan
{
  Kind Type = Kind::Float;
  int Array = -1; // index into Plan::Arrays
  int Component = 0;
};

struct ArrayPlan
{
  std::string Name;
  Kind Type = Kind::Float;
  int Components = 1;
};

// Coordinate flavours.
enum Flavour
{
  WrappedXYZ = 0,
  UnwrappedXYZ = 1,
  ScaledXYZ = 2,
  ScaledUnwrappedXYZ = 3,
  ImageXYZ = 4,
  NumberOfFlavours = 5
};
const char* const FlavourColumns[NumberOfFlavours][3] = { { "x", "y", "z" }, { "xu", "yu", "zu" },
  { "xs", "ys", "zs" }, { "xsu", "ysu", "zsu" }, { "ix", "iy", "iz" } };
const char* const FlavourArrays[NumberOfFlavours] = { "wrapped", "unwrapped", "scaled",
  "scaled_unwrapped", "image" };

struct Plan
{
  std::vector<ColumnPlan> Columns;
  std::vector<ArrayPlan> Arrays;
  int PointFlavour = -1; // the flavour that becomes the points (-1: none: all points 0)
  bool UnwrapWithImage = false;
  bool Scaled = false;
  int IdArray = -1;
  int TypeArray = -1;
  int RadiusArray = -1;   // "radius" column
  int DiameterArray = -1; // "diameter" column
  int ImageArray = -1;
  int ShapeArray = -1; // "shapex shapey shapez" (diameters of ellipsoids)
  std::string Warning;
};

// The array of LAMMPS's vector attributes, by the column name without its x/y/z suffix.
const std::map<std::string, std::string>& VectorNames()
{
  static const std::map<std::string, std::string> names = { { "v", "velocity" }, { "f", "force" },
    { "mu", "mu" }, { "omega", "omega" }, { "angmom", "angmom" }, { "tq", "torque" } };
  return names;
}

bool IsIntegerColumn(const std::string& name)
{
  return name == "id" || name == "mol" || name == "type" || name == "proc" || name == "procp1";
}

// "c_name[3]" -> ("c_name", 3); 0 when the name has no bracketed index.
int BracketIndex(const std::string& column, std::string& base)
{
  const size_t open = column.rfind('[');
  if (open == std::string::npos || open == 0 || column.back() != ']')
  {
    return 0;
  }
  int index = 0;
  const char* first = column.data() + open + 1;
  const char* last = column.data() + column.size() - 1;
  const auto r = std::from_chars(first, last, index);
  if (r.ec != std::errc() || r.ptr != last || index < 1)
  {
    return 0;
  }
  base = column.substr(0, open);
  return index;
}

// The index of the column called name, -1 when there is none.
int FindColumn(const std::vector<std::string>& columns, const char* name)
{
  for (size_t i = 0; i < columns.size(); ++i)
  {
    if (columns[i] == name)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

int AddArray(Plan& plan, const std::string& name, Kind type, int components)
{
  plan.Arrays.push_back({ name, type, components });
  return static_cast<int>(plan.Arrays.size()) - 1;
}

// Which flavour becomes the points (plan.PointFlavour, Scaled, UnwrapWithImage, Warning).
void ChoosePoints(const bool present[NumberOfFlavours], int positionSource, Plan& plan)
{
  const int automatic[4] = { WrappedXYZ, UnwrappedXYZ, ScaledXYZ, ScaledUnwrappedXYZ };
  int chosen = -1;
  if (positionSource == vtkLAMMPSDumpReader::WRAPPED)
  {
    chosen = present[WrappedXYZ] ? WrappedXYZ : (present[ScaledXYZ] ? ScaledXYZ : -1);
  }
  else if (positionSource == vtkLAMMPSDumpReader::UNWRAPPED)
  {
    chosen = present[UnwrappedXYZ] ? UnwrappedXYZ
                                   : (present[ScaledUnwrappedXYZ] ? ScaledUnwrappedXYZ : -1);
    if (chosen < 0 && present[WrappedXYZ] && present[ImageXYZ])
    {
      chosen = WrappedXYZ;
      plan.UnwrapWithImage = true;
    }
  }
  if (chosen < 0)
  {
    if (positionSource != vtkLAMMPSDumpReader::AUTOMATIC)
    {
      plan.Warning = std::string("the columns have no ") +
        (positionSource == vtkLAMMPSDumpReader::WRAPPED
            ? "wrapped coordinates (x y z or xs ys zs)"
            : "unwrapped coordinates (xu yu zu, xsu ysu zsu, or x y z with ix iy iz)") +
        ": using the first coordinates present";
    }
    for (int f : automatic)
    {
      if (present[f])
      {
        chosen = f;
        break;
      }
    }
  }
  plan.PointFlavour = chosen;
  plan.Scaled = chosen == ScaledXYZ || chosen == ScaledUnwrappedXYZ;
  if (chosen < 0)
  {
    plan.Warning += std::string(plan.Warning.empty() ? "" : "; ") +
      "no complete set of coordinates (x y z, xu yu zu, xs ys zs or xsu ysu zsu): every atom "
      "is at the origin";
  }
}

// The coordinate flavours present: the points, and a 3-component array for each of the others.
void PlanCoordinates(const bool present[NumberOfFlavours],
  const int flavourColumns[NumberOfFlavours][3], Plan& plan, std::vector<bool>& done)
{
  for (int f = 0; f < NumberOfFlavours; ++f)
  {
    if (!present[f])
    {
      continue;
    }
    int array = -1;
    Kind type = Kind::Point;
    if (f != plan.PointFlavour)
    {
      type = f == ImageXYZ ? Kind::Int : Kind::Float;
      array = AddArray(plan, FlavourArrays[f], type, 3);
      if (f == ImageXYZ)
      {
        plan.ImageArray = array;
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      plan.Columns[flavourColumns[f][k]] = { type, array, k };
      done[flavourColumns[f][k]] = true;
    }
  }
}

// vectors: vx vy vz and friends
void PlanVectors(const std::vector<std::string>& columns, Plan& plan, std::vector<bool>& done)
{
  for (const auto& item : VectorNames())
  {
    int c[3];
    bool all = true;
    for (int k = 0; k < 3; ++k)
    {
      c[k] = FindColumn(columns, (item.first + "xyz"[k]).c_str());
      all &= c[k] >= 0 && !done[c[k]];
    }
    if (all)
    {
      const int array = AddArray(plan, item.second, Kind::Float, 3);
      for (int k = 0; k < 3; ++k)
      {
        plan.Columns[c[k]] = { Kind::Float, array, k };
        done[c[k]] = true;
      }
    }
  }
}

// aspherical particles (atom_style ellipsoid): shapex shapey shapez -> "shape" (LAMMPS's
// diameters; AddSemiAxes halves them), quatw quati quatj quatk -> "orientation" (w, i, j, k),
// each when all its columns are there, in any column order
void PlanEllipsoids(const std::vector<std::string>& columns, Plan& plan, std::vector<bool>& done)
{
  const std::vector<std::string> groups[2] = { { "shapex", "shapey", "shapez" },
    { "quatw", "quati", "quatj", "quatk" } };
  const char* const names[2] = { "shape", "orientation" };
  for (int g = 0; g < 2; ++g)
  {
    std::vector<int> c;
    for (const std::string& name : groups[g])
    {
      const int column = FindColumn(columns, name.c_str());
      if (column < 0 || done[column])
      {
        break;
      }
      c.push_back(column);
    }
    if (c.size() != groups[g].size())
    {
      continue;
    }
    const int array = AddArray(plan, names[g], Kind::Float, static_cast<int>(c.size()));
    for (size_t k = 0; k < c.size(); ++k)
    {
      plan.Columns[c[k]] = { Kind::Float, array, static_cast<int>(k) };
      done[c[k]] = true;
    }
    if (g == 0)
    {
      plan.ShapeArray = array;
    }
  }
}

// bracketed vectors c_name[1] c_name[2] ... (consecutive, starting at 1)
void PlanBracketedVectors(
  const std::vector<std::string>& columns, Plan& plan, std::vector<bool>& done)
{
  for (size_t i = 0; i < columns.size(); ++i)
  {
    std::string base;
    if (done[i] || BracketIndex(columns[i], base) != 1)
    {
      continue;
    }
    size_t n = 1;
    std::string next;
    while (i + n < columns.size() && !done[i + n] &&
      BracketIndex(columns[i + n], next) == static_cast<int>(n) + 1 && next == base)
    {
      ++n;
    }
    if (n < 2)
    {
      continue;
    }
    const int array = AddArray(plan, base, Kind::Float, static_cast<int>(n));
    for (size_t k = 0; k < n; ++k)
    {
      plan.Columns[i + k] = { Kind::Float, array, static_cast<int>(k) };
      done[i + k] = true;
    }
  }
}

// everything else, one array per column
void PlanScalars(const std::vector<std::string>& columns, const std::vector<std::string>& firstRow,
  Plan& plan, const std::vector<bool>& done)
{
  for (size_t i = 0; i < columns.size(); ++i)
  {
    if (done[i])
    {
      continue;
    }
    Kind type = Kind::Float;
    double value;
    if (columns[i] == "id")
    {
      type = Kind::IdType;
    }
    else if (IsIntegerColumn(columns[i]))
    {
      type = Kind::Int;
    }
    else if (columns[i] == "element" || (i < firstRow.size() && !ParseWord(firstRow[i], value)))
    {
      type = Kind::String;
    }
    const int array = AddArray(plan, columns[i], type, 1);
    plan.Columns[i] = { type, array, 0 };
    if (columns[i] == "id")
    {
      plan.IdArray = array;
    }
    else if (columns[i] == "type")
    {
      plan.TypeArray = array;
    }
    else if (columns[i] == "radius" && type == Kind::Float)
    {
      plan.RadiusArray = array;
    }
    else if (columns[i] == "diameter" && type == Kind::Float)
    {
      plan.DiameterArray = array;
    }
  }
}

Plan MakePlan(const std::vector<std::string>& columns, const std::vector<std::string>& firstRow,
  int positionSource)
{
  Plan plan;
  plan.Columns.resize(columns.size());
  std::vector<bool> done(columns.size(), false);
  // coordinate flavours present (all three components)
  int flavourColumns[NumberOfFlavours][3];
  bool present[NumberOfFlavours];
  for (int f = 0; f < NumberOfFlavours; ++f)
  {
    present[f] = true;
    for (int k = 0; k < 3; ++k)
    {
      flavourColumns[f][k] = FindColumn(columns, FlavourColumns[f][k]);
      present[f] &= flavourColumns[f][k] >= 0;
    }
  }
  // which flavour becomes the points
  ChoosePoints(present, positionSource, plan);
  PlanCoordinates(present, flavourColumns, plan, done);
  PlanVectors(columns, plan, done);
  PlanEllipsoids(columns, plan, done);
  PlanBracketedVectors(columns, plan, done);
  PlanScalars(columns, firstRow, plan, done);
  return plan;
}

//------------------------------------------------------------------------------
// Destinations of one step's values.
struct Outputs
{
  double* Points = nullptr;
  std::vector<void*> Arrays; // float*, int*, vtkIdType* or std::vector<std::string>*
  std::vector<vtkSmartPointer<vtkAbstractArray>> Objects;
  std::vector<std::vector<std::string>> Strings;
};

// Where the value of one column of row r goes: Base + Stride * r + Component, as Type.
struct Target
{
  Kind Type = Kind::Float;
  void* Base = nullptr;
  int Stride = 1;
  int Component = 0;
};

std::vector<Target> MakeTargets(const Plan& plan, Outputs& out)
{
  std::vector<Target> targets(plan.Columns.size());
  for (size_t i = 0; i < plan.Columns.size(); ++i)
  {
    const ColumnPlan& c = plan.Columns[i];
    Target& t = targets[i];
    t.Type = c.Type;
    t.Component = c.Component;
    if (c.Type == Kind::Point)
    {
      t.Base = out.Points;
      t.Stride = 3;
    }
    else
    {
      t.Base = out.Arrays[c.Array];
      t.Stride = plan.Arrays[c.Array].Components;
    }
  }
  return targets;
}

// The first error of a parse, by row.
struct ParseError
{
  long long Row = -1;
  std::string What;
};

// Parse the lines [begin, end) (complete lines, each ending in '\n' except possibly the last)
// into rows starting at firstRow. Returns false and fills error on the first bad line.
bool ParseLines(const char* begin, const char* end, long long firstRow,
  const std::vector<Target>& targets, ParseError& error, long long& nonFinite)
{
  const size_t columns = targets.size();
  long long row = firstRow;
  const char* p = begin;
  while (p < end)
  {
    const char* lineEnd = static_cast<const char*>(std::memchr(p, '\n', end - p));
    if (!lineEnd)
    {
      lineEnd = end;
    }
    const char* q = p;
    size_t column = 0;
    while (true)
    {
      while (q < lineEnd && (*q == ' ' || *q == '\t' || *q == '\r'))
      {
        ++q;
      }
      if (q == lineEnd)
      {
        break;
      }
      const char* tokenEnd = q;
      while (tokenEnd < lineEnd && *tokenEnd != ' ' && *tokenEnd != '\t' && *tokenEnd != '\r')
      {
        ++tokenEnd;
      }
      if (column >= columns)
      {
        ++column; // count them all for the message
        q = tokenEnd;
        continue;
      }
      const Target& t = targets[column];
      const size_t at = static_cast<size_t>(t.Stride * row + t.Component);
      bool ok = true;
      switch (t.Type)
      {
        case Kind::Point:
        {
          double v = 0.0;
          ok = ParseDouble(q, tokenEnd, v);
          nonFinite += std::isfinite(v) ? 0 : 1;
          static_cast<double*>(t.Base)[at] = v;
          break;
        }
        case Kind::Float:
        {
          double v = 0.0;
          ok = ParseDouble(q, tokenEnd, v);
          nonFinite += std::isfinite(v) ? 0 : 1;
          static_cast<float*>(t.Base)[at] = static_cast<float>(v);
          break;
        }
        case Kind::Int:
        {
          long long v = 0;
          ok = ParseInt64(q, tokenEnd, v) && v >= INT32_MIN && v <= INT32_MAX;
          static_cast<int*>(t.Base)[at] = static_cast<int>(v);
          break;
        }
        case Kind::IdType:
        {
          long long v = 0;
          ok = ParseInt64(q, tokenEnd, v);
          static_cast<vtkIdType*>(t.Base)[at] = static_cast<vtkIdType>(v);
          break;
        }
        case Kind::String:
          static_cast<std::vector<std::string>*>(t.Base)->at(at).assign(q, tokenEnd);
          break;
      }
      if (!ok)
      {
        error.Row = row;
        error.What = "column " + std::to_string(column + 1) + " ('" + std::string(q, tokenEnd) +
          "') is not " +
          (t.Type == Kind::Int || t.Type == Kind::IdType ? "an integer" : "a number");
        return false;
      }
      ++column;
      q = tokenEnd;
    }
    if (column != columns)
    {
      error.Row = row;
      error.What = column == 0 ? std::string("empty line in the atom section")
                               : std::to_string(column) + " values where ITEM: ATOMS names " +
          std::to_string(columns) + " columns";
      return false;
    }
    ++row;
    p = lineEnd + 1;
  }
  return true;
}
}

//------------------------------------------------------------------------------
class vtkLAMMPSDumpReader::vtkInternals
{
public:
  std::vector<std::string> FileNames;
  std::vector<Snapshot> Steps;
  std::vector<double> TimeValues;
  // the index is valid for these files, these settings and this modification state
  std::vector<std::string> IndexedFiles;
  std::vector<long long> IndexedSizes; // FileStamp of each file
  std::string LastWarning;
};

//------------------------------------------------------------------------------
vtkLAMMPSDumpReader::vtkLAMMPSDumpReader()
  : Internals(new vtkInternals)
{
}

vtkLAMMPSDumpReader::~vtkLAMMPSDumpReader() = default;

//------------------------------------------------------------------------------
void vtkLAMMPSDumpReader::SetFileName(const char* fileName)
{
  std::vector<std::string> names;
  if (fileName && *fileName)
  {
    names.emplace_back(fileName);
  }
  if (names != this->Internals->FileNames)
  {
    this->Internals->FileNames = names;
    this->Modified();
  }
}

const char* vtkLAMMPSDumpReader::GetFileName()
{
  return this->GetFileName(0);
}

void vtkLAMMPSDumpReader::AddFileName(const char* fileName)
{
  if (fileName && *fileName)
  {
    this->Internals->FileNames.emplace_back(fileName);
    this->Modified();
  }
}

void vtkLAMMPSDumpReader::RemoveAllFileNames()
{
  if (!this->Internals->FileNames.empty())
  {
    this->Internals->FileNames.clear();
    this->Modified();
  }
}

int vtkLAMMPSDumpReader::GetNumberOfFileNames()
{
  return static_cast<int>(this->Internals->FileNames.size());
}

const char* vtkLAMMPSDumpReader::GetFileName(int index)
{
  const auto& names = this->Internals->FileNames;
  return index >= 0 && index < static_cast<int>(names.size()) ? names[index].c_str() : nullptr;
}

//------------------------------------------------------------------------------
int vtkLAMMPSDumpReader::GetNumberOfSteps()
{
  return static_cast<int>(this->Internals->Steps.size());
}

long long vtkLAMMPSDumpReader::GetStepTimestep(int step)
{
  const auto& steps = this->Internals->Steps;
  return step >= 0 && step < static_cast<int>(steps.size()) ? steps[step].Timestep : -1;
}

vtkIdType vtkLAMMPSDumpReader::GetStepNumberOfAtoms(int step)
{
  const auto& steps = this->Internals->Steps;
  return step >= 0 && step < static_cast<int>(steps.size())
    ? static_cast<vtkIdType>(steps[step].NumberOfAtoms)
    : -1;
}

//------------------------------------------------------------------------------
int vtkLAMMPSDumpReader::CanReadFile(const char* fileName)
{
  InputFile file;
  if (!fileName || !file.Open(fileName))
  {
    return 0;
  }
  LineReader lines(file, 16384);
  std::string line;
  for (int i = 0; i < 16 && lines.Next(line); ++i)
  {
    if (line.find('\0') != std::string::npos)
    {
      return 0;
    }
    if (!Split(line).empty())
    {
      return StartsWith(line, "ITEM: TIMESTEP") || StartsWith(line, "ITEM: UNITS") ||
          StartsWith(line, "ITEM: TIME")
        ? 1
        : 0;
    }
  }
  return 0;
}

//------------------------------------------------------------------------------
namespace
{
// The next line that is not empty (only blanks); false at the end of the file.
bool NextNonEmpty(LineReader& lines, std::string& out)
{
  while (lines.Next(out))
  {
    if (!Split(out).empty())
    {
      return true;
    }
  }
  return false;
}

// Why the file is not a text dump (empty, unreadable, binary), or "" when it may be one. The
// file is read from its start and left there.
std::string CheckText(InputFile& file, const std::string& name)
{
  // a binary file (NUL bytes) is not a text dump
  std::vector<char> head(4096);
  const long long got = file.Read(head.data(), head.size());
  if (got == 0)
  {
    return name + ": the file is empty";
  }
  if (got < 0)
  {
    return name + ": cannot read the file";
  }
  if (std::memchr(head.data(), '\0', static_cast<size_t>(got)))
  {
    return name +
      ": a binary file, not a LAMMPS text dump (binary dumps can be converted with LAMMPS's "
      "tools/binary2txt)";
  }
  file.Seek(0);
  return std::string();
}

// The box of a snapshot from its line "ITEM: BOX BOUNDS ..." (in line) and the three lines after
// it. Returns what is wrong, or "".
std::string ReadBoxBounds(LineReader& lines, std::string& line, Snapshot& s)
{
  std::vector<std::string> words = Split(line.substr(std::strlen("ITEM: BOX BOUNDS")));
  s.SimulationBox.Triclinic = words.size() >= 3 && words[0] == "xy";
  std::string periodicity;
  for (size_t k = s.SimulationBox.Triclinic ? 3 : 0; k < words.size(); ++k)
  {
    periodicity += (periodicity.empty() ? "" : " ") + words[k];
  }
  s.SimulationBox.Periodicity = periodicity;
  double bounds[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  for (int k = 0; k < 3; ++k)
  {
    if (!NextNonEmpty(lines, line))
    {
      return "the file ends inside ITEM: BOX BOUNDS";
    }
    words = Split(line);
    const size_t need = s.SimulationBox.Triclinic ? 3 : 2;
    if (words.size() < need)
    {
      return "expected " + std::to_string(need) + " numbers in the box bounds";
    }
    for (size_t j = 0; j < need; ++j)
    {
      if (!ParseWord(words[j], bounds[k][j]))
      {
        return "'" + words[j] + "' in the box bounds is not a number";
      }
    }
  }
  Box& box = s.SimulationBox;
  for (int k = 0; k < 3; ++k)
  {
    box.Tilt[k] = s.SimulationBox.Triclinic ? bounds[k][2] : 0.0;
  }
  // LAMMPS writes the bounding box of a triclinic box: remove the tilt (dump manual)
  const double xy = box.Tilt[0];
  const double xz = box.Tilt[1];
  const double yz = box.Tilt[2];
  box.Lo[0] = bounds[0][0] - std::min({ 0.0, xy, xz, xy + xz });
  box.Hi[0] = bounds[0][1] - std::max({ 0.0, xy, xz, xy + xz });
  box.Lo[1] = bounds[1][0] - std::min(0.0, yz);
  box.Hi[1] = bounds[1][1] - std::max(0.0, yz);
  box.Lo[2] = bounds[2][0];
  box.Hi[2] = bounds[2][1];
  return std::string();
}

// The header of a snapshot, from its first line (in line) to ITEM: ATOMS and the column names:
// timestep, number of atoms, box, columns. Returns what is wrong, or "".
std::string ReadHeader(LineReader& lines, std::string& line, Snapshot& s)
{
  // optional ITEM: UNITS / ITEM: TIME blocks (dump_modify units/time)
  while (StartsWith(line, "ITEM: UNITS") ||
    (StartsWith(line, "ITEM: TIME") && !StartsWith(line, "ITEM: TIMESTEP")))
  {
    if (!NextNonEmpty(lines, line) || !NextNonEmpty(lines, line))
    {
      return "the file ends inside a snapshot header";
    }
  }
  if (!StartsWith(line, "ITEM: TIMESTEP"))
  {
    return "expected 'ITEM: TIMESTEP', found '" + line.substr(0, 60) + "'";
  }
  std::vector<std::string> words;
  if (!NextNonEmpty(lines, line) || (words = Split(line)).size() != 1 ||
    !ParseInt64(words[0].data(), words[0].data() + words[0].size(), s.Timestep))
  {
    return "expected the timestep (an integer) after ITEM: TIMESTEP";
  }
  if (!NextNonEmpty(lines, line) || !StartsWith(line, "ITEM: NUMBER OF ATOMS"))
  {
    return "expected 'ITEM: NUMBER OF ATOMS'";
  }
  if (!NextNonEmpty(lines, line) || (words = Split(line)).size() != 1 ||
    !ParseInt64(words[0].data(), words[0].data() + words[0].size(), s.NumberOfAtoms) ||
    s.NumberOfAtoms < 0)
  {
    return "expected the number of atoms (an integer >= 0)";
  }
  if (!NextNonEmpty(lines, line) || !StartsWith(line, "ITEM: BOX BOUNDS"))
  {
    return "expected 'ITEM: BOX BOUNDS'";
  }
  const std::string box = ReadBoxBounds(lines, line, s);
  if (!box.empty())
  {
    return box;
  }
  if (!NextNonEmpty(lines, line) || !StartsWith(line, "ITEM: ATOMS"))
  {
    return "expected 'ITEM: ATOMS' and the column names";
  }
  s.Columns = Split(line.substr(std::strlen("ITEM: ATOMS")));
  if (s.Columns.empty() && s.NumberOfAtoms > 0)
  {
    return "ITEM: ATOMS names no columns";
  }
  return std::string();
}

// Index the snapshots of one file. Returns false (with a message) when the file cannot be used
// at all; a bad or truncated snapshot after good ones ends the file with a warning in warning.
bool IndexFile(const std::string& name, int fileIndex, std::vector<Snapshot>& steps,
  std::string& error, std::string& warning)
{
  InputFile file;
  if (!file.Open(name))
  {
    error = name + ": cannot open the file";
    return false;
  }
  const std::string notText = CheckText(file, name);
  if (!notText.empty())
  {
    error = notText;
    return false;
  }
  const auto size = vtksys::SystemTools::FileLength(name);
  LineReader lines(file, static_cast<size_t>(std::min<decltype(size)>(size + 1, 1 << 20)));
  std::string line;
  const size_t first = steps.size();
  auto fail = [&](const std::string& what) -> bool
  {
    const std::string where = name + ", line " + std::to_string(lines.LineNumber()) + ": " + what;
    if (steps.size() == first)
    {
      error = where;
      return false;
    }
    warning +=
      where + "; the " + std::to_string(steps.size() - first) + " snapshot(s) before it are read. ";
    return true;
  };
  while (NextNonEmpty(lines, line))
  {
    Snapshot s;
    s.File = fileIndex;
    const std::string problem = ReadHeader(lines, line, s);
    if (!problem.empty())
    {
      return fail(problem);
    }
    s.AtomsOffset = lines.Offset();
    s.AtomsLine = lines.LineNumber() + 1;
    const long long skipped = lines.Skip(s.NumberOfAtoms);
    if (skipped < s.NumberOfAtoms)
    {
      return fail("the file ends here, in the snapshot of timestep " + std::to_string(s.Timestep) +
        " (atoms from line " + std::to_string(s.AtomsLine) + "), which is truncated: " +
        std::to_string(skipped) + " of " + std::to_string(s.NumberOfAtoms) + " atom lines");
    }
    s.EndOffset = lines.Offset();
    steps.push_back(std::move(s));
  }
  if (steps.size() == first)
  {
    error = name + ": no snapshot (no 'ITEM: TIMESTEP' line)";
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
int vtkLAMMPSDumpReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInternals& internals = *this->Internals;
  if (internals.FileNames.empty())
  {
    vtkErrorMacro(<< "No file name.");
    return 0;
  }
  // (re)build the index when the files or their sizes changed
  std::vector<long long> sizes;
  for (const std::string& name : internals.FileNames)
  {
    sizes.push_back(FileStamp(name));
  }
  if (internals.IndexedFiles != internals.FileNames || internals.IndexedSizes != sizes)
  {
    internals.Steps.clear();
    internals.IndexedFiles.clear();
    std::string warnings;
    for (size_t i = 0; i < internals.FileNames.size(); ++i)
    {
      std::string error;
      std::string warning;
      if (!IndexFile(internals.FileNames[i], static_cast<int>(i), internals.Steps, error, warning))
      {
        vtkErrorMacro(<< error);
      }
      warnings += warning;
      this->UpdateProgress(0.1 * (i + 1) / internals.FileNames.size());
    }
    if (!warnings.empty())
    {
      vtkWarningMacro(<< warnings);
    }
    // order by timestep; a timestep that appears twice is read from its first file
    std::stable_sort(internals.Steps.begin(), internals.Steps.end(),
      [](const Snapshot& a, const Snapshot& b) { return a.Timestep < b.Timestep; });
    const size_t before = internals.Steps.size();
    internals.Steps.erase(
      std::unique(internals.Steps.begin(), internals.Steps.end(),
        [](const Snapshot& a, const Snapshot& b) { return a.Timestep == b.Timestep; }),
      internals.Steps.end());
    if (internals.Steps.size() != before)
    {
      vtkWarningMacro(<< (before - internals.Steps.size())
                      << " snapshot(s) repeat a timestep of an earlier one and are skipped.");
    }
    internals.IndexedFiles = internals.FileNames;
    internals.IndexedSizes = sizes;
  }
  if (internals.Steps.empty())
  {
    return 0;
  }
  internals.TimeValues.clear();
  for (const Snapshot& s : internals.Steps)
  {
    internals.TimeValues.push_back(
      this->DeltaTime > 0.0 ? s.Timestep * this->DeltaTime : static_cast<double>(s.Timestep));
  }
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), internals.TimeValues.data(),
      static_cast<int>(internals.TimeValues.size()));
    const double range[2] = { internals.TimeValues.front(), internals.TimeValues.back() };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

//------------------------------------------------------------------------------
// The state of one RequestData: the snapshot read, its file, the plan of its columns and the
// outputs being filled.
struct vtkLAMMPSDumpReader::vtkRequestState
{
  vtkRequestState(const Snapshot& step, const std::string& fileName)
    : Step(step)
    , FileName(fileName)
    , N(step.NumberOfAtoms)
  {
  }

  const Snapshot& Step;
  const std::string& FileName;
  const long long N; // atoms
  InputFile File;
  Plan Columns;
  vtkNew<vtkPoints> Points;
  Outputs Out;
  std::vector<vtkIdType> Order; // the atoms in id order (SortById); empty: as read
};

//------------------------------------------------------------------------------
namespace
{
// The step of the requested time: the last one at or before it.
size_t RequestedStep(const std::vector<double>& timeValues, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  size_t step = 0;
  if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    const double t = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    const auto it = std::upper_bound(timeValues.begin(), timeValues.end(), t);
    step = it == timeValues.begin() ? 0 : static_cast<size_t>(it - timeValues.begin()) - 1;
  }
  return step;
}

// Split the complete lines data[0, complete) into pieces at line ends: the bounds of the pieces.
std::vector<size_t> SplitAtLineEnds(const char* data, size_t complete)
{
  const size_t pieces = std::max<size_t>(1, std::min<size_t>(complete / 65536, 256));
  std::vector<size_t> bounds(pieces + 1, complete);
  bounds[0] = 0;
  for (size_t i = 1; i < pieces; ++i)
  {
    const size_t guess = std::max(bounds[i - 1], complete * i / pieces);
    const char* nl = guess < complete
      ? static_cast<const char*>(std::memchr(data + guess, '\n', complete - guess))
      : nullptr;
    bounds[i] = nl ? static_cast<size_t>(nl - data) + 1 : complete;
  }
  return bounds;
}

// Count the lines of each piece, in parallel.
void CountLines(
  const char* data, const std::vector<size_t>& bounds, std::vector<long long>& lineCounts)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(lineCounts.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        long long count = 0;
        const char* p = data + bounds[i];
        const char* stop = data + bounds[i + 1];
        while (p < stop)
        {
          const char* nl = static_cast<const char*>(std::memchr(p, '\n', stop - p));
          ++count;
          p = nl ? nl + 1 : stop;
        }
        lineCounts[i] = count;
      }
    });
}

// Parse the complete lines data[0, complete) of one block in parallel pieces (with STDThread
// when threads is set) into the rows from row on, and move row past them. The first error, by
// row, goes to firstError.
void ParseBlock(const char* data, size_t complete, long long n, const std::vector<Target>& targets,
  bool threads, long long& row, ParseError& firstError, std::atomic<long long>& nonFinite)
{
  // split the complete lines into pieces at line ends, count the lines of each piece
  const std::vector<size_t> bounds = SplitAtLineEnds(data, complete);
  const size_t pieces = bounds.size() - 1;
  std::vector<long long> lineCounts(pieces, 0);
  std::vector<ParseError> errors(pieces);
  auto run = [&]()
  {
    CountLines(data, bounds, lineCounts);
    long long lines = 0;
    std::vector<long long> firstRows(pieces);
    for (size_t i = 0; i < pieces; ++i)
    {
      firstRows[i] = row + lines;
      lines += lineCounts[i];
    }
    if (row + lines > n)
    {
      firstError.Row = n;
      firstError.What = "more atom lines than ITEM: NUMBER OF ATOMS";
      return;
    }
    vtkSMPTools::For(0, static_cast<vtkIdType>(pieces),
      [&](vtkIdType begin, vtkIdType end)
      {
        long long localNonFinite = 0;
        for (vtkIdType i = begin; i < end; ++i)
        {
          ParseLines(data + bounds[i], data + bounds[i + 1], firstRows[i], targets, errors[i],
            localNonFinite);
        }
        nonFinite += localNonFinite;
      });
    row += lines;
  };
  if (threads)
  {
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ std::string("STDThread") }, run);
  }
  else
  {
    run();
  }
  for (const ParseError& e : errors)
  {
    if (e.Row >= 0 && (firstError.Row < 0 || e.Row < firstError.Row))
    {
      firstError = e;
    }
  }
}
}

//------------------------------------------------------------------------------
int vtkLAMMPSDumpReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInternals& internals = *this->Internals;
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* outline = vtkPolyData::GetData(outputVector, 1);
  if (internals.Steps.empty())
  {
    return 0;
  }
  // the step of the requested time, its time and its box
  const size_t step = RequestedStep(internals.TimeValues, outputVector);
  const Snapshot& s = internals.Steps[step];
  vtkRequestState state(s, internals.FileNames[s.File]);
  for (int port = 0; port < 2; ++port)
  {
    outputVector->GetInformationObject(port)->Set(
      vtkDataObject::DATA_TIME_STEP(), internals.TimeValues[step]);
  }
  outline->ShallowCopy(BoxOutline(s.SimulationBox));
  AddBoxFieldData(outline->GetFieldData(), s.SimulationBox, s.Timestep);

  if (!this->OpenAtoms(state))
  {
    return 0;
  }
  this->PlanColumns(state);
  AllocateOutputs(state);
  if (!this->ParseAtoms(state))
  {
    return 0;
  }
  MapPoints(state);
  MoveStrings(state);
  this->AddRadius(state);
  this->AddSemiAxes(state);
  this->OrderById(state);
  AssembleOutput(state, output);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
// Open the file at the first atom line of the step.
bool vtkLAMMPSDumpReader::OpenAtoms(vtkRequestState& state)
{
  if (!state.File.Open(state.FileName) || !state.File.Seek(state.Step.AtomsOffset))
  {
    vtkErrorMacro(<< state.FileName << ": cannot open or seek the file (was it changed?)");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// Where each column goes (MakePlan), with a warning when it differs from the last one.
void vtkLAMMPSDumpReader::PlanColumns(vtkRequestState& state)
{
  vtkInternals& internals = *this->Internals;
  const Snapshot& s = state.Step;
  // the first atom line decides which non-numeric columns hold strings
  std::vector<std::string> firstRow;
  if (state.N > 0)
  {
    LineReader lines(state.File,
      static_cast<size_t>(std::min<std::uint64_t>(s.EndOffset - s.AtomsOffset + 1, 1 << 16)));
    std::string line;
    lines.Next(line);
    firstRow = Split(line);
    state.File.Seek(s.AtomsOffset);
  }
  state.Columns = MakePlan(s.Columns, firstRow, this->PositionSource);
  const Plan& plan = state.Columns;
  if (!plan.Warning.empty() && plan.Warning != internals.LastWarning)
  {
    vtkWarningMacro(<< state.FileName << ": " << plan.Warning);
  }
  internals.LastWarning = plan.Warning;
}

//------------------------------------------------------------------------------
// Allocate the outputs: the points and one array per planned array, N tuples each.
void vtkLAMMPSDumpReader::AllocateOutputs(vtkRequestState& state)
{
  const long long n = state.N;
  const Plan& plan = state.Columns;
  Outputs& out = state.Out;
  vtkPoints* points = state.Points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(n));
  out.Points = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
  AdviseHugePages(out.Points, sizeof(double) * 3 * static_cast<size_t>(n));
  if (plan.PointFlavour < 0)
  {
    std::fill(out.Points, out.Points + 3 * n, 0.0);
  }
  out.Strings.resize(plan.Arrays.size());
  for (size_t a = 0; a < plan.Arrays.size(); ++a)
  {
    const ArrayPlan& ap = plan.Arrays[a];
    // a numeric array of N tuples, parsed straight into its contiguous storage
    auto numeric = [&](auto typed)
    {
      typed->SetNumberOfComponents(ap.Components);
      typed->SetNumberOfTuples(static_cast<vtkIdType>(n));
      void* storage = typed->GetPointer(0);
      out.Arrays.push_back(storage);
      AdviseHugePages(storage,
        static_cast<size_t>(typed->GetDataTypeSize()) * ap.Components * static_cast<size_t>(n));
      return vtkSmartPointer<vtkAbstractArray>(typed);
    };
    vtkSmartPointer<vtkAbstractArray> array;
    switch (ap.Type)
    {
      case Kind::Float:
        array = numeric(vtkSmartPointer<vtkFloatArray>::New());
        break;
      case Kind::Int:
        array = numeric(vtkSmartPointer<vtkIntArray>::New());
        break;
      case Kind::IdType:
        array = numeric(vtkSmartPointer<vtkIdTypeArray>::New());
        break;
      case Kind::String:
      case Kind::Point:
        array = vtkSmartPointer<vtkStringArray>::New();
        array->SetNumberOfComponents(ap.Components);
        out.Strings[a].resize(static_cast<size_t>(n));
        out.Arrays.push_back(&out.Strings[a]);
        break;
    }
    array->SetName(ap.Name.c_str());
    out.Objects.push_back(array);
  }
}

//------------------------------------------------------------------------------
// Parse the atom lines block by block, each block in parallel (ParseBlock), straight into the
// outputs. Returns false, with an error, on a bad line or a short read.
bool vtkLAMMPSDumpReader::ParseAtoms(vtkRequestState& state)
{
  const Snapshot& s = state.Step;
  const std::string& fileName = state.FileName;
  const long long n = state.N;
  InputFile& file = state.File;
  const std::vector<Target> targets = MakeTargets(state.Columns, state.Out);

  // parse the atom lines block by block, each block in parallel
  const std::uint64_t total = s.EndOffset - s.AtomsOffset;
  std::vector<char> buffer(static_cast<size_t>(
    std::min<std::uint64_t>(total, static_cast<std::uint64_t>(this->BlockSize)) + 1));
  size_t carry = 0;
  std::uint64_t consumed = 0;
  long long row = 0;
  ParseError firstError;
  std::atomic<long long> nonFinite(0);
  const bool threads = std::string(vtkSMPTools::GetBackend()) == "Sequential" &&
    !std::getenv("VTK_SMP_BACKEND_IN_USE");
  while (consumed < total || carry > 0)
  {
    const size_t want =
      static_cast<size_t>(std::min<std::uint64_t>(total - consumed, buffer.size() - 1 - carry));
    const long long got = want > 0 ? file.Read(buffer.data() + carry, want) : 0;
    if (got < 0 || static_cast<size_t>(got) != want)
    {
      vtkErrorMacro(<< fileName << ": the file ends or cannot be read before line "
                    << s.AtomsLine + row << " (was it changed?)");
      return false;
    }
    consumed += static_cast<std::uint64_t>(got);
    const size_t length = carry + static_cast<size_t>(got);
    // complete lines: up to the last line end, or everything at the end of the section
    size_t complete = length;
    if (consumed < total)
    {
      const char* last = static_cast<const char*>(memrchr(buffer.data(), '\n', length));
      if (!last)
      {
        if (length >= buffer.size() - 1)
        {
          buffer.resize(buffer.size() * 2); // a line longer than a block
        }
        carry = length;
        continue;
      }
      complete = static_cast<size_t>(last - buffer.data()) + 1;
    }
    ParseBlock(buffer.data(), complete, n, targets, threads, row, firstError, nonFinite);
    if (firstError.Row >= 0)
    {
      break;
    }
    // keep the partial last line for the next block
    carry = length - complete;
    std::memmove(buffer.data(), buffer.data() + complete, carry);
    if (consumed >= total)
    {
      carry = 0;
    }
    this->UpdateProgress(
      0.1 + 0.85 * static_cast<double>(consumed) / std::max<std::uint64_t>(total, 1));
  }
  if (firstError.Row < 0 && row != n)
  {
    firstError.Row = row;
    firstError.What = "expected " + std::to_string(n) + " atom lines, found " + std::to_string(row);
  }
  if (firstError.Row >= 0)
  {
    vtkErrorMacro(<< fileName << ", line " << s.AtomsLine + firstError.Row << ": "
                  << firstError.What << " (timestep " << s.Timestep << ")");
    return false;
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro(<< fileName << ", timestep " << s.Timestep << ": " << nonFinite.load()
                    << " NaN or infinite value(s).");
  }
  return true;
}

//------------------------------------------------------------------------------
// Points: scaled coordinates through the box, wrapped ones unwrapped with the image flags.
void vtkLAMMPSDumpReader::MapPoints(vtkRequestState& state)
{
  const Plan& plan = state.Columns;
  if (!plan.Scaled && !plan.UnwrapWithImage)
  {
    return;
  }
  const Box& box = state.Step.SimulationBox;
  const double l[3] = { box.Length(0), box.Length(1), box.Length(2) };
  const double xy = box.Tilt[0];
  const double xz = box.Tilt[1];
  const double yz = box.Tilt[2];
  const int* image =
    plan.UnwrapWithImage ? static_cast<int*>(state.Out.Arrays[plan.ImageArray]) : nullptr;
  double* p = state.Out.Points;
  vtkSMPTools::For(0, static_cast<vtkIdType>(state.N),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double* x = p + 3 * i;
        if (plan.Scaled)
        {
          const double sx = x[0];
          const double sy = x[1];
          const double sz = x[2];
          x[0] = box.Lo[0] + sx * l[0] + sy * xy + sz * xz;
          x[1] = box.Lo[1] + sy * l[1] + sz * yz;
          x[2] = box.Lo[2] + sz * l[2];
        }
        else
        {
          const int* im = image + 3 * i;
          x[0] += im[0] * l[0] + im[1] * xy + im[2] * xz;
          x[1] += im[1] * l[1] + im[2] * yz;
          x[2] += im[2] * l[2];
        }
      }
    });
}

//------------------------------------------------------------------------------
// String columns into their arrays.
void vtkLAMMPSDumpReader::MoveStrings(vtkRequestState& state)
{
  const Plan& plan = state.Columns;
  Outputs& out = state.Out;
  const long long n = state.N;
  for (size_t a = 0; a < plan.Arrays.size(); ++a)
  {
    if (plan.Arrays[a].Type == Kind::String)
    {
      auto* strings = vtkStringArray::SafeDownCast(out.Objects[a]);
      strings->SetNumberOfValues(static_cast<vtkIdType>(n));
      for (long long i = 0; i < n; ++i)
      {
        strings->SetValue(static_cast<vtkIdType>(i), std::move(out.Strings[a][i]));
      }
    }
  }
}

//------------------------------------------------------------------------------
// Radius (GenerateRadius): the radius column as read, or an array from half the diameter
// column, the per-type table or DefaultRadius.
void vtkLAMMPSDumpReader::AddRadius(vtkRequestState& state)
{
  const Plan& plan = state.Columns;
  Outputs& out = state.Out;
  const long long n = state.N;
  if (!this->GenerateRadius || plan.RadiusArray >= 0)
  {
    return; // no radius, or the radius column, already an output array
  }
  vtkSmartPointer<vtkFloatArray> radius = vtkSmartPointer<vtkFloatArray>::New();
  radius->SetName("radius");
  radius->SetNumberOfTuples(static_cast<vtkIdType>(n));
  float* r = radius->GetPointer(0);
  AdviseHugePages(r, sizeof(float) * static_cast<size_t>(n));
  if (plan.DiameterArray >= 0)
  {
    const float* d = static_cast<const float*>(out.Arrays[plan.DiameterArray]);
    for (long long i = 0; i < n; ++i)
    {
      r[i] = 0.5f * d[i];
    }
  }
  else if (plan.TypeArray >= 0 && n > 0)
  {
    this->RadiiFromTypes(static_cast<const int*>(out.Arrays[plan.TypeArray]), n, r);
  }
  else
  {
    std::fill(r, r + n, static_cast<float>(this->DefaultRadius));
  }
  out.Objects.push_back(radius);
}

//------------------------------------------------------------------------------
// Semi-axes of ellipsoids: half the "shape" array (LAMMPS's shapex/y/z are diameters), as the
// 3-component array "semi_axes" that vtkParticleSphereMapper's Shape Ellipsoid takes.
void vtkLAMMPSDumpReader::AddSemiAxes(vtkRequestState& state)
{
  const Plan& plan = state.Columns;
  if (plan.ShapeArray < 0)
  {
    return;
  }
  const long long n = state.N;
  vtkSmartPointer<vtkFloatArray> axes = vtkSmartPointer<vtkFloatArray>::New();
  axes->SetName("semi_axes");
  axes->SetNumberOfComponents(3);
  axes->SetNumberOfTuples(static_cast<vtkIdType>(n));
  float* a = axes->GetPointer(0);
  const float* d = static_cast<const float*>(state.Out.Arrays[plan.ShapeArray]);
  for (long long i = 0; i < 3 * n; ++i)
  {
    a[i] = 0.5f * d[i];
  }
  state.Out.Objects.push_back(axes);
}

//------------------------------------------------------------------------------
// The radii r[0, n) of the types type[0, n) (n > 0), from the per-type table.
void vtkLAMMPSDumpReader::RadiiFromTypes(const int* type, long long n, float* r)
{
  // a table over the types present (LAMMPS types are small positive integers)
  const auto range = std::minmax_element(type, type + n);
  const long long lo = *range.first;
  const long long span = static_cast<long long>(*range.second) - lo + 1;
  if (span <= (1 << 20))
  {
    std::vector<float> table(static_cast<size_t>(span));
    for (long long t = 0; t < span; ++t)
    {
      table[t] = static_cast<float>(this->GetTypeRadius(static_cast<int>(lo + t)));
    }
    vtkSMPTools::For(0, static_cast<vtkIdType>(n),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          r[i] = table[static_cast<size_t>(type[i] - lo)];
        }
      });
  }
  else
  {
    for (long long i = 0; i < n; ++i)
    {
      r[i] = static_cast<float>(this->GetTypeRadius(type[i]));
    }
  }
}

//------------------------------------------------------------------------------
// Order by id (SortById): the order of the atoms when the ids are not sorted already.
void vtkLAMMPSDumpReader::OrderById(vtkRequestState& state)
{
  const Plan& plan = state.Columns;
  const long long n = state.N;
  std::vector<vtkIdType>& order = state.Order;
  if (this->SortById && plan.IdArray >= 0 && n > 1)
  {
    const vtkIdType* ids = static_cast<const vtkIdType*>(state.Out.Arrays[plan.IdArray]);
    if (!std::is_sorted(ids, ids + n))
    {
      order.resize(static_cast<size_t>(n));
      std::iota(order.begin(), order.end(), 0);
      vtkSMPTools::Sort(
        order.begin(), order.end(), [ids](vtkIdType a, vtkIdType b) { return ids[a] < ids[b]; });
    }
  }
  else if (this->SortById && plan.IdArray < 0 && n > 0)
  {
    vtkWarningMacro(<< state.FileName << ": SortById is on, but the dump has no id column.");
  }
}

//------------------------------------------------------------------------------
// The output: the points and the arrays (in id order when sorted), a vertex per atom, the box.
void vtkLAMMPSDumpReader::AssembleOutput(vtkRequestState& state, vtkPolyData* output)
{
  const std::vector<vtkIdType>& order = state.Order;
  vtkPoints* points = state.Points;
  if (!order.empty())
  {
    vtkSmartPointer<vtkAbstractArray> sorted = Permuted(points->GetData(), order);
    points->SetData(vtkDataArray::SafeDownCast(sorted));
  }
  output->SetPoints(points);
  for (auto& array : state.Out.Objects)
  {
    output->GetPointData()->AddArray(order.empty() ? array : Permuted(array, order));
  }
  vtkSmartPointer<vtkCellArray> verts = VertexCells(static_cast<vtkIdType>(state.N));
  output->SetVerts(verts);
  AddBoxFieldData(output->GetFieldData(), state.Step.SimulationBox, state.Step.Timestep);
}

//------------------------------------------------------------------------------
void vtkLAMMPSDumpReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileNames: " << this->Internals->FileNames.size() << "\n";
  for (const std::string& name : this->Internals->FileNames)
  {
    os << indent.GetNextIndent() << name << "\n";
  }
  os << indent << "DeltaTime: " << this->DeltaTime << "\n";
  os << indent << "PositionSource: " << this->PositionSource << "\n";
  os << indent << "BlockSize: " << this->BlockSize << "\n";
  os << indent << "NumberOfSteps: " << this->Internals->Steps.size() << "\n";
}
