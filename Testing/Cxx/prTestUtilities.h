// Shared helpers of the ParticleRendering C++ tests.
#ifndef prTestUtilities_h
#define prTestUtilities_h

#include "vtkCommand.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <string>
#include <vector>

class vtkPolyData;
class vtkRenderWindow;

namespace prTest
{
/**
 * Baseline-image comparison with VTK's regression machinery (vtkTesting, -V/-T arguments).
 * Unlike vtkRegressionTestImage, a missing -V argument or a missing baseline file is a failure,
 * not NOT_RUN (which `return !retVal` would turn into a silent pass). Returns true on success.
 */
bool CompareWithBaseline(int argc, char* argv[], vtkRenderWindow* window, double threshold = 0.15);

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

/** Count a check: print the message when it fails. Returns the condition. */
bool Check(bool condition, const std::string& what);
}

#endif
