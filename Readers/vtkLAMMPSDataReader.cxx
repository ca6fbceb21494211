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
int vtkLAMMPSDataReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* outline = vtkPolyData::GetData(outputVector, 1);
  const std::string& name = this->FileName;
  if (name.empty())
  {
    vtkErrorMacro(<< "No file name.");
    return 0;
  }
  InputFile file;
  if (!file.Open(name))
  {
    vtkErrorMacro(<< name << ": cannot open the file");
    return 0;
  }
  LineReader lines(file);
  auto fail = [&](const std::string& what)
  {
    vtkErrorMacro(<< name << ", line " << lines.LineNumber() << ": " << what);
    return 0;
  };

  // title, e.g. "LAMMPS data file via write_data, version ..., timestep = 200, units = lj"
  std::string line;
  if (!lines.Next(line))
  {
    vtkErrorMacro(<< name << ": the file is empty");
    return 0;
  }
  if (line.find('\0') != std::string::npos)
  {
    return fail("a binary file, not a LAMMPS data file");
  }
  long long timestep = 0;
  {
    const size_t at = line.find("timestep =");
    if (at != std::string::npos)
    {
      const std::vector<std::string> words = Split(line.substr(at + 10));
      if (!words.empty())
      {
        std::string digits = words[0];
        while (!digits.empty() && !std::isdigit(static_cast<unsigned char>(digits.back())))
        {
          digits.pop_back(); // "200,"
        }
        ParseInt64(digits.data(), digits.data() + digits.size(), timestep);
      }
    }
  }

  // header
  long long atoms = -1;
  long long types = 0;
  Box box;
  std::string section;
  std::string sectionComment;
  while (lines.Next(line))
  {
    std::string comment;
    const std::vector<std::string> words = Split(StripComment(line, &comment));
    if (words.empty())
    {
      continue;
    }
    if (!IsNumber(words[0]))
    {
      section = words[0];
      for (size_t k = 1; k < words.size(); ++k)
      {
        section += " " + words[k];
      }
      sectionComment = comment;
      break;
    }
    double a, b, c;
    if (words.size() == 2 && words[1] == "atoms")
    {
      ParseInt64(words[0].data(), words[0].data() + words[0].size(), atoms);
    }
    else if (words.size() == 3 && words[1] == "atom" && words[2] == "types")
    {
      ParseInt64(words[0].data(), words[0].data() + words[0].size(), types);
    }
    else if (words.size() == 4 && ParseWord(words[0], a) && ParseWord(words[1], b) &&
      (words[2] == "xlo" || words[2] == "ylo" || words[2] == "zlo"))
    {
      const int k = words[2][0] - 'x';
      box.Lo[k] = a;
      box.Hi[k] = b;
    }
    else if (words.size() == 6 && words[3] == "xy" && ParseWord(words[0], a) &&
      ParseWord(words[1], b) && ParseWord(words[2], c))
    {
      box.Tilt[0] = a;
      box.Tilt[1] = b;
      box.Tilt[2] = c;
      box.Triclinic = true;
    }
  }
  if (atoms < 0)
  {
    return fail("no 'N atoms' line in the header: not a LAMMPS data file?");
  }

  // sections
  const vtkIdType n = static_cast<vtkIdType>(atoms);
  std::vector<std::string> columns;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("id");
  ids->SetNumberOfTuples(n);
  std::map<std::string, vtkSmartPointer<vtkDataArray>> arrays;
  vtkSmartPointer<vtkIntArray> image;
  vtkSmartPointer<vtkFloatArray> velocity;
  std::map<long long, double> masses;
  bool haveAtoms = false;
  std::vector<std::string> words;
  while (!section.empty())
  {
    const std::string current = section;
    const std::string currentComment = sectionComment;
    section.clear();
    // the lines of this section up to the next section header (or the end)
    auto nextData = [&](std::vector<std::string>& out) -> bool
    {
      while (lines.Next(line))
      {
        std::string comment;
        out = Split(StripComment(line, &comment));
        if (out.empty())
        {
          continue;
        }
        if (!IsNumber(out[0]))
        {
          section = out[0];
          for (size_t k = 1; k < out.size(); ++k)
          {
            section += " " + out[k];
          }
          sectionComment = comment;
          return false;
        }
        return true;
      }
      return false;
    };
    if (current == "Atoms")
    {
      std::string style =
        Split(currentComment).empty() ? this->AtomStyle : Split(currentComment)[0];
      const auto it = AtomStyles().find(style);
      if (it == AtomStyles().end())
      {
        std::string known;
        for (const auto& item : AtomStyles())
        {
          known += " " + item.first;
        }
        return fail("atom style '" + style + "' is not supported (supported:" + known + ")");
      }
      columns = it->second;
      for (const std::string& c : columns)
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
        a->SetNumberOfTuples(n);
        arrays[c] = a;
      }
      vtkSmartPointer<vtkFloatArray> mu;
      if (style == "dipole")
      {
        mu = vtkSmartPointer<vtkFloatArray>::New();
        mu->SetName("mu");
        mu->SetNumberOfComponents(3);
        mu->SetNumberOfTuples(n);
        arrays["mu"] = mu;
      }
      const size_t base = columns.size() + 1;
      for (vtkIdType i = 0; i < n; ++i)
      {
        if (!nextData(words))
        {
          return fail("the Atoms section ends after " + std::to_string(i) + " of " +
            std::to_string(atoms) + " atoms");
        }
        if (words.size() != base && words.size() != base + 3)
        {
          return fail(std::to_string(words.size()) + " values where atom style '" + style +
            "' has " + std::to_string(base) + " (or " + std::to_string(base + 3) +
            " with image flags)");
        }
        long long id;
        if (!ParseInt64(words[0].data(), words[0].data() + words[0].size(), id))
        {
          return fail("the atom id '" + words[0] + "' is not an integer");
        }
        ids->SetValue(i, static_cast<vtkIdType>(id));
        double x[3] = { 0, 0, 0 };
        for (size_t c = 0; c < columns.size(); ++c)
        {
          const std::string& word = words[c + 1];
          const std::string& col = columns[c];
          double value;
          long long integer;
          const bool isInt = col == "type" || col == "mol";
          if (isInt ? !ParseInt64(word.data(), word.data() + word.size(), integer)
                    : !ParseWord(word, value))
          {
            return fail(
              "'" + word + "' (" + col + ") is not " + (isInt ? "an integer" : "a number"));
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
            arrays[col]->SetComponent(i, 0, isInt ? static_cast<double>(integer) : value);
          }
        }
        if (words.size() == base + 3)
        {
          if (!image)
          {
            image = vtkSmartPointer<vtkIntArray>::New();
            image->SetName("image");
            image->SetNumberOfComponents(3);
            image->SetNumberOfTuples(n);
            image->FillValue(0);
          }
          for (int k = 0; k < 3; ++k)
          {
            long long flag;
            const std::string& word = words[base + k];
            if (!ParseInt64(word.data(), word.data() + word.size(), flag))
            {
              return fail("the image flag '" + word + "' is not an integer");
            }
            image->SetTypedComponent(i, k, static_cast<int>(flag));
          }
        }
        points->SetPoint(i, x);
      }
      haveAtoms = true;
      if (!section.empty() || nextData(words))
      {
        if (section.empty())
        {
          return fail("more lines in the Atoms section than the header's " + std::to_string(atoms) +
            " atoms");
        }
      }
    }
    else if (current == "Velocities")
    {
      if (!haveAtoms)
      {
        return fail("Velocities before Atoms");
      }
      std::unordered_map<long long, vtkIdType> row;
      row.reserve(static_cast<size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
      {
        row[ids->GetValue(i)] = i;
      }
      velocity = vtkSmartPointer<vtkFloatArray>::New();
      velocity->SetName("velocity");
      velocity->SetNumberOfComponents(3);
      velocity->SetNumberOfTuples(n);
      velocity->FillValue(0.0f);
      while (nextData(words))
      {
        long long id;
        double v[3];
        if (words.size() < 4 ||
          !ParseInt64(words[0].data(), words[0].data() + words[0].size(), id) ||
          !ParseWord(words[1], v[0]) || !ParseWord(words[2], v[1]) || !ParseWord(words[3], v[2]))
        {
          return fail("expected 'id vx vy vz' in the Velocities section");
        }
        const auto it = row.find(id);
        if (it == row.end())
        {
          return fail("velocity of atom " + std::to_string(id) + ", which is not in Atoms");
        }
        velocity->SetTuple(it->second, v);
      }
    }
    else if (current == "Masses")
    {
      while (nextData(words))
      {
        long long type;
        double mass;
        if (words.size() < 2 ||
          !ParseInt64(words[0].data(), words[0].data() + words[0].size(), type) ||
          !ParseWord(words[1], mass))
        {
          return fail("expected 'type mass' in the Masses section");
        }
        masses[type] = mass;
      }
    }
    else
    {
      while (nextData(words))
      {
      }
    }
  }
  if (!haveAtoms && n > 0)
  {
    return fail("the file has no Atoms section");
  }

  // unwrapped positions, radius, mass
  if (this->PositionSource == UNWRAPPED)
  {
    if (!image)
    {
      vtkWarningMacro(<< name << ": no image flags in Atoms: the positions stay wrapped.");
    }
    else
    {
      const double l[3] = { box.Length(0), box.Length(1), box.Length(2) };
      for (vtkIdType i = 0; i < n; ++i)
      {
        double x[3];
        points->GetPoint(i, x);
        int im[3];
        image->GetTypedTuple(i, im);
        x[0] += im[0] * l[0] + im[1] * box.Tilt[0] + im[2] * box.Tilt[1];
        x[1] += im[1] * l[1] + im[2] * box.Tilt[2];
        x[2] += im[2] * l[2];
        points->SetPoint(i, x);
      }
    }
  }
  vtkIntArray* type = vtkIntArray::SafeDownCast(arrays.count("type") ? arrays["type"] : nullptr);
  if (this->GenerateRadius)
  {
    vtkNew<vtkFloatArray> radius;
    radius->SetName("radius");
    radius->SetNumberOfTuples(n);
    vtkDataArray* diameter = arrays.count("diameter") ? arrays["diameter"].GetPointer() : nullptr;
    for (vtkIdType i = 0; i < n; ++i)
    {
      radius->SetValue(i,
        static_cast<float>(diameter ? 0.5 * diameter->GetComponent(i, 0)
            : type                  ? this->GetTypeRadius(type->GetValue(i))
                                    : this->DefaultRadius));
    }
    arrays["radius"] = radius;
  }
  if (!masses.empty() && type)
  {
    vtkNew<vtkFloatArray> mass;
    mass->SetName("mass");
    mass->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const auto it = masses.find(type->GetValue(i));
      mass->SetValue(i, it == masses.end() ? std::nanf("") : static_cast<float>(it->second));
    }
    arrays["mass"] = mass;
  }
  if (image)
  {
    arrays["image"] = image;
  }
  if (velocity)
  {
    arrays["velocity"] = velocity;
  }

  // output, optionally ordered by id
  std::vector<vtkIdType> order;
  if (this->SortById && n > 1)
  {
    order.resize(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    const vtkIdType* id = ids->GetPointer(0);
    std::stable_sort(
      order.begin(), order.end(), [id](vtkIdType a, vtkIdType b) { return id[a] < id[b]; });
  }
  auto place = [&order](vtkAbstractArray* a) -> vtkSmartPointer<vtkAbstractArray>
  { return order.empty() ? vtkSmartPointer<vtkAbstractArray>(a) : Permuted(a, order); };
  if (order.empty())
  {
    output->SetPoints(points);
  }
  else
  {
    vtkNew<vtkPoints> sorted;
    sorted->SetData(vtkDataArray::SafeDownCast(Permuted(points->GetData(), order)));
    output->SetPoints(sorted);
  }
  output->GetPointData()->AddArray(place(ids));
  for (const auto& item : arrays)
  {
    output->GetPointData()->AddArray(place(item.second));
  }
  output->SetVerts(VertexCells(n));
  AddBoxFieldData(output->GetFieldData(), box, timestep);
  outline->ShallowCopy(BoxOutline(box));
  AddBoxFieldData(outline->GetFieldData(), box, timestep);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLAMMPSDataReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "AtomStyle: " << this->AtomStyle << "\n";
  os << indent << "PositionSource: " << this->PositionSource << "\n";
}
