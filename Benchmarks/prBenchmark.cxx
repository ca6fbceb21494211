// prBenchmark -- renders one particle data set with several mappers in the same process, on the
// same data, camera path and window, and reports per mapper:
//   first_frame_s     wall time of the first frame (upload + shader compile + draw)
//   median_frame_s    median wall time of the following frames (camera orbiting, data fixed),
//                     each frame finished with glFinish
//   median_gpu_s      median GPU time of those frames (timer query around the whole render)
//   upload_s          ParticleRendering mappers: CPU wall time of the particle upload stage
//   median_draw_gpu_s ParticleRendering mappers: median GPU time of the sphere draw stage
//   ratio_vs_peer     median_frame_s / median_frame_s of the peer (the first --mapper given)
//
// usage: prBenchmark --data particles.vtp [--mapper particle|vtksphere|pointgaussian ...]
//                    [--frames 10] [--size 1024x768] [--csv out.csv] [--label text]
//                    [--radius-array radius] [--color-array speed] [--screenshot DIR]
// The CSV gets one row per mapper (header written when the file is new).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkParticleSphereMapper.h"
#include "vtkPointData.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkPNGWriter.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Options
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
};

struct Result
{
  std::string Mapper;
  double FirstFrame = 0;
  double MedianFrame = 0;
  double MedianGPU = 0;
  double Upload = -1;
  double MedianDrawGPU = -1;
};

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

bool Parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--data")
      o.Data = next();
    else if (a == "--mapper")
      o.Mappers.push_back(next());
    else if (a == "--frames")
      o.Frames = std::atoi(next().c_str());
    else if (a == "--size")
    {
      const std::string s = next();
      if (std::sscanf(s.c_str(), "%dx%d", &o.Width, &o.Height) != 2)
        return false;
    }
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
    {
      std::cerr << "unknown argument " << a << "\n";
      return false;
    }
  }
  if (o.Mappers.empty())
  {
    o.Mappers = { "vtksphere", "pointgaussian", "particle" };
  }
  return !o.Data.empty() && o.Frames > 0;
}

// ParaView's Point Gaussian "Sphere" look: a disc with a radial darkening, no ray casting.
const char* SphereSplat = "//VTK::Color::Impl\n"
                          "float r2 = dot(offsetVCVSOutput.xy, offsetVCVSOutput.xy);\n"
                          "if (r2 > 1.0) { discard; }\n"
                          "ambientColor *= 1.0 - r2;\n"
                          "diffuseColor *= 1.0 - r2;\n";

Result Run(const std::string& kind, vtkPolyData* data, const Options& o, vtkLookupTable* lut,
  const double range[2], vtkRenderWindow* window)
{
  Result result;
  result.Mapper = kind;

  vtkSmartPointer<vtkPolyDataMapper> mapper;
  vtkParticleSphereMapper* particleMapper = nullptr;
  if (kind == "particle")
  {
    vtkNew<vtkParticleSphereMapper> m;
    m->SetRadiusArrayName(o.RadiusArray.c_str());
    m->CollectTimingsOn();
    particleMapper = m;
    mapper = m;
  }
  else if (kind == "vtksphere")
  {
    vtkNew<vtkOpenGLSphereMapper> m;
    m->SetScaleArray(o.RadiusArray.c_str());
    mapper = m;
  }
  else if (kind == "pointgaussian")
  {
    vtkNew<vtkPointGaussianMapper> m;
    m->SetScaleArray(o.RadiusArray.c_str());
    m->SetScaleFactor(1.0);
    m->SetEmissive(0);
    m->SetSplatShaderCode(SphereSplat);
    mapper = m;
  }
  else
  {
    std::cerr << "unknown mapper " << kind << "\n";
    std::exit(2);
  }
  mapper->SetInputData(data);
  mapper->SetLookupTable(lut);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(o.ColorArray.c_str());
  mapper->SetScalarRange(range[0], range[1]);
  mapper->ScalarVisibilityOn();

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(20);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.15);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Elevation(20);
  renderer->GetActiveCamera()->Zoom(1.3);
  renderer->ResetCameraClippingRange();

  double t = vtkTimerLog::GetUniversalTime();
  window->Render();
  window->WaitForCompletion();
  result.FirstFrame = vtkTimerLog::GetUniversalTime() - t;
  if (particleMapper)
  {
    result.Upload = particleMapper->GetLastUploadSeconds();
  }

  std::vector<double> frames, gpu, draw;
  vtkOpenGLRenderTimer timer;
  for (int f = 0; f < o.Frames; ++f)
  {
    renderer->GetActiveCamera()->Azimuth(360.0 / o.Frames / 4.0);
    renderer->ResetCameraClippingRange();
    t = vtkTimerLog::GetUniversalTime();
    window->MakeCurrent();
    timer.Reset();
    timer.Start();
    window->Render();
    window->MakeCurrent();
    timer.Stop();
    window->WaitForCompletion();
    frames.push_back(vtkTimerLog::GetUniversalTime() - t);
    gpu.push_back(timer.GetElapsedSeconds());
    if (particleMapper)
    {
      draw.push_back(particleMapper->GetLastDrawGPUSeconds());
    }
  }
  timer.ReleaseGraphicsResources();
  if (!o.ScreenshotDir.empty())
  {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    const std::string file = o.ScreenshotDir + "/" + o.Label + (o.Label.empty() ? "" : "_") +
      std::to_string(data->GetNumberOfPoints()) + "_" + kind + ".png";
    writer->SetFileName(file.c_str());
    writer->Write();
  }
  renderer->RemoveAllViewProps();
  mapper->ReleaseGraphicsResources(window);
  window->RemoveRenderer(renderer);
  result.MedianFrame = Median(frames);
  result.MedianGPU = Median(gpu);
  if (particleMapper)
  {
    result.MedianDrawGPU = Median(draw);
  }
  return result;
}
}

int main(int argc, char* argv[])
{
  Options o;
  if (!Parse(argc, argv, o))
  {
    std::cerr << "usage: prBenchmark --data particles.vtp [--mapper particle|vtksphere|"
                 "pointgaussian ...] [--frames N] [--size WxH] [--csv out.csv] [--label text]\n";
    return 2;
  }
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(o.Data.c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  if (!data || data->GetNumberOfPoints() == 0)
  {
    std::cerr << "cannot read particles from " << o.Data << "\n";
    return 1;
  }
  vtkDataArray* color = data->GetPointData()->GetArray(o.ColorArray.c_str());
  double range[2] = { 0, 1 };
  if (color)
  {
    color->GetRange(range);
  }
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->Build();

  // one window for all mappers: the same context, size and default framebuffer
  vtkNew<vtkRenderWindow> window;
  window->SetSize(o.Width, o.Height);
  window->SetMultiSamples(0);
  std::vector<Result> results;
  for (const std::string& kind : o.Mappers)
  {
    results.push_back(Run(kind, data, o, lut, range, window));
  }

  const bool newFile = !o.Csv.empty() && !std::ifstream(o.Csv).good();
  std::ofstream csv;
  if (!o.Csv.empty())
  {
    csv.open(o.Csv, std::ios::app);
    if (newFile)
    {
      csv << "label,particles,width,height,frames,mapper,first_frame_s,median_frame_s,"
             "median_gpu_s,upload_s,median_draw_gpu_s,peer,ratio_vs_peer\n";
    }
  }
  const Result& peer = results.front();
  std::cout << "particles " << data->GetNumberOfPoints() << ", " << o.Width << "x" << o.Height
            << ", " << o.Frames << " frames\n";
  for (const Result& r : results)
  {
    const double ratio = r.MedianFrame / peer.MedianFrame;
    std::cout << "  " << r.Mapper << ": first " << r.FirstFrame << " s, median " << r.MedianFrame
              << " s, gpu " << r.MedianGPU << " s";
    if (r.Upload >= 0)
    {
      std::cout << ", upload " << r.Upload << " s, draw gpu " << r.MedianDrawGPU << " s";
    }
    std::cout << ", ratio vs " << peer.Mapper << " " << ratio << "\n";
    if (csv.is_open())
    {
      csv << o.Label << "," << data->GetNumberOfPoints() << "," << o.Width << "," << o.Height
          << "," << o.Frames << "," << r.Mapper << "," << r.FirstFrame << "," << r.MedianFrame
          << "," << r.MedianGPU << "," << r.Upload << "," << r.MedianDrawGPU << ","
          << peer.Mapper << "," << ratio << "\n";
    }
  }
  return 0;
}
