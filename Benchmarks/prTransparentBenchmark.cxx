// prTransparentBenchmark -- translucent particles: vtkTransparentSphereMapper against what a
// ParaView user gets today, all in the same process, window and OpenGL context, on the same data
// and camera path, with the same constant opacity (the actor property's Opacity) and with
// ParaView's translucency compositing (dual depth peeling, 4 peels, occlusion ratio 0):
//   transparent     vtkTransparentSphereMapper, constant density, VolumeMix 0.5, no early
//   termination transparent-et  the same with EarlyTermination on (--chunks depth chunks, default
//   20) vtksphere-ddp   vtkOpenGLSphereMapper (flat per-fragment opacity), composited by the
//   peeling pointgaussian   vtkPointGaussianMapper with ParaView's Point Gaussian defaults
//   ("Sphere" splat),
//                   scaled by the radius array, composited by the peeling
//
// Timing mode (default): per mapper a first frame, then --frames frames orbiting the data (the
// camera moves every frame, so the transparent mapper sorts every frame: the interactive case),
// then, for the transparent mappers, --static-frames frames with the camera at rest (the sort is
// skipped). One CSV row per mapper and camera mode:
//   first_frame_s     wall time of the first frame (upload + shader compile + sort + draw)
//   median_frame_s    median wall time per frame, each finished with glFinish
//   median_gpu_s      median GPU time (timer query around the whole render)
//   upload_s          transparent: CPU wall time of the particle upload (first frame)
//   sort_gpu_s, draw_gpu_s, composite_gpu_s
//                     transparent: median GPU time of the depth sort (keys + radix sort, 0 when
//                     skipped), of the translucent draw (all chunks and masks) and of the rest of
//                     the translucent stage (opaque depth copy, final blend)
//                     (on llvmpipe only the sort's is meaningful, see Benchmarks/README.md)
//   sorts_per_frame   transparent: depth sorts per frame (1 orbiting, 0 static)
//   masked_fraction   transparent-et: fraction of the image's pixels masked as saturated after
//                     the last chunk (one extra, untimed frame with the masked-pixel count on)
//   covered_fraction  transparent: fraction of the image's pixels the particles change (> 1/255)
//   empty_frame_s, one_particle_frame_s
//                     transparent: median static frame time of the same renderer without the
//                     actor, and with the first particle only (the translucent stage's fixed
//                     cost); the wall-clock stage split is draw = static - one particle,
//                     composite = one particle - empty
//   rmse_vs_transparent, max_vs_transparent
//                     RGB difference of the last frame to the `transparent` mapper's last frame
//                     (same camera; for transparent-et the error of the early termination)
//   ratio_vs_peer     median_frame_s / the peer's (--peer, default vtksphere-ddp when present)
//
// Error mode (--errors FILE): one frame per mapper at a fixed camera, compared (RGB) with the
// double-precision vtkParticleReferenceRenderer of the `transparent` actor; for the peers also
// the same mapper with --converged-peels peels (default 200) and occlusion ratio 0, i.e. their
// order error alone (4 peels vs converged) and their model error alone (converged vs reference).
// --drop-intersecting removes every particle that intersects one kept before it (the GPU sort
// and the reference order intersecting spheres differently).
//
// usage: prTransparentBenchmark --data particles.vtp [--mapper KIND ...] [--frames 10]
//          [--static-frames 3] [--size 1024x768] [--opacity 0.5] [--chunks 20] [--csv out.csv]
//          [--errors out.csv] [--converged-peels 200] [--drop-intersecting] [--label text]
//          [--peer KIND] [--radius-array radius] [--color-array speed] [--screenshot DIR]
//          [--max-particles N]   (N > 0: only the first N particles of the file)
// CSV files get their header when they are new; rows are appended.
#include "prBenchmarkCommon.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkParticleFrontToBackTarget.h"
#include "vtkParticleImageComparison.h"
#include "vtkParticleReferenceRenderer.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"
#include "vtkTransparentSphereMapper.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

namespace
{
struct Options : prBench::CommonOptions
{
  int StaticFrames = 3;
  double Opacity = 0.5;
  int Chunks = 20;
  std::string Errors;
  int ConvergedPeels = 200;
  bool DropIntersecting = false;
  vtkIdType MaxParticles = 0;
  std::string Peer;
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
    if (common > 0)
      continue;
    if (a == "--static-frames")
      o.StaticFrames = std::atoi(next().c_str());
    else if (a == "--opacity")
      o.Opacity = std::atof(next().c_str());
    else if (a == "--chunks")
      o.Chunks = std::atoi(next().c_str());
    else if (a == "--errors")
      o.Errors = next();
    else if (a == "--converged-peels")
      o.ConvergedPeels = std::atoi(next().c_str());
    else if (a == "--drop-intersecting")
      o.DropIntersecting = true;
    else if (a == "--max-particles")
      o.MaxParticles = std::atoll(next().c_str());
    else if (a == "--peer")
      o.Peer = next();
    else
    {
      std::cerr << "unknown argument " << a << "\n";
      return false;
    }
  }
  if (o.Mappers.empty())
  {
    o.Mappers = { "vtksphere-ddp", "pointgaussian", "transparent", "transparent-et" };
  }
  for (const std::string& kind : o.Mappers)
  {
    if (kind != "transparent" && kind != "transparent-et" && kind != "vtksphere-ddp" &&
      kind != "pointgaussian")
    {
      std::cerr << "unknown mapper " << kind << "\n";
      return false;
    }
  }
  if (o.Peer.empty())
  {
    o.Peer = std::find(o.Mappers.begin(), o.Mappers.end(), "vtksphere-ddp") != o.Mappers.end()
      ? "vtksphere-ddp"
      : o.Mappers.front();
  }
  return !o.Data.empty() && o.Frames > 0 && o.StaticFrames >= 0 && o.Opacity > 0 &&
    o.Opacity <= 1 && o.Chunks > 0 && o.ConvergedPeels > 0;
}

bool IsTransparent(const std::string& kind)
{
  return kind == "transparent" || kind == "transparent-et";
}

/** A mapper of the given kind on the data, and its actor with the benchmark's opacity. */
struct Setup
{
  vtkSmartPointer<vtkPolyDataMapper> Mapper;
  vtkTransparentSphereMapper* Transparent = nullptr;
  vtkNew<vtkActor> Actor;

  Setup(
    const std::string& kind, vtkPolyData* data, const Options& o, const prBench::Coloring& coloring)
  {
    if (IsTransparent(kind))
    {
      vtkNew<vtkTransparentSphereMapper> m;
      m->SetRadiusArrayName(o.RadiusArray.c_str());
      m->SetDensityModelToConstant();
      m->SetVolumeMix(0.5);
      m->SetEarlyTermination(kind == "transparent-et");
      m->SetNumberOfChunks(o.Chunks);
      // the paper's sorted path, as in the tables of Benchmarks/README.md (the random gas has
      // overlapping spheres, for which AUTOMATIC would take the exact-overlap lists; those are
      // measured by overlap_benchmark.py)
      m->SetOverlapCompositing(vtkTransparentSphereMapper::SORTED_SPHERES);
      m->CollectTimingsOn();
      this->Transparent = m;
      this->Mapper = m;
    }
    else if (kind == "vtksphere-ddp")
    {
      this->Mapper = prBench::MakeVTKSphereMapper(o.RadiusArray);
    }
    else
    {
      this->Mapper = prBench::MakePointGaussianMapper(o.RadiusArray);
    }
    this->Mapper->SetInputData(data);
    coloring.Apply(this->Mapper);
    this->Actor->SetMapper(this->Mapper);
    prBench::SetupMaterial(this->Actor->GetProperty());
    this->Actor->GetProperty()->SetOpacity(o.Opacity);
  }
};

vtkSmartPointer<vtkImageData> GrabRGB(vtkRenderWindow* window)
{
  vtkNew<vtkImageData> rgba;
  vtkParticleImageComparison::GrabColorBuffer(window, rgba);
  return vtkParticleImageComparison::ExtractRGB(rgba);
}

vtkParticleImageComparison::Result Compare(vtkImageData* a, vtkImageData* b)
{
  vtkParticleImageComparison::Result r;
  if (!a || !b || !vtkParticleImageComparison::Compare(a, b, nullptr, 2.0 / 255.0, r))
  {
    r.RMSE = r.MaxAbsError = -1.0;
  }
  return r;
}

/**
 * Ids of the particles kept when every particle that intersects one kept before it (in id order)
 * is dropped; all particles when drop is false. Returns the number of particles that intersect
 * any other (before dropping).
 */
vtkIdType IntersectingParticles(
  vtkPolyData* data, const std::string& radiusArray, bool drop, std::vector<vtkIdType>& kept)
{
  const vtkIdType n = data->GetNumberOfPoints();
  vtkDataArray* radii = data->GetPointData()->GetArray(radiusArray.c_str());
  double range[2] = { 0.5, 0.5 };
  if (radii)
  {
    radii->GetRange(range, 0);
  }
  auto radius = [&](vtkIdType i) { return radii ? radii->GetComponent(i, 0) : 0.5; };
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(data);
  locator->BuildLocator();
  vtkNew<vtkIdList> near;
  std::vector<char> isKept(n, 1);
  vtkIdType intersecting = 0;
  kept.clear();
  double p[3];
  double q[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    data->GetPoint(i, p);
    const double ri = radius(i);
    locator->FindPointsWithinRadius(ri + range[1], p, near);
    bool any = false;
    bool anyKeptBefore = false;
    for (vtkIdType k = 0; k < near->GetNumberOfIds(); ++k)
    {
      const vtkIdType j = near->GetId(k);
      if (j == i)
      {
        continue;
      }
      data->GetPoint(j, q);
      const double rr = ri + radius(j);
      if (vtkMath::Distance2BetweenPoints(p, q) < rr * rr)
      {
        any = true;
        anyKeptBefore |= j < i && isKept[j];
      }
    }
    intersecting += any ? 1 : 0;
    isKept[i] = !(drop && anyKeptBefore);
    if (isKept[i])
    {
      kept.push_back(i);
    }
  }
  return intersecting;
}

vtkSmartPointer<vtkPolyData> Subset(vtkPolyData* data, const std::vector<vtkIdType>& ids)
{
  vtkNew<vtkPolyData> out;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(ids.size()));
  out->GetPointData()->CopyAllocate(data->GetPointData(), static_cast<vtkIdType>(ids.size()));
  vtkNew<vtkCellArray> verts;
  for (vtkIdType k = 0; k < static_cast<vtkIdType>(ids.size()); ++k)
  {
    points->SetPoint(k, data->GetPoint(ids[k]));
    out->GetPointData()->CopyData(data->GetPointData(), ids[k], k);
    verts->InsertNextCell(1, &k);
  }
  out->SetPoints(points);
  out->SetVerts(verts);
  return out.GetPointer();
}

// ------------------------------------------------------------------------------ timing mode
struct Row
{
  std::string Mapper;
  std::string Camera; // orbit | static
  int Frames = 0;
  double FirstFrame = -1;
  double MedianFrame = 0;
  double MedianGPU = 0;
  double Upload = -1;
  double Sort = -1;
  double Draw = -1;
  double Composite = -1;
  double SortsPerFrame = -1;
  double MaskedFraction = -1;
  double CoveredFraction = -1;
  double EmptyFrame = -1;
  double OneParticleFrame = -1;
  double RMSEvsTransparent = -1;
  double MaxvsTransparent = -1;
};

std::vector<Row> RunTiming(const std::string& kind, vtkPolyData* data, const Options& o,
  const prBench::Coloring& coloring, vtkRenderWindow* window, vtkSmartPointer<vtkImageData>& image)
{
  Setup setup(kind, data, o, coloring);
  vtkTransparentSphereMapper* tm = setup.Transparent;
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(setup.Actor);
  prBench::SetupRenderer(renderer);
  prBench::SetupDepthPeeling(renderer);
  window->AddRenderer(renderer);
  prBench::SetupCamera(renderer);

  std::vector<Row> rows;
  Row orbit;
  orbit.Mapper = kind;
  orbit.Camera = "orbit";
  orbit.Frames = o.Frames;
  double t = vtkTimerLog::GetUniversalTime();
  window->Render();
  window->WaitForCompletion();
  orbit.FirstFrame = vtkTimerLog::GetUniversalTime() - t;
  if (tm)
  {
    orbit.Upload = tm->GetLastUploadSeconds();
  }

  vtkOpenGLRenderTimer timer;
  auto measure = [&](Row& row, int frames, bool move)
  {
    std::vector<double> wall, gpu, sort, draw, composite;
    const vtkIdType sorts = tm ? tm->GetNumberOfSorts() : 0;
    for (int f = 0; f < frames; ++f)
    {
      if (move)
      {
        prBench::OrbitStep(renderer, o.Frames);
      }
      const prBench::FrameTime frame = prBench::TimeFrame(window, timer);
      wall.push_back(frame.Wall);
      gpu.push_back(frame.GPU);
      if (tm)
      {
        sort.push_back(tm->GetLastSortGPUSeconds());
        draw.push_back(tm->GetLastTranslucentDrawGPUSeconds());
        composite.push_back(tm->GetLastCompositeGPUSeconds());
      }
    }
    row.MedianFrame = prBench::Median(wall);
    row.MedianGPU = prBench::Median(gpu);
    if (tm)
    {
      row.Sort = prBench::Median(sort);
      row.Draw = prBench::Median(draw);
      row.Composite = prBench::Median(composite);
      row.SortsPerFrame = static_cast<double>(tm->GetNumberOfSorts() - sorts) / frames;
    }
  };
  measure(orbit, o.Frames, true);
  rows.push_back(orbit);
  if (tm && o.StaticFrames > 0)
  {
    Row still;
    still.Mapper = kind;
    still.Camera = "static";
    still.Frames = o.StaticFrames;
    still.Upload = orbit.Upload;
    measure(still, o.StaticFrames, false);
    rows.push_back(still);
  }
  timer.ReleaseGraphicsResources();

  if (tm && tm->GetEarlyTermination())
  {
    // one more (untimed) frame at rest, counting the masked pixels: a blocking read-back per chunk
    tm->GetFrontToBackTarget()->SetCountMaskedPixels(true);
    window->Render();
    tm->GetFrontToBackTarget()->SetCountMaskedPixels(false);
    const double fraction =
      static_cast<double>(tm->GetFrontToBackTarget()->GetNumberOfMaskedPixels()) /
      (static_cast<double>(o.Width) * o.Height);
    for (Row& row : rows)
    {
      row.MaskedFraction = fraction;
    }
  }
  else
  {
    window->Render(); // the same image for every mapper: the last orbit camera
  }
  image = GrabRGB(window);
  if (tm)
  {
    // pixels the particles change by more than a grey level (the 8-bit background itself is
    // off by up to half a level)
    double background[3];
    renderer->GetBackground(background);
    vtkDataArray* rgb = image->GetPointData()->GetScalars();
    vtkIdType covered = 0;
    for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
    {
      bool differs = false;
      for (int k = 0; k < 3; ++k)
      {
        differs |= std::abs(rgb->GetComponent(i, k) - background[k]) > 1.5 / 255.0;
      }
      covered += differs ? 1 : 0;
    }
    for (Row& row : rows)
    {
      row.CoveredFraction = static_cast<double>(covered) / rgb->GetNumberOfTuples();
    }
  }
  if (!o.ScreenshotDir.empty())
  {
    prBench::WriteScreenshot(window,
      o.ScreenshotDir + "/" + o.Label + (o.Label.empty() ? "" : "_") +
        std::to_string(data->GetNumberOfPoints()) + "_" + kind + ".png");
  }

  if (tm && o.StaticFrames > 0)
  {
    // Wall-clock stage split (the mapper's in-scene GPU timers are not usable on llvmpipe, see
    // README): the same renderer without the actor (clear, swap) and with one particle (the
    // translucent stage's fixed per-pixel cost: opaque depth copy, final blend, peeling set-up).
    Row empty;
    Row one;
    setup.Actor->VisibilityOff();
    window->Render();
    measure(empty, o.StaticFrames, false);
    setup.Actor->VisibilityOn();
    std::vector<vtkIdType> first(1, 0);
    tm->SetInputData(Subset(data, first));
    window->Render();
    measure(one, o.StaticFrames, false);
    tm->SetInputData(data);
    for (Row& row : rows)
    {
      row.EmptyFrame = empty.MedianFrame;
      row.OneParticleFrame = one.MedianFrame;
    }
  }
  renderer->RemoveAllViewProps();
  setup.Mapper->ReleaseGraphicsResources(window);
  window->RemoveRenderer(renderer);
  return rows;
}

int Timing(vtkPolyData* data, const Options& o, const prBench::Coloring& coloring)
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(o.Width, o.Height);
  window->SetMultiSamples(0);
  std::vector<Row> rows;
  std::map<std::string, vtkSmartPointer<vtkImageData>> images;
  for (const std::string& kind : o.Mappers)
  {
    std::vector<Row> r = RunTiming(kind, data, o, coloring, window, images[kind]);
    rows.insert(rows.end(), r.begin(), r.end());
  }
  if (images.count("transparent"))
  {
    for (Row& row : rows)
    {
      const vtkParticleImageComparison::Result r =
        Compare(images[row.Mapper], images["transparent"]);
      row.RMSEvsTransparent = r.RMSE;
      row.MaxvsTransparent = r.MaxAbsError;
    }
  }
  double peerTime = 0;
  for (const Row& row : rows)
  {
    if (row.Mapper == o.Peer && row.Camera == "orbit")
    {
      peerTime = row.MedianFrame;
    }
  }

  const bool newFile = !o.Csv.empty() && !std::ifstream(o.Csv).good();
  std::ofstream csv;
  if (!o.Csv.empty())
  {
    csv.open(o.Csv, std::ios::app);
    if (newFile)
    {
      csv << "label,particles,width,height,opacity,mapper,camera,frames,first_frame_s,"
             "median_frame_s,median_gpu_s,upload_s,sort_gpu_s,draw_gpu_s,composite_gpu_s,"
             "sorts_per_frame,masked_fraction,covered_fraction,empty_frame_s,one_particle_frame_s,"
             "rmse_vs_transparent,max_vs_transparent,peer,"
             "ratio_vs_peer\n";
    }
  }
  std::cout << "particles " << data->GetNumberOfPoints() << ", " << o.Width << "x" << o.Height
            << ", opacity " << o.Opacity << ", " << o.Frames << " frames\n";
  for (const Row& r : rows)
  {
    const double ratio = peerTime > 0 ? r.MedianFrame / peerTime : -1;
    std::cout << "  " << r.Mapper << " (" << r.Camera << "): first " << r.FirstFrame
              << " s, median " << r.MedianFrame << " s, gpu " << r.MedianGPU << " s";
    if (r.Sort >= 0)
    {
      std::cout << ", upload " << r.Upload << " s, sort " << r.Sort << " s, draw " << r.Draw
                << " s, composite " << r.Composite << " s, sorts/frame " << r.SortsPerFrame;
    }
    if (r.MaskedFraction >= 0)
    {
      std::cout << ", masked " << r.MaskedFraction << " (covered " << r.CoveredFraction << ")";
    }
    if (r.EmptyFrame >= 0)
    {
      std::cout << ", empty frame " << r.EmptyFrame << " s, one particle " << r.OneParticleFrame
                << " s";
    }
    if (r.MaxvsTransparent >= 0)
    {
      std::cout << ", max diff vs transparent " << r.MaxvsTransparent * 255 << "/255";
    }
    std::cout << ", ratio vs " << o.Peer << " " << ratio << "\n";
    if (csv.is_open())
    {
      csv << o.Label << "," << data->GetNumberOfPoints() << "," << o.Width << "," << o.Height << ","
          << o.Opacity << "," << r.Mapper << "," << r.Camera << "," << r.Frames << ","
          << r.FirstFrame << "," << r.MedianFrame << "," << r.MedianGPU << "," << r.Upload << ","
          << r.Sort << "," << r.Draw << "," << r.Composite << "," << r.SortsPerFrame << ","
          << r.MaskedFraction << "," << r.CoveredFraction << "," << r.EmptyFrame << ","
          << r.OneParticleFrame << "," << r.RMSEvsTransparent << "," << r.MaxvsTransparent << ","
          << o.Peer << "," << ratio << "\n";
    }
  }
  return 0;
}

// ------------------------------------------------------------------------------ error mode
int Errors(
  vtkPolyData* data, vtkIdType dropped, const Options& o, const prBench::Coloring& coloring)
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(o.Width, o.Height);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  prBench::SetupRenderer(renderer);
  prBench::SetupDepthPeeling(renderer);
  window->AddRenderer(renderer);

  // the reference's actor: the transparent mapper without early termination
  Setup reference("transparent", data, o, coloring);
  renderer->AddActor(reference.Actor);
  prBench::SetupCamera(renderer);
  window->Render();
  vtkSmartPointer<vtkImageData> transparentImage = GrabRGB(window);

  vtkNew<vtkParticleReferenceRenderer> ref;
  ref->SetRenderer(renderer);
  ref->SetActor(reference.Actor);
  if (!ref->Render())
  {
    std::cerr << "the reference failed\n";
    return 1;
  }
  vtkSmartPointer<vtkImageData> refImage =
    vtkParticleImageComparison::ExtractRGB(ref->GetColorImage());
  renderer->RemoveActor(reference.Actor);
  if (!o.ScreenshotDir.empty())
  {
    vtkParticleImageComparison::WritePNG(refImage,
      (o.ScreenshotDir + "/" + o.Label + "_" + std::to_string(data->GetNumberOfPoints()) +
        "_reference.png")
        .c_str());
  }

  const bool newFile = !std::ifstream(o.Errors).good();
  std::ofstream csv(o.Errors, std::ios::app);
  if (newFile)
  {
    csv << "label,particles,dropped_intersecting,width,height,opacity,mapper,peels,"
           "rmse_vs_reference,max_vs_reference,over_2_255_fraction,rmse_vs_converged,"
           "max_vs_converged,reference_s\n";
  }
  std::cout << "particles " << data->GetNumberOfPoints() << " (" << dropped
            << " intersecting dropped), " << o.Width << "x" << o.Height << ", opacity " << o.Opacity
            << ", reference " << ref->GetLastRenderSeconds() << " s\n";
  auto report = [&](
                  const std::string& kind, int peels, vtkImageData* image, vtkImageData* converged)
  {
    const vtkParticleImageComparison::Result r = Compare(image, refImage);
    vtkParticleImageComparison::Result c;
    c.RMSE = c.MaxAbsError = -1;
    if (converged)
    {
      c = Compare(image, converged);
    }
    const double over = static_cast<double>(r.NumberOfPixelsOverTolerance) /
      std::max<long long>(1, r.NumberOfComparedPixels);
    std::cout << "  " << kind << " (" << peels << " peels): vs reference rmse " << r.RMSE * 255
              << "/255, max " << r.MaxAbsError * 255 << "/255, " << over * 100
              << " % of pixels > 2/255";
    if (converged)
    {
      std::cout << "; vs converged rmse " << c.RMSE * 255 << "/255, max " << c.MaxAbsError * 255
                << "/255";
    }
    std::cout << "\n";
    csv << o.Label << "," << data->GetNumberOfPoints() << "," << dropped << "," << o.Width << ","
        << o.Height << "," << o.Opacity << "," << kind << "," << peels << "," << r.RMSE << ","
        << r.MaxAbsError << "," << over << "," << c.RMSE << "," << c.MaxAbsError << ","
        << ref->GetLastRenderSeconds() << "\n";
    if (!o.ScreenshotDir.empty())
    {
      const std::string base = o.ScreenshotDir + "/" + o.Label + "_" +
        std::to_string(data->GetNumberOfPoints()) + "_" + kind + "_" + std::to_string(peels);
      vtkParticleImageComparison::WritePNG(image, (base + ".png").c_str());
      vtkParticleImageComparison::WriteErrorMap(
        image, refImage, nullptr, (base + "_error.png").c_str(), 10.0);
    }
  };

  for (const std::string& kind : o.Mappers)
  {
    if (kind == "transparent")
    {
      report(kind, 4, transparentImage, nullptr);
      continue;
    }
    Setup setup(kind, data, o, coloring);
    renderer->AddActor(setup.Actor);
    renderer->SetMaximumNumberOfPeels(4);
    window->Render();
    vtkSmartPointer<vtkImageData> image = GrabRGB(window);
    if (IsTransparent(kind))
    {
      report(kind, 4, image, nullptr);
    }
    else
    {
      renderer->SetMaximumNumberOfPeels(o.ConvergedPeels);
      window->Render();
      vtkSmartPointer<vtkImageData> converged = GrabRGB(window);
      renderer->SetMaximumNumberOfPeels(4);
      report(kind, 4, image, converged);
      report(kind, o.ConvergedPeels, converged, converged);
    }
    renderer->RemoveActor(setup.Actor);
    setup.Mapper->ReleaseGraphicsResources(window);
  }
  renderer->RemoveAllViewProps();
  reference.Mapper->ReleaseGraphicsResources(window);
  return 0;
}
}

int main(int argc, char* argv[])
{
  Options o;
  if (!Parse(argc, argv, o))
  {
    std::cerr << "usage: prTransparentBenchmark --data particles.vtp [--mapper transparent|"
                 "transparent-et|vtksphere-ddp|pointgaussian ...] [--frames N] [--static-frames N]"
                 " [--size WxH] [--opacity O] [--chunks C] [--csv out.csv] [--errors out.csv]"
                 " [--converged-peels N] [--drop-intersecting] [--label text] [--peer KIND]"
                 " [--radius-array NAME] [--color-array NAME] [--screenshot DIR]"
                 " [--max-particles N]\n";
    return 2;
  }
  vtkSmartPointer<vtkPolyData> data = prBench::ReadParticles(o.Data);
  if (!data)
  {
    return 1;
  }
  if (o.MaxParticles > 0 && data->GetNumberOfPoints() > o.MaxParticles)
  {
    std::vector<vtkIdType> first(static_cast<size_t>(o.MaxParticles));
    for (vtkIdType i = 0; i < o.MaxParticles; ++i)
    {
      first[i] = i;
    }
    data = Subset(data, first);
  }
  const prBench::Coloring coloring(data, o.ColorArray);
  if (o.Errors.empty())
  {
    return Timing(data, o, coloring);
  }
  vtkSMPTools::SetBackend("STDThread");
  std::vector<vtkIdType> kept;
  const vtkIdType intersecting =
    IntersectingParticles(data, o.RadiusArray, o.DropIntersecting, kept);
  std::cout << intersecting << " of " << data->GetNumberOfPoints()
            << " particles intersect another\n";
  vtkIdType dropped = 0;
  if (o.DropIntersecting && kept.size() < static_cast<size_t>(data->GetNumberOfPoints()))
  {
    dropped = data->GetNumberOfPoints() - static_cast<vtkIdType>(kept.size());
    data = Subset(data, kept);
  }
  return Errors(data, dropped, o, coloring);
}
