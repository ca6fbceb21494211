#include "vtkParticleImageComparison.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkParticleGLDebugLog.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkParticleImageComparison);

namespace
{
// The colour values of an image, in [0,1] units.
class ImageValues
{
public:
  bool Set(vtkImageData* image, const char* which)
  {
    this->Array = nullptr;
    if (!image)
    {
      vtkGenericWarningMacro(<< "vtkParticleImageComparison: image " << which << " is null.");
      return false;
    }
    int dims[3];
    image->GetDimensions(dims);
    this->Width = dims[0];
    this->Height = dims[1];
    this->Array = image->GetPointData()->GetScalars();
    if (!this->Array || dims[2] != 1 || this->Width <= 0 || this->Height <= 0)
    {
      vtkGenericWarningMacro(<< "vtkParticleImageComparison: image " << which
                             << " is not a 2D image with scalars.");
      this->Array = nullptr;
      return false;
    }
    switch (this->Array->GetDataType())
    {
      case VTK_UNSIGNED_CHAR:
        this->Scale = 1.0 / 255.0;
        break;
      case VTK_UNSIGNED_SHORT:
        this->Scale = 1.0 / 65535.0;
        break;
      default:
        this->Scale = 1.0;
    }
    this->Components = this->Array->GetNumberOfComponents();
    return true;
  }

  double Get(vtkIdType pixel, int component) const
  {
    return this->Array->GetComponent(pixel, component) * this->Scale;
  }

  vtkDataArray* Array = nullptr;
  double Scale = 1.0;
  int Width = 0;
  int Height = 0;
  int Components = 0;
};

bool CheckMask(vtkDataArray* mask, vtkIdType pixels)
{
  if (mask && mask->GetNumberOfTuples() != pixels)
  {
    vtkGenericWarningMacro(<< "vtkParticleImageComparison: the mask has "
                           << mask->GetNumberOfTuples() << " values for " << pixels << " pixels.");
    return false;
  }
  return true;
}

bool Excluded(vtkDataArray* mask, vtkIdType pixel)
{
  return mask && mask->GetComponent(pixel, 0) != 0.0;
}

void ResizeMask(vtkUnsignedCharArray* mask, vtkIdType pixels)
{
  mask->SetNumberOfComponents(1);
  mask->SetNumberOfTuples(pixels);
  mask->FillValue(0);
}
}

//------------------------------------------------------------------------------
bool vtkParticleImageComparison::Compare(vtkImageData* a, vtkImageData* b, vtkDataArray* excluded,
  double tolerance, Result& result, int maxComponents)
{
  result = Result();
  ImageValues va;
  ImageValues vb;
  if (!va.Set(a, "a") || !vb.Set(b, "b"))
  {
    return false;
  }
  if (va.Width != vb.Width || va.Height != vb.Height)
  {
    vtkGenericWarningMacro(<< "vtkParticleImageComparison: sizes differ, " << va.Width << "x"
                           << va.Height << " vs. " << vb.Width << "x" << vb.Height << ".");
    return false;
  }
  const vtkIdType pixels = static_cast<vtkIdType>(va.Width) * va.Height;
  if (!CheckMask(excluded, pixels))
  {
    return false;
  }
  const int nc =
    std::max(1, std::min(std::min(va.Components, vb.Components), std::min(maxComponents, 4)));
  result.NumberOfComponents = nc;
  double sum2 = 0.0;
  double sum[4] = { 0, 0, 0, 0 };
  for (vtkIdType pixel = 0; pixel < pixels; ++pixel)
  {
    if (Excluded(excluded, pixel))
    {
      ++result.NumberOfExcludedPixels;
      continue;
    }
    ++result.NumberOfComparedPixels;
    bool over = false;
    for (int c = 0; c < nc; ++c)
    {
      double e = std::abs(va.Get(pixel, c) - vb.Get(pixel, c));
      if (!std::isfinite(e))
      {
        e = 1.0; // a NaN or Inf in an image is an error, never a pass
      }
      sum2 += e * e;
      sum[c] += e;
      over |= e > tolerance;
      result.ChannelMaxAbsError[c] = std::max(result.ChannelMaxAbsError[c], e);
      if (e > result.MaxAbsError)
      {
        result.MaxAbsError = e;
        result.MaxErrorPixel[0] = static_cast<int>(pixel % va.Width);
        result.MaxErrorPixel[1] = static_cast<int>(pixel / va.Width);
      }
    }
    if (over)
    {
      const int x = static_cast<int>(pixel % va.Width);
      const int y = static_cast<int>(pixel / va.Width);
      int* box = result.OverToleranceBox;
      if (result.NumberOfPixelsOverTolerance == 0)
      {
        box[0] = box[1] = x;
        box[2] = box[3] = y;
      }
      box[0] = std::min(box[0], x);
      box[1] = std::max(box[1], x);
      box[2] = std::min(box[2], y);
      box[3] = std::max(box[3], y);
      ++result.NumberOfPixelsOverTolerance;
    }
  }
  const double values = static_cast<double>(result.NumberOfComparedPixels) * nc;
  result.RMSE = values > 0 ? std::sqrt(sum2 / values) : 0.0;
  for (int c = 0; c < nc; ++c)
  {
    result.ChannelMeanAbsError[c] =
      result.NumberOfComparedPixels > 0 ? sum[c] / result.NumberOfComparedPixels : 0.0;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleImageComparison::KeepResult(const Result& r)
{
  this->RMSE = r.RMSE;
  this->MaxAbsError = r.MaxAbsError;
  std::copy(r.ChannelMaxAbsError, r.ChannelMaxAbsError + 4, this->ChannelMaxAbsError);
  std::copy(r.ChannelMeanAbsError, r.ChannelMeanAbsError + 4, this->ChannelMeanAbsError);
  this->MaxErrorPixel[0] = r.MaxErrorPixel[0];
  this->MaxErrorPixel[1] = r.MaxErrorPixel[1];
  this->NumberOfComponents = r.NumberOfComponents;
  this->NumberOfComparedPixels = static_cast<vtkIdType>(r.NumberOfComparedPixels);
  this->NumberOfExcludedPixels = static_cast<vtkIdType>(r.NumberOfExcludedPixels);
  this->NumberOfPixelsOverTolerance = static_cast<vtkIdType>(r.NumberOfPixelsOverTolerance);
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkParticleImageComparison::CompareImages(
  vtkImageData* a, vtkImageData* b, vtkDataArray* excluded)
{
  Result r;
  const bool ok = Compare(a, b, excluded, this->Tolerance, r, this->ComparedComponents);
  this->KeepResult(r);
  return ok;
}

//------------------------------------------------------------------------------
// Image tests
//------------------------------------------------------------------------------
namespace
{
std::string Format255(double v)
{
  std::ostringstream os;
  os << std::setprecision(3) << v * 255.0 << "/255";
  return os.str();
}
}

double vtkParticleImageComparison::Evaluate(const Result& r, std::string& reason) const
{
  reason.clear();
  double worstMean = 0.0;
  int meanChannel = 0;
  for (int c = 0; c < r.NumberOfComponents; ++c)
  {
    if (r.ChannelMeanAbsError[c] > worstMean)
    {
      worstMean = r.ChannelMeanAbsError[c];
      meanChannel = c;
    }
  }
  const double share = r.NumberOfComparedPixels > 0
    ? static_cast<double>(r.NumberOfPixelsOverTolerance) / r.NumberOfComparedPixels
    : 0.0;
  const double terms[3] = { worstMean / this->MaximumMeanError, r.MaxAbsError / this->MaximumError,
    share / this->MaximumOverToleranceFraction };
  const double score = std::max(terms[0], std::max(terms[1], terms[2]));
  std::ostringstream why;
  const char* separator = "";
  if (terms[0] > 1.0)
  {
    why << "mean error " << Format255(worstMean) << " (channel " << meanChannel << ") > "
        << Format255(this->MaximumMeanError);
    separator = "; ";
  }
  if (terms[1] > 1.0)
  {
    why << separator << "max error " << Format255(r.MaxAbsError) << " at (" << r.MaxErrorPixel[0]
        << ", " << r.MaxErrorPixel[1] << ") > " << Format255(this->MaximumError);
    separator = "; ";
  }
  if (terms[2] > 1.0)
  {
    why << separator << r.NumberOfPixelsOverTolerance << " pixels (" << std::setprecision(3)
        << 100.0 * share << " %) over " << Format255(this->Tolerance) << " > "
        << 100.0 * this->MaximumOverToleranceFraction << " %";
  }
  if (r.NumberOfComparedPixels == 0)
  {
    why << separator << "no pixel compared";
    reason = why.str();
    return std::numeric_limits<double>::infinity();
  }
  reason = why.str();
  return score;
}

vtkSmartPointer<vtkUnsignedCharArray> vtkParticleImageComparison::CriteriaMask(
  vtkImageData* expected, vtkDataArray* excluded)
{
  if (this->MaskRadius <= 0 && !excluded)
  {
    return nullptr;
  }
  auto mask = vtkSmartPointer<vtkUnsignedCharArray>::New();
  if (this->MaskRadius > 0)
  {
    if (!MakeEdgeMask(expected, nullptr, this->MaskRadius, this->EdgeThreshold, mask))
    {
      return nullptr;
    }
  }
  else
  {
    ResizeMask(mask, excluded->GetNumberOfTuples());
  }
  if (excluded)
  {
    if (excluded->GetNumberOfTuples() != mask->GetNumberOfTuples())
    {
      vtkErrorMacro(<< "The exclusion mask has " << excluded->GetNumberOfTuples() << " values for "
                    << mask->GetNumberOfTuples() << " pixels.");
      return nullptr;
    }
    for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
    {
      mask->SetValue(i, (mask->GetValue(i) || Excluded(excluded, i)) ? 1 : 0);
    }
  }
  return mask;
}

bool vtkParticleImageComparison::Judge(vtkImageData* image, vtkImageData* expected,
  vtkDataArray* excluded, Result& result, double& score, std::string& reason)
{
  score = std::numeric_limits<double>::infinity();
  vtkSmartPointer<vtkUnsignedCharArray> mask = this->CriteriaMask(expected, excluded);
  if ((this->MaskRadius > 0 || excluded) && !mask)
  {
    reason = "the exclusion mask could not be made";
    return false;
  }
  if (!Compare(image, expected, mask, this->Tolerance, result, this->ComparedComponents))
  {
    reason = "the images cannot be compared (size or scalars)";
    return false;
  }
  score = this->Evaluate(result, reason);
  return true;
}

bool vtkParticleImageComparison::TestImages(vtkImageData* image, vtkImageData* expected,
  vtkDataArray* excluded, const char* tempDirectory, const char* name)
{
  const std::string label = name ? name : "image";
  Result r;
  std::string reason;
  const bool compared = this->Judge(image, expected, excluded, r, this->Score, reason);
  this->KeepResult(r);
  const bool passed = compared && this->Score <= 1.0;
  this->FailureReason = passed ? std::string() : reason;

  double worstMean = 0.0;
  for (int c = 0; c < r.NumberOfComponents; ++c)
  {
    worstMean = std::max(worstMean, r.ChannelMeanAbsError[c]);
  }
  std::cout << "image test " << label << ": " << (passed ? "passed" : "FAILED") << ", score "
            << std::setprecision(4) << this->Score << " (pass <= 1)\n"
            << "  criteria: mean <= " << Format255(this->MaximumMeanError)
            << ", max <= " << Format255(this->MaximumError) << ", pixels over "
            << Format255(this->Tolerance) << " <= " << 100.0 * this->MaximumOverToleranceFraction
            << " %, mask radius " << this->MaskRadius << "\n";
  if (compared)
  {
    std::cout << "  measured: mean " << Format255(worstMean) << ", max " << Format255(r.MaxAbsError)
              << " at (" << r.MaxErrorPixel[0] << ", " << r.MaxErrorPixel[1] << "), "
              << r.NumberOfPixelsOverTolerance << " pixels over tolerance";
    if (r.NumberOfPixelsOverTolerance > 0)
    {
      std::cout << " in x " << r.OverToleranceBox[0] << ".." << r.OverToleranceBox[1] << ", y "
                << r.OverToleranceBox[2] << ".." << r.OverToleranceBox[3];
    }
    std::cout << " (of " << r.NumberOfComparedPixels << " compared, " << r.NumberOfExcludedPixels
              << " masked), RMSE " << Format255(r.RMSE) << "\n";
  }
  if (!passed)
  {
    std::cout << "  reason: " << this->FailureReason << "\n";
  }
  if (compared && tempDirectory && *tempDirectory)
  {
    const std::string diff = std::string(tempDirectory) + "/" + label + ".diff.png";
    vtkSmartPointer<vtkUnsignedCharArray> mask = this->CriteriaMask(expected, excluded);
    if (WriteErrorMap(image, expected, mask, diff.c_str(), 8.0))
    {
      std::cout << "  difference image (|error| x 8, masked grey): " << diff << "\n";
    }
  }
  std::cout.flush();
  return passed;
}

bool vtkParticleImageComparison::TestRejects(
  vtkImageData* wrong, vtkImageData* expected, vtkDataArray* excluded, const char* name)
{
  Result r;
  double score;
  std::string reason;
  const bool compared = this->Judge(wrong, expected, excluded, r, score, reason);
  const bool rejected = compared && score > 1.0;
  std::cout << "MUST-FAIL " << (name ? name : "picture") << ": "
            << (rejected ? "rejected"
                         : (compared ? "ACCEPTED (the criteria cannot see it)"
                                     : "NOT COMPARED (wrong reason)"))
            << ", score " << std::setprecision(4) << score;
  if (!reason.empty())
  {
    std::cout << " (" << reason << ")";
  }
  std::cout << "\n";
  std::cout.flush();
  this->Score = score;
  this->FailureReason = reason;
  return rejected;
}

bool vtkParticleImageComparison::TestImage(
  vtkImageData* image, const char* baselineFile, const char* tempDirectory, const char* name)
{
  const std::string label = name ? name : "image";
  const std::string temp = (tempDirectory && *tempDirectory) ? tempDirectory : ".";
  const std::string written = temp + "/" + label + ".png";
  if (image)
  {
    WritePNG(image, written.c_str());
  }
  vtkNew<vtkImageData> baseline;
  if (!baselineFile || !*baselineFile || !std::ifstream(baselineFile).good())
  {
    std::cout << "image test " << label << ": FAILED, baseline "
              << (baselineFile ? baselineFile : "(none)") << " does not exist (the image is "
              << written << ")\n";
    this->Score = std::numeric_limits<double>::infinity();
    this->FailureReason = "no baseline";
    return false;
  }
  if (!ReadImage(baselineFile, baseline))
  {
    std::cout << "image test " << label << ": FAILED, cannot read " << baselineFile << "\n";
    this->Score = std::numeric_limits<double>::infinity();
    this->FailureReason = "unreadable baseline";
    return false;
  }
  std::cout << "image test " << label << ": " << written << " against " << baselineFile << "\n";
  bool ok = this->TestImages(image, baseline, nullptr, temp.c_str(), label.c_str());
  const double score = this->Score;
  const std::string reason = this->FailureReason;

  // The criteria must see what a baseline test exists for: a 10 % darker picture and an edge
  // one pixel outside the mask.
  const bool darkened = this->TestRejects(
    Scaled(baseline, 0.9), baseline, nullptr, (label + " (baseline 10 % darker)").c_str());
  this->DarkenedScore = this->Score;
  const int shift = this->MaskRadius + 1;
  const bool shifted = this->TestRejects(Shifted(baseline, shift, 0), baseline, nullptr,
    (label + " (baseline shifted " + std::to_string(shift) + " px)").c_str());
  this->ShiftedScore = this->Score;
  if (!darkened || !shifted)
  {
    std::cout << "FAIL: the criteria of " << label << " accept a wrong picture\n";
    ok = false;
  }
  std::cout << "  margin: image score " << std::setprecision(4) << score
            << ", nearest built-in must-fail score "
            << std::min(this->DarkenedScore, this->ShiftedScore) << "\n";
  std::cout.flush();
  this->Score = score;
  this->FailureReason = reason;
  return ok;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkParticleImageComparison::Scaled(vtkImageData* image, double factor)
{
  auto out = vtkSmartPointer<vtkImageData>::New();
  if (!image || !image->GetPointData()->GetScalars())
  {
    return out;
  }
  out->DeepCopy(image);
  vtkDataArray* values = out->GetPointData()->GetScalars();
  const int nc = values->GetNumberOfComponents();
  const int colour = nc == 4 || nc == 2 ? nc - 1 : nc; // alpha stays
  const bool bytes = values->GetDataType() == VTK_UNSIGNED_CHAR;
  const double top = bytes ? 255.0 : values->GetDataTypeMax();
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < colour; ++c)
    {
      double v = values->GetComponent(i, c) * factor;
      if (bytes)
      {
        v = std::min(top, std::max(0.0, std::round(v)));
      }
      values->SetComponent(i, c, v);
    }
  }
  return out;
}

vtkSmartPointer<vtkImageData> vtkParticleImageComparison::Shifted(
  vtkImageData* image, int dx, int dy)
{
  auto out = vtkSmartPointer<vtkImageData>::New();
  if (!image || !image->GetPointData()->GetScalars())
  {
    return out;
  }
  out->DeepCopy(image);
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* in = image->GetPointData()->GetScalars();
  vtkDataArray* values = out->GetPointData()->GetScalars();
  for (int y = 0; y < dims[1]; ++y)
  {
    const int sy = std::min(dims[1] - 1, std::max(0, y - dy));
    for (int x = 0; x < dims[0]; ++x)
    {
      const int sx = std::min(dims[0] - 1, std::max(0, x - dx));
      values->SetTuple(
        static_cast<vtkIdType>(y) * dims[0] + x, static_cast<vtkIdType>(sy) * dims[0] + sx, in);
    }
  }
  return out;
}

//------------------------------------------------------------------------------
void vtkParticleImageComparison::MakeSilhouetteMask(
  vtkIdTypeArray* ids, int width, int height, int radius, vtkUnsignedCharArray* mask)
{
  if (!mask)
  {
    return;
  }
  const vtkIdType pixels = static_cast<vtkIdType>(std::max(width, 0)) * std::max(height, 0);
  ResizeMask(mask, pixels);
  if (!ids || ids->GetNumberOfTuples() != pixels)
  {
    vtkGenericWarningMacro(<< "vtkParticleImageComparison: the id image does not have " << pixels
                           << " values: every pixel excluded.");
    mask->FillValue(1);
    return;
  }
  radius = std::max(radius, 0);
  const vtkIdType* id = ids->GetPointer(0);
  unsigned char* out = mask->GetPointer(0);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const vtkIdType self = id[static_cast<vtkIdType>(y) * width + x];
      // what lies beyond the image border is unknown
      bool edge = x < radius || y < radius || x >= width - radius || y >= height - radius;
      for (int yy = std::max(0, y - radius); yy <= std::min(height - 1, y + radius) && !edge; ++yy)
      {
        for (int xx = std::max(0, x - radius); xx <= std::min(width - 1, x + radius); ++xx)
        {
          const int dx = xx - x;
          const int dy = yy - y;
          if (dx * dx + dy * dy <= radius * radius &&
            id[static_cast<vtkIdType>(yy) * width + xx] != self)
          {
            edge = true;
            break;
          }
        }
      }
      out[static_cast<vtkIdType>(y) * width + x] = edge ? 1 : 0;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkParticleImageComparison::MakeEdgeMask(
  vtkImageData* a, vtkImageData* b, int radius, double threshold, vtkUnsignedCharArray* mask)
{
  if (!mask)
  {
    return false;
  }
  ImageValues images[2];
  int count = 0;
  if (!images[0].Set(a, "a"))
  {
    return false;
  }
  ++count;
  if (b)
  {
    if (!images[1].Set(b, "b"))
    {
      return false;
    }
    if (images[1].Width != images[0].Width || images[1].Height != images[0].Height)
    {
      vtkGenericWarningMacro(<< "vtkParticleImageComparison: sizes differ.");
      return false;
    }
    ++count;
  }
  const int width = images[0].Width;
  const int height = images[0].Height;
  ResizeMask(mask, static_cast<vtkIdType>(width) * height);
  unsigned char* out = mask->GetPointer(0);
  radius = std::max(radius, 0);
  for (int i = 0; i < count; ++i)
  {
    const ImageValues& image = images[i];
    const int nc = std::min(image.Components, 4);
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        const vtkIdType pixel = static_cast<vtkIdType>(y) * width + x;
        if (out[pixel])
        {
          continue;
        }
        bool edge = false;
        for (int yy = std::max(0, y - radius); yy <= std::min(height - 1, y + radius) && !edge;
             ++yy)
        {
          for (int xx = std::max(0, x - radius); xx <= std::min(width - 1, x + radius) && !edge;
               ++xx)
          {
            if ((xx - x) * (xx - x) + (yy - y) * (yy - y) > radius * radius)
            {
              continue;
            }
            const vtkIdType other = static_cast<vtkIdType>(yy) * width + xx;
            for (int c = 0; c < nc; ++c)
            {
              if (!(std::abs(image.Get(pixel, c) - image.Get(other, c)) <= threshold))
              {
                edge = true;
                break;
              }
            }
          }
        }
        out[pixel] = edge ? 1 : 0;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleImageComparison::WriteErrorMap(
  vtkImageData* a, vtkImageData* b, vtkDataArray* excluded, const char* fileName, double scale)
{
  ImageValues va;
  ImageValues vb;
  if (!fileName || !va.Set(a, "a") || !vb.Set(b, "b"))
  {
    return false;
  }
  if (va.Width != vb.Width || va.Height != vb.Height)
  {
    vtkGenericWarningMacro(<< "vtkParticleImageComparison: sizes differ.");
    return false;
  }
  const vtkIdType pixels = static_cast<vtkIdType>(va.Width) * va.Height;
  if (!CheckMask(excluded, pixels))
  {
    return false;
  }
  const int nc = std::min(std::min(va.Components, vb.Components), 4);
  vtkNew<vtkImageData> map;
  map->SetDimensions(va.Width, va.Height, 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(pixels);
  for (vtkIdType pixel = 0; pixel < pixels; ++pixel)
  {
    unsigned char* out = rgb->GetPointer(3 * pixel);
    if (Excluded(excluded, pixel))
    {
      out[0] = out[1] = out[2] = 128;
      continue;
    }
    double e = 0.0;
    for (int c = 0; c < nc; ++c)
    {
      const double d = std::abs(va.Get(pixel, c) - vb.Get(pixel, c));
      e = std::isfinite(d) ? std::max(e, d) : 1e300;
    }
    const double v = std::min(1.0, std::max(0.0, e * scale));
    // black -> red -> yellow -> white
    const double channel[3] = { 3.0 * v, 3.0 * v - 1.0, 3.0 * v - 2.0 };
    for (int c = 0; c < 3; ++c)
    {
      out[c] =
        static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, channel[c]))));
    }
  }
  map->GetPointData()->SetScalars(rgb);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(fileName);
  writer->SetInputData(map);
  writer->Write();
  return writer->GetErrorCode() == 0;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkParticleImageComparison::ExtractRGB(vtkImageData* rgba)
{
  auto rgb = vtkSmartPointer<vtkImageData>::New();
  rgb->SetDimensions(rgba->GetDimensions());
  rgb->AllocateScalars(VTK_DOUBLE, 3);
  vtkDataArray* in = rgba->GetPointData()->GetScalars();
  vtkDataArray* out = rgb->GetPointData()->GetScalars();
  const int components = std::min(3, in->GetNumberOfComponents());
  for (vtkIdType i = 0; i < in->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      out->SetComponent(i, k, in->GetComponent(i, std::min(k, components - 1)));
    }
  }
  return rgb;
}

//------------------------------------------------------------------------------
bool vtkParticleImageComparison::WritePNG(vtkImageData* image, const char* fileName)
{
  ImageValues values;
  if (!fileName || !values.Set(image, "image"))
  {
    return false;
  }
  const int nc = std::min(values.Components, 4);
  const vtkIdType pixels = static_cast<vtkIdType>(values.Width) * values.Height;
  vtkNew<vtkImageData> out;
  out->SetDimensions(values.Width, values.Height, 1);
  vtkNew<vtkUnsignedCharArray> bytes;
  bytes->SetNumberOfComponents(nc);
  bytes->SetNumberOfTuples(pixels);
  for (vtkIdType pixel = 0; pixel < pixels; ++pixel)
  {
    for (int c = 0; c < nc; ++c)
    {
      const double v = values.Get(pixel, c);
      bytes->SetValue(nc * pixel + c,
        static_cast<unsigned char>(
          std::lround(255.0 * (std::isfinite(v) ? std::min(1.0, std::max(0.0, v)) : 0.0))));
    }
  }
  out->GetPointData()->SetScalars(bytes);
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(fileName);
  writer->SetInputData(out);
  writer->Write();
  return writer->GetErrorCode() == 0;
}

//------------------------------------------------------------------------------
bool vtkParticleImageComparison::ReadImage(const char* fileName, vtkImageData* image)
{
  if (!fileName || !image)
  {
    return false;
  }
  if (!std::ifstream(fileName).good())
  {
    vtkGenericWarningMacro(<< "vtkParticleImageComparison: cannot open " << fileName << ".");
    return false;
  }
  vtkNew<vtkImageReader2Factory> factory;
  vtkSmartPointer<vtkImageReader2> reader;
  reader.TakeReference(factory->CreateImageReader2(fileName));
  if (!reader)
  {
    vtkGenericWarningMacro(<< "vtkParticleImageComparison: cannot read " << fileName << ".");
    return false;
  }
  reader->SetFileName(fileName);
  reader->Update();
  vtkImageData* out = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || !out || !out->GetPointData()->GetScalars())
  {
    vtkGenericWarningMacro(<< "vtkParticleImageComparison: cannot read " << fileName << ".");
    return false;
  }
  image->ShallowCopy(out);
  return true;
}

//------------------------------------------------------------------------------
namespace
{
bool Region(vtkRenderWindow* window, vtkRenderer* viewport, int& x0, int& y0, int& w, int& h)
{
  if (!window)
  {
    return false;
  }
  if (viewport)
  {
    viewport->GetTiledSizeAndOrigin(&w, &h, &x0, &y0);
  }
  else
  {
    const int* size = window->GetSize();
    x0 = y0 = 0;
    w = size[0];
    h = size[1];
  }
  return w > 0 && h > 0;
}
}

bool vtkParticleImageComparison::GrabColorBuffer(
  vtkRenderWindow* window, vtkImageData* color, vtkRenderer* viewport)
{
  int x0, y0, w, h;
  if (!color || !Region(window, viewport, x0, y0, w, h))
  {
    return false;
  }
  vtkNew<vtkFloatArray> rgba;
  if (window->GetRGBAPixelData(x0, y0, x0 + w - 1, y0 + h - 1, 0, rgba) != VTK_OK)
  {
    vtkGenericWarningMacro(<< "vtkParticleImageComparison: cannot read the colour buffer.");
    return false;
  }
  vtkNew<vtkDoubleArray> values;
  values->SetName("Color");
  values->SetNumberOfComponents(4);
  values->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  const float* in = rgba->GetPointer(0);
  double* out = values->GetPointer(0);
  std::copy(in, in + 4 * static_cast<vtkIdType>(w) * h, out);
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->GetPointData()->SetScalars(values);
  color->ShallowCopy(image);
  return true;
}

bool vtkParticleImageComparison::GrabDepthBuffer(
  vtkRenderWindow* window, vtkImageData* depth, vtkRenderer* viewport)
{
  int x0, y0, w, h;
  if (!depth || !Region(window, viewport, x0, y0, w, h))
  {
    return false;
  }
  vtkNew<vtkFloatArray> z;
  z->SetNumberOfComponents(1);
  z->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  if (window->GetZbufferData(x0, y0, x0 + w - 1, y0 + h - 1, z) != VTK_OK)
  {
    vtkGenericWarningMacro(<< "vtkParticleImageComparison: cannot read the depth buffer.");
    return false;
  }
  vtkNew<vtkDoubleArray> values;
  values->SetName("Depth");
  values->SetNumberOfComponents(1);
  values->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  const float* in = z->GetPointer(0);
  std::copy(in, in + static_cast<vtkIdType>(w) * h, values->GetPointer(0));
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->GetPointData()->SetScalars(values);
  depth->ShallowCopy(image);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleImageComparison::TestIdentical(
  vtkImageData* first, vtkImageData* again, const char* name)
{
  const char* label = name ? name : "picture";
  ImageValues va;
  ImageValues vb;
  if (!va.Set(first, "first") || !vb.Set(again, "again") || va.Width != vb.Width ||
    va.Height != vb.Height || va.Components < 3 || vb.Components < 3)
  {
    std::cout << "REPEAT " << label << ": NOT COMPARED (no RGB images of the same size)\n";
    std::cout.flush();
    return false;
  }
  // the 8-bit value of a channel (NaN and Inf, never in an 8-bit picture, as -1)
  auto byte = [](double v) { return std::isfinite(v) ? std::lround(v * 255.0) : -1L; };
  long long differing = 0;
  long worst = 0;
  int worstPixel[2] = { -1, -1 };
  int box[4] = { va.Width, -1, va.Height, -1 };
  const vtkIdType pixels = static_cast<vtkIdType>(va.Width) * va.Height;
  for (vtkIdType pixel = 0; pixel < pixels; ++pixel)
  {
    long largest = 0;
    for (int c = 0; c < 3; ++c)
    {
      const long a = byte(va.Get(pixel, c));
      const long b = byte(vb.Get(pixel, c));
      largest = std::max(largest, (a < 0 || b < 0) ? (a == b ? 0L : 255L) : std::abs(a - b));
    }
    if (largest == 0)
    {
      continue;
    }
    const int x = static_cast<int>(pixel % va.Width);
    const int y = static_cast<int>(pixel / va.Width);
    ++differing;
    if (largest > worst)
    {
      worst = largest;
      worstPixel[0] = x;
      worstPixel[1] = y;
    }
    box[0] = std::min(box[0], x);
    box[1] = std::max(box[1], x);
    box[2] = std::min(box[2], y);
    box[3] = std::max(box[3], y);
  }
  std::cout << "REPEAT " << label << ": ";
  if (differing == 0)
  {
    std::cout << "identical (" << va.Width << " x " << va.Height << ")\n";
  }
  else
  {
    std::cout << "DIFFERS on " << differing << " of " << pixels << " pixels, max " << worst
              << "/255 at (" << worstPixel[0] << ", " << worstPixel[1] << "), in x " << box[0]
              << ".." << box[1] << ", y " << box[2] << ".." << box[3]
              << " (the same frame drawn twice)\n";
  }
  std::cout.flush();
  return differing == 0;
}

//------------------------------------------------------------------------------
bool vtkParticleImageComparison::TestRepeatable(
  vtkRenderWindow* window, const char* name, vtkRenderer* viewport)
{
  vtkNew<vtkImageData> first;
  vtkNew<vtkImageData> again;
  const char* label = name ? name : "picture";
  window->Render();
  if (!GrabColorBuffer(window, first, viewport))
  {
    std::cout << "REPEAT " << label << ": NOT COMPARED (no picture)\n";
    return false;
  }
  // the second frame under the context's debug output: a GL error or undefined behaviour that
  // the driver reports fails the check too
  vtkParticleGLDebugLog* log = vtkParticleGLDebugLog::GetInstance();
  log->StartFrame(window);
  window->Render();
  const bool clean = log->EndFrame(label);
  if (!GrabColorBuffer(window, again, viewport))
  {
    std::cout << "REPEAT " << label << ": NOT COMPARED (no picture)\n";
    return false;
  }
  return TestIdentical(first, again, name) && clean;
}

//------------------------------------------------------------------------------
void vtkParticleImageComparison::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumOverToleranceFraction: " << this->MaximumOverToleranceFraction << "\n";
  os << indent << "MaximumMeanError: " << this->MaximumMeanError << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "MaskRadius: " << this->MaskRadius << "\n";
  os << indent << "EdgeThreshold: " << this->EdgeThreshold << "\n";
  os << indent << "ComparedComponents: " << this->ComparedComponents << "\n";
  os << indent << "Score: " << this->Score << "\n";
  os << indent << "FailureReason: " << this->FailureReason << "\n";
  os << indent << "DarkenedScore: " << this->DarkenedScore << "\n";
  os << indent << "ShiftedScore: " << this->ShiftedScore << "\n";
  os << indent << "RMSE: " << this->RMSE << "\n";
  os << indent << "MaxAbsError: " << this->MaxAbsError << "\n";
  os << indent << "ChannelMaxAbsError: " << this->ChannelMaxAbsError[0] << " "
     << this->ChannelMaxAbsError[1] << " " << this->ChannelMaxAbsError[2] << " "
     << this->ChannelMaxAbsError[3] << "\n";
  os << indent << "MaxErrorPixel: " << this->MaxErrorPixel[0] << " " << this->MaxErrorPixel[1]
     << "\n";
  os << indent << "NumberOfComponents: " << this->NumberOfComponents << "\n";
  os << indent << "NumberOfComparedPixels: " << this->NumberOfComparedPixels << "\n";
  os << indent << "NumberOfExcludedPixels: " << this->NumberOfExcludedPixels << "\n";
  os << indent << "NumberOfPixelsOverTolerance: " << this->NumberOfPixelsOverTolerance << "\n";
}
