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
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <fstream>
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
bool vtkParticleImageComparison::Compare(
  vtkImageData* a, vtkImageData* b, vtkDataArray* excluded, double tolerance, Result& result)
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
  const int nc = std::min(std::min(va.Components, vb.Components), 4);
  result.NumberOfComponents = nc;
  double sum2 = 0.0;
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
      over |= e > tolerance;
      result.ChannelMaxAbsError[c] = std::max(result.ChannelMaxAbsError[c], e);
      if (e > result.MaxAbsError)
      {
        result.MaxAbsError = e;
        result.MaxErrorPixel[0] = static_cast<int>(pixel % va.Width);
        result.MaxErrorPixel[1] = static_cast<int>(pixel / va.Width);
      }
    }
    result.NumberOfPixelsOverTolerance += over ? 1 : 0;
  }
  const double values = static_cast<double>(result.NumberOfComparedPixels) * nc;
  result.RMSE = values > 0 ? std::sqrt(sum2 / values) : 0.0;
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleImageComparison::CompareImages(
  vtkImageData* a, vtkImageData* b, vtkDataArray* excluded)
{
  Result r;
  const bool ok = Compare(a, b, excluded, this->Tolerance, r);
  this->RMSE = r.RMSE;
  this->MaxAbsError = r.MaxAbsError;
  std::copy(r.ChannelMaxAbsError, r.ChannelMaxAbsError + 4, this->ChannelMaxAbsError);
  this->MaxErrorPixel[0] = r.MaxErrorPixel[0];
  this->MaxErrorPixel[1] = r.MaxErrorPixel[1];
  this->NumberOfComponents = r.NumberOfComponents;
  this->NumberOfComparedPixels = static_cast<vtkIdType>(r.NumberOfComparedPixels);
  this->NumberOfExcludedPixels = static_cast<vtkIdType>(r.NumberOfExcludedPixels);
  this->NumberOfPixelsOverTolerance = static_cast<vtkIdType>(r.NumberOfPixelsOverTolerance);
  this->Modified();
  return ok;
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
void vtkParticleImageComparison::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
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
