/**
 * @file   vtkParticleMemory.h
 * @brief  the check before a large allocation: will it fit in the memory that is free?
 *
 * Large buffers (density volumes, sort buffers, reference images) are checked before they are
 * allocated: on Linux an allocation larger than the free memory may succeed and the process is
 * killed when it touches the pages, or it throws std::bad_alloc where nobody catches it. Callers
 * give up the feature for this frame with an error that names the size instead.
 */
#ifndef vtkParticleMemory_h
#define vtkParticleMemory_h

#include "vtkParticleRenderingCoreModule.h" // for export macro

#include <string> // for std::string

namespace vtkParticleMemory
{
/**
 * True when `bytes` fit into 90 % of the host's free physical memory (total minus used, as
 * vtksys::SystemInformation reports it; when that cannot be read, true). Otherwise false and
 * `why` says "needs X GB, Y GB free".
 */
VTKPARTICLERENDERINGCORE_EXPORT bool CanAllocate(double bytes, std::string& why);

/**
 * A byte count as text: "512 MB", "34.4 GB".
 */
VTKPARTICLERENDERINGCORE_EXPORT std::string FormatBytes(double bytes);
}

#endif
