/**
 * @file   vtkParticleShaders.h
 * @brief  access to the GLSL sources of Shaders/, with //PR::Include resolved
 *
 * Each module owns the GLSL of its folder Shaders/<Module>/ (Shaders/Core/ the core's): CMake
 * embeds those files in the module's library (vtk_encode_string, particlerendering_embed_shaders
 * in Shaders/ParticleRenderingShaders.cmake) with a generated table that Register()s them when the
 * library loads. Names are unique across modules. Shared pieces are included, never pasted: a line
 * `//PR::Include Name` is replaced by the text of Name.glsl (recursively, each file at most once
 * per shader). A module's shaders include only its own and the core's, and its C++ names only
 * those (Scripts/check_layering.py checks both), so every name a shader needs is registered
 * whenever the code that builds the shader is loaded.
 */
#ifndef vtkParticleShaders_h
#define vtkParticleShaders_h

#include "vtkParticleRenderingCoreModule.h" // for export macro

#include <cstddef>
#include <string>

namespace vtkParticleShaders
{
/**
 * One embedded file: its name (the file name without .glsl) and its text.
 */
struct Source
{
  const char* Name;
  const char* Text;
};

/**
 * Register a module's embedded files (called by the generated table when the library loads; the
 * texts must outlive the registry). A name another module registered already is reported on
 * stderr and ignored; returns false then.
 */
VTKPARTICLERENDERINGCORE_EXPORT bool Register(
  const char* module, const Source* sources, std::size_t count);

/**
 * The module (its Shaders/ folder) that registered `name`; empty when none did.
 */
VTKPARTICLERENDERINGCORE_EXPORT std::string GetModule(const std::string& name);

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
