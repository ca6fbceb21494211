// The image comparison of the whole suite (vtkParticleImageComparison::TestImage, TestImages,
// TestRejects) tested on its own, with synthetic pictures whose differences are known exactly:
// a shaded disk ("sphere") on a background, 160 x 120 pixels, and wrong pictures of it:
//   - the same picture: passes with score 0;
//   - 10 % darker: rejected (mean error);
//   - the sphere's edge moved by one pixel: accepted with MaskRadius 1 (the move stays inside
//     the one-pixel band around the baseline's edges), rejected without a mask;
//   - the edge moved by two pixels, i.e. one pixel outside the mask: rejected;
//   - one pixel of 20/255 error: accepted under a share limit, rejected under MaximumError 10/255;
//   - a NaN pixel: rejected (an error of 1), never a pass;
//   - another size: not compared, which TestRejects reports as a rejection for the wrong reason
//     (false) and TestImages as a failure;
//   - a missing baseline file: TestImage fails (and still writes the image);
//   - criteria so loose that a 10 % darker baseline passes: TestImage fails;
//   - the repeatability check (TestIdentical): the same picture and its float copy are
//     identical; one value one step off, a moved edge, NaN and another size are not.
// It also checks the numbers behind the score: mean and maximum per channel, share of pixels
// over tolerance, the bounding box of those pixels, and the mask sizes.
#include "prTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParticleImageComparison.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>

namespace
{
const int Width = 160;
const int Height = 120;

// A disk of radius r centred at (cx, cy) on a dark background, 8-bit RGB: shaded (a lit
// sphere) or flat (only its edge changes when it moves).
vtkSmartPointer<vtkImageData> Disk(double cx, double cy, double r, bool shaded = true)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(Width, Height, 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(Width * Height);
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      const double dx = (x + 0.5 - cx) / r;
      const double dy = (y + 0.5 - cy) / r;
      const double d2 = dx * dx + dy * dy;
      double c[3] = { 0.1, 0.1, 0.15 };
      if (d2 < 1.0)
      {
        const double shade = shaded ? 0.3 + 0.7 * std::sqrt(1.0 - d2) : 0.8; // Lambert
        c[0] = 0.9 * shade;
        c[1] = 0.5 * shade;
        c[2] = 0.2 * shade;
      }
      for (int k = 0; k < 3; ++k)
      {
        rgb->SetValue(3 * (y * Width + x) + k, static_cast<unsigned char>(std::lround(255 * c[k])));
      }
    }
  }
  image->GetPointData()->SetScalars(rgb);
  return image;
}

void Criteria(vtkParticleImageComparison* comparison, int maskRadius)
{
  comparison->SetTolerance(2.0 / 255.0);
  comparison->SetMaximumOverToleranceFraction(1e-3);
  comparison->SetMaximumMeanError(0.5 / 255.0);
  comparison->SetMaximumError(1.0);
  comparison->SetMaskRadius(maskRadius);
}
}

int TestImageComparison(int argc, char* argv[])
{
  const std::string temp = prTest::TempDirectory(argc, argv);
  bool ok = true;
  vtkSmartPointer<vtkImageData> baseline = Disk(80.0, 60.0, 40.0);
  vtkNew<vtkParticleImageComparison> comparison;
  Criteria(comparison, 0);

  // the same picture
  ok &= prTest::Check(
    comparison->TestImages(Disk(80.0, 60.0, 40.0), baseline, nullptr, temp.c_str(), "same"),
    "the same picture passes");
  ok &= prTest::Check(comparison->GetScore() == 0.0, "the same picture scores 0");

  // 10 % darker: the mean error is 10 % of the mean colour
  vtkSmartPointer<vtkImageData> darker = vtkParticleImageComparison::Scaled(baseline, 0.9);
  ok &= prTest::Check(
    comparison->TestRejects(darker, baseline, nullptr, "10 % darker"), "10 % darker is rejected");
  comparison->CompareImages(darker, baseline);
  double meanRed = 0.0;
  vtkDataArray* values = baseline->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    meanRed += values->GetComponent(i, 0);
  }
  meanRed /= values->GetNumberOfTuples() * 255.0;
  std::cout << "10 % darker: mean red error " << comparison->GetChannelMeanAbsError()[0]
            << ", 10 % of the mean red " << 0.1 * meanRed << "\n";
  ok &= prTest::Check(std::abs(comparison->GetChannelMeanAbsError()[0] - 0.1 * meanRed) < 0.5 / 255,
    "the mean error of the darker picture is 10 % of the mean colour (to rounding)");

  // the sphere's edge moved by one pixel (a flat disk: only the edge changes): inside the
  // one-pixel mask, outside without a mask
  vtkSmartPointer<vtkImageData> flat = Disk(80.0, 60.0, 40.0, false);
  vtkSmartPointer<vtkImageData> moved1 = Disk(81.0, 60.0, 40.0, false);
  vtkSmartPointer<vtkImageData> moved2 = Disk(82.0, 60.0, 40.0, false);
  ok &= prTest::Check(comparison->TestRejects(moved1, flat, nullptr, "edge moved 1 px, no mask"),
    "an edge moved by one pixel is rejected without a mask");
  {
    vtkParticleImageComparison::Result r;
    vtkParticleImageComparison::Compare(moved1, flat, nullptr, 2.0 / 255.0, r, 3);
    const int* box = r.OverToleranceBox;
    std::cout << "edge moved 1 px: " << r.NumberOfPixelsOverTolerance << " pixels over 2/255 in x "
              << box[0] << ".." << box[1] << ", y " << box[2] << ".." << box[3] << "\n";
    // the changed pixels lie on the disk's two vertical edges: x in [40, 121], y in [20, 99]
    ok &= prTest::Check(box[0] >= 39 && box[1] <= 122 && box[2] >= 19 && box[3] <= 100 &&
        r.NumberOfPixelsOverTolerance > 20,
      "the pixels over tolerance are on the disk's edge");
  }
  Criteria(comparison, 1);
  ok &= prTest::Check(
    comparison->TestImages(moved1, flat, nullptr, temp.c_str(), "edge moved 1 px, mask 1"),
    "an edge moved by one pixel passes inside a one-pixel mask");
  ok &= prTest::Check(comparison->GetNumberOfExcludedPixels() > 0, "the mask excludes pixels");
  ok &= prTest::Check(comparison->TestRejects(moved2, flat, nullptr, "edge moved 2 px, mask 1"),
    "an edge one pixel outside the mask is rejected");
  Criteria(comparison, 0);

  // one wrong pixel: under the share limit it passes, a maximum error rejects it
  vtkSmartPointer<vtkImageData> speck = Disk(80.0, 60.0, 40.0);
  vtkDataArray* speckValues = speck->GetPointData()->GetScalars();
  speckValues->SetComponent(60 * Width + 80, 1, speckValues->GetComponent(60 * Width + 80, 1) + 20);
  ok &= prTest::Check(comparison->TestImages(speck, baseline, nullptr, "", "one pixel, share"),
    "one pixel of 20/255 is within a share limit of 0.1 %");
  comparison->SetMaximumError(10.0 / 255.0);
  ok &= prTest::Check(comparison->TestRejects(speck, baseline, nullptr, "one pixel, max 10/255"),
    "one pixel of 20/255 is rejected under a maximum error of 10/255");
  ok &= prTest::Check(
    comparison->GetMaxErrorPixel()[0] == 80 && comparison->GetMaxErrorPixel()[1] == 60,
    "the largest error is reported where it is");
  Criteria(comparison, 0);

  // a NaN pixel (floating-point image) is an error of 1
  vtkNew<vtkImageData> nan;
  nan->SetDimensions(Width, Height, 1);
  vtkNew<vtkDoubleArray> nanValues;
  nanValues->SetNumberOfComponents(3);
  nanValues->SetNumberOfTuples(Width * Height);
  for (vtkIdType i = 0; i < Width * Height; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      nanValues->SetComponent(i, k, values->GetComponent(i, k) / 255.0);
    }
  }
  nanValues->SetComponent(100, 0, std::numeric_limits<double>::quiet_NaN());
  nan->GetPointData()->SetScalars(nanValues);
  comparison->SetMaximumError(0.5);
  ok &= prTest::Check(
    comparison->TestRejects(nan, baseline, nullptr, "NaN pixel"), "a NaN pixel is rejected");
  Criteria(comparison, 0);

  // another size: not compared, a rejection for the wrong reason
  vtkNew<vtkImageData> small;
  small->SetDimensions(Width / 2, Height / 2, 1);
  small->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  ok &= prTest::Check(!comparison->TestRejects(small, baseline, nullptr, "other size"),
    "a picture of another size is not counted as rejected for its pixels");
  ok &= prTest::Check(!comparison->TestImages(small, baseline, nullptr, "", "other size"),
    "a picture of another size fails");

  // the baseline test: a missing baseline fails; a real one passes, and the built-in wrong
  // pictures are rejected
  const std::string baselineFile = temp + "/TestImageComparison_baseline.png";
  ok &= prTest::Check(
    vtkParticleImageComparison::WritePNG(baseline, baselineFile.c_str()), "baseline written");
  ok &= prTest::Check(!comparison->TestImage(moved1, (temp + "/no_such_file.png").c_str(),
                        temp.c_str(), "TestImageComparison_missing"),
    "a missing baseline fails");
  ok &= prTest::Check(comparison->TestImage(Disk(80.0, 60.0, 40.0), baselineFile.c_str(),
                        temp.c_str(), "TestImageComparison_same"),
    "the baseline test passes the same picture");
  ok &= prTest::Check(comparison->GetDarkenedScore() > 1.0 && comparison->GetShiftedScore() > 1.0,
    "the built-in must-fail pictures score > 1");
  ok &= prTest::Check(!comparison->TestImage(Disk(82.0, 60.0, 40.0), baselineFile.c_str(),
                        temp.c_str(), "TestImageComparison_moved"),
    "the baseline test rejects the moved sphere");

  // criteria that cannot see a 10 % darker picture make the test fail
  vtkNew<vtkParticleImageComparison> loose;
  loose->SetTolerance(0.5);
  loose->SetMaximumOverToleranceFraction(1.0);
  loose->SetMaximumMeanError(0.2);
  ok &= prTest::Check(!loose->TestImage(Disk(80.0, 60.0, 40.0), baselineFile.c_str(), temp.c_str(),
                        "TestImageComparison_loose"),
    "criteria that accept a 10 % darker picture fail the test");

  // the repeatability check: identical only when every 8-bit RGB value is the same
  ok &= prTest::Check(
    vtkParticleImageComparison::TestIdentical(baseline, Disk(80.0, 60.0, 40.0), "same picture"),
    "the same picture is identical");
  vtkSmartPointer<vtkImageData> oneStep = Disk(80.0, 60.0, 40.0);
  vtkDataArray* oneStepRGB = oneStep->GetPointData()->GetScalars();
  oneStepRGB->SetComponent(37 * Width + 101, 2, oneStepRGB->GetComponent(37 * Width + 101, 2) + 1);
  ok &= prTest::Check(
    !vtkParticleImageComparison::TestIdentical(baseline, oneStep, "one value one step off"),
    "one channel of one pixel 1/255 off is not identical");
  ok &=
    prTest::Check(!vtkParticleImageComparison::TestIdentical(baseline, moved1, "edge moved 1 px"),
      "a moved edge is not identical");
  ok &= prTest::Check(
    !vtkParticleImageComparison::TestIdentical(baseline, nan, "NaN pixel"), "NaN is not identical");
  ok &= prTest::Check(!vtkParticleImageComparison::TestIdentical(baseline, small, "other size"),
    "another size is not identical");
  // a float picture of the same 8-bit values (as GrabColorBuffer reads them) is identical
  vtkNew<vtkImageData> asFloat;
  asFloat->SetDimensions(Width, Height, 1);
  vtkNew<vtkDoubleArray> floats;
  floats->SetNumberOfComponents(3);
  floats->SetNumberOfTuples(Width * Height);
  vtkDataArray* bytes = baseline->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < Width * Height; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      floats->SetComponent(i, c, static_cast<float>(bytes->GetComponent(i, c) / 255.0));
    }
  }
  asFloat->GetPointData()->SetScalars(floats);
  ok &= prTest::Check(vtkParticleImageComparison::TestIdentical(baseline, asFloat, "as float"),
    "the float picture of the same 8-bit values is identical");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
