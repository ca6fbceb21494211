/**
 * @class   vtkParticleDistributedPartition
 * @brief   the representation's particles under distributed rendering: partition when the
 *          technique needs it, spread statistics, global column-layer estimate, ghost removal
 *
 * With more than one process (pvbatch, pvserver with MPI), each process holds a piece of the
 * particles. vtkParticleDistributedPartition decides what the representation does with that
 * piece, beside vtkParticleDistributedVolumes (the AO volumes of all processes):
 *
 * - Partition (Update, in RequestData; collective): when the caller says the technique needs it
 *   (translucent spheres, metaballs) the particles go through a vtkParticlePartition (one k-d box
 *   per process, ghost copies of the spheres reaching into other boxes), again only when the
 *   data, the radius array, the radii or the reach changed on some process. Otherwise the data
 *   stays where it is.
 * - Partition by the view (vtkParticleViewPartition): while the view composites in order, it
 *   partitions all its Particles representations into one set of boxes (PartitionTogether, after
 *   the representations' RequestData; opaque ones too). Update then only records what it was
 *   given, and the representation delivers its piece again (TakeRedelivery).
 * - Distribution: 5 values per process (see vtkParticlePartition::GetDistribution); without a
 *   partition every process owns its piece.
 * - Column layers: the column-opacity layer estimate of all processes' particles (what
 *   vtkTransparentSphereMapper::GetEffectiveColumnLayers counts), so every process gives its
 *   particles the same opacity; 0 with one process (the mapper estimates itself).
 * - Pieces (REQUEST_UPDATE, REQUEST_RENDER): PieceToDeliver gives the view the partition's output
 *   and this process's box (IceT orders the processes' images by the boxes); PieceToDraw gives
 *   the mapper the box to clip to, or drops the ghost copies of partitioned particles gathered
 *   elsewhere (a client rendering locally), which would otherwise draw their spheres twice.
 *
 * Every collective step uses the global controller and runs on all processes together.
 *
 * @sa vtkParticleRepresentation vtkParticlePartition vtkParticleDistributedVolumes
 */
#ifndef vtkParticleDistributedPartition_h
#define vtkParticleDistributedPartition_h

#include "vtkNew.h" // for vtkNew
#include "vtkObject.h"
#include "vtkParticleRenderingParaViewModule.h" // for export macro
#include "vtkSmartPointer.h"                    // for vtkSmartPointer

#include <string> // for std::string
#include <vector> // for std::vector

class vtkDataObject;
class vtkDoubleArray;
class vtkInformationDoubleVectorKey;
class vtkProp;
class vtkParticlePartition;
class vtkDataArray;
class vtkPolyData;

class VTKPARTICLERENDERINGPARAVIEW_EXPORT vtkParticleDistributedPartition : public vtkObject
{
public:
  static vtkParticleDistributedPartition* New();
  vtkTypeMacro(vtkParticleDistributedPartition, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Bring the partition, the distribution and the column layers up to date for `particles`
   * (this process's processed piece, made from `input`). needed: the technique needs the
   * partition; radiusArray: the radius array in use ("" for the constant `radius`); reach: how
   * far a particle's drawing reaches, in radii; sphereBounds: this process's sphere bounds.
   * Collective (RequestData).
   */
  void Update(vtkPolyData* particles, vtkDataObject* input, bool needed,
    const std::string& radiusArray, double radius, double radiusScale, double reach,
    const double sphereBounds[6]);

  ///@{
  /**
   * The point array whose values count as the particles' radii in the column-layer estimate
   * (vtkTransparentSphereMapper::EstimateColumnLayers) when it differs from the drawing radius:
   * for ellipsoids sqrt(a b c / a_max), what the mapper counts on one process. Empty (the
   * default): the radius array of Update().
   */
  void SetColumnRadiusArray(const std::string& name) { this->ColumnRadiusArray = name; }
  ///@}

  ///@{
  /**
   * The view partitions these particles together with its other Particles representations
   * (vtkParticleViewPartition): Update records its arguments and the column layers only.
   */
  vtkSetMacro(PartitionedByView, bool);
  vtkGetMacro(PartitionedByView, bool);
  ///@}

  /**
   * What the last Update was given (the input and its time, the radius settings, the reach,
   * whether the technique needs the partition), as text: the view's key for a new partition.
   */
  const std::string& GetInputKey() const { return this->InputKey; }

  /**
   * Partition the particles of the last Update as Update does on its own (collective): when the
   * view stops partitioning them.
   */
  void PartitionAlone();

#if !defined(__VTK_WRAP__)
  /**
   * Partition the particles of every partition's last Update into one set of boxes
   * (vtkParticlePartition::PartitionTogether; collective, the same partitions in the same order
   * on every process). Each then delivers its part with the common boxes, opaque ones included.
   */
  static void PartitionTogether(const std::vector<vtkParticleDistributedPartition*>& partitions);
#endif

  ///@{
  /**
   * Set by the view when the partition changed after the representation delivered its piece;
   * TakeRedelivery returns it once and clears it (the representation's RequestData then only
   * delivers again).
   */
  void SetRedelivery(bool on)
  {
    this->Redelivery = on;
  }
  bool TakeRedelivery();
  ///@}

  /**
   * Whether the partition's output and box are in use (after Update).
   */
  vtkGetMacro(Partitioned, bool);

  /**
   * The column-opacity layer estimate of all processes' particles (0 with one process).
   */
  vtkGetMacro(ColumnLayers, double);

  /**
   * How the particles are spread over the processes, 5 values per process.
   */
  vtkDoubleArray* GetDistribution();

  /**
   * The piece to hand the view for `particles` (the local processed piece): the partition's
   * output, with this process's box as `bounds`, when partitioned; otherwise `particles` and
   * `bounds` unchanged.
   */
  vtkPolyData* PieceToDeliver(vtkPolyData* particles, double bounds[6]);

  /**
   * Every process's box, 6 values each in process order, in the particles' (data) coordinates;
   * empty when not partitioned.
   */
  std::vector<double> GetBoxes();

  ///@{
  /**
   * The prop that carries the boxes (GetBoxes) under BOXES() in its property keys, for the
   * view's compositing order (vtkParticleRenderView), while it is shown and partitioned; they
   * are set or removed whenever the partition or `shown` changes. Not referenced: the
   * representation owns both.
   */
  void SetProp(vtkProp* prop);
  void SetPropShown(bool shown);
  static vtkInformationDoubleVectorKey* BOXES();
  ///@}

  /**
   * The particles to draw of the `delivered` piece and the box to clip them to (`clipBox`
   * uninitialised: no clipping). Partitioned: this process's box. Otherwise a piece with ghost
   * copies loses them (cached).
   */
  vtkPolyData* PieceToDraw(vtkPolyData* delivered, double clipBox[6]);

  /**
   * The radius array the mapper reads from `particles` (`name`, one component), or null where the
   * particles have none, it is not a one-component data array or there are no points (the
   * constant radius then).
   */
  static vtkDataArray* GetRadiusValues(vtkPolyData* particles, const std::string& name);

protected:
  vtkParticleDistributedPartition();
  ~vtkParticleDistributedPartition() override;

  // partition the recorded particles when needed; true when the partition's output and box are
  // in use
  bool PartitionParticles();
  void UpdateColumnLayers();
  void MarkProp();
  // the partition's statistics into Distribution
  void CopyDistribution();

  // what the last Update was given
  vtkSmartPointer<vtkPolyData> Particles;
  bool Needed = false;
  std::string RadiusArray;
  std::string ColumnRadiusArray;
  double Radius = 1.0;
  double RadiusScale = 1.0;
  double Reach = 1.0;
  double SphereBounds[6] = { 0, -1, 0, -1, 0, -1 };
  std::string InputKey;

  bool PartitionedByView = false;
  bool Redelivery = false;
  vtkProp* Prop = nullptr;
  bool PropShown = false;

  vtkNew<vtkParticlePartition> Partition;
  vtkNew<vtkDoubleArray> Distribution;
  std::string PartitionKey;
  bool Partitioned = false;
  double ColumnLayers = 0.0;
  // the delivered piece without its ghost copies, and what it was made from
  vtkSmartPointer<vtkPolyData> OwnedData;
  vtkPolyData* OwnedDataSource = nullptr;
  vtkMTimeType OwnedDataTime = 0;

private:
  vtkParticleDistributedPartition(const vtkParticleDistributedPartition&) = delete;
  void operator=(const vtkParticleDistributedPartition&) = delete;
};

#endif
