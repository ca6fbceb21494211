// Mutation fuzzing of vtkMMPLDReader under AddressSanitizer (see prFuzzLAMMPSDump.cxx).
//
//   prFuzzMMPLD <temp dir> [cases] [seed]
//
// A valid MMPLD 1.3 file (3 frames; lists of float xyzr + uint8 RGBA, float xyz + global colour,
// double xyz + double intensity, uint16 xyz + float RGB) and a 1.1 file with cluster info are
// mutated -- random bytes, bytes in the header, frame table and list headers set to extreme
// values (0, 0xff, huge counts), truncation, deleted and duplicated ranges -- and read: header,
// frame table, every frame. A crash or an AddressSanitizer report fails the test.
#include "prFuzzCommon.h"
#include "vtkMMPLDReader.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
template <typename T>
void Put(std::string& s, T value)
{
  s.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

std::string List(int vertex, int colour, int count, int version, std::mt19937& random)
{
  static const int vertexSize[5] = { 0, 12, 16, 6, 24 };
  static const int colourSize[8] = { 0, 3, 4, 4, 12, 16, 8, 8 };
  std::string s;
  Put<std::uint8_t>(s, static_cast<std::uint8_t>(vertex));
  Put<std::uint8_t>(s, static_cast<std::uint8_t>(colour));
  if (vertex == 1 || vertex == 3 || vertex == 4)
  {
    Put<float>(s, 0.5f);
  }
  if (colour == 0)
  {
    Put<std::uint32_t>(s, 0xff8040c0u);
  }
  else if (colour == 3 || colour == 7)
  {
    Put<float>(s, 0.0f);
    Put<float>(s, 1.0f);
  }
  Put<std::uint64_t>(s, static_cast<std::uint64_t>(count));
  if (version >= 103)
  {
    for (int k = 0; k < 6; ++k)
    {
      Put<float>(s, k < 3 ? -1.0f : 1.0f);
    }
  }
  for (int i = 0; i < count * (vertexSize[vertex] + colourSize[colour]); ++i)
  {
    s.push_back(static_cast<char>(random() % 256));
  }
  if (version == 101)
  {
    Put<std::uint32_t>(s, 2);
    Put<std::uint64_t>(s, 8);
    s.append(8, '\x01');
  }
  return s;
}

std::string File(int version, std::mt19937& random)
{
  std::vector<std::string> frames;
  for (int f = 0; f < 3; ++f)
  {
    std::string frame;
    if (version >= 102)
    {
      Put<float>(frame, static_cast<float>(f));
    }
    const bool v13 = version >= 103;
    Put<std::uint32_t>(frame, 4);
    frame += List(2, 2, 5 + f, version, random);
    frame += List(1, 0, 3, version, random);
    frame += List(v13 ? 4 : 1, v13 ? 7 : 3, 4, version, random);
    frame += List(3, 4, 2, version, random);
    frames.push_back(frame);
  }
  std::string s("MMPLD", 6);
  Put<std::uint16_t>(s, static_cast<std::uint16_t>(version));
  Put<std::uint32_t>(s, 3);
  for (int k = 0; k < 12; ++k)
  {
    Put<float>(s, k % 6 < 3 ? -1.0f : 1.0f);
  }
  std::uint64_t offset = 60 + 8 * 4;
  for (const std::string& frame : frames)
  {
    Put<std::uint64_t>(s, offset);
    offset += frame.size();
  }
  Put<std::uint64_t>(s, offset);
  for (const std::string& frame : frames)
  {
    s += frame;
  }
  return s;
}

std::string Mutate(std::string s, std::mt19937& random)
{
  const int mutations = 1 + static_cast<int>(random() % 4);
  for (int m = 0; m < mutations && !s.empty(); ++m)
  {
    // half of the mutations hit the first 200 bytes: header, frame table, first list header
    const size_t at =
      random() % 2 ? random() % std::min<size_t>(s.size(), 200) : random() % s.size();
    switch (random() % 6)
    {
      case 0:
        s[at] = static_cast<char>(random() % 256);
        break;
      case 1:
        s[at] = random() % 2 ? '\0' : '\xff';
        break;
      case 2: // a huge 64-bit value
        for (size_t k = 0; k < 8 && at + k < s.size(); ++k)
        {
          s[at + k] = k < 5 ? '\xff' : '\x7f';
        }
        break;
      case 3:
        s.resize(at);
        break;
      case 4:
        s.erase(at, 1 + random() % 24);
        break;
      default:
        s.insert(at, s.substr(at, 1 + random() % 24));
    }
  }
  return s;
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: prFuzzMMPLD <temp dir> [cases] [seed]\n";
    return 2;
  }
  const std::string path = std::string(argv[1]) + "/fuzz.mmpld";
  const int cases = argc > 2 ? std::atoi(argv[2]) : 3000;
  std::mt19937 random(argc > 3 ? static_cast<unsigned>(std::atoi(argv[3])) : 777u);
  const std::string valid[2] = { File(103, random), File(101, random) };
  long long indexed = 0;
  long long frames = 0;
  long long points = 0;
  vtkNew<prFuzz::Counter> messages;
  for (int c = 0; c < cases; ++c)
  {
    const std::string& base = valid[c % 2];
    const std::string text = c < 2 ? base : Mutate(base, random);
    std::ofstream(path, std::ios::binary).write(text.data(), static_cast<long>(text.size()));
    vtkNew<vtkMMPLDReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, messages);
    reader->AddObserver(vtkCommand::WarningEvent, messages);
    reader->SetFileName(path.c_str());
    const int n = prFuzz::ReadAllSteps(reader, points);
    if (n < 0)
    {
      continue;
    }
    ++indexed;
    frames += n;
    if (c < 2 && (n != 3 || reader->GetOutput()->GetNumberOfPoints() != 16))
    {
      std::cerr << "FAIL: the unmutated file (version " << reader->GetVersion() << ") reads as "
                << n << " frames, " << reader->GetOutput()->GetNumberOfPoints() << " points\n";
      return 1;
    }
  }
  std::remove(path.c_str());
  std::cout << cases << " cases: " << indexed << " indexed, " << frames << " frames read ("
            << points << " points), " << messages->Count << " error/warning messages, no crash\n";
  return 0;
}
