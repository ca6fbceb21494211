#include "vtkMMPLDReader.h"
#include "vtkParticleReaderInternals.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

vtkStandardNewMacro(vtkMMPLDReader);

namespace
{
const unsigned char Magic[6] = { 'M', 'M', 'P', 'L', 'D', 0 };
const std::uint64_t HeaderSize = 60;

// sizes in bytes of the file's vertex and colour types (MMPLD numbering; 0 = unknown/none)
int VertexSize(int type)
{
  static const int sizes[5] = { 0, 12, 16, 6, 24 };
  return type >= 0 && type < 5 ? sizes[type] : -1;
}
int ColourSize(int type)
{
  static const int sizes[8] = { 0, 3, 4, 4, 12, 16, 8, 8 };
  return type >= 0 && type < 8 ? sizes[type] : -1;
}

// One particle list of a frame.
struct List
{
  int VertexType = 0;
  int ColourType = 0;
  float Radius = 0.05f; // MegaMol's defaults
  unsigned char Colour[4] = { 192, 192, 192, 255 };
  float IntensityRange[2] = { 0.0f, 1.0f };
  std::uint64_t Count = 0;
  std::uint64_t Data = 0; // offset of the particle data
  int Stride = 0;
};

// Read the list headers of the frame [begin, end) and skip their data; the frame's timestamp
// (version >= 102, unless timestamp is false). Returns the bytes the frame's structure takes, or
// 0 (and why) when it does not fit in the frame.
std::uint64_t ScanFrame(prReader::InputFile& file, std::uint64_t begin, std::uint64_t end,
  int version, bool timestamp, float& time, std::vector<List>& lists, std::string& why)
{
  lists.clear();
  std::uint64_t at = begin;
  auto need = [&](std::uint64_t bytes) -> bool
  {
    if (at + bytes > end)
    {
      why = "the frame's data runs past its end (byte " + std::to_string(end) + ")";
      return false;
    }
    at += bytes;
    return true;
  };
  if (!file.Seek(begin))
  {
    why = "cannot seek to byte " + std::to_string(begin);
    return 0;
  }
  time = std::numeric_limits<float>::quiet_NaN();
  if (version >= 102 && timestamp)
  {
    if (!need(4) || !file.Get(time))
    {
      return 0;
    }
  }
  std::uint32_t count = 0;
  if (!need(4) || !file.Get(count))
  {
    return 0;
  }
  for (std::uint32_t l = 0; l < count; ++l)
  {
    List list;
    std::uint8_t types[2];
    if (!need(2) || !file.ReadAll(types, 2))
    {
      return 0;
    }
    list.VertexType = types[0];
    list.ColourType = types[1];
    const int vertexSize = VertexSize(list.VertexType);
    const int colourSize = ColourSize(list.ColourType);
    if (vertexSize < 0 || colourSize < 0)
    {
      why = "list " + std::to_string(l) + " has an unknown vertex type " +
        std::to_string(list.VertexType) + " or colour type " + std::to_string(list.ColourType);
      return 0;
    }
    const int vertex = list.VertexType;
    if (vertex == 1 || vertex == 3 || vertex == 4)
    {
      if (!need(4) || !file.Get(list.Radius))
      {
        return 0;
      }
    }
    if (list.ColourType == 0)
    {
      if (!need(4) || !file.ReadAll(list.Colour, 4))
      {
        return 0;
      }
    }
    else if (list.ColourType == 3 || list.ColourType == 7)
    {
      if (!need(8) || !file.ReadAll(list.IntensityRange, 8))
      {
        return 0;
      }
    }
    if (!need(8) || !file.Get(list.Count))
    {
      return 0;
    }
    if (version >= 103)
    {
      float box[6];
      if (!need(24) || !file.ReadAll(box, 24))
      {
        return 0;
      }
    }
    list.Stride = vertex == 0 ? 0 : vertexSize + colourSize;
    if (vertex == 0)
    {
      list.Count = 0;
    }
    list.Data = at;
    const std::uint64_t bytes = list.Count * static_cast<std::uint64_t>(list.Stride);
    if (list.Stride > 0 && list.Count > (end - begin) / static_cast<std::uint64_t>(list.Stride))
    {
      why = "list " + std::to_string(l) + " claims " + std::to_string(list.Count) +
        " particles, more than its frame holds";
      return 0;
    }
    if (!need(bytes))
    {
      return 0;
    }
    if (version == 101)
    {
      std::uint32_t clusters;
      std::uint64_t size;
      if (!file.Seek(at) || !need(12) || !file.Get(clusters) || !file.Get(size) || !need(size))
      {
        why = why.empty() ? "bad cluster information after list " + std::to_string(l) : why;
        return 0;
      }
    }
    if (!file.Seek(at))
    {
      return 0;
    }
    lists.push_back(list);
  }
  return at - begin;
}

// Scan a frame, recognising the version 1.3 frames MegaMol wrote without a timestamp.
bool ScanFrameAnyway(prReader::InputFile& file, std::uint64_t begin, std::uint64_t end, int version,
  float& time, std::vector<List>& lists, std::string& why)
{
  std::string first;
  const std::uint64_t used = ScanFrame(file, begin, end, version, true, time, lists, first);
  if (used == end - begin)
  {
    return true;
  }
  if (version == 103)
  {
    std::string second;
    std::vector<List> other;
    float none;
    if (ScanFrame(file, begin, end, version, false, none, other, second) == end - begin)
    {
      lists = other;
      time = std::numeric_limits<float>::quiet_NaN();
      return true;
    }
  }
  if (used > 0)
  {
    return true; // data after the frame's lists: ignored (as MegaMol does)
  }
  why = first;
  return false;
}
}

//------------------------------------------------------------------------------
vtkMMPLDReader::vtkMMPLDReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

vtkMMPLDReader::~vtkMMPLDReader() = default;

//------------------------------------------------------------------------------
int vtkMMPLDReader::CanReadFile(const char* fileName)
{
  prReader::InputFile file;
  unsigned char magic[6];
  return fileName && file.Open(fileName) && file.ReadAll(magic, 6) &&
      std::memcmp(magic, Magic, 6) == 0
    ? 1
    : 0;
}

//------------------------------------------------------------------------------
int vtkMMPLDReader::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkMMPLDReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const std::string& name = this->FileName;
  const long long stamp = prReader::FileStamp(name);
  if (name != this->IndexedFile || stamp != this->IndexedStamp)
  {
    this->Frames.clear();
    this->Version = 0;
    this->NumberOfFrames = 0;
    this->IndexedFile.clear();
    prReader::InputFile file;
    if (name.empty() || !file.Open(name))
    {
      vtkErrorMacro(<< (name.empty() ? std::string("No file name.")
                                     : name + ": cannot open the file"));
      return 0;
    }
    const std::uint64_t size = vtksys::SystemTools::FileLength(name);
    unsigned char magic[6];
    std::uint16_t version = 0;
    std::uint32_t frames = 0;
    if (size < HeaderSize || !file.ReadAll(magic, 6) || std::memcmp(magic, Magic, 6) != 0 ||
      !file.Get(version) || !file.Get(frames) || !file.ReadAll(this->BoundingBox, 24) ||
      !file.ReadAll(this->ClipBox, 24))
    {
      vtkErrorMacro(<< name << ": not an MMPLD file (no 'MMPLD' header of 60 bytes)");
      return 0;
    }
    if (version == 0)
    {
      vtkErrorMacro(<< name << ": version 0, the mark of a file MegaMol did not finish writing");
      return 0;
    }
    if (version < 100 || version > 103)
    {
      vtkErrorMacro(<< name << ": MMPLD version " << version << " (readable: 100 to 103)");
      return 0;
    }
    if (frames == 0)
    {
      vtkErrorMacro(<< name << ": the file has no frames (frame count 0)");
      return 0;
    }
    this->Version = version;
    this->NumberOfFrames = static_cast<int>(frames);
    const std::uint64_t tableEnd = HeaderSize + 8 * (static_cast<std::uint64_t>(frames) + 1);
    if (tableEnd > size)
    {
      vtkErrorMacro(<< name << ": the file ends inside its frame table (" << frames
                    << " frames need " << tableEnd << " bytes, the file has " << size << ")");
      return 0;
    }
    std::vector<std::uint64_t> table(static_cast<size_t>(frames) + 1);
    if (!file.ReadAll(table.data(), 8 * table.size()))
    {
      vtkErrorMacro(<< name << ": cannot read the frame table");
      return 0;
    }
    std::string problems;
    std::vector<List> lists;
    for (std::uint32_t f = 0; f < frames; ++f)
    {
      const std::uint64_t begin = table[f];
      const std::uint64_t end = table[f + 1];
      if (begin < tableEnd || end < begin)
      {
        problems += "frame " + std::to_string(f) + ": bad frame table entries " +
          std::to_string(begin) + ".." + std::to_string(end) + "; ";
        break; // the table cannot be trusted beyond this point
      }
      if (end > size)
      {
        problems += "frame " + std::to_string(f) + " (bytes " + std::to_string(begin) + ".." +
          std::to_string(end) + ") is truncated: the file has " + std::to_string(size) + " bytes; ";
        break;
      }
      float time;
      std::string why;
      if (!ScanFrameAnyway(file, begin, end, version, time, lists, why))
      {
        problems += "frame " + std::to_string(f) + " (from byte " + std::to_string(begin) +
          "): " + why + "; ";
        continue;
      }
      this->Frames.push_back({ begin, end, static_cast<double>(time) });
      this->UpdateProgress(0.1 * (f + 1) / frames);
    }
    if (!problems.empty())
    {
      vtkWarningMacro(<< name << ": " << problems << this->Frames.size() << " of " << frames
                      << " frames are read.");
    }
    // times: increasing finite timestamps, else the frame index
    bool stamps = this->Version >= 102;
    for (size_t i = 0; i < this->Frames.size() && stamps; ++i)
    {
      stamps = std::isfinite(this->Frames[i].Time) &&
        (i == 0 || this->Frames[i].Time > this->Frames[i - 1].Time);
    }
    this->TimeValues.clear();
    for (size_t i = 0; i < this->Frames.size(); ++i)
    {
      this->TimeValues.push_back(stamps ? this->Frames[i].Time : static_cast<double>(i));
    }
    this->IndexedFile = name;
    this->IndexedStamp = stamp;
  }
  if (this->Frames.empty())
  {
    vtkErrorMacro(<< name << ": no readable frame");
    return 0;
  }
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), this->TimeValues.data(),
      static_cast<int>(this->TimeValues.size()));
    const double range[2] = { this->TimeValues.front(), this->TimeValues.back() };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

//------------------------------------------------------------------------------
// The state of one RequestData: the frame read, its file and lists, and the outputs being filled.
struct vtkMMPLDReader::vtkRequestState
{
  size_t Index = 0; // the frame
  prReader::InputFile File;
  std::vector<List> Lists;
  vtkIdType N = 0; // particles, all lists
  bool DoublePoints = false;
  bool AnyColour = false;
  bool AnyIntensity = false;
  vtkSmartPointer<vtkPoints> Points;
  vtkSmartPointer<vtkFloatArray> Radius;
  vtkSmartPointer<vtkIntArray> ListIndex;
  vtkSmartPointer<vtkUnsignedCharArray> Colour;
  vtkSmartPointer<vtkFloatArray> Intensity;
  vtkSmartPointer<vtkFloatArray> IntensityRanges;
};

//------------------------------------------------------------------------------
namespace
{
// The frame of the requested time: the last one at or before it.
size_t RequestedFrame(const std::vector<double>& timeValues, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  size_t index = 0;
  if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    const double t = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    const auto it = std::upper_bound(timeValues.begin(), timeValues.end(), t);
    index = it == timeValues.begin() ? 0 : static_cast<size_t>(it - timeValues.begin()) - 1;
  }
  return index;
}

// The position (and, for float xyzr, the radius) of the particle at v in list l.
void DecodePosition(const List& l, const unsigned char* v, int vertexSize, double x[3], float& r)
{
  switch (l.VertexType)
  {
    case 1:
    case 2:
    {
      float f[4];
      std::memcpy(f, v, vertexSize);
      x[0] = f[0];
      x[1] = f[1];
      x[2] = f[2];
      r = l.VertexType == 2 ? f[3] : r;
      break;
    }
    case 3:
    {
      std::uint16_t s[3];
      std::memcpy(s, v, 6);
      x[0] = s[0];
      x[1] = s[1];
      x[2] = s[2];
      break;
    }
    default:
      std::memcpy(x, v, 24);
  }
}

// The 8-bit RGBA colour of the particle whose colour is at c in list l.
void DecodeColour(const List& l, const unsigned char* c, unsigned char rgba[4])
{
  std::memcpy(rgba, l.Colour, 4);
  switch (l.ColourType)
  {
    case 1:
      std::memcpy(rgba, c, 3);
      rgba[3] = 255;
      break;
    case 2:
      std::memcpy(rgba, c, 4);
      break;
    case 4:
    case 5:
    {
      float f[4] = { 0, 0, 0, 1 };
      std::memcpy(f, c, l.ColourType == 4 ? 12 : 16);
      for (int k = 0; k < 4; ++k)
      {
        const float value = std::isfinite(f[k]) ? f[k] : 0.0f;
        rgba[k] =
          static_cast<unsigned char>(std::lround(255.0f * std::min(1.0f, std::max(0.0f, value))));
      }
      break;
    }
    case 6:
    {
      std::uint16_t s[4];
      std::memcpy(s, c, 8);
      for (int k = 0; k < 4; ++k)
      {
        rgba[k] = static_cast<unsigned char>((s[k] + 128) / 257);
      }
      break;
    }
    case 3:
    case 7:
      rgba[0] = rgba[1] = rgba[2] = 192; // intensity lists: MegaMol's default grey
      rgba[3] = 255;
      break;
    default:
      break;
  }
}

// The intensity of the particle whose colour is at c in list l (NaN for a list of colours).
float DecodeIntensity(const List& l, const unsigned char* c)
{
  float value = std::numeric_limits<float>::quiet_NaN();
  if (l.ColourType == 3)
  {
    std::memcpy(&value, c, 4);
  }
  else if (l.ColourType == 7)
  {
    double d;
    std::memcpy(&d, c, 8);
    value = static_cast<float>(d);
  }
  return value;
}
}

//------------------------------------------------------------------------------
int vtkMMPLDReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* outline = vtkPolyData::GetData(outputVector, 1);
  if (this->Frames.empty())
  {
    return 0;
  }
  // the frame of the requested time and its time
  vtkRequestState state;
  state.Index = RequestedFrame(this->TimeValues, outputVector);
  for (int port = 0; port < 2; ++port)
  {
    outputVector->GetInformationObject(port)->Set(
      vtkDataObject::DATA_TIME_STEP(), this->TimeValues[state.Index]);
  }

  if (!this->OpenFrame(state))
  {
    return 0;
  }
  AllocateOutputs(state);
  if (!this->ReadParticles(state))
  {
    return 0;
  }
  this->AssembleOutput(state, output);
  this->AddOutline(outline);
  return 1;
}

//------------------------------------------------------------------------------
// Open the file and read the list headers of the frame (ScanFrameAnyway).
bool vtkMMPLDReader::OpenFrame(vtkRequestState& state)
{
  const Frame& frame = this->Frames[state.Index];
  float time;
  std::string why;
  if (!state.File.Open(this->FileName) ||
    !ScanFrameAnyway(state.File, frame.Begin, frame.End, this->Version, time, state.Lists, why))
  {
    vtkErrorMacro(<< this->FileName << ": frame " << state.Index << " cannot be read: " << why);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// The outputs, sized for all lists: the points (double when a list has double xyz), "radius",
// "list", "color" when a list has colours, "intensity" when a list has intensities, and the
// lists' intensity ranges.
void vtkMMPLDReader::AllocateOutputs(vtkRequestState& state)
{
  vtkIdType n = 0;
  for (const List& l : state.Lists)
  {
    n += static_cast<vtkIdType>(l.Count);
    state.DoublePoints |= l.VertexType == 4 && l.Count > 0;
    state.AnyColour |= l.ColourType != 3 && l.ColourType != 7;
    state.AnyIntensity |= l.ColourType == 3 || l.ColourType == 7;
  }
  state.N = n;
  state.Points = vtkSmartPointer<vtkPoints>::New();
  state.Points->SetDataType(state.DoublePoints ? VTK_DOUBLE : VTK_FLOAT);
  state.Points->SetNumberOfPoints(n);
  state.Radius = vtkSmartPointer<vtkFloatArray>::New();
  state.Radius->SetName("radius");
  state.Radius->SetNumberOfTuples(n);
  state.ListIndex = vtkSmartPointer<vtkIntArray>::New();
  state.ListIndex->SetName("list");
  state.ListIndex->SetNumberOfTuples(n);
  state.Colour = vtkSmartPointer<vtkUnsignedCharArray>::New();
  state.Colour->SetName("color");
  state.Colour->SetNumberOfComponents(4);
  state.Colour->SetNumberOfTuples(state.AnyColour ? n : 0);
  state.Intensity = vtkSmartPointer<vtkFloatArray>::New();
  state.Intensity->SetName("intensity");
  state.Intensity->SetNumberOfTuples(state.AnyIntensity ? n : 0);
  state.IntensityRanges = vtkSmartPointer<vtkFloatArray>::New();
  state.IntensityRanges->SetName("IntensityRange");
  state.IntensityRanges->SetNumberOfComponents(2);
}

//------------------------------------------------------------------------------
// Read the particles of every list into the outputs, list after list. Returns false, with an
// error, when a list's data cannot be read.
bool vtkMMPLDReader::ReadParticles(vtkRequestState& state)
{
  const std::vector<List>& lists = state.Lists;
  std::vector<unsigned char> raw;
  vtkIdType row = 0;
  for (size_t li = 0; li < lists.size(); ++li)
  {
    const List& l = lists[li];
    state.IntensityRanges->InsertNextTuple2(l.IntensityRange[0], l.IntensityRange[1]);
    if (l.Count == 0)
    {
      continue;
    }
    raw.resize(static_cast<size_t>(l.Count) * l.Stride);
    if (!state.File.Seek(l.Data) || !state.File.ReadAll(raw.data(), raw.size()))
    {
      vtkErrorMacro(<< this->FileName << ": cannot read the particles of frame " << state.Index
                    << ", list " << li << " (byte " << l.Data << ")");
      return false;
    }
    const int vertexSize = VertexSize(l.VertexType);
    for (std::uint64_t p = 0; p < l.Count; ++p, ++row)
    {
      const unsigned char* v = raw.data() + p * l.Stride;
      const unsigned char* c = v + vertexSize;
      double x[3];
      float r = l.Radius;
      DecodePosition(l, v, vertexSize, x, r);
      state.Points->SetPoint(row, x);
      state.Radius->SetValue(row, r);
      state.ListIndex->SetValue(row, static_cast<int>(li));
      if (state.AnyColour)
      {
        unsigned char rgba[4];
        DecodeColour(l, c, rgba);
        state.Colour->SetTypedTuple(row, rgba);
      }
      if (state.AnyIntensity)
      {
        state.Intensity->SetValue(row, DecodeIntensity(l, c));
      }
    }
    this->UpdateProgress(0.1 + 0.9 * (li + 1) / lists.size());
  }
  return true;
}

//------------------------------------------------------------------------------
// The output: the points and the arrays, a vertex per particle, the file's boxes and the lists'
// intensity ranges in the field data.
void vtkMMPLDReader::AssembleOutput(vtkRequestState& state, vtkPolyData* output)
{
  output->SetPoints(state.Points);
  output->GetPointData()->AddArray(state.Radius);
  output->GetPointData()->AddArray(state.ListIndex);
  if (state.AnyColour)
  {
    output->GetPointData()->AddArray(state.Colour);
  }
  if (state.AnyIntensity)
  {
    output->GetPointData()->AddArray(state.Intensity);
  }
  output->SetVerts(prReader::VertexCells(state.N));
  vtkFieldData* fd = output->GetFieldData();
  vtkNew<vtkFloatArray> bbox;
  bbox->SetName("BoundingBox");
  vtkNew<vtkFloatArray> clip;
  clip->SetName("ClipBox");
  for (int k = 0; k < 6; ++k)
  {
    bbox->InsertNextValue(this->BoundingBox[k]);
    clip->InsertNextValue(this->ClipBox[k]);
  }
  fd->AddArray(bbox);
  fd->AddArray(clip);
  fd->AddArray(state.IntensityRanges);
}

//------------------------------------------------------------------------------
// The outline of the file's bounding box (output port 1).
void vtkMMPLDReader::AddOutline(vtkPolyData* outline)
{
  prReader::Box box;
  for (int k = 0; k < 3; ++k)
  {
    box.Lo[k] = this->BoundingBox[k];
    box.Hi[k] = this->BoundingBox[k + 3];
  }
  outline->ShallowCopy(prReader::BoxOutline(box));
}

//------------------------------------------------------------------------------
void vtkMMPLDReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "Version: " << this->Version << "\n";
  os << indent << "NumberOfFrames: " << this->NumberOfFrames << "\n";
  os << indent << "ReadableFrames: " << this->Frames.size() << "\n";
}

//------------------------------------------------------------------------------
vtkTypeBool vtkMMPLDReader::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inInfo, vtkInformationVector* outInfo)
{
  return prReader::GuardMemory(
    this, outInfo, [&] { return this->Superclass::ProcessRequest(request, inInfo, outInfo); });
}
