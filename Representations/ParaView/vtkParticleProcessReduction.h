/**
 * @class   vtkParticleProcessReduction
 * @brief   collective reductions the distributed parts of the Particles representation share
 *
 * Plain helpers over vtkMultiProcessController (every process must call them together): the
 * bounds, count and radius sum of particles over all processes (Extent), whether a condition
 * holds everywhere, a float vector summed in place, and whether a cache key changed on any
 * process. Used by vtkParticleRepresentation (partition, column layers) and
 * vtkParticleDistributedVolumes (the AO volumes).
 */
#ifndef vtkParticleProcessReduction_h
#define vtkParticleProcessReduction_h

#include "vtkParticleRenderingParaViewModule.h" // for export macro
#include "vtkType.h"                            // for VTK_DOUBLE_MAX

#include <string> // for std::string
#include <vector> // for std::vector

class vtkMultiProcessController;

class VTKPARTICLERENDERINGPARAVIEW_EXPORT vtkParticleProcessReduction
{
public:
  /**
   * Bounds and a count and radius sum of particles, gathered on each process and reduced over
   * all of them (the grids and estimates every process must share).
   */
  struct Extent
  {
    double Bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
      VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    double Count = 0.0;
    double RadiusSum = 0.0;

    // the box [lo, hi] into the bounds
    void AddBox(const double lo[3], const double hi[3]);
    // a particle: its centre grown by `grow` into the bounds, its radius into the mean
    void AddParticle(const double center[3], double grow, double radius);
    // over all processes (collective)
    void Reduce(vtkMultiProcessController* controller);
    double MeanRadius() const { return this->Count > 0.0 ? this->RadiusSum / this->Count : 0.0; }
  };

  // whether the global controller has more than one process (not collective)
  static bool Distributed();
  // whether ok holds on every process (collective)
  static bool OnEveryProcess(vtkMultiProcessController* controller, bool ok);
  // the values summed over the processes, in place (collective)
  static void SumOverProcesses(vtkMultiProcessController* controller, std::vector<float>& values);
  // whether key differs from stored on any process of the global controller (collective);
  // stores key
  static bool StaleOnAnyProcess(const std::string& key, std::string& stored);
};

#endif
