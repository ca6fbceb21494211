#include "prTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkTesting.h"
#include "vtkXMLPolyDataReader.h"

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

bool CompareWithBaseline(int argc, char* argv[], vtkRenderWindow* window, double threshold)
{
  const std::string baseline = ArgumentAfter(argc, argv, "-V");
  if (baseline.empty())
  {
    std::cerr << "FAIL: no baseline image given (-V <file.png>)\n";
    return false;
  }
  if (!std::ifstream(baseline).good())
  {
    std::cerr << "FAIL: baseline image " << baseline << " does not exist\n";
  }
  vtkNew<vtkTesting> testing;
  for (int i = 0; i < argc; ++i)
  {
    testing->AddArgument(argv[i]);
  }
  testing->SetRenderWindow(window);
  const int result = testing->RegressionTest(threshold);
  if (!std::ifstream(baseline).good())
  {
    return false; // the image was written to -T for inspection, but there is nothing to pass
  }
  if (result != vtkTesting::PASSED)
  {
    std::cerr << "FAIL: image differs from " << baseline << "\n";
    return false;
  }
  return true;
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

bool Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAIL: " << what << "\n";
  }
  return condition;
}
}
