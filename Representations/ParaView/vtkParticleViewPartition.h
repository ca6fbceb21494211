/**
 * @class   vtkParticleViewPartition
 * @brief   one partition per view: the Particles representations of a view that composites in
 *          order share one set of k-d boxes
 *
 * Under distributed rendering with ordered compositing (any translucent representation in the
 * view) IceT blends the processes' colour images in the order of ParaView's cuts, without depth,
 * opaque geometry included. ParaView's cut of a process is the union of the geometry bounds that
 * the representations using USE_BOUNDS_FOR_REDISTRIBUTION report there (ours do), and surfaces
 * that allow it are cut into those boxes. So every process's image must hold exactly the
 * geometry inside one box of one partition: with two Particles representations partitioned each
 * on its own, or an opaque one not partitioned at all, the cuts overlap and the blend is wrong.
 *
 * vtkParticleViewPartition holds the view's Particles representations (each registers its
 * vtkParticleDistributedPartition when added to the view). After the view's Update (every
 * representation has run RequestData and knows its data, the view knows whether it composites
 * in order), Update() decides for all of them together:
 *
 * - ordered compositing on and more than one process: the shown representations' particles are
 *   partitioned into one set of boxes (vtkParticleDistributedPartition::PartitionTogether: the
 *   root box is the union of all their spheres, the splits weigh all their centres), opaque
 *   ones too (the sphere mapper keeps the fragments whose visible point lies in its box), each
 *   with ghosts to its own reach. Each then reports its process's box as its bounds, so the cuts
 *   are those boxes, and translucent surfaces are cut into them by ParaView.
 * - otherwise each representation partitions on its own, as its technique needs.
 *
 * A new partition is made only when the key changes on some process: ordered or not, which
 * representations are shown, and what each last partitioned (input and its time, radius
 * settings, reach). When it changed a piece on some process, the view marks the shown
 * representations modified on all its processes (Redeliver) and updates again: they deliver
 * their new pieces (ParaView takes a new piece only from a newer RequestData, and a client
 * fetches one only after its own representation updated; see
 * vtkParticleDistributedPartition::TakeRedelivery).
 *
 * Every representation shares the boxes in its data coordinates: representations whose actors
 * carry different transforms are partitioned together all the same, and their order across the
 * processes is then only as good as ParaView's cuts (see vtkParticleRenderView).
 *
 * @sa vtkParticleDistributedPartition vtkParticlePartition vtkParticleRenderView
 */
#ifndef vtkParticleViewPartition_h
#define vtkParticleViewPartition_h

#include "vtkObject.h"
#include "vtkParticleRenderingParaViewModule.h" // for export macro

#include <string> // for std::string
#include <vector> // for std::vector

class vtkPVDataRepresentation;
class vtkParticleDistributedPartition;

class VTKPARTICLERENDERINGPARAVIEW_EXPORT vtkParticleViewPartition : public vtkObject
{
public:
  static vtkParticleViewPartition* New();
  vtkTypeMacro(vtkParticleViewPartition, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * A Particles representation of the view and its partition (not referenced: the
   * representation removes itself before it goes).
   */
  void AddRepresentation(vtkPVDataRepresentation* repr, vtkParticleDistributedPartition* partition);
  void RemoveRepresentation(vtkPVDataRepresentation* repr);
  ///@}

  /**
   * After the view's Update: partition the representations together or each on its own (see the
   * class documentation). Collective over the global controller's processes (the data servers;
   * a client without data returns false at once). Returns true when a representation's piece
   * changed and the view must update again.
   */
  bool Update(bool orderedCompositing);

  /**
   * Marks every shown representation modified, to deliver again in the view's next update (its
   * RequestData only delivers, see vtkParticleDistributedPartition::TakeRedelivery). Called on
   * every process of the view, client included, when Update changed a piece on any: the
   * client's representations then fetch the new pieces too.
   */
  void Redeliver();

  /**
   * After the view's second update: every representation has delivered again (or was not
   * updated, e.g. cached): clears what is left of the redelivery marks.
   */
  void FinishRedelivery();

  /**
   * Whether the shown representations share one partition (after Update).
   */
  vtkGetMacro(Shared, bool);

protected:
  vtkParticleViewPartition();
  ~vtkParticleViewPartition() override;

  struct vtkMember
  {
    vtkPVDataRepresentation* Representation;
    vtkParticleDistributedPartition* Partition;
  };
  std::vector<vtkMember> Members;
  std::string Key;
  bool Shared = false;

private:
  vtkParticleViewPartition(const vtkParticleViewPartition&) = delete;
  void operator=(const vtkParticleViewPartition&) = delete;
};

#endif
