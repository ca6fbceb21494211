/**
 * @class   vtkLAMMPSDumpReader
 * @brief   reads LAMMPS text dump files (atom, custom, xyz-like columns; gzip) as particles
 *
 * vtkLAMMPSDumpReader reads the snapshots of LAMMPS text dumps (`dump atom`, `dump custom`, and
 * their gzip variants) -- one file or a series of files -- and produces one vtkPolyData per time
 * step with a vertex cell per atom, so that ParaView treats the atoms as points and the Particles
 * representation draws them.
 *
 * Snapshots. A snapshot is the LAMMPS block
 *     ITEM: TIMESTEP / t / ITEM: NUMBER OF ATOMS / N / ITEM: BOX BOUNDS [xy xz yz] pp pp pp /
 *     3 box lines / ITEM: ATOMS col1 col2 ... / N atom lines
 * A file may hold many snapshots; a series of files (AddFileName) is read as one sequence, ordered
 * by timestep. The time of a step is its LAMMPS timestep times DeltaTime, or the raw timestep when
 * DeltaTime is 0 (the default) -- never the frame index. RequestInformation builds an index of
 * byte offsets once per file (it reads the headers and skips the atom lines by counting line
 * ends), so reading step k parses only step k. Gzip files (`*.gz`) are read through zlib; gzip
 * has no random access, so reaching step k of a compressed file decompresses (without parsing) the
 * bytes before it.
 *
 * Columns. Every column of `ITEM: ATOMS` is read:
 * - positions (the points, double precision) from, in this order of preference unless
 *   PositionSource says otherwise: wrapped `x y z`, unwrapped `xu yu zu`, scaled `xs ys zs`, scaled
 *   unwrapped `xsu ysu zsu`. Scaled coordinates are mapped through the (triclinic) box:
 *   x = xlo + xs lx + ys xy + zs xz, y = ylo + ys ly + zs yz, z = zlo + zs lz. PositionSource
 *   UNWRAPPED with wrapped coordinates and image flags `ix iy iz` unwraps them:
 *   x_u = x + ix lx + iy xy + iz xz, y_u = y + iy ly + iz yz, z_u = z + iz lz.
 * - the coordinate triples not used for the points, and `ix iy iz`, as 3-component arrays
 *   ("wrapped", "unwrapped", "scaled", "scaled_unwrapped", "image");
 * - `vx vy vz`, `fx fy fz`, `mux muy muz`, `omegax ...`, `angmomx ...`, `tqx ...` as the
 *   3-component arrays "velocity", "force", "mu", "omega", "angmom", "torque"; consecutive
 *   bracketed columns `c_name[1] c_name[2] ...` as one multi-component array "c_name";
 * - ellipsoids (atom_style ellipsoid): `shapex shapey shapez` as the 3-component array "shape"
 *   (LAMMPS's diameters, as written) and "semi_axes" (half of them), `quatw quati quatj quatk`
 *   as the 4-component array "orientation" (w, i, j, k): what vtkParticleSphereMapper's Shape
 *   Ellipsoid takes (AxesArrayName "semi_axes", OrientationArrayName "orientation"). LAMMPS
 *   versions whose `dump custom` does not know these names (the 2021 LAMMPS of Debian 12) write
 *   them through `compute ID all property/atom shapex shapey shapez quatw quati quatj quatk` as
 *   `c_ID[1]` ... `c_ID[7]`, read as the 7-component "c_ID": there the columns' meaning is the
 *   user's to give (components 0-2 diameters, 3-6 the quaternion);
 * - `id`, `mol`, `type`, `proc`, `procp1` as integer arrays (vtkIdTypeArray for id, vtkIntArray
 *   otherwise); `element` (and any column whose first value is not a number) as a string array;
 *   every other column as a float array named like the column.
 * SortById reorders the atoms of every step by id, so that arrays line up across steps.
 *
 * Radii (vtkLAMMPSReaderBase: GenerateRadius, SetTypeRadius, DefaultRadius): the `radius`
 * column, or half the `diameter` column, or else the per-type table, or DefaultRadius for every
 * atom when there is no type column.
 *
 * Box. The field data holds "Timestep" (1 value), "BoxBounds" (xlo xhi ylo yhi zlo zhi of the
 * box itself, i.e. LAMMPS's bounding-box bounds with the tilt removed), "BoxTilt" (xy xz yz, 0
 * for orthogonal boxes) and "BoxPeriodicity" (the three boundary flags, e.g. "pp pp ff"). Output
 * port 1 holds the box outline (12 line cells).
 *
 * Bad input gets an error that names the file and the line (a column count that differs from the
 * header, a field that is not a number, a missing ITEM: line, an empty or binary file) and an
 * empty output for that step; the steps before a bad or truncated snapshot stay readable (a
 * truncated last snapshot is dropped with a warning). NaN and Inf values are read as such, with a
 * warning (the particle mappers skip NaN positions).
 *
 * Speed. Atom lines are parsed in blocks of BlockSize bytes, each block in parallel with
 * vtkSMPTools (STDThread for the parse when the process's backend is the Sequential default of
 * Debian's VTK and VTK_SMP_BACKEND_IN_USE does not ask for it), straight into the output arrays,
 * so the memory beyond the output is one block; progress is reported per block. Numbers go
 * through Clinger's exact fast path (at most 19 digits and |exponent| <= 22: one correctly
 * rounded multiplication or division, the same double as std::from_chars, which handles
 * everything else). On Linux the output arrays ask for transparent huge pages (madvise), which
 * removes most first-touch page faults. Measured on 2 cores (Benchmarks/results/reader_speed.csv):
 * a 607 MB dump of 10^7 atoms in about 1.1-1.7 s, 3.5-5.5x faster than numpy.loadtxt, with
 * about 1.05x the output arrays' memory added.
 *
 * @sa vtkParticleSphereMapper
 */
#ifndef vtkLAMMPSDumpReader_h
#define vtkLAMMPSDumpReader_h

#include "vtkLAMMPSReaderBase.h"
#include "vtkParticleRenderingIOModule.h" // for export macro

#include <memory> // for std::unique_ptr

class VTKPARTICLERENDERINGIO_EXPORT vtkLAMMPSDumpReader : public vtkLAMMPSReaderBase
{
public:
  static vtkLAMMPSDumpReader* New();
  vtkTypeMacro(vtkLAMMPSDumpReader, vtkLAMMPSReaderBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read (clears the series), or a series of files (AddFileName, in any order: the
   * snapshots are ordered by timestep).
   */
  void SetFileName(const char* fileName);
  const char* GetFileName();
  void AddFileName(const char* fileName);
  void RemoveAllFileNames();
  int GetNumberOfFileNames();
  const char* GetFileName(int index);
  ///@}

  /**
   * Whether the file looks like a LAMMPS text dump (its first non-empty line is
   * "ITEM: TIMESTEP"; gzip files are looked into). For reader factories.
   */
  static int CanReadFile(const char* fileName);

  ///@{
  /**
   * Time value of a step = LAMMPS timestep x DeltaTime; 0 (default) = the raw timestep.
   */
  vtkSetClampMacro(DeltaTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DeltaTime, double);
  ///@}

  enum PositionSources
  {
    AUTOMATIC = 0, // wrapped, unwrapped, scaled, scaled unwrapped: the first present
    WRAPPED = 1,   // x y z, or xs ys zs mapped through the box
    UNWRAPPED = 2, // xu yu zu, xsu ysu zsu mapped, or x y z with image flags
  };

  ///@{
  /**
   * Which coordinates become the points (see the class description). Default AUTOMATIC. A
   * request the columns cannot serve gives a warning and the AUTOMATIC choice.
   */
  vtkSetClampMacro(PositionSource, int, AUTOMATIC, UNWRAPPED);
  vtkGetMacro(PositionSource, int);
  ///@}

  ///@{
  /**
   * Bytes of text parsed per block (default 32 MiB; at least 4 KiB).
   */
  vtkSetClampMacro(BlockSize, vtkIdType, 4096, VTK_ID_MAX);
  vtkGetMacro(BlockSize, vtkIdType);
  ///@}

  ///@{
  /**
   * What the index found: number of steps and their timesteps and atom counts; the columns of
   * the last step read.
   */
  int GetNumberOfSteps();
  long long GetStepTimestep(int step);
  vtkIdType GetStepNumberOfAtoms(int step);
  ///@}

protected:
  vtkLAMMPSDumpReader();
  ~vtkLAMMPSDumpReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double DeltaTime = 0.0;
  int PositionSource = AUTOMATIC;
  vtkIdType BlockSize = 32 << 20;

private:
  vtkLAMMPSDumpReader(const vtkLAMMPSDumpReader&) = delete;
  void operator=(const vtkLAMMPSDumpReader&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  ///@{
  /**
   * The stages of RequestData, in order, on the state of one request (the snapshot, its file,
   * the plan of its columns, the outputs). OpenAtoms and ParseAtoms return false after an error.
   */
  struct vtkRequestState;
  bool OpenAtoms(vtkRequestState& state);
  void PlanColumns(vtkRequestState& state);
  static void AllocateOutputs(vtkRequestState& state);
  bool ParseAtoms(vtkRequestState& state);
  static void MapPoints(vtkRequestState& state);
  static void MoveStrings(vtkRequestState& state);
  void AddRadius(vtkRequestState& state);
  void AddSemiAxes(vtkRequestState& state);
  void RadiiFromTypes(const int* type, long long n, float* r);
  void OrderById(vtkRequestState& state);
  static void AssembleOutput(vtkRequestState& state, vtkPolyData* output);
  ///@}
};

#endif
