#include "prTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkLookupTable.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkParticleImageComparison.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLPolyDataReader.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>

namespace prTest
{
namespace
{
std::string ArgumentAfter(int argc, char* argv[], const char* flag)
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::strcmp(argv[i], flag) == 0)
    {
      return argv[i + 1];
    }
  }
  return std::string();
}
}

// the --must-fail case the test asked for and found (see MustFail)
static std::string MatchedMustFail;

bool MustFail(int argc, char* argv[], const char* name)
{
  if (ArgumentAfter(argc, argv, "--must-fail") == name)
  {
    MatchedMustFail = name;
    return true;
  }
  return false;
}

vtkSmartPointer<vtkImageData> GrabImage(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  vtkNew<vtkUnsignedCharArray> rgb;
  window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, rgb);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(size[0], size[1], 1);
  image->GetPointData()->SetScalars(rgb);
  return image;
}

bool CompareWithBaseline(
  int argc, char* argv[], vtkRenderWindow* window, const ImageCriteria& criteria)
{
  const std::string baseline = ArgumentAfter(argc, argv, "-V");
  const std::string mustFail = ArgumentAfter(argc, argv, "--must-fail");
  if (baseline.empty())
  {
    std::cerr << "FAIL: no baseline image given (-V <file.png>)\n";
    return false;
  }
  std::string name = vtksys::SystemTools::GetFilenameWithoutLastExtension(baseline);
  vtkNew<vtkParticleImageComparison> comparison;
  comparison->SetTolerance(criteria.Tolerance / 255.0);
  comparison->SetMaximumOverToleranceFraction(criteria.MaxOverToleranceShare);
  comparison->SetMaximumMeanError(criteria.MaxMean / 255.0);
  comparison->SetMaximumError(criteria.MaxError / 255.0);
  comparison->SetMaskRadius(criteria.MaskRadius);
  vtkSmartPointer<vtkImageData> image = GrabImage(window);
  if (mustFail.empty())
  {
    const bool matches = comparison->TestImage(
      image, baseline.c_str(), TempDirectory(argc, argv).c_str(), name.c_str());
    return vtkParticleImageComparison::TestRepeatable(window, name.c_str()) && matches;
  }
  if (MatchedMustFail != mustFail)
  {
    std::cerr << "FAIL: unknown must-fail case " << mustFail << "\n";
    return false;
  }
  vtkNew<vtkImageData> expected;
  if (!vtkParticleImageComparison::ReadImage(baseline.c_str(), expected))
  {
    std::cerr << "FAIL: cannot read the baseline " << baseline << "\n";
    return false;
  }
  name += "_mustfail_" + mustFail;
  vtkParticleImageComparison::WritePNG(
    image, (TempDirectory(argc, argv) + "/" + name + ".png").c_str());
  return comparison->TestRejects(image, expected, nullptr, name.c_str());
}

std::string DataFile(int argc, char* argv[], const std::string& name)
{
  std::string dir = ArgumentAfter(argc, argv, "-D");
  if (dir.empty())
  {
    dir = ".";
  }
  return dir + "/" + name;
}

std::string TempDirectory(int argc, char* argv[])
{
  std::string dir = ArgumentAfter(argc, argv, "-T");
  return dir.empty() ? std::string(".") : dir;
}

vtkSmartPointer<vtkPolyData> ReadPolyData(const std::string& fileName)
{
  if (!std::ifstream(fileName).good())
  {
    std::cerr << "FAIL: cannot open " << fileName << "\n";
    return nullptr;
  }
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(fileName.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> out = reader->GetOutput();
  if (!out || out->GetNumberOfPoints() == 0)
  {
    std::cerr << "FAIL: " << fileName << " has no points\n";
    return nullptr;
  }
  return out;
}

vtkSmartPointer<vtkPolyData> MakeLattice(int n, double spacing, unsigned int seed)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(seed);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> radius;
  radius->SetName("radius");
  vtkNew<vtkFloatArray> value;
  value->SetName("value");
  vtkNew<vtkIntArray> type;
  type->SetName("type");
  vtkNew<vtkCellArray> verts;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        double p[3] = { i * spacing, j * spacing, k * spacing };
        for (double& c : p)
        {
          c += 0.2 * spacing * (random->GetNextRangeValue(-1.0, 1.0));
        }
        const vtkIdType id = points->InsertNextPoint(p);
        verts->InsertNextCell(1, &id);
        radius->InsertNextValue(static_cast<float>(spacing * random->GetNextRangeValue(0.3, 0.6)));
        value->InsertNextValue(static_cast<float>(i + j + k));
        type->InsertNextValue((i + j + k) % 3);
      }
    }
  }
  vtkSmartPointer<vtkPolyData> poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);
  poly->GetPointData()->AddArray(radius);
  poly->GetPointData()->AddArray(type);
  poly->GetPointData()->SetScalars(value);
  return poly;
}

void MessageCounter::Observe(vtkObject* object, bool warnings, bool errors)
{
  if (warnings)
  {
    this->Tags.emplace_back(object, object->AddObserver(vtkCommand::WarningEvent, this));
  }
  if (errors)
  {
    this->Tags.emplace_back(object, object->AddObserver(vtkCommand::ErrorEvent, this));
  }
}

void MessageCounter::StopObserving()
{
  for (auto& tag : this->Tags)
  {
    if (tag.first)
    {
      tag.first->RemoveObserver(tag.second);
    }
  }
  this->Tags.clear();
}

void MessageCounter::Reset()
{
  this->Warnings = this->Errors = 0;
  this->LastWarning.clear();
  this->LastError.clear();
  this->All.clear();
}

void MessageCounter::Execute(vtkObject*, unsigned long event, void* callData)
{
  const std::string text = callData ? static_cast<const char*>(callData) : "";
  if (event == vtkCommand::WarningEvent)
  {
    ++this->Warnings;
    this->LastWarning = text;
  }
  else
  {
    ++this->Errors;
    this->LastError = text;
  }
  this->All += text;
}

ParticleAttributes RawAttributes(vtkPolyData* input, const std::string& radiusArray,
  double constantRadius, const std::string& colorArray, vtkLookupTable* lut, const double range[2],
  const std::string& opacityArray, const double opacityRange[2])
{
  ParticleAttributes out;
  const vtkIdType n = input->GetNumberOfPoints();
  out.Radii = vtkSmartPointer<vtkDoubleArray>::New();
  out.Radii->SetNumberOfTuples(n);
  vtkDataArray* radius =
    radiusArray.empty() ? nullptr : input->GetPointData()->GetArray(radiusArray.c_str());
  for (vtkIdType i = 0; i < n; ++i)
  {
    out.Radii->SetValue(i, radius ? radius->GetComponent(i, 0) : constantRadius);
  }
  vtkDataArray* scalars =
    colorArray.empty() ? nullptr : input->GetPointData()->GetArray(colorArray.c_str());
  if (lut && scalars)
  {
    vtkNew<vtkLookupTable> table;
    table->DeepCopy(lut);
    table->SetRange(range[0], range[1]);
    out.Colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    out.Colors->SetNumberOfComponents(4);
    out.Colors->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const unsigned char* rgba = table->MapValue(scalars->GetComponent(i, 0));
      for (int k = 0; k < 4; ++k)
      {
        out.Colors->SetValue(4 * i + k, rgba[k]);
      }
    }
  }
  vtkDataArray* opacity =
    opacityArray.empty() ? nullptr : input->GetPointData()->GetArray(opacityArray.c_str());
  if (opacity && opacityRange)
  {
    out.Opacities = vtkSmartPointer<vtkDoubleArray>::New();
    out.Opacities->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double t =
        (opacity->GetComponent(i, 0) - opacityRange[0]) / (opacityRange[1] - opacityRange[0]);
      out.Opacities->SetValue(i, std::isnan(t) ? 0.0 : std::min(1.0, std::max(0.0, t)));
    }
  }
  return out;
}

bool Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAIL: " << what << "\n";
  }
  return condition;
}
}
