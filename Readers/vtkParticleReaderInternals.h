// Private helpers of ParticleRendering's readers (vtkLAMMPSDumpReader, vtkLAMMPSDataReader,
// vtkMMPLDReader): files read through zlib with 64-bit positions, lines with their numbers, exact
// number parsing, the file stamp that invalidates an index, the simulation box and its outline
// and field data, vertex cells, permutation of arrays.
#ifndef vtkParticleReaderInternals_h
#define vtkParticleReaderInternals_h

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include "vtk_zlib.h"
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <new>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h> // madvise
#endif

namespace prReader
{
//------------------------------------------------------------------------------
// A reader's pipeline request with running out of memory (std::bad_alloc) turned into an error
// and an empty output instead of an abort (the readers' ProcessRequest).
template <typename Request>
vtkTypeBool GuardMemory(vtkAlgorithm* self, vtkInformationVector* outInfo, Request&& request)
{
  try
  {
    return request();
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(self, << "Out of memory while reading: the particles need more "
                                     "memory than is free. The output is empty.");
    if (vtkPolyData* output = vtkPolyData::GetData(outInfo, 0))
    {
      output->Initialize();
    }
    return 0;
  }
}

//------------------------------------------------------------------------------
// A file read sequentially with 64-bit positions: plain or gzip-compressed (zlib reads plain
// files "transparently" and seeks them directly; in a gzip file a seek decompresses up to the
// position).
class InputFile
{
public:
  ~InputFile() { this->Close(); }
  bool Open(const std::string& name)
  {
    this->Close();
    this->File = gzopen(name.c_str(), "rb");
    if (this->File)
    {
      gzbuffer(this->File, 256 << 10);
    }
    this->Position = 0;
    return this->File != nullptr;
  }
  void Close()
  {
    if (this->File)
    {
      gzclose(this->File);
      this->File = nullptr;
    }
  }
  // Reads up to n bytes; returns the count (0 at the end), -1 on a read error.
  long long Read(char* buffer, size_t n)
  {
    long long total = 0;
    while (n > 0)
    {
      const unsigned chunk = static_cast<unsigned>(std::min<size_t>(n, 1u << 30));
      const int got = gzread(this->File, buffer, chunk);
      if (got < 0)
      {
        return -1;
      }
      if (got == 0)
      {
        break;
      }
      total += got;
      buffer += got;
      n -= static_cast<size_t>(got);
    }
    this->Position += static_cast<std::uint64_t>(total);
    return total;
  }
  bool Seek(std::uint64_t position)
  {
    if (gzseek(this->File, static_cast<z_off_t>(position), SEEK_SET) < 0)
    {
      return false;
    }
    this->Position = position;
    return true;
  }
  // Exactly n bytes, or false.
  bool ReadAll(void* data, size_t n)
  {
    return n == 0 || this->Read(static_cast<char*>(data), n) == static_cast<long long>(n);
  }
  // One value in the file's byte order (the formats read here are little-endian, like every
  // platform VTK runs on).
  template <typename T>
  bool Get(T& value)
  {
    return this->ReadAll(&value, sizeof(T));
  }
  bool Compressed() const { return this->File && gzdirect(this->File) == 0; }
  std::uint64_t Tell() const { return this->Position; }

private:
  gzFile File = nullptr;
  std::uint64_t Position = 0;
};

//------------------------------------------------------------------------------
// Large output arrays are written once, right after allocation: with 4 KiB pages, the first
// touch of every page is a fault (a fifth of the parse time of 10^7 atoms). Where Linux's
// transparent huge pages are in "madvise" mode, ask for them on the array's whole 2 MiB pages.
inline void AdviseHugePages(void* data, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const std::uintptr_t huge = std::uintptr_t(2) << 20;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + huge - 1) & ~(huge - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(huge - 1);
  if (end > begin)
  {
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  }
#else
  (void)data;
  (void)bytes;
#endif
}

//------------------------------------------------------------------------------
// Lines of an InputFile, with the byte offset and the (1-based) number of each line.
class LineReader
{
public:
  // bufferSize: bytes read at a time (at least 4 KiB)
  LineReader(InputFile& file, size_t bufferSize = 1 << 20)
    : File(file)
  {
    this->Buffer.resize(std::max<size_t>(bufferSize, 4096));
  }
  // The next line without its end (and a '\r' before it); false at the end of the file.
  bool Next(std::string& line)
  {
    line.clear();
    bool any = false;
    while (true)
    {
      if (this->Begin == this->End && !this->Fill())
      {
        break;
      }
      any = true;
      const char* start = this->Buffer.data() + this->Begin;
      const char* nl = static_cast<const char*>(std::memchr(start, '\n', this->End - this->Begin));
      if (nl)
      {
        line.append(start, static_cast<size_t>(nl - start));
        this->Begin += static_cast<size_t>(nl - start) + 1;
        ++this->Line;
        if (!line.empty() && line.back() == '\r')
        {
          line.pop_back();
        }
        return true;
      }
      line.append(start, this->End - this->Begin);
      this->Begin = this->End;
    }
    if (any)
    {
      ++this->Line; // a last line without a line end
      if (!line.empty() && line.back() == '\r')
      {
        line.pop_back();
      }
    }
    return any;
  }
  // Skip n lines (counting line ends); returns the number skipped (< n at the end of the file;
  // a last line without a line end counts as one).
  long long Skip(long long n)
  {
    long long skipped = 0;
    bool midLine = false; // bytes of a line consumed, its end not yet seen
    while (skipped < n)
    {
      if (this->Begin == this->End && !this->Fill())
      {
        skipped += midLine ? 1 : 0;
        break;
      }
      const char* start = this->Buffer.data() + this->Begin;
      const char* stop = this->Buffer.data() + this->End;
      const char* p = start;
      while (skipped < n && p < stop)
      {
        const char* nl = static_cast<const char*>(std::memchr(p, '\n', stop - p));
        if (!nl)
        {
          p = stop;
          midLine = true;
          break;
        }
        p = nl + 1;
        ++skipped;
        midLine = false;
      }
      this->Begin += static_cast<size_t>(p - start);
    }
    this->Line += skipped;
    return skipped;
  }
  std::uint64_t Offset() const { return this->BufferOffset + this->Begin; }
  long long LineNumber() const { return this->Line; } // lines consumed so far

private:
  bool Fill()
  {
    this->BufferOffset += this->End;
    this->Begin = this->End = 0;
    const long long got = this->File.Read(this->Buffer.data(), this->Buffer.size());
    if (got <= 0)
    {
      return false;
    }
    this->End = static_cast<size_t>(got);
    return true;
  }

  InputFile& File;
  std::vector<char> Buffer;
  size_t Begin = 0;
  size_t End = 0;
  std::uint64_t BufferOffset = 0;
  long long Line = 0;
};

//------------------------------------------------------------------------------
inline bool StartsWith(const std::string& s, const char* prefix)
{
  return s.compare(0, std::strlen(prefix), prefix) == 0;
}

inline std::vector<std::string> Split(const std::string& s)
{
  std::vector<std::string> words;
  std::istringstream in(s);
  std::string w;
  while (in >> w)
  {
    words.push_back(w);
  }
  return words;
}

// Decimal numbers as LAMMPS writes them ("%g", "%.15g": at most 19 significant digits and a
// small exponent) by Clinger's fast path: the digits as an integer m <= 2^53 and a power of ten
// 10^e with |e| <= 22, both exact in double, so m * 10^e (or m / 10^-e) is one correctly rounded
// operation -- the same double as std::from_chars. Anything else (more digits, larger exponents,
// nan, inf) goes through std::from_chars.
inline bool ParseDouble(const char* begin, const char* end, double& value)
{
  static const double powers[23] = { 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22 };
  if (begin < end && *begin == '+')
  {
    ++begin;
  }
  const char* p = begin;
  const bool negative = p < end && *p == '-';
  p += negative ? 1 : 0;
  std::uint64_t m = 0;
  int significant = 0;
  int exponent = 0;
  bool digits = false;
  for (; p < end && static_cast<unsigned>(*p - '0') < 10; ++p)
  {
    m = m * 10 + static_cast<unsigned>(*p - '0');
    significant += (m != 0) ? 1 : 0;
    digits = true;
  }
  if (p < end && *p == '.')
  {
    for (++p; p < end && static_cast<unsigned>(*p - '0') < 10; ++p)
    {
      m = m * 10 + static_cast<unsigned>(*p - '0');
      significant += (m != 0) ? 1 : 0;
      --exponent;
      digits = true;
    }
  }
  bool fast = digits && significant <= 19;
  if (fast && p < end && (*p == 'e' || *p == 'E'))
  {
    ++p;
    const bool negativeExponent = p < end && *p == '-';
    p += (p < end && (*p == '-' || *p == '+')) ? 1 : 0;
    int e = 0;
    bool exponentDigits = false;
    for (; p < end && static_cast<unsigned>(*p - '0') < 10 && e < 10000; ++p)
    {
      e = e * 10 + (*p - '0');
      exponentDigits = true;
    }
    fast = exponentDigits;
    exponent += negativeExponent ? -e : e;
  }
  if (fast && p == end && m <= (std::uint64_t(1) << 53) && exponent >= -22 && exponent <= 22)
  {
    const double x = static_cast<double>(m);
    value = exponent < 0 ? x / powers[-exponent] : x * powers[exponent];
    value = negative ? -value : value;
    return true;
  }
  const auto r = std::from_chars(begin, end, value);
  return r.ec == std::errc() && r.ptr == end;
}

inline bool ParseInt64(const char* begin, const char* end, long long& value)
{
  if (begin < end && *begin == '+')
  {
    ++begin;
  }
  const auto r = std::from_chars(begin, end, value);
  return r.ec == std::errc() && r.ptr == end;
}

inline bool ParseWord(const std::string& word, double& value)
{
  return ParseDouble(word.data(), word.data() + word.size(), value);
}

//------------------------------------------------------------------------------
// The simulation box (of a dump snapshot or a data file).
struct Box
{
  double Lo[3] = { 0, 0, 0 };
  double Hi[3] = { 0, 0, 0 };
  double Tilt[3] = { 0, 0, 0 }; // xy xz yz
  std::string Periodicity;      // e.g. "pp pp pp"
  bool Triclinic = false;
  double Length(int k) const { return this->Hi[k] - this->Lo[k]; }
};

//------------------------------------------------------------------------------
// Size and modification time of a file: an index built from it is rebuilt when either changes.
inline long long FileStamp(const std::string& name)
{
  return static_cast<long long>(vtksys::SystemTools::FileLength(name)) * 1000003LL +
    static_cast<long long>(vtksys::SystemTools::ModifiedTime(name));
}

//------------------------------------------------------------------------------
// The box as 12 line cells (the parallelepiped spanned by the box vectors).
inline vtkSmartPointer<vtkPolyData> BoxOutline(const Box& box)
{
  auto outline = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const double a[3] = { box.Length(0), 0, 0 };
  const double b[3] = { box.Tilt[0], box.Length(1), 0 };
  const double c[3] = { box.Tilt[1], box.Tilt[2], box.Length(2) };
  for (int corner = 0; corner < 8; ++corner)
  {
    double p[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = box.Lo[k] + ((corner & 1) ? a[k] : 0) + ((corner & 2) ? b[k] : 0) +
        ((corner & 4) ? c[k] : 0);
    }
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> lines;
  const int edges[12][2] = { { 0, 1 }, { 2, 3 }, { 4, 5 }, { 6, 7 }, { 0, 2 }, { 1, 3 }, { 4, 6 },
    { 5, 7 }, { 0, 4 }, { 1, 5 }, { 2, 6 }, { 3, 7 } };
  for (const auto& e : edges)
  {
    const vtkIdType ids[2] = { e[0], e[1] };
    lines->InsertNextCell(2, ids);
  }
  outline->SetPoints(points);
  outline->SetLines(lines);
  return outline;
}

inline void AddBoxFieldData(vtkFieldData* fd, const Box& box, long long timestep)
{
  vtkNew<vtkTypeInt64Array> step;
  step->SetName("Timestep");
  step->InsertNextValue(timestep);
  fd->AddArray(step);
  vtkNew<vtkDoubleArray> bounds;
  bounds->SetName("BoxBounds");
  for (int k = 0; k < 3; ++k)
  {
    bounds->InsertNextValue(box.Lo[k]);
    bounds->InsertNextValue(box.Hi[k]);
  }
  fd->AddArray(bounds);
  vtkNew<vtkDoubleArray> tilt;
  tilt->SetName("BoxTilt");
  for (double t : box.Tilt)
  {
    tilt->InsertNextValue(t);
  }
  fd->AddArray(tilt);
  vtkNew<vtkStringArray> periodicity;
  periodicity->SetName("BoxPeriodicity");
  periodicity->InsertNextValue(box.Periodicity);
  fd->AddArray(periodicity);
}

//------------------------------------------------------------------------------
// One vertex cell per point, in 32-bit storage when the ids fit (half the memory).
inline vtkSmartPointer<vtkCellArray> VertexCells(vtkIdType n)
{
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  if (n < VTK_INT_MAX)
  {
    vtkNew<vtkTypeInt32Array> offsets;
    offsets->SetNumberOfTuples(static_cast<vtkIdType>(n + 1));
    AdviseHugePages(offsets->GetPointer(0), sizeof(*offsets->GetPointer(0)) * (n + 1));
    std::iota(offsets->GetPointer(0), offsets->GetPointer(0) + n + 1, 0);
    vtkNew<vtkTypeInt32Array> connectivity;
    connectivity->SetNumberOfTuples(static_cast<vtkIdType>(n));
    AdviseHugePages(connectivity->GetPointer(0), sizeof(*connectivity->GetPointer(0)) * n);
    std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, 0);
    verts->SetData(offsets, connectivity);
  }
  else
  {
    vtkNew<vtkTypeInt64Array> offsets;
    offsets->SetNumberOfTuples(static_cast<vtkIdType>(n + 1));
    AdviseHugePages(offsets->GetPointer(0), sizeof(*offsets->GetPointer(0)) * (n + 1));
    std::iota(offsets->GetPointer(0), offsets->GetPointer(0) + n + 1, 0);
    vtkNew<vtkTypeInt64Array> connectivity;
    connectivity->SetNumberOfTuples(static_cast<vtkIdType>(n));
    AdviseHugePages(connectivity->GetPointer(0), sizeof(*connectivity->GetPointer(0)) * n);
    std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, 0);
    verts->SetData(offsets, connectivity);
  }
  return verts;
}

//------------------------------------------------------------------------------
// A new array of the same type and components with the tuples in the given order.
inline vtkSmartPointer<vtkAbstractArray> Permuted(
  vtkAbstractArray* in, const std::vector<vtkIdType>& order)
{
  vtkSmartPointer<vtkAbstractArray> out;
  out.TakeReference(in->NewInstance());
  out->SetName(in->GetName());
  out->SetNumberOfComponents(in->GetNumberOfComponents());
  out->SetNumberOfTuples(static_cast<vtkIdType>(order.size()));
  vtkNew<vtkIdList> source;
  source->SetNumberOfIds(static_cast<vtkIdType>(order.size()));
  std::copy(order.begin(), order.end(), source->GetPointer(0));
  vtkNew<vtkIdList> destination;
  destination->SetNumberOfIds(static_cast<vtkIdType>(order.size()));
  std::iota(destination->GetPointer(0), destination->GetPointer(0) + order.size(), 0);
  out->InsertTuples(destination, source, in);
  return out;
}
}

#endif
