/**
 * @class   vtkParticlePartition
 * @brief   k-d partition of particles over the processes of a vtkMultiProcessController, with
 *          ghost copies of the spheres that reach into other processes' boxes
 *
 * vtkParticlePartition gives every process one convex box of a k-d partition of the global
 * sphere bounds and moves the particles there, without XML (VTK 9.2's appended-XML
 * redistribution, which ParaView's ordered compositing uses, loses pieces with Debian's expat
 * security updates): the raw point arrays travel with vtkMultiProcessController::Send/Receive of
 * vtkDataArray.
 *
 * - Boxes: every process contributes an evenly strided sample of at most MaximumSamples /
 *   processes particle centres, each weighted by its share of the local count; all processes
 *   gather the samples and build the same tree: a box is split along its longest axis at the
 *   weighted quantile that gives each side particles in proportion to its number of processes
 *   (a k-d split on particle counts, any number of processes). The root is the union of every
 *   process's sphere bounds, so the boxes tile exactly the bounds a single process has.
 * - Owner: the process whose box holds the centre (a centre on a split plane goes to the upper
 *   side). Centres that are not finite stay where they are (they are not drawn).
 * - Ghosts: a sphere is also sent to every other process whose box its bounding cube (centre
 *   +- radius * |RadiusScale| * Reach) overlaps, with vtkGhostType = DUPLICATEPOINT; owned
 *   particles have 0. A renderer that clips each sphere to its process's box (see
 *   vtkParticleSphereMapper::SetClipBox) then draws every part of every sphere exactly once.
 * - Arrays: the points (their data type) and every point array common to all processes that
 *   have particles (name, type, components); the others are dropped with a warning.
 *
 * Partition() is collective: every process of the controller must call it, also those without
 * particles. Statistics (GetDistribution): per process, particles given, owned and ghost
 * particles after, bytes sent, seconds.
 *
 * @sa vtkParticleRepresentation vtkParticleSphereMapper
 */
#ifndef vtkParticlePartition_h
#define vtkParticlePartition_h

#include "vtkObject.h"
#include "vtkParticleRenderingParaViewModule.h" // for export macro
#include "vtkSmartPointer.h"                    // for vtkSmartPointer

#include <vector> // for std::vector

class vtkMultiProcessController;
class vtkPolyData;

class VTKPARTICLERENDERINGPARAVIEW_EXPORT vtkParticlePartition : public vtkObject
{
public:
  static vtkParticlePartition* New();
  vtkTypeMacro(vtkParticlePartition, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes to partition over (default: the global controller).
   */
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController();
  ///@}

  ///@{
  /**
   * Most particle centres gathered for the splits, over all processes. Default 65536.
   */
  vtkSetClampMacro(MaximumSamples, vtkIdType, 16, VTK_ID_MAX);
  vtkGetMacro(MaximumSamples, vtkIdType);
  ///@}

  /**
   * Partition `particles` (this process's piece; may be null or empty). Radii: the point array
   * `radiusArray` (null: every particle has `radius`), times |radiusScale| times `reach` (how
   * far a particle's drawing reaches, in radii: 1 for spheres). `sphereBounds`: this process's
   * sphere bounds (uninitialised when it has none); their union over the processes is the
   * root box. Collective. Returns false (and leaves the output empty) when no process has a
   * particle.
   */
  bool Partition(vtkPolyData* particles, const char* radiusArray, double radius, double radiusScale,
    double reach, const double sphereBounds[6]);

#if !defined(__VTK_WRAP__)
  /**
   * One set of particles for PartitionTogether: the arguments of Partition().
   */
  struct vtkParticleSet
  {
    vtkPolyData* Particles;
    const char* RadiusArray;
    double Radius;
    double RadiusScale;
    double Reach;
    const double* SphereBounds;
  };

  /**
   * Partition several sets of particles (the Particles representations of one view) into one set
   * of boxes, each set into its partition: the root box is the union of all sets' sphere bounds,
   * the splits weigh all their centres alike, and each set gets its own ghosts (its own reach).
   * With one set this is Partition(). Collective; every process passes the same number of sets
   * in the same order. Returns false when no process has a particle in any set.
   */
  static bool PartitionTogether(
    const std::vector<vtkParticlePartition*>& partitions, const std::vector<vtkParticleSet>& sets);
#endif

  /**
   * The particles of this process after Partition(): owned ones and ghost copies.
   */
  vtkPolyData* GetOutput();

  /**
   * This process's box, and every process's (6 doubles each, in process order).
   */
  void GetBox(double box[6]) const;
  const std::vector<double>& GetBoxes() const
  {
    return this->Boxes;
  }

  /**
   * Per process, 5 values: particles given to Partition(), owned and ghost particles after it,
   * bytes sent to other processes, seconds the partition took there (the same on every
   * process).
   */
  const std::vector<double>& GetDistribution() const
  {
    return this->Distribution;
  }

protected:
  vtkParticlePartition();
  ~vtkParticlePartition() override;

  vtkIdType MaximumSamples = 65536;
  vtkSmartPointer<vtkMultiProcessController> Controller;
  vtkSmartPointer<vtkPolyData> Output;
  std::vector<double> Boxes;
  std::vector<double> Distribution;

private:
  ///@{
  /**
   * The stages of Partition(), in order, each collective, and what they share. SplitIntoBoxes
   * samples the centres of every run and returns false when no process has a particle (every
   * box uninitialised).
   */
  struct vtkRun;
  void BeginRun(vtkRun& run, vtkPolyData* particles, const char* radiusArray);
  void FindRootBox(vtkRun& run, const double sphereBounds[6]);
  bool SplitIntoBoxes(std::vector<vtkRun>& runs);
  void AgreeOnArrays(vtkRun& run);
  void AssignParticles(vtkRun& run, double radius, double radiusScale, double reach);
  void ExchangeParticles(vtkRun& run);
  void AssembleOutput(vtkRun& run);
  void GatherDistribution(vtkRun& run, double start);
  ///@}

  vtkParticlePartition(const vtkParticlePartition&) = delete;
  void operator=(const vtkParticlePartition&) = delete;
};

#endif
