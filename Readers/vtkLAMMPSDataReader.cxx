#include "vtkLAMMPSDataReader.h"
#include "vtkParticleReaderInternals.h"

#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <cmath>
#include <map>
#include <memory>
#include <unordered_map>

vtkStandardNewMacro(vtkLAMMPSDataReader);

using namespace prReader;

namespace
{
// Columns of an Atoms line after the atom id, per atom style (LAMMPS read_data manual).
const std::map<std::string, std::vector<std::string>>& AtomStyles()
{
  static const std::map<std::string, std::vector<std::string>> styles = {
    { "atomic", { "type", "x", "y", "z" } },
    { "charge", { "type", "q", "x", "y", "z" } },
    { "bond", { "mol", "type", "x", "y", "z" } },
    { "angle", { "mol", "type", "x", "y", "z" } },
    { "molecular", { "mol", "type", "x", "y", "z" } },
    { "full", { "mol", "type", "q", "x", "y", "z" } },
    { "sphere", { "type", "diameter", "density", "x", "y", "z" } },
    { "dipole", { "type", "q", "x", "y", "z", "mux", "muy", "muz" } },
  };
  return styles;
}

// A line without its comment, and the comment.
std::string StripComment(const std::string& line, std::string* comment = nullptr)
{
  const size_t hash = line.find('#');
  if (comment)
  {
    *comment = hash == std::string::npos ? std::string() : line.substr(hash + 1);
  }
  return hash == std::string::npos ? line : line.substr(0, hash);
}

bool IsNumber(const std::string& word)
{
  double value;
  return ParseWord(word, value);
}
}

//------------------------------------------------------------------------------
vtkLAMMPSDataReader::vtkLAMMPSDataReader() = default;

vtkLAMMPSDataReader::~vtkLAMMPSDataReader() = default;

//------------------------------------------------------------------------------
int vtkLAMMPSDataReader::CanReadFile(const char* fileName)
{
  InputFile file;
  if (!fileName || !file.Open(fileName))
  {
    return 0;
  }
  LineReader lines(file, 16384);
  std::string line;
  if (!lines.Next(line) || line.find('\0') != std::string::npos) // the title
  {
    return 0;
  }
  for (int i = 0; i < 40 && lines.Next(line); ++i)
  {
    const std::vector<std::string> words = Split(StripComment(line));
    if (words.size() == 2 && words[1] == "atoms" && IsNumber(words[0]))
    {
      return 1;
    }
    if (!words.empty() && !IsNumber(words[0]))
    {
      return 0; // a section before "N atoms"
    }
  }
  return 0;
}

//------------------------------------------------------------------------------
// What RequestData reads, stage by stage: the file and its lines, the header, and the arrays the
// sections fill.
struct vtkLAMMPSDataReader::vtkParse
{
  explicit vtkParse(const std::string& name)
    : Name(name)
  {
  }

  // The next data line of the current section, split into words; false at the next section's
  // header (then in Section and SectionComment) or at the end of the file.
  bool NextData(std::vector<std::string>& out)
  {
    while (this->Lines->Next(this->Line))
    {
      std::string comment;
      out = Split(StripComment(this->Line, &comment));
      if (out.empty())
      {
        continue;
      }
      if (!IsNumber(out[0]))
      {
        this->Section = out[0];
        for (size_t k = 1; k < out.size(); ++k)
        {
          this->Section += " " + out[k];
        }
        this->SectionComment = comment;
        return false;
      }
      return true;
    }
    return false;
  }

  std::string Name;
  InputFile File;
  std::unique_ptr<LineReader> Lines;
  std::string Line;
  // the header
  long long Timestep = 0;
  long long Atoms = -1;
  long long Types = 0;
  Box Cell;
  // the section header that ended the last section ("": the end of the file)
  std::string Section;
  std::string SectionComment;
  // the sections' data, N atoms
  vtkIdType N = 0;
  std::vector<std::string> Columns;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkIdTypeArray> Ids;
  std::map<std::string, vtkSmartPointer<vtkDataArray>> Arrays;
  vtkSmartPointer<vtkIntArray> Image;
  vtkSmartPointer<vtkFloatArray> Velocity;
  std::map<long long, double> Masses;
  bool HaveAtoms = false;
  std::vector<std::string> Words;
};

//------------------------------------------------------------------------------
int vtkLAMMPSDataReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* outline = vtkPolyData::GetData(outputVector, 1);
  if (this->FileName.empty())
  {
    vtkErrorMacro(<< "No file name.");
    return 0;
  }
  vtkParse p(this->FileName);
  if (!this->OpenFile(p) || !this->ReadTitle(p) || !this->ReadHeader(p) || !this->ReadSections(p))
  {
    return 0;
  }
  this->UnwrapPositions(p);
  this->AddDerivedArrays(p);
  this->Assemble(p, output, outline);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLAMMPSDataReader::Fail(const vtkParse& p, const std::string& what)
{
  vtkErrorMacro(<< p.Name << ", line " << p.Lines->LineNumber() << ": " << what);
  return false;
}

//------------------------------------------------------------------------------
bool vtkLAMMPSDataReader::OpenFile(vtkParse& p)
{
  if (!p.File.Open(p.Name))
  {
    vtkErrorMacro(<< p.Name << ": cannot open the file");
    return false;
  }
  p.Lines.reset(new LineReader(p.File));
  return true;
}

//------------------------------------------------------------------------------
bool vtkLAMMPSDataReader::ReadTitle(vtkParse& p)
{
  // title, e.g. "LAMMPS data file via write_data, version ..., timestep = 200, units = lj"
  if (!p.Lines->Next(p.Line))
  {
    vtkErrorMacro(<< p.Name << ": the file is empty");
    return false;
  }
  if (p.Line.find('\0') != std::string::npos)
  {
    return this->Fail(p, "a binary file, not a LAMMPS data file");
  }
  {
    const size_t at = p.Line.find("timestep =");
    if (at != std::string::npos)
    {
      const std::vector<std::string> words = Split(p.Line.substr(at + 10));
      if (!words.empty())
      {
        std::string digits = words[0];
        while (!digits.empty() && !std::isdigit(static_cast<unsigned char>(digits.back())))
        {
          digits.pop_back(); // "200,"
        }
        ParseInt64(digits.data(), digits.data() + digits.size(), p.Timestep);
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLAMMPSDataReader::ReadHeader(vtkParse& p)
{
  // header
  while (p.Lines->Next(p.Line))
  {
    std::string comment;
    const std::vector<std::string> words = Split(StripComment(p.Line, &comment));
    if (words.empty())
    {
      continue;
    }
    if (!IsNumber(words[0]))
    {
      p.Section = words[0];
      for (size_t k = 1; k < words.size(); ++k)
      {
        p.Section += " " + words[k];
      }
      p.SectionComment = comment;
      break;
    }
    double a, b, c;
    if (words.size() == 2 && words[1] == "atoms")
    {
      ParseInt64(words[0].data(), words[0].data() + words[0].size(), p.Atoms);
    }
    else if (words.size() == 3 && words[1] == "atom" && words[2] == "types")
    {
      ParseInt64(words[0].data(), words[0].data() + words[0].size(), p.Types);
    }
    else if (words.size() == 4 && ParseWord(words[0], a) && ParseWord(words[1], b) &&
      (words[2] == "xlo" || words[2] == "ylo" || words[2] == "zlo"))
    {
      const int k = words[2][0] - 'x';
      p.Cell.Lo[k] = a;
      p.Cell.Hi[k] = b;
    }
    else if (words.size() == 6 && words[3] == "xy" && ParseWord(words[0], a) &&
      ParseWord(words[1], b) && ParseWord(words[2], c))
    {
      p.Cell.Tilt[0] = a;
      p.Cell.Tilt[1] = b;
      p.Cell.Tilt[2] = c;
      p.Cell.Triclinic = true;
    }
  }
  if (p.Atoms < 0)
  {
    return this->Fail(p, "no 'N atoms' line in the header: not a LAMMPS data file?");
  }

  // the arrays of the N atoms the sections fill
  p.N = static_cast<vtkIdType>(p.Atoms);
  p.Points->SetDataTypeToDouble();
  p.Points->SetNumberOfPoints(p.N);
  p.Ids->SetName("id");
  p.Ids->SetNumberOfTuples(p.N);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLAMMPSDataReader::ReadSections(vtkParse& p)
{
  while (!p.Section.empty())
  {
    const std::string current = p.Section;
    const std::string comment = p.SectionComment;
    p.Section.clear();
    bool ok = true;
    if (current == "Atoms")
    {
      ok = this->ReadAtoms(p, comment);
    }
    else if (current == "Velocities")
    {
      ok = this->ReadVelocities(p);
    }
    else if (current == "Masses")
    {
      ok = this->ReadMasses(p);
    }
    else
    {
      while (p.NextData(p.Words))
      {
      }
    }
    if (!ok)
    {
      return false;
    }
  }
  if (!p.HaveAtoms && p.N > 0)
  {
    return this->Fail(p, "the file has no Atoms section");
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLAMMPSDataReader::ReadAtoms(vtkParse& p, const std::string& comment)
{
  std::string style = Split(comment).empty() ? this->AtomStyle : Split(comment)[0];
  const auto it = AtomStyles().find(style);
  if (it == AtomStyles().end())
  {
    std::string known;
    for (const auto& item : AtomStyles())
    {
      known += " " + item.first;
    }
    return this->Fail(p, "atom style '" + style + "' is not supported (supported:" + known + ")");
  }
  p.Columns = it->second;
  for (const std::string& c : p.Columns)
  {
    if (c == "x" || c == "y" || c == "z" || c == "mux" || c == "muy" || c == "muz")
    {
      continue;
    }
    vtkSmartPointer<vtkDataArray> a;
    if (c == "type" || c == "mol")
    {
      a = vtkSmartPointer<vtkIntArray>::New();
    }
    else
    {
      a = vtkSmartPointer<vtkFloatArray>::New();
    }
    a->SetName(c.c_str());
    a->SetNumberOfTuples(p.N);
    p.Arrays[c] = a;
  }
  vtkSmartPointer<vtkFloatArray> mu;
  if (style == "dipole")
  {
    mu = vtkSmartPointer<vtkFloatArray>::New();
    mu->SetName("mu");
    mu->SetNumberOfComponents(3);
    mu->SetNumberOfTuples(p.N);
    p.Arrays["mu"] = mu;
  }
  const size_t base = p.Columns.size() + 1;
  for (vtkIdType i = 0; i < p.N; ++i)
  {
    if (!p.NextData(p.Words))
    {
      return this->Fail(p,
        "the Atoms section ends after " + std::to_string(i) + " of " + std::to_string(p.Atoms) +
          " atoms");
    }
    if (p.Words.size() != base && p.Words.size() != base + 3)
    {
      return this->Fail(p,
        std::to_string(p.Words.size()) + " values where atom style '" + style + "' has " +
          std::to_string(base) + " (or " + std::to_string(base + 3) + " with image flags)");
    }
    long long id;
    if (!ParseInt64(p.Words[0].data(), p.Words[0].data() + p.Words[0].size(), id))
    {
      return this->Fail(p, "the atom id '" + p.Words[0] + "' is not an integer");
    }
    p.Ids->SetValue(i, static_cast<vtkIdType>(id));
    double x[3] = { 0, 0, 0 };
    for (size_t c = 0; c < p.Columns.size(); ++c)
    {
      const std::string& word = p.Words[c + 1];
      const std::string& col = p.Columns[c];
      double value;
      long long integer;
      const bool isInt = col == "type" || col == "mol";
      if (isInt ? !ParseInt64(word.data(), word.data() + word.size(), integer)
                : !ParseWord(word, value))
      {
        return this->Fail(
          p, "'" + word + "' (" + col + ") is not " + (isInt ? "an integer" : "a number"));
      }
      if (col == "x" || col == "y" || col == "z")
      {
        x[col[0] - 'x'] = value;
      }
      else if (col == "mux" || col == "muy" || col == "muz")
      {
        mu->SetComponent(i, col[2] - 'x', value);
      }
      else
      {
        p.Arrays[col]->SetComponent(i, 0, isInt ? static_cast<double>(integer) : value);
      }
    }
    if (p.Words.size() == base + 3)
    {
      if (!p.Image)
      {
        p.Image = vtkSmartPointer<vtkIntArray>::New();
        p.Image->SetName("image");
        p.Image->SetNumberOfComponents(3);
        p.Image->SetNumberOfTuples(p.N);
        p.Image->FillValue(0);
      }
      for (int k = 0; k < 3; ++k)
      {
        long long flag;
        const std::string& word = p.Words[base + k];
        if (!ParseInt64(word.data(), word.data() + word.size(), flag))
        {
          return this->Fail(p, "the image flag '" + word + "' is not an integer");
        }
        p.Image->SetTypedComponent(i, k, static_cast<int>(flag));
      }
    }
    p.Points->SetPoint(i, x);
  }
  p.HaveAtoms = true;
  if (!p.Section.empty() || p.NextData(p.Words))
  {
    if (p.Section.empty())
    {
      return this->Fail(p,
        "more lines in the Atoms section than the header's " + std::to_string(p.Atoms) + " atoms");
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLAMMPSDataReader::ReadVelocities(vtkParse& p)
{
  if (!p.HaveAtoms)
  {
    return this->Fail(p, "Velocities before Atoms");
  }
  std::unordered_map<long long, vtkIdType> row;
  row.reserve(static_cast<size_t>(p.N));
  for (vtkIdType i = 0; i < p.N; ++i)
  {
    row[p.Ids->GetValue(i)] = i;
  }
  p.Velocity = vtkSmartPointer<vtkFloatArray>::New();
  p.Velocity->SetName("velocity");
  p.Velocity->SetNumberOfComponents(3);
  p.Velocity->SetNumberOfTuples(p.N);
  p.Velocity->FillValue(0.0f);
  while (p.NextData(p.Words))
  {
    long long id;
    double v[3];
    if (p.Words.size() < 4 ||
      !ParseInt64(p.Words[0].data(), p.Words[0].data() + p.Words[0].size(), id) ||
      !ParseWord(p.Words[1], v[0]) || !ParseWord(p.Words[2], v[1]) || !ParseWord(p.Words[3], v[2]))
    {
      return this->Fail(p, "expected 'id vx vy vz' in the Velocities section");
    }
    const auto it = row.find(id);
    if (it == row.end())
    {
      return this->Fail(p, "velocity of atom " + std::to_string(id) + ", which is not in Atoms");
    }
    p.Velocity->SetTuple(it->second, v);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLAMMPSDataReader::ReadMasses(vtkParse& p)
{
  while (p.NextData(p.Words))
  {
    long long type;
    double mass;
    if (p.Words.size() < 2 ||
      !ParseInt64(p.Words[0].data(), p.Words[0].data() + p.Words[0].size(), type) ||
      !ParseWord(p.Words[1], mass))
    {
      return this->Fail(p, "expected 'type mass' in the Masses section");
    }
    p.Masses[type] = mass;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLAMMPSDataReader::UnwrapPositions(vtkParse& p)
{
  // unwrapped positions, radius, mass
  if (this->PositionSource == UNWRAPPED)
  {
    if (!p.Image)
    {
      vtkWarningMacro(<< p.Name << ": no image flags in Atoms: the positions stay wrapped.");
    }
    else
    {
      const double l[3] = { p.Cell.Length(0), p.Cell.Length(1), p.Cell.Length(2) };
      for (vtkIdType i = 0; i < p.N; ++i)
      {
        double x[3];
        p.Points->GetPoint(i, x);
        int im[3];
        p.Image->GetTypedTuple(i, im);
        x[0] += im[0] * l[0] + im[1] * p.Cell.Tilt[0] + im[2] * p.Cell.Tilt[1];
        x[1] += im[1] * l[1] + im[2] * p.Cell.Tilt[2];
        x[2] += im[2] * l[2];
        p.Points->SetPoint(i, x);
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkLAMMPSDataReader::AddDerivedArrays(vtkParse& p)
{
  vtkIntArray* type =
    vtkIntArray::SafeDownCast(p.Arrays.count("type") ? p.Arrays["type"] : nullptr);
  if (this->GenerateRadius)
  {
    vtkNew<vtkFloatArray> radius;
    radius->SetName("radius");
    radius->SetNumberOfTuples(p.N);
    vtkDataArray* diameter =
      p.Arrays.count("diameter") ? p.Arrays["diameter"].GetPointer() : nullptr;
    for (vtkIdType i = 0; i < p.N; ++i)
    {
      radius->SetValue(i,
        static_cast<float>(diameter ? 0.5 * diameter->GetComponent(i, 0)
            : type                  ? this->GetTypeRadius(type->GetValue(i))
                                    : this->DefaultRadius));
    }
    p.Arrays["radius"] = radius;
  }
  if (!p.Masses.empty() && type)
  {
    vtkNew<vtkFloatArray> mass;
    mass->SetName("mass");
    mass->SetNumberOfTuples(p.N);
    for (vtkIdType i = 0; i < p.N; ++i)
    {
      const auto it = p.Masses.find(type->GetValue(i));
      mass->SetValue(i, it == p.Masses.end() ? std::nanf("") : static_cast<float>(it->second));
    }
    p.Arrays["mass"] = mass;
  }
  if (p.Image)
  {
    p.Arrays["image"] = p.Image;
  }
  if (p.Velocity)
  {
    p.Arrays["velocity"] = p.Velocity;
  }
}

//------------------------------------------------------------------------------
void vtkLAMMPSDataReader::Assemble(vtkParse& p, vtkPolyData* output, vtkPolyData* outline)
{
  // output, optionally ordered by id
  std::vector<vtkIdType> order;
  if (this->SortById && p.N > 1)
  {
    order.resize(static_cast<size_t>(p.N));
    std::iota(order.begin(), order.end(), 0);
    const vtkIdType* id = p.Ids->GetPointer(0);
    std::stable_sort(
      order.begin(), order.end(), [id](vtkIdType a, vtkIdType b) { return id[a] < id[b]; });
  }
  auto place = [&order](vtkAbstractArray* a) -> vtkSmartPointer<vtkAbstractArray>
  { return order.empty() ? vtkSmartPointer<vtkAbstractArray>(a) : Permuted(a, order); };
  if (order.empty())
  {
    output->SetPoints(p.Points);
  }
  else
  {
    vtkNew<vtkPoints> sorted;
    sorted->SetData(vtkDataArray::SafeDownCast(Permuted(p.Points->GetData(), order)));
    output->SetPoints(sorted);
  }
  output->GetPointData()->AddArray(place(p.Ids));
  for (const auto& item : p.Arrays)
  {
    output->GetPointData()->AddArray(place(item.second));
  }
  output->SetVerts(VertexCells(p.N));
  AddBoxFieldData(output->GetFieldData(), p.Cell, p.Timestep);
  outline->ShallowCopy(BoxOutline(p.Cell));
  AddBoxFieldData(outline->GetFieldData(), p.Cell, p.Timestep);
}

//------------------------------------------------------------------------------
void vtkLAMMPSDataReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "AtomStyle: " << this->AtomStyle << "\n";
  os << indent << "PositionSource: " << this->PositionSource << "\n";
}
