/**
 * @class   vtkMMPLDReader
 * @brief   reads MegaMol particle list files (MMPLD 1.0-1.3) as particles with time steps
 *
 * vtkMMPLDReader reads MegaMol's binary particle files (MMPLD, the format of the papers' data
 * sets), versions 1.0 (100), 1.1 (101: 1.0 with cluster info after each list), 1.2 (102: a
 * timestamp per frame) and 1.3 (103: a bounding box per list, double positions, 16-bit and
 * double colours). Every frame is a time step (the frame's timestamp when the file has
 * increasing timestamps, otherwise the frame index); every particle list of a frame is appended
 * to one vtkPolyData with a vertex cell per particle:
 * - points: float xyz, float xyzr (the radius into "radius"), uint16 xyz (as stored) or double
 *   xyz (then the points are double);
 * - "radius": per particle (xyzr) or the list's global radius;
 * - "color" (4 x uint8 RGBA): from uint8 RGB/RGBA, float RGB/RGBA and uint16 RGBA colours
 *   (converted to 8 bit), or the list's global colour; "intensity" (float) for intensity
 *   colours, with the list's intensity range in the field data ("IntensityRange", per list);
 * - "list": the index of the particle's list (lists are often particle types).
 * The file's bounding box is in the field data ("BoundingBox", "ClipBox") and its outline on
 * output port 1.
 *
 * Bad or incomplete files: version 0 (MegaMol writes it until a file is complete), a frame
 * count of 0, a seek table that decreases or points outside the file, unknown vertex or colour
 * types, a list whose data runs past its frame. Frames that lie wholly in the file are read; the
 * others are reported (with the byte offset) and skipped, e.g. a truncated last frame. The
 * version 1.3 frames that MegaMol wrote without a timestamp (2018-2019) are recognised by their
 * size and read.
 *
 * Byte layout from MegaMol's MMPLD specification (SpecMMPLD, 1.3 release hotfix 1) and its
 * reader (MMPLDDataSource); where they disagree the reader's behaviour is followed (a global
 * radius also for double xyz, an intensity range also for double intensity).
 *
 * @sa vtkLAMMPSDumpReader
 */
#ifndef vtkMMPLDReader_h
#define vtkMMPLDReader_h

#include "vtkParticleRenderingIOModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <cstdint> // for std::uint64_t
#include <string>  // for std::string
#include <vector>  // for the frame table

class VTKPARTICLERENDERINGIO_EXPORT vtkMMPLDReader : public vtkPolyDataAlgorithm
{
public:
  static vtkMMPLDReader* New();
  vtkTypeMacro(vtkMMPLDReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The pipeline requests, with running out of memory (std::bad_alloc, e.g. a file with more
   * particles than fit) turned into an error and an empty output instead of an abort.
   */
  vtkTypeBool ProcessRequest(
    vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo) override;

  ///@{
  /**
   * The MMPLD file.
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /**
   * Whether the file starts with MMPLD's magic bytes. For reader factories.
   */
  static int CanReadFile(const char* fileName);

  ///@{
  /**
   * What the header says: the version (100-103), the number of frames in the file's table
   * and the number that can be read.
   */
  vtkGetMacro(Version, int);
  vtkGetMacro(NumberOfFrames, int);
  int GetNumberOfReadableFrames() { return static_cast<int>(this->Frames.size()); }
  ///@}

protected:
  vtkMMPLDReader();
  ~vtkMMPLDReader() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;
  int Version = 0;
  int NumberOfFrames = 0;

private:
  vtkMMPLDReader(const vtkMMPLDReader&) = delete;
  void operator=(const vtkMMPLDReader&) = delete;

  struct Frame
  {
    std::uint64_t Begin = 0;
    std::uint64_t End = 0;
    double Time = 0.0;
  };
  std::vector<Frame> Frames;
  std::vector<double> TimeValues;
  float BoundingBox[6] = { 0, 0, 0, 0, 0, 0 };
  float ClipBox[6] = { 0, 0, 0, 0, 0, 0 };
  std::string IndexedFile;
  long long IndexedStamp = -1;

  ///@{
  /**
   * The stages of RequestData, in order, on the state of one request (the frame, its file and
   * lists, the outputs being filled). OpenFrame and ReadParticles return false after an error.
   */
  struct vtkRequestState;
  bool OpenFrame(vtkRequestState& state);
  static void AllocateOutputs(vtkRequestState& state);
  bool ReadParticles(vtkRequestState& state);
  void AssembleOutput(vtkRequestState& state, vtkPolyData* output);
  void AddOutline(vtkPolyData* outline);
  ///@}
};

#endif
