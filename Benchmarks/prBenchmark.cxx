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
// usage: prBenchmark --data particles.vtp [--mapper
// particle|particle-nocull|vtksphere|pointgaussian ...]
//                    [--frames 10] [--size 1024x768] [--csv out.csv] [--label text]
//                    [--radius-array radius] [--color-array speed] [--screenshot DIR]
// The CSV gets one row per mapper (header written when the file is new).
#include "prBenchmarkCommon.h"

#include "vtkActor.h"
#include "vtkParticleSphereMapper.h"

#include <cstdlib>
#include <fstream>

namespace
{
using Options = prBench::CommonOptions;

struct Result
{
  std::string Mapper;
  double FirstFrame = 0;
  double MedianFrame = 0;
  double MedianGPU = 0;
  double Upload = -1;
  double MedianDrawGPU = -1;
};

bool Parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    const int common = prBench::ParseCommonOption(a, next, o);
    if (common < 0)
      return false;
    if (common == 0)
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

Result Run(const std::string& kind, vtkPolyData* data, const Options& o,
  const prBench::Coloring& coloring, vtkRenderWindow* window)
{
  Result result;
  result.Mapper = kind;

  vtkSmartPointer<vtkPolyDataMapper> mapper;
  vtkParticleSphereMapper* particleMapper = nullptr;
  if (kind == "particle" || kind == "particle-nocull")
  {
    vtkNew<vtkParticleSphereMapper> m;
    m->SetRadiusArrayName(o.RadiusArray.c_str());
    m->CollectTimingsOn();
    m->SetOcclusionCulling(kind == "particle"); // particle-nocull: the plain draw, for comparison
    particleMapper = m;
    mapper = m;
  }
  else if (kind == "vtksphere")
  {
    mapper = prBench::MakeVTKSphereMapper(o.RadiusArray);
  }
  else if (kind == "pointgaussian")
  {
    mapper = prBench::MakePointGaussianMapper(o.RadiusArray);
  }
  else
  {
    std::cerr << "unknown mapper " << kind << "\n";
    std::exit(2);
  }
  mapper->SetInputData(data);
  coloring.Apply(mapper);

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  prBench::SetupMaterial(actor->GetProperty(), o.Specular);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  prBench::SetupRenderer(renderer);
  window->AddRenderer(renderer);
  prBench::SetupCamera(renderer);

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
    prBench::OrbitStep(renderer, o.Frames);
    const prBench::FrameTime frame = prBench::TimeFrame(window, timer);
    frames.push_back(frame.Wall);
    gpu.push_back(frame.GPU);
    if (particleMapper)
    {
      draw.push_back(particleMapper->GetLastDrawGPUSeconds());
    }
  }
  timer.ReleaseGraphicsResources();
  if (!o.ScreenshotDir.empty())
  {
    const std::string file = o.ScreenshotDir + "/" + o.Label + (o.Label.empty() ? "" : "_") +
      std::to_string(data->GetNumberOfPoints()) + "_" + kind + ".png";
    prBench::WriteScreenshot(window, file);
  }
  renderer->RemoveAllViewProps();
  mapper->ReleaseGraphicsResources(window);
  window->RemoveRenderer(renderer);
  result.MedianFrame = prBench::Median(frames);
  result.MedianGPU = prBench::Median(gpu);
  if (particleMapper)
  {
    result.MedianDrawGPU = prBench::Median(draw);
  }
  return result;
}
}

int main(int argc, char* argv[])
{
  Options o;
  if (!Parse(argc, argv, o))
  {
    std::cerr
      << "usage: prBenchmark --data particles.vtp [--mapper particle|particle-nocull|vtksphere|"
         "pointgaussian ...] [--frames N] [--size WxH] [--csv out.csv] [--label text]\n";
    return 2;
  }
  vtkSmartPointer<vtkPolyData> data = prBench::ReadParticles(o.Data);
  if (!data)
  {
    return 1;
  }
  const prBench::Coloring coloring(data, o.ColorArray);

  // one window for all mappers: the same context, size and default framebuffer
  vtkNew<vtkRenderWindow> window;
  window->SetSize(o.Width, o.Height);
  window->SetMultiSamples(0);
  std::vector<Result> results;
  for (const std::string& kind : o.Mappers)
  {
    results.push_back(Run(kind, data, o, coloring, window));
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
      csv << o.Label << "," << data->GetNumberOfPoints() << "," << o.Width << "," << o.Height << ","
          << o.Frames << "," << r.Mapper << "," << r.FirstFrame << "," << r.MedianFrame << ","
          << r.MedianGPU << "," << r.Upload << "," << r.MedianDrawGPU << "," << peer.Mapper << ","
          << ratio << "\n";
    }
  }
  return 0;
}
