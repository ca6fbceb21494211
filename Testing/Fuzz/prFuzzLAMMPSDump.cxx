// Mutation fuzzing of vtkLAMMPSDumpReader, built with AddressSanitizer (this executable compiles
// the reader's source itself with -fsanitize=address; see CMakeLists.txt).
//
//   prFuzzLAMMPSDump <temp dir> [cases] [seed]
//
// A valid dump (three snapshots: an orthogonal box with id/type/wrapped/scaled/image/velocity/
// bracketed/string columns, a triclinic box, a snapshot with 0 atoms) is mutated case by case --
// random byte changes (to digits, signs, spaces, line ends, NUL, letters, anything), deleted and
// duplicated ranges, truncation, duplicated lines -- written (every 8th case gzip-compressed),
// and read: the index, then every step. Errors and warnings are expected; a crash, a hang or an
// AddressSanitizer report is a failure (ASan aborts the process). Prints how many cases were
// indexed, how many steps read and how many messages the reader gave.
#include "prFuzzCommon.h"
#include "vtkLAMMPSDumpReader.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include "vtk_zlib.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
const char* const Valid =
  "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n5\nITEM: BOX BOUNDS pp pp ff\n"
  "0 10\n-1 9\n0 5\n"
  "ITEM: ATOMS id type element x y z xs ys zs ix iy iz vx vy vz c_f[1] c_f[2] q\n"
  "3 1 C 1 2 3 0.1 0.3 0.6 0 1 -1 0.5 -0.5 0.25 1e-3 2e+3 -1\n"
  "1 2 O 4 5 1 0.4 0.6 0.2 1 0 0 0.1 0.2 0.3 4 5 0\n"
  "5 1 C 7.5 8 4.5 0.75 0.9 0.9 -1 -1 2 1 1 1 nan inf 0.5\n"
  "2 2 H 0 0 0 0 0.1 0 0 0 0 0 0 0 0 0 1\n"
  "4 1 C 9.99 -0.5 2.5 0.999 0.05 0.5 3 2 1 -2 -3 -4 -1e-9 1e9 2\n"
  "ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n3\nITEM: BOX BOUNDS xy xz yz pp pp pp\n"
  "-1 11 1.5\n0 10 -0.5\n0 10 0.25\n"
  "ITEM: ATOMS id type xs ys zs\n"
  "1 1 0.5 0.5 0.5\n2 1 0.1 0.9 0.2\n3 2 0.999999 0 1\n"
  "ITEM: TIMESTEP\n200\nITEM: NUMBER OF ATOMS\n0\nITEM: BOX BOUNDS pp pp pp\n"
  "0 1\n0 1\n0 1\nITEM: ATOMS id type x y z\n";

std::string Mutate(const std::string& in, std::mt19937& random)
{
  std::string s = in;
  const char alphabet[] = "0123456789+-.eE \t\n\r\0abcITEM:[]xyz";
  std::uniform_int_distribution<int> kind(0, 6);
  const int mutations = 1 + static_cast<int>(random() % 4);
  for (int m = 0; m < mutations && !s.empty(); ++m)
  {
    const size_t at = random() % s.size();
    switch (kind(random))
    {
      case 0: // a byte from the dump's alphabet
        s[at] = alphabet[random() % (sizeof(alphabet) - 1)];
        break;
      case 1: // any byte
        s[at] = static_cast<char>(random() % 256);
        break;
      case 2: // delete a range
        s.erase(at, 1 + random() % 16);
        break;
      case 3: // duplicate a range
        s.insert(at, s.substr(at, 1 + random() % 32));
        break;
      case 4: // truncate
        s.resize(at);
        break;
      case 5: // duplicate the line at 'at'
      {
        const size_t b = s.rfind('\n', at);
        const size_t e = s.find('\n', at);
        const size_t begin = b == std::string::npos ? 0 : b + 1;
        const size_t end = e == std::string::npos ? s.size() : e + 1;
        s.insert(end, s.substr(begin, end - begin));
        break;
      }
      default: // a huge or negative number
        s.insert(at, random() % 2 ? "99999999999999999999" : "-7");
        break;
    }
  }
  return s;
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: prFuzzLAMMPSDump <temp dir> [cases] [seed]\n";
    return 2;
  }
  const std::string dir = argv[1];
  const int cases = argc > 2 ? std::atoi(argv[2]) : 3000;
  std::mt19937 random(argc > 3 ? static_cast<unsigned>(std::atoi(argv[3])) : 12345u);
  long long indexed = 0;
  long long stepsRead = 0;
  long long pointsRead = 0;
  vtkNew<prFuzz::Counter> messages;
  for (int c = 0; c < cases; ++c)
  {
    const std::string text = c == 0 ? std::string(Valid) : Mutate(Valid, random);
    const bool compressed = c % 8 == 7;
    const std::string path = dir + "/fuzz" + (compressed ? ".dump.gz" : ".dump");
    if (compressed)
    {
      gzFile f = gzopen(path.c_str(), "wb");
      gzwrite(f, text.data(), static_cast<unsigned>(text.size()));
      gzclose(f);
    }
    else
    {
      std::ofstream(path, std::ios::binary).write(text.data(), static_cast<long>(text.size()));
    }
    vtkNew<vtkLAMMPSDumpReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, messages);
    reader->AddObserver(vtkCommand::WarningEvent, messages);
    reader->SetFileName(path.c_str());
    reader->SetBlockSize(4096 + (c % 3) * 4096);
    reader->SetSortById(c % 2 == 0);
    reader->SetPositionSource(c % 3);
    const int n = prFuzz::ReadAllSteps(reader, pointsRead);
    if (n < 0)
    {
      continue;
    }
    ++indexed;
    stepsRead += n;
    if (c == 0 && (n != 3 || reader->GetOutput()->GetNumberOfPoints() != 0))
    {
      std::cerr << "FAIL: the unmutated dump does not read as 3 steps\n";
      return 1;
    }
  }
  std::remove((dir + "/fuzz.dump").c_str());
  std::remove((dir + "/fuzz.dump.gz").c_str());
  std::cout << cases << " cases: " << indexed << " indexed, " << stepsRead << " steps read ("
            << pointsRead << " points), " << messages->Count << " error/warning messages, "
            << "no crash\n";
  return 0;
}
