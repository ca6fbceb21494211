/**
 * @class   vtkParticleImageComparison
 * @brief   per-pixel comparison of rendered images (GPU framebuffer vs. reference renderer)
 *
 * vtkParticleImageComparison compares two colour images pixel by pixel, in [0,1] units, and
 * reports the root-mean-square error, the maximum absolute error (per channel and overall), the
 * number of compared pixels and the number of pixels whose error exceeds a tolerance. An
 * optional exclusion mask (one value per pixel, non-zero = excluded) removes pixels from the
 * comparison, typically silhouettes and sphere/sphere intersection curves where a sub-pixel
 * difference legitimately changes the colour (MakeSilhouetteMask, MakeEdgeMask).
 *
 * Images: vtkImageData with point scalars of w x h pixels (x fastest, rows bottom-up like
 * vtkRenderWindow::GetRGBAPixelData and vtkPNGReader's output). Unsigned char values are divided
 * by 255, unsigned short by 65535, floating-point values are used as they are. The number of
 * compared channels is the smaller of the two images' component counts (at most 4): an RGB
 * image against an RGBA image compares RGB.
 *
 * Static helpers grab a render window's colour and depth buffers into double images, write
 * error heat maps and PNGs, and read images.
 *
 * @sa vtkParticleReferenceRenderer
 */
#ifndef vtkParticleImageComparison_h
#define vtkParticleImageComparison_h

#include "vtkObject.h"
#include "vtkParticleRenderingModule.h" // for export macro
#include "vtkSmartPointer.h"            // for vtkSmartPointer

class vtkDataArray;
class vtkIdTypeArray;
class vtkImageData;
class vtkRenderWindow;
class vtkRenderer;
class vtkUnsignedCharArray;

class VTKPARTICLERENDERING_EXPORT vtkParticleImageComparison : public vtkObject
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
    int MaxErrorPixel[2] = { -1, -1 }; // (x, y) of the largest error
    int NumberOfComponents = 0;        // channels compared
    long long NumberOfComparedPixels = 0;
    long long NumberOfExcludedPixels = 0;
    long long NumberOfPixelsOverTolerance = 0; // pixels with a channel error > tolerance
  };

  /**
   * Compare a and b (same dimensions). excluded: optional, one value per pixel, non-zero
   * excludes the pixel. Returns false (and reports why) when the images cannot be compared.
   */
  static bool Compare(
    vtkImageData* a, vtkImageData* b, vtkDataArray* excluded, double tolerance, Result& result);
#endif

  ///@{
  /**
   * Tolerance for NumberOfPixelsOverTolerance, in [0,1] units. Default 2/255.
   */
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  /**
   * Compare a and b like the static Compare and keep the results below (for wrapped languages).
   */
  bool CompareImages(vtkImageData* a, vtkImageData* b, vtkDataArray* excluded = nullptr);

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
  double RMSE = 0.0;
  double MaxAbsError = 0.0;
  double ChannelMaxAbsError[4] = { 0, 0, 0, 0 };
  int MaxErrorPixel[2] = { -1, -1 };
  int NumberOfComponents = 0;
  vtkIdType NumberOfComparedPixels = 0;
  vtkIdType NumberOfExcludedPixels = 0;
  vtkIdType NumberOfPixelsOverTolerance = 0;

private:
  vtkParticleImageComparison(const vtkParticleImageComparison&) = delete;
  void operator=(const vtkParticleImageComparison&) = delete;
};

#endif
