// prCompareImages: compare two images (PNG or any format VTK reads) pixel by pixel.
//
//   prCompareImages a.png b.png [--mask-edges] [--edge-radius N] [--edge-threshold T]
//                   [--tolerance T] [--max-error E] [--diff out.png] [--diff-scale S]
//
// Prints, one "key value" pair per line (errors in [0,1] units, *_255 in 8-bit steps):
//   width, height, components, compared_pixels, excluded_pixels, rmse, rmse_255,
//   max_abs_error, max_abs_error_255, max_abs_error_channels (one value per channel),
//   max_error_pixel (x y, rows bottom-up), over_tolerance (pixels with a channel error > T).
// --mask-edges     exclude pixels near colour edges (silhouettes): a pixel is excluded when a
//                  pixel within --edge-radius (default 1) differs from it by more than
//                  --edge-threshold (default 0.1) in a or in b
// --tolerance T    per-channel tolerance for over_tolerance (default 2/255)
// --max-error E    exit with status 1 when max_abs_error > E (default: never)
// --diff out.png   write a heat map of |a - b| x S (--diff-scale, default 32), excluded grey
// Exit status: 0 success, 1 max error exceeded, 2 usage or read error.
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParticleImageComparison.h"
#include "vtkUnsignedCharArray.h"

#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>

namespace
{
int Usage()
{
  std::cerr << "usage: prCompareImages a.png b.png [--mask-edges] [--edge-radius N]"
               " [--edge-threshold T] [--tolerance T] [--max-error E] [--diff out.png]"
               " [--diff-scale S]\n";
  return 2;
}

bool ParseDouble(const char* text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0';
}
}

int main(int argc, char* argv[])
{
  std::string files[2];
  int fileCount = 0;
  bool maskEdges = false;
  double edgeRadius = 1;
  double edgeThreshold = 0.1;
  double tolerance = 2.0 / 255.0;
  double maxError = -1.0;
  double diffScale = 32.0;
  std::string diff;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--mask-edges")
    {
      maskEdges = true;
    }
    else if (arg == "--diff" && hasValue)
    {
      diff = argv[++i];
    }
    else if ((arg == "--edge-radius" || arg == "--edge-threshold" || arg == "--tolerance" ||
               arg == "--max-error" || arg == "--diff-scale") &&
      hasValue)
    {
      double value;
      if (!ParseDouble(argv[++i], value))
      {
        return Usage();
      }
      (arg == "--edge-radius"         ? edgeRadius
          : arg == "--edge-threshold" ? edgeThreshold
          : arg == "--tolerance"      ? tolerance
          : arg == "--max-error"      ? maxError
                                      : diffScale) = value;
    }
    else if (arg.rfind("--", 0) == 0 || fileCount == 2)
    {
      return Usage();
    }
    else
    {
      files[fileCount++] = arg;
    }
  }
  if (fileCount != 2)
  {
    return Usage();
  }

  vtkNew<vtkImageData> a;
  vtkNew<vtkImageData> b;
  if (!vtkParticleImageComparison::ReadImage(files[0].c_str(), a) ||
    !vtkParticleImageComparison::ReadImage(files[1].c_str(), b))
  {
    std::cerr << "prCompareImages: cannot read the images\n";
    return 2;
  }
  vtkNew<vtkUnsignedCharArray> mask;
  vtkUnsignedCharArray* excluded = nullptr;
  if (maskEdges)
  {
    if (!vtkParticleImageComparison::MakeEdgeMask(
          a, b, static_cast<int>(edgeRadius), edgeThreshold, mask))
    {
      std::cerr << "prCompareImages: the images do not match in size\n";
      return 2;
    }
    excluded = mask;
  }
  vtkParticleImageComparison::Result r;
  if (!vtkParticleImageComparison::Compare(a, b, excluded, tolerance, r))
  {
    std::cerr << "prCompareImages: the images cannot be compared\n";
    return 2;
  }
  int dims[3];
  a->GetDimensions(dims);
  std::cout << std::setprecision(6) << "width " << dims[0] << "\nheight " << dims[1]
            << "\ncomponents " << r.NumberOfComponents << "\ncompared_pixels "
            << r.NumberOfComparedPixels << "\nexcluded_pixels " << r.NumberOfExcludedPixels
            << "\nrmse " << r.RMSE << "\nrmse_255 " << 255.0 * r.RMSE << "\nmax_abs_error "
            << r.MaxAbsError << "\nmax_abs_error_255 " << 255.0 * r.MaxAbsError
            << "\nmax_abs_error_channels";
  for (int c = 0; c < r.NumberOfComponents; ++c)
  {
    std::cout << " " << r.ChannelMaxAbsError[c];
  }
  std::cout << "\nmax_error_pixel " << r.MaxErrorPixel[0] << " " << r.MaxErrorPixel[1]
            << "\nover_tolerance " << r.NumberOfPixelsOverTolerance << "\n";
  if (!diff.empty() &&
    !vtkParticleImageComparison::WriteErrorMap(a, b, excluded, diff.c_str(), diffScale))
  {
    std::cerr << "prCompareImages: cannot write " << diff << "\n";
    return 2;
  }
  return (maxError >= 0.0 && r.MaxAbsError > maxError) ? 1 : 0;
}
