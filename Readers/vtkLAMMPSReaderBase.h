/**
 * @class   vtkLAMMPSReaderBase
 * @brief   what the LAMMPS readers share: the radius array, the order of the atoms, the outputs
 *
 * The superclass of vtkLAMMPSDumpReader and vtkLAMMPSDataReader: no input, two vtkPolyData
 * outputs (the atoms with a vertex cell each, and the box outline), and the settings both
 * readers have:
 * - GenerateRadius (default on): a point array "radius" -- from the file's radius or diameter
 *   where it has one, otherwise from the per-type table (SetTypeRadius) with DefaultRadius (0.5,
 *   half the Lennard-Jones sigma) for the types without an entry;
 * - SortById (default off): order the atoms by their id, so that arrays line up across steps.
 *
 * @sa vtkLAMMPSDumpReader vtkLAMMPSDataReader
 */
#ifndef vtkLAMMPSReaderBase_h
#define vtkLAMMPSReaderBase_h

#include "vtkParticleRenderingIOModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <map> // for the type radii

class VTKPARTICLERENDERINGIO_EXPORT vtkLAMMPSReaderBase : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkLAMMPSReaderBase, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The pipeline requests, with running out of memory (std::bad_alloc, e.g. a file with more
   * particles than fit) turned into an error and an empty output instead of an abort.
   */
  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo) override;

  ///@{
  /**
   * Order the atoms by id (default off: file order).
   */
  vtkSetMacro(SortById, bool);
  vtkGetMacro(SortById, bool);
  vtkBooleanMacro(SortById, bool);
  ///@}

  ///@{
  /**
   * The "radius" array: on/off (default on), the radius of types without a table entry
   * (default 0.5), and the per-type table.
   */
  vtkSetMacro(GenerateRadius, bool);
  vtkGetMacro(GenerateRadius, bool);
  vtkBooleanMacro(GenerateRadius, bool);
  vtkSetClampMacro(DefaultRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DefaultRadius, double);
  void SetTypeRadius(int type, double radius);
  void SetTypeRadius(double type, double radius); // for ParaView's (type, radius) pairs
  double GetTypeRadius(int type);
  void RemoveAllTypeRadii();
  ///@}

protected:
  vtkLAMMPSReaderBase();
  ~vtkLAMMPSReaderBase() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;

  bool SortById = false;
  bool GenerateRadius = true;
  double DefaultRadius = 0.5;
  std::map<int, double> TypeRadii;

private:
  vtkLAMMPSReaderBase(const vtkLAMMPSReaderBase&) = delete;
  void operator=(const vtkLAMMPSReaderBase&) = delete;
};

#endif
