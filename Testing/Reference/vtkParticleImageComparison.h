/**
 * @class   vtkParticleImageComparison
 * @brief   per-pixel image comparison: the one image test of the whole suite
 *
 * vtkParticleImageComparison compares two colour images pixel by pixel, in [0,1] units, and
 * reports the root-mean-square error, the mean and maximum absolute error per channel, the
 * number of compared pixels and the number (and bounding box) of pixels whose error exceeds a
 * tolerance. An optional exclusion mask (one value per pixel, non-zero = excluded) removes pixels
 * from the comparison, typically silhouettes and sphere/sphere intersection curves where a
 * sub-pixel difference legitimately changes the colour (MakeSilhouetteMask, MakeEdgeMask).
 *
 * Image test (TestImage, TestImages, TestRejects): every C++, VTK Python and pvpython image test
 * of ParticleRendering goes through these methods, with criteria the test states:
 * - Tolerance: per pixel and channel; a pixel whose largest channel error exceeds it is
 *   "over tolerance".
 * - MaximumOverToleranceFraction: the largest share of compared pixels over tolerance.
 * - MaximumMeanError: the largest mean absolute error of any channel over the compared pixels.
 * - MaximumError: the largest absolute error of any channel at any compared pixel.
 * - MaskRadius: 0 compares every pixel; r > 0 excludes the pixels within r pixels of a colour
 *   edge (a neighbour differing by more than EdgeThreshold) of the expected image only, so a
 *   silhouette that moves by up to r pixels is tolerated and one that moves farther is not.
 * The test's score is the largest of mean/MaximumMeanError, max/MaximumError and
 * share/MaximumOverToleranceFraction: the image passes when the score is <= 1, and the score of
 * a wrong picture tells by how much it is rejected. Images are compared in RGB (the first
 * ComparedComponents channels): the alpha of a screenshot is not what a user sees.
 *
 * TestImage also checks the criteria themselves: the expected image darkened by 10 % and the
 * expected image shifted by MaskRadius + 1 pixels (an edge one pixel outside the mask) must both be
 * rejected, otherwise the test fails ("the criteria cannot see ..."). The report (printed to
 * stdout) gives each score, so every image test shows its margin.
 *
 * Images: vtkImageData with point scalars of w x h pixels (x fastest, rows bottom-up like
 * vtkRenderWindow::GetRGBAPixelData and vtkPNGReader's output). Unsigned char values are divided
 * by 255, unsigned short by 65535, floating-point values are used as they are. A NaN or Inf in
 * either image is an error of 1 (never a pass).
 *
 * Static helpers grab a render window's colour and depth buffers into double images, write
 * error heat maps and PNGs, read images, and make the wrong pictures of must-fail tests
 * (Scaled, Shifted).
 *
 * @sa vtkParticleReferenceRenderer
 */
#ifndef vtkParticleImageComparison_h
#define vtkParticleImageComparison_h

#include "vtkObject.h"
#include "vtkParticleRenderingReferenceModule.h" // for export macro
#include "vtkSmartPointer.h"                     // for vtkSmartPointer

#include <string> // for std::string

class vtkDataArray;
class vtkIdTypeArray;
class vtkImageData;
class vtkRenderWindow;
class vtkRenderer;
class vtkUnsignedCharArray;

class VTKPARTICLERENDERINGREFERENCE_EXPORT vtkParticleImageComparison : public vtkObject
{
public:
  static vtkParticleImageComparison* New();
  vtkTypeMacro(vtkParticleImageComparison, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

#ifndef __VTK_WRAP__
  /**
   * Result of a comparison (errors in [0,1] units).
   */
  struct Result
  {
    double RMSE = 0.0;        // over every compared channel value
    double MaxAbsError = 0.0; // over every compared channel
    double ChannelMaxAbsError[4] = { 0, 0, 0, 0 };
    double ChannelMeanAbsError[4] = { 0, 0, 0, 0 };
    int MaxErrorPixel[2] = { -1, -1 };            // (x, y) of the largest error
    int OverToleranceBox[4] = { -1, -1, -1, -1 }; // x0, x1, y0, y1 of the pixels over tolerance
    int NumberOfComponents = 0;                   // channels compared
    long long NumberOfComparedPixels = 0;
    long long NumberOfExcludedPixels = 0;
    long long NumberOfPixelsOverTolerance = 0; // pixels with a channel error > tolerance
  };

  /**
   * Compare a and b (same dimensions). excluded: optional, one value per pixel, non-zero
   * excludes the pixel. At most maxComponents channels are compared. Returns false (and
   * reports why) when the images cannot be compared.
   */
  static bool Compare(vtkImageData* a, vtkImageData* b, vtkDataArray* excluded, double tolerance,
    Result& result, int maxComponents = 4);
#endif

  ///@{
  /**
   * Tolerance for NumberOfPixelsOverTolerance, in [0,1] units. Default 2/255.
   */
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  /**
   * Compare a and b like the static Compare (Tolerance, the first ComparedComponents channels)
   * and keep the results below (for wrapped languages). No criteria, no report.
   */
  bool CompareImages(vtkImageData* a, vtkImageData* b, vtkDataArray* excluded = nullptr);

  ///@{
  /**
   * Criteria of TestImage/TestImages/TestRejects (see the class description), in [0,1] units.
   * Defaults: Tolerance 2/255, MaximumOverToleranceFraction 1e-3, MaximumMeanError 0.5/255,
   * MaximumError 1 (no limit), MaskRadius 0, EdgeThreshold 0.1, ComparedComponents 3. Limits
   * are clamped to at least 1e-9 so that scores stay finite.
   */
  vtkSetClampMacro(MaximumOverToleranceFraction, double, 1e-9, 1.0);
  vtkGetMacro(MaximumOverToleranceFraction, double);
  vtkSetClampMacro(MaximumMeanError, double, 1e-9, 1.0);
  vtkGetMacro(MaximumMeanError, double);
  vtkSetClampMacro(MaximumError, double, 1e-9, 1.0);
  vtkGetMacro(MaximumError, double);
  vtkSetClampMacro(MaskRadius, int, 0, 16);
  vtkGetMacro(MaskRadius, int);
  vtkSetClampMacro(EdgeThreshold, double, 0.0, 1.0);
  vtkGetMacro(EdgeThreshold, double);
  vtkSetClampMacro(ComparedComponents, int, 1, 4);
  vtkGetMacro(ComparedComponents, int);
  ///@}

  /**
   * The image test of the suite: compare image with the baseline file (PNG) under the criteria,
   * print a report named name, write <tempDirectory>/<name>.png (the image, so that a new
   * baseline can be taken from there after looking at it) and <tempDirectory>/<name>.diff.png
   * (heat map of the largest channel error x 8, excluded pixels grey), and check that the
   * criteria reject the baseline darkened by 10 % and shifted by MaskRadius + 1 pixels.
   * Returns true when the image passes and both wrong pictures are rejected; a missing or
   * unreadable baseline or a size mismatch is a failure.
   */
  bool TestImage(
    vtkImageData* image, const char* baselineFile, const char* tempDirectory, const char* name);

  /**
   * Compare image with expected under the criteria (the MaskRadius mask, built from expected,
   * is combined with the optional exclusion mask excluded) and print the report. Returns true
   * when the score is <= 1. With a tempDirectory, writes <name>.diff.png there.
   */
  bool TestImages(vtkImageData* image, vtkImageData* expected, vtkDataArray* excluded,
    const char* tempDirectory, const char* name);

  /**
   * Must-fail check: returns true when the wrong picture is rejected by the criteria for its
   * pixels (score > 1), false when it passes or cannot be compared (size mismatch, no scalars:
   * a rejection for the wrong reason). Prints "MUST-FAIL name: rejected/ACCEPTED, score ...".
   */
  bool TestRejects(
    vtkImageData* wrong, vtkImageData* expected, vtkDataArray* excluded, const char* name);

  /**
   * Score, failure reason (empty when passed) and mean absolute error per channel of the last
   * TestImages/TestRejects/TestImage comparison of the image itself.
   */
  vtkGetMacro(Score, double);
  const char* GetFailureReason()
  {
    return this->FailureReason.c_str();
  }
  vtkGetVector4Macro(ChannelMeanAbsError, double);

  /**
   * The repeatability check of the suite: the same frame drawn twice must give the same picture.
   * Compares the RGB channels of two images of the same size exactly, as the 8-bit values a user
   * sees and saves (values of floating-point images are taken times 255 and rounded; two values
   * differ when their 8-bit values do). Prints "REPEAT name: identical (w x h)" or "REPEAT name:
   * DIFFERS ..." (how many pixels, the largest difference and where, the box of the differing
   * pixels) and returns whether the images are identical; images that cannot be compared fail.
   */
  static bool TestIdentical(vtkImageData* first, vtkImageData* again, const char* name);

  /**
   * Repeatability of a window's frame: renders the window twice without changing anything,
   * reading its render framebuffer (the back buffer, as GrabColorBuffer) after each, and compares
   * the two through TestIdentical. (Both frames come from Render(): vtkWindowToImageFilter
   * renders with a camera recomputed through atan(tan()), whose frame may differ from Render()'s
   * in the last bit.) The second frame is drawn under the context's debug output
   * (vtkParticleGLDebugLog): an OpenGL error or undefined behaviour the driver reports fails the
   * check too. With a renderer, only its (tiled) viewport is compared. Not for progressive
   * passes, whose next frame refines the picture.
   */
  static bool TestRepeatable(
    vtkRenderWindow* window, const char* name, vtkRenderer* viewport = nullptr);

  ///@{
  /**
   * Scores of the built-in must-fail pictures of the last TestImage (the baseline darkened by
   * 10 %, and shifted by MaskRadius + 1 pixels): both must be > 1.
   */
  vtkGetMacro(DarkenedScore, double);
  vtkGetMacro(ShiftedScore, double);
  ///@}

  /**
   * A copy of image (any scalar type) with every channel but alpha multiplied by factor, in the
   * image's own type (unsigned char values rounded and clamped).
   */
  static vtkSmartPointer<vtkImageData> Scaled(vtkImageData* image, double factor);

  /**
   * A copy of image moved by (dx, dy) pixels; the pixels uncovered at the border repeat the
   * nearest edge pixel.
   */
  static vtkSmartPointer<vtkImageData> Shifted(vtkImageData* image, int dx, int dy);

  ///@{
  /**
   * Results of the last CompareImages().
   */
  vtkGetMacro(RMSE, double);
  vtkGetMacro(MaxAbsError, double);
  vtkGetVector4Macro(ChannelMaxAbsError, double);
  vtkGetVector2Macro(MaxErrorPixel, int);
  vtkGetMacro(NumberOfComponents, int);
  vtkGetMacro(NumberOfComparedPixels, vtkIdType);
  vtkGetMacro(NumberOfExcludedPixels, vtkIdType);
  vtkGetMacro(NumberOfPixelsOverTolerance, vtkIdType);
  ///@}

  /**
   * Exclusion mask of the silhouettes of an id image (one id per pixel, w x h, e.g.
   * vtkParticleReferenceRenderer::GetIdImage()): a pixel is excluded (mask value 1) when any pixel
   * within the (Euclidean) radius, in pixels, has another id; radius 1 looks at the 4 edge
   * neighbours, so a 1-pixel band on each side of every id change is excluded. Pixels within the
   * radius of the image border are excluded too: what lies beyond the border is unknown (a
   * silhouette may pass between the last pixel centre and the edge, where hits graze). This removes
   * sphere outlines against the background, sphere/sphere occlusion edges and intersection curves.
   * Other pixels get 0.
   */
  static void MakeSilhouetteMask(
    vtkIdTypeArray* ids, int width, int height, int radius, vtkUnsignedCharArray* mask);

  /**
   * Exclusion mask for images without ids: a pixel is excluded when any pixel within the
   * (Euclidean) radius differs from it by more than threshold (any channel, [0,1]
   * units) in image a or in image b (b may be null). Returns false if the images do not match.
   */
  static bool MakeEdgeMask(
    vtkImageData* a, vtkImageData* b, int radius, double threshold, vtkUnsignedCharArray* mask);

  /**
   * Write a PNG heat map of the largest per-channel |a - b| of each pixel multiplied by scale
   * (black 0, then red, yellow, white at 1 and above); excluded pixels are grey.
   */
  static bool WriteErrorMap(
    vtkImageData* a, vtkImageData* b, vtkDataArray* excluded, const char* fileName, double scale);

  /**
   * The first three components (RGB) of a colour image, as a new 3-component double image (e.g.
   * to compare RGB only, when the alphas of two images mean different things).
   */
  static vtkSmartPointer<vtkImageData> ExtractRGB(vtkImageData* rgba);

  /**
   * Write a colour image (any type/scale accepted by Compare, 1-4 components) as an 8-bit PNG.
   */
  static bool WritePNG(vtkImageData* image, const char* fileName);

  /**
   * Read an image file (any format vtkImageReader2Factory knows, e.g. PNG) into image.
   */
  static bool ReadImage(const char* fileName, vtkImageData* image);

  ///@{
  /**
   * Read the render framebuffer (the back buffer VTK renders into, read with front = 0) of a
   * window after Render(): the colour as a 4-component double RGBA image in [0,1]
   * (GetRGBAPixelData), the depth as a 1-component double image of window depths in [0,1]
   * (GetZbufferData). Rows are bottom-up like the reference renderer's images. With a renderer,
   * only its (tiled) viewport is read, otherwise the whole window.
   */
  static bool GrabColorBuffer(
    vtkRenderWindow* window, vtkImageData* color, vtkRenderer* viewport = nullptr);
  static bool GrabDepthBuffer(
    vtkRenderWindow* window, vtkImageData* depth, vtkRenderer* viewport = nullptr);
  ///@}

protected:
  vtkParticleImageComparison() = default;
  ~vtkParticleImageComparison() override = default;

  double Tolerance = 2.0 / 255.0;
  double MaximumOverToleranceFraction = 1e-3;
  double MaximumMeanError = 0.5 / 255.0;
  double MaximumError = 1.0;
  int MaskRadius = 0;
  double EdgeThreshold = 0.1;
  int ComparedComponents = 3;
  double Score = 0.0;
  std::string FailureReason;
  double ChannelMeanAbsError[4] = { 0, 0, 0, 0 };
  double DarkenedScore = 0.0;
  double ShiftedScore = 0.0;
  double RMSE = 0.0;
  double MaxAbsError = 0.0;
  double ChannelMaxAbsError[4] = { 0, 0, 0, 0 };
  int MaxErrorPixel[2] = { -1, -1 };
  int NumberOfComponents = 0;
  vtkIdType NumberOfComparedPixels = 0;
  vtkIdType NumberOfExcludedPixels = 0;
  vtkIdType NumberOfPixelsOverTolerance = 0;

  // Keep a result for the Get methods.
  void KeepResult(const Result& result);
  // Score and reason of a result under the criteria.
  double Evaluate(const Result& result, std::string& reason) const;
  // The mask of the criteria (MaskRadius around the edges of expected) or'ed with excluded.
  vtkSmartPointer<vtkUnsignedCharArray> CriteriaMask(
    vtkImageData* expected, vtkDataArray* excluded);
  // Compare under the criteria; false when the images cannot be compared.
  bool Judge(vtkImageData* image, vtkImageData* expected, vtkDataArray* excluded, Result& result,
    double& score, std::string& reason);

private:
  vtkParticleImageComparison(const vtkParticleImageComparison&) = delete;
  void operator=(const vtkParticleImageComparison&) = delete;
};

#endif
