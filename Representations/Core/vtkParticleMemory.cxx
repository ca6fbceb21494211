#include "vtkParticleMemory.h"

#include <vtksys/SystemInformation.hxx>

#include <cstdio>

namespace vtkParticleMemory
{
//------------------------------------------------------------------------------
std::string FormatBytes(double bytes)
{
  char text[64];
  if (bytes >= 1e9)
  {
    std::snprintf(text, sizeof(text), "%.1f GB", bytes / 1e9);
  }
  else
  {
    std::snprintf(text, sizeof(text), "%.0f MB", bytes / 1e6);
  }
  return text;
}

//------------------------------------------------------------------------------
bool CanAllocate(double bytes, std::string& why)
{
  vtksys::SystemInformation info;
  const long long total = info.GetHostMemoryTotal(); // KiB
  const long long used = info.GetHostMemoryUsed();   // KiB
  if (total <= 0 || used < 0 || used > total)
  {
    return true; // unknown: try
  }
  const double free = 1024.0 * static_cast<double>(total - used);
  if (bytes <= 0.9 * free)
  {
    return true;
  }
  why = "needs " + FormatBytes(bytes) + ", " + FormatBytes(free) + " free";
  return false;
}
}
