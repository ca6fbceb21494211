/**
 * @file   vtkParticleShaders.h
 * @brief  access to the GLSL sources of Shaders/, with //PR::Include resolved
 *
 * Every .glsl file of Shaders/ is embedded at build time (vtk_encode_string). Shared pieces are
 * included, never pasted: a line `//PR::Include Name` is replaced by the text of Shaders/Name.glsl
 * (recursively, each file at most once per shader).
 */
#ifndef vtkParticleShaders_h
#define vtkParticleShaders_h

#include "vtkParticleRenderingCoreModule.h" // for export macro

#include <string>

namespace vtkParticleShaders
{
/**
 * The source of Shaders/<name>.glsl with its includes resolved. An unknown name or include is a
 * programming error: it is reported on stderr and yields a source that fails to compile.
 */
VTKPARTICLERENDERINGCORE_EXPORT std::string Get(const std::string& name);

/**
 * Resolve the //PR::Include lines of an arbitrary source.
 */
VTKPARTICLERENDERINGCORE_EXPORT std::string ResolveIncludes(const std::string& source);

/**
 * Replace the first hook tag (e.g. "//PR::Sphere::Dec") that stands alone on its line -- tags
 * quoted in comments are skipped -- by replacement. Returns false when there is none.
 */
VTKPARTICLERENDERINGCORE_EXPORT bool ReplaceHook(
  std::string& source, const std::string& hook, const std::string& replacement);
}

#endif
