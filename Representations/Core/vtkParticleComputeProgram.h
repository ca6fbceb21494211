/**
 * @class   vtkParticleComputeProgram
 * @brief   a GLSL compute shader program over raw OpenGL (VTK 9.2's vtkShaderProgram has none)
 *
 * A small wrapper for OpenGL 4.3 compute shaders: set the full GLSL source (including its
 * `#version 430` line; sources of Shaders/ come from vtkParticleShaders::Get()), Build() it in a
 * context, Use() it, set uniforms by name and Dispatch() work groups. It is also the project's one
 * shader-storage layer: buffers are VTK's vtkOpenGLBufferObject (a mapper's vertex buffers serve
 * as input as they are), allocated, filled, read and bound to the binding points a compute source
 * declares through the static *Storage() functions -- shaped like newer VTK's compute shaders
 * and shader-storage buffer objects, so that it can give way to them when ParaView moves on. The
 * caller issues the glMemoryBarrier() its next reader needs.
 *
 * Every method that talks to OpenGL expects the context given to Build() to be current.
 *
 * Uniform setters look the location up once per name and program (cached; the cache is cleared
 * when the program is rebuilt). They act on the program bound by Use() (glUniform*), so call Use()
 * first. A name the program does not have (or that the linker optimised away) is ignored and the
 * setter returns false, as glUniform* does with location -1.
 *
 * Large one-dimensional dispatches: Dispatch(x) with x above GL_MAX_COMPUTE_WORK_GROUP_COUNT[0]
 * (at least 65535) is split into a two-dimensional grid of x' * y' >= x groups. A shader that
 * may receive more than 65535 groups must therefore compute its linear group index as
 * `gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x` (prLinearGroupID() of
 * Shaders/Core/ComputeCommon.glsl) and ignore the groups at or above x (pass x as a uniform).
 *
 * @sa vtkParticleDepthSort vtkParticleShaders
 */
#ifndef vtkParticleComputeProgram_h
#define vtkParticleComputeProgram_h

#include "vtkObject.h"
#include "vtkParticleRenderingCoreModule.h" // for export macro
#include "vtkSmartPointer.h"                // for vtkSmartPointer

#include <cstddef> // for std::size_t
#include <string>  // for std::string

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkWindow;

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleComputeProgram : public vtkObject
{
public:
  static vtkParticleComputeProgram* New();
  vtkTypeMacro(vtkParticleComputeProgram, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * True when the (current) context can run compute shaders with shader storage buffers, i.e. it
   * is OpenGL >= 4.3. Otherwise false, and *reason (when given) says why, e.g. "OpenGL 4.3 is
   * required for compute shaders and shader storage buffers; this context is 3.3 (renderer)".
   */
  static bool IsSupported(vtkOpenGLRenderWindow* context, std::string* reason = nullptr);

  /**
   * GL_MAX_COMPUTE_WORK_GROUP_COUNT of the current context, and the largest group count a
   * one-dimensional Dispatch() accepts (the x limit times the y limit, see the class comment).
   * Zero when the context has no compute shaders.
   */
  static void GetMaxWorkGroupCount(vtkOpenGLRenderWindow* context, unsigned int count[3]);
  static unsigned long long GetMaxLinearWorkGroupCount(vtkOpenGLRenderWindow* context);

  /**
   * Make `context` current before deleting the OpenGL objects it owns (ParaView releases a view's
   * props while another view's context is current, and names mean nothing in another context).
   * False when there is no such context any more or it cannot be made current: its objects went
   * with it, delete nothing.
   */
  static bool MakeCurrentForRelease(vtkOpenGLRenderWindow* context);

  /**
   * Release a storage buffer when its context is gone or going: with `current` (the caller made
   * the buffer's context current) its GL name is deleted; otherwise the name went with its
   * context and must not be deleted -- vtkOpenGLBufferObject's destructor would delete the same
   * name in whatever context is current, i.e. another context's buffer -- so the object is let go
   * (kept alive, a few bytes) and `buffer` gets a fresh one of the same type.
   */
  static void ReleaseStorage(vtkSmartPointer<vtkOpenGLBufferObject>& buffer, bool current);

  ///@{
  /**
   * Shader storage, on VTK's buffer objects (so a mapper's vertex buffers serve as input too):
   * AllocateStorage() creates `buffer` in the current context when needed and sizes it to
   * `bytes` for GPU-side use (contents undefined); BindStorage() binds it to the indexed shader
   * storage binding point `binding` that the compute source declares (nullptr unbinds);
   * UploadStorage() / DownloadStorage() copy bytes to / from it and ClearStorage() fills its
   * first `bytes` with a 32-bit value. They use the GL_COPY_READ/WRITE targets, so the
   * array, element and storage bindings of the caller stay as they were. False on a GL error.
   */
  static bool AllocateStorage(vtkOpenGLBufferObject* buffer, std::size_t bytes);
  static void BindStorage(unsigned int binding, vtkOpenGLBufferObject* buffer);
  static bool UploadStorage(
    vtkOpenGLBufferObject* buffer, std::size_t offset, std::size_t bytes, const void* data);
  static bool DownloadStorage(
    vtkOpenGLBufferObject* buffer, std::size_t offset, std::size_t bytes, void* data);
  static bool ClearStorage(vtkOpenGLBufferObject* buffer, std::size_t bytes, unsigned int value);
  ///@}

  /**
   * For a program that declares storage blocks without layout(binding) (VTK's GLSL 1.50
   * shaders with the storage extension): give its block `block` the binding point `binding`
   * (glShaderStorageBlockBinding; nothing when the program has no such active block) and bind
   * `buffer` there (BindStorage).
   */
  static void BindStorageBlock(
    unsigned int program, const char* block, unsigned int binding, vtkOpenGLBufferObject* buffer);

  ///@{
  /**
   * The complete GLSL source, including the `#version` line. Changing it makes the next Build()
   * compile and link again.
   */
  void SetSource(const std::string& source);
  const std::string& GetSource() const { return this->Source; }
  ///@}

  /**
   * Compile and link the source in the context (once; again when the source changed, after
   * ReleaseGraphicsResources() or in another context, the old context's program released). Compile
   * and link logs are reported with vtkErrorMacro (with the numbered source on a compile error).
   * Returns false on failure or when the context is below OpenGL 4.3.
   */
  bool Build(vtkOpenGLRenderWindow* context);

  /** True after a successful Build() whose program is still alive. */
  bool IsBuilt() const { return this->Handle != 0; }

  /**
   * Bind the program (glUseProgram), telling VTK's shader cache that its program is no longer
   * bound (the next VTK draw rebinds its own). UseNone() binds no program.
   */
  void Use();
  static void UseNone();

  /** The GL program name, 0 before a successful Build(). */
  unsigned int GetHandle() const { return this->Handle; }

  ///@{
  /**
   * Set a uniform of the program bound by Use(). False when the program has no active uniform of
   * that name (nothing is set then).
   */
  bool SetUniformi(const char* name, int value);
  bool SetUniformui(const char* name, unsigned int value);
  bool SetUniformf(const char* name, float value);
  bool SetUniform2i(const char* name, int x, int y);
  bool SetUniform2f(const char* name, float x, float y);
  bool SetUniform3f(const char* name, float x, float y, float z);
  bool SetUniform4f(const char* name, float x, float y, float z, float w);
  /** A column-major 4x4 matrix (OpenGL order, as vtkMatrix4x4's transposed data). */
  bool SetUniformMatrix4x4(const char* name, const float* matrix);
  /** A column-major 3x3 matrix. */
  bool SetUniformMatrix3x3(const char* name, const float* matrix);
  ///@}

  /** Location of a uniform (cached), -1 when there is none. */
  int GetUniformLocation(const char* name);

  /**
   * glDispatchCompute(x, y, z) with the program bound by Use(). x above the x limit with
   * y == z == 1 is split into a 2D grid (see the class comment). Returns false (vtkErrorMacro,
   * nothing dispatched) when the counts exceed GL_MAX_COMPUTE_WORK_GROUP_COUNT or the program is
   * not built. A zero count dispatches nothing and returns true.
   */
  bool Dispatch(unsigned int x, unsigned int y = 1, unsigned int z = 1);

  /**
   * Delete the GL program (the context must be current). The destructor does not delete it: owners
   * call this first, as for every VTK graphics resource.
   */
  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkParticleComputeProgram();
  ~vtkParticleComputeProgram() override;

  std::string Source;
  unsigned int Handle = 0;
  bool SourceChanged = true;
  unsigned int MaxGroups[3] = { 0, 0, 0 };

private:
  vtkParticleComputeProgram(const vtkParticleComputeProgram&) = delete;
  void operator=(const vtkParticleComputeProgram&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
