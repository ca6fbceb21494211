// Shared helpers of the ParticleRendering C++ tests.
#ifndef prTestUtilities_h
#define prTestUtilities_h

#include "vtkCommand.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <string>
#include <vector>

class vtkDoubleArray;
class vtkImageData;
class vtkLookupTable;
class vtkUnsignedCharArray;
class vtkPolyData;
class vtkRenderWindow;

namespace prTest
{
/**
 * Criteria of an image test (vtkParticleImageComparison, see its class description), in 8-bit
 * steps (x/255) where that is how they are read: per-pixel tolerance, largest share of pixels
 * over it, largest mean and largest single error of a channel, silhouette mask radius. Each
 * test states its own.
 */
struct ImageCriteria
{
  double Tolerance = 2.0;              // /255, per pixel and channel
  double MaxOverToleranceShare = 1e-3; // share of compared pixels
  double MaxMean = 0.5;                // /255, per channel
  double MaxError = 255.0;             // /255, per channel and pixel
  int MaskRadius = 0;                  // pixels around the baseline's colour edges not compared
};

/**
 * The baseline test of the suite: the window's image against the -V baseline under the
 * criteria, through vtkParticleImageComparison::TestImage (report, <Test>.png and
 * <Test>.diff.png in the -T directory, built-in must-fail checks), and the frame drawn once more
 * must be identical (vtkParticleImageComparison::TestRepeatable). A missing -V argument or
 * baseline file is a failure.
 * In must-fail mode (the test was started with --must-fail CASE, see MustFail()) the test has
 * drawn a wrong picture on purpose: then true means the picture was rejected for its pixels.
 */
bool CompareWithBaseline(
  int argc, char* argv[], vtkRenderWindow* window, const ImageCriteria& criteria);

/**
 * True when the test was started with --must-fail name: the test then draws that wrong picture
 * instead of the right one and CompareWithBaseline must reject it. CompareWithBaseline fails
 * when a --must-fail case was given that the test never asked for (an unknown case).
 */
bool MustFail(int argc, char* argv[], const char* name);

/** The window's colour buffer (RGB, 8 bit, as a PNG baseline holds it). */
vtkSmartPointer<vtkImageData> GrabImage(vtkRenderWindow* window);

/** Path of a file of Testing/Data, from the -D argument. */
std::string DataFile(int argc, char* argv[], const std::string& name);

/** Directory for test outputs, from the -T argument ("." when absent). */
std::string TempDirectory(int argc, char* argv[]);

/** Read a .vtp file; fails the test (returns nullptr and prints) when unreadable. */
vtkSmartPointer<vtkPolyData> ReadPolyData(const std::string& fileName);

/** Small deterministic scene: n x n x n spheres on a jittered lattice with a scalar and radii. */
vtkSmartPointer<vtkPolyData> MakeLattice(int n, double spacing, unsigned int seed);

/**
 * Counts the warnings and errors of the objects it observes (VTK then does not print them) and
 * keeps the last of each and all their texts. StopObserving() (or Observe() again) detaches it.
 */
class MessageCounter : public vtkCommand
{
public:
  static MessageCounter* New() { return new MessageCounter; }
  void Observe(vtkObject* object, bool warnings = true, bool errors = true);
  void StopObserving();
  void Reset();
  void Execute(vtkObject*, unsigned long event, void* callData) override;
  int Warnings = 0;
  int Errors = 0;
  std::string LastWarning;
  std::string LastError;
  std::string All; // every message, in order

private:
  std::vector<std::pair<vtkWeakPointer<vtkObject>, unsigned long>> Tags;
};

/**
 * Particle attributes computed by a test from the raw point arrays, independently of the mapper
 * under test (for vtkParticleReferenceRenderer::SetParticleAttributes): radii from the named
 * array (constantRadius when the name is empty), 8-bit RGBA colours by mapping the named array's
 * first component through a copy of lut over [range[0], range[1]] (none without a lut), and
 * maximum opacities Theta_a from the named array mapped linearly from opacityRange to [0, 1] and
 * clamped, NaN giving 0 (none when the name is empty).
 */
struct ParticleAttributes
{
  vtkSmartPointer<vtkDoubleArray> Radii;
  vtkSmartPointer<vtkUnsignedCharArray> Colors;
  vtkSmartPointer<vtkDoubleArray> Opacities;
};
ParticleAttributes RawAttributes(vtkPolyData* input, const std::string& radiusArray,
  double constantRadius, const std::string& colorArray, vtkLookupTable* lut, const double range[2],
  const std::string& opacityArray = std::string(), const double opacityRange[2] = nullptr);

/** Count a check: print the message when it fails. Returns the condition. */
bool Check(bool condition, const std::string& what);
}

#endif
