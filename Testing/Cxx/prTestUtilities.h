// Shared helpers of the ParticleRendering C++ tests.
#ifndef prTestUtilities_h
#define prTestUtilities_h

#include "vtkSmartPointer.h"

#include <string>

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

/** Count a check: print the message when it fails. Returns the condition. */
bool Check(bool condition, const std::string& what);
}

#endif
