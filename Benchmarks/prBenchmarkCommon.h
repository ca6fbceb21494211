// Shared pieces of the benchmark drivers (prBenchmark, prTransparentBenchmark): data, colours,
// material, camera path, the ParaView-like peer set-ups and the frame timing. Header-only.
#ifndef prBenchmarkCommon_h
#define prBenchmarkCommon_h

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkLookupTable.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkPNGWriter.h"
#include "vtkParticleCompat.h"
#include "vtkPointData.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace prBench
{
inline double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

inline bool ParseSize(const std::string& s, int& width, int& height)
{
  return std::sscanf(s.c_str(), "%dx%d", &width, &height) == 2 && width > 0 && height > 0;
}

// The command-line options both drivers have.
struct CommonOptions
{
  std::string Data;
  std::vector<std::string> Mappers;
  int Frames = 10;
  int Width = 1024;
  int Height = 768;
  std::string Csv;
  std::string Label;
  std::string RadiusArray = "radius";
  std::string ColorArray = "speed";
  std::string ScreenshotDir;
  double Specular = 0.3; // --specular: 0 is ParaView's default material
};

// Parses argument a if it is one of CommonOptions (next() returns its value): 1 if it was,
// 0 if it is not a common option, -1 if its value is invalid.
inline int ParseCommonOption(
  const std::string& a, const std::function<std::string()>& next, CommonOptions& o)
{
  if (a == "--data")
    o.Data = next();
  else if (a == "--specular")
    o.Specular = std::atof(next().c_str());
  else if (a == "--mapper")
    o.Mappers.push_back(next());
  else if (a == "--frames")
    o.Frames = std::atoi(next().c_str());
  else if (a == "--size")
    return ParseSize(next(), o.Width, o.Height) ? 1 : -1;
  else if (a == "--csv")
    o.Csv = next();
  else if (a == "--label")
    o.Label = next();
  else if (a == "--radius-array")
    o.RadiusArray = next();
  else if (a == "--color-array")
    o.ColorArray = next();
  else if (a == "--screenshot")
    o.ScreenshotDir = next();
  else
    return 0;
  return 1;
}

inline vtkSmartPointer<vtkPolyData> ReadParticles(const std::string& file)
{
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> data = reader->GetOutput();
  if (!data || data->GetNumberOfPoints() == 0)
  {
    std::cerr << "cannot read particles from " << file << "\n";
    return nullptr;
  }
  return data;
}

/** The colouring of every benchmark: a point array through one rainbow lookup table. */
struct Coloring
{
  vtkNew<vtkLookupTable> Table;
  std::string Array;
  double Range[2] = { 0.0, 1.0 };

  Coloring(vtkPolyData* data, const std::string& array)
    : Array(array)
  {
    this->Table->SetHueRange(0.667, 0.0);
    this->Table->Build();
    if (vtkDataArray* values = data->GetPointData()->GetArray(array.c_str()))
    {
      values->GetRange(this->Range);
    }
  }

  void Apply(vtkMapper* mapper) const
  {
    mapper->SetLookupTable(this->Table);
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray(this->Array.c_str());
    mapper->SetScalarRange(this->Range[0], this->Range[1]);
    mapper->ScalarVisibilityOn();
  }
};

/** Headlight material of every benchmark (VTK defaults plus a specular highlight, 0.3 unless
 * --specular says otherwise). */
inline void SetupMaterial(vtkProperty* property, double specular = 0.3)
{
  property->SetSpecular(specular);
  property->SetSpecularPower(20);
}

inline void SetupRenderer(vtkRenderer* renderer)
{
  renderer->SetBackground(0.1, 0.1, 0.15);
}

/** The start of the camera path: the whole data set, seen from 20 degrees above, zoomed in. */
inline void SetupCamera(vtkRenderer* renderer)
{
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Elevation(20);
  renderer->GetActiveCamera()->Zoom(1.3);
  renderer->ResetCameraClippingRange();
}

/** One step of the orbit: a quarter turn over `frames` steps. */
inline void OrbitStep(vtkRenderer* renderer, int frames)
{
  renderer->GetActiveCamera()->Azimuth(360.0 / frames / 4.0);
  renderer->ResetCameraClippingRange();
}

/** ParaView's translucency compositing: dual depth peeling, 4 peels, occlusion ratio 0. */
inline void SetupDepthPeeling(vtkRenderer* renderer, int peels = 4)
{
  renderer->SetUseDepthPeeling(1);
  renderer->SetMaximumNumberOfPeels(peels);
  renderer->SetOcclusionRatio(0.0);
}

/** vtkOpenGLSphereMapper scaled by a radius array (ParaView's "Render Points As Spheres" peer). */
inline vtkSmartPointer<vtkOpenGLSphereMapper> MakeVTKSphereMapper(const std::string& radiusArray)
{
  vtkNew<vtkOpenGLSphereMapper> mapper;
  mapper->SetScaleArray(radiusArray.c_str());
  return mapper.GetPointer();
}

/**
 * vtkPointGaussianMapper as ParaView 5.11's Point Gaussian representation sets it up by default
 * (shader preset "Sphere" with its triangle scale 1, not emissive), scaled by the radius array
 * ("Use Scale Array" on, scale factor 1).
 */
inline vtkSmartPointer<vtkPointGaussianMapper> MakePointGaussianMapper(
  const std::string& radiusArray)
{
  vtkNew<vtkPointGaussianMapper> mapper;
  mapper->SetScaleArray(radiusArray.c_str());
  mapper->SetScaleFactor(1.0);
  mapper->SetEmissive(0);
  mapper->SetSplatShaderCode("//VTK::Color::Impl\n"
                             "float dist = dot(offsetVCVSOutput.xy,offsetVCVSOutput.xy);\n"
                             "if (dist > 1.0) {\n"
                             "  discard;\n"
                             "} else {\n"
                             "  float scale = (1.0 - dist);\n"
                             "  ambientColor *= scale;\n"
                             "  diffuseColor *= scale;\n"
                             "}\n");
  vtkParticleSetPointGaussianBoundScale(mapper.GetPointer(), 1.0f);
  return mapper.GetPointer();
}

/** Wall time (finished with glFinish) and GPU time (timer query) of one window->Render(). */
struct FrameTime
{
  double Wall = 0.0;
  double GPU = 0.0;
};

inline FrameTime TimeFrame(vtkRenderWindow* window, vtkOpenGLRenderTimer& timer)
{
  FrameTime result;
  const double t = vtkTimerLog::GetUniversalTime();
  window->MakeCurrent();
  timer.Reset();
  timer.Start();
  window->Render();
  window->MakeCurrent();
  timer.Stop();
  window->WaitForCompletion();
  result.Wall = vtkTimerLog::GetUniversalTime() - t;
  result.GPU = timer.GetElapsedSeconds();
  return result;
}

/** The window's back buffer as a PNG. */
inline void WriteScreenshot(vtkRenderWindow* window, const std::string& file)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(file.c_str());
  writer->Write();
}
}

#endif
