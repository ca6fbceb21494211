/**
 * @class   vtkLAMMPSDataReader
 * @brief   reads LAMMPS data files (read_data / write_data format) as particles
 *
 * vtkLAMMPSDataReader reads the atoms of a LAMMPS data file -- what `write_data` writes and
 * `read_data` reads -- as points with a vertex cell per atom:
 * - the header: "N atoms", "N atom types", the box ("xlo xhi", "ylo yhi", "zlo zhi" and, for a
 *   triclinic box, "xy xz yz"), other header lines are skipped;
 * - "Atoms" in the common atom styles, taken from the section's comment ("Atoms # full", as
 *   write_data writes it) or from AtomStyle when there is none: atomic (id type x y z), charge
 *   (id type q x y z), bond / angle / molecular (id mol type x y z), full (id mol type q x y z),
 *   sphere (id type diameter density x y z), dipole (id type q x y z mux muy muz), plus the
 *   optional image flags ix iy iz at the end of a line (then PositionSource UNWRAPPED unwraps
 *   with them, x_u = x + ix lx + iy xy + iz xz and so on);
 * - "Velocities" (id vx vy vz, joined to the atoms by id) as "velocity";
 * - "Masses" (type mass) as a per-atom "mass" array;
 * - other sections (Bonds, Pair Coeffs, ...) are skipped.
 * Point arrays: "id" (vtkIdTypeArray), "type", "mol" (vtkIntArray), "q", "diameter", "density",
 * "mu" (3 components), "image" (3 int components), "velocity", "mass", and "radius" (half the
 * diameter for sphere styles, else the per-type table of vtkLAMMPSReaderBase). The box is in the
 * field data ("BoxBounds", "BoxTilt") and on output port 1 as an outline. Atoms are in file order
 * (SortById orders them by id).
 *
 * Bad input gets an error naming the file and the line (a header count that does not match the
 * section, a line with too few values, a non-number, an unknown atom style, velocities of ids
 * that are not atoms) and an empty output; gzip files are read through zlib.
 *
 * @sa vtkLAMMPSDumpReader
 */
#ifndef vtkLAMMPSDataReader_h
#define vtkLAMMPSDataReader_h

#include "vtkLAMMPSReaderBase.h"
#include "vtkParticleRenderingIOModule.h" // for export macro

#include <string> // for std::string

class VTKPARTICLERENDERINGIO_EXPORT vtkLAMMPSDataReader : public vtkLAMMPSReaderBase
{
public:
  static vtkLAMMPSDataReader* New();
  vtkTypeMacro(vtkLAMMPSDataReader, vtkLAMMPSReaderBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The data file.
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /**
   * Whether the file looks like a LAMMPS data file (a title line, then "N atoms" among the
   * first header lines). For reader factories.
   */
  static int CanReadFile(const char* fileName);

  ///@{
  /**
   * The atom style to assume when the Atoms section has no "# style" comment: "atomic"
   * (default), "charge", "bond", "angle", "molecular", "full", "sphere", "dipole". The comment
   * wins when present.
   */
  vtkSetStdStringFromCharMacro(AtomStyle);
  vtkGetCharFromStdStringMacro(AtomStyle);
  ///@}

  enum PositionSources
  {
    WRAPPED = 1,   // x y z as written
    UNWRAPPED = 2, // x y z unwrapped with the image flags (when the file has them)
  };
  ///@{
  /**
   * Wrapped (default) or unwrapped positions.
   */
  vtkSetClampMacro(PositionSource, int, WRAPPED, UNWRAPPED);
  vtkGetMacro(PositionSource, int);
  ///@}

protected:
  vtkLAMMPSDataReader();
  ~vtkLAMMPSDataReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;
  std::string AtomStyle = "atomic";
  int PositionSource = WRAPPED;

private:
  vtkLAMMPSDataReader(const vtkLAMMPSDataReader&) = delete;
  void operator=(const vtkLAMMPSDataReader&) = delete;

  ///@{
  /**
   * The stages of RequestData, in the order of the file (each that returns bool returns false
   * after reporting the file's error, with its line), and what they share.
   */
  struct vtkParse;
  bool Fail(const vtkParse& p, const std::string& what);
  bool OpenFile(vtkParse& p);
  bool ReadTitle(vtkParse& p);
  bool ReadHeader(vtkParse& p);
  bool ReadSections(vtkParse& p);
  bool ReadAtoms(vtkParse& p, const std::string& comment);
  bool ReadVelocities(vtkParse& p);
  bool ReadMasses(vtkParse& p);
  void UnwrapPositions(vtkParse& p);
  void AddDerivedArrays(vtkParse& p);
  void Assemble(vtkParse& p, vtkPolyData* output, vtkPolyData* outline);
  ///@}
};

#endif
