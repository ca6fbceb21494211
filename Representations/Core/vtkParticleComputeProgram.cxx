#include "vtkParticleComputeProgram.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkWeakPointer.h"

#include "vtkParticleCompat.h"

#include <map>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkParticleComputeProgram);

//------------------------------------------------------------------------------
class vtkParticleComputeProgram::vtkInternals
{
public:
  std::map<std::string, GLint> Locations;
  // the context the program was built in
  vtkWeakPointer<vtkOpenGLRenderWindow> Context;
};

namespace
{
// The info log of a shader or program (the GL query functions of either).
template <class GetIv, class GetLog>
std::string InfoLog(GLuint object, GetIv getIv, GetLog getLog)
{
  GLint length = 0;
  getIv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 0) + 1, '\0');
  if (length > 0)
  {
    getLog(object, length, nullptr, log.data());
  }
  return log.data();
}

std::string ShaderLog(GLuint shader)
{
  return InfoLog(shader, glGetShaderiv, glGetShaderInfoLog);
}

std::string ProgramLog(GLuint program)
{
  return InfoLog(program, glGetProgramiv, glGetProgramInfoLog);
}

std::string NumberedSource(const std::string& source)
{
  std::ostringstream out;
  std::istringstream in(source);
  std::string line;
  int number = 1;
  while (std::getline(in, line))
  {
    out << number++ << ": " << line << "\n";
  }
  return out.str();
}
}

//------------------------------------------------------------------------------
vtkParticleComputeProgram::vtkParticleComputeProgram()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkParticleComputeProgram::~vtkParticleComputeProgram()
{
  // A program still alive here is left to its context (which deletes it with itself): no context
  // may be current at destruction. Owners call ReleaseGraphicsResources() first.
  delete this->Internals;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::IsSupported(vtkOpenGLRenderWindow* context, std::string* reason)
{
  if (!context)
  {
    if (reason)
    {
      *reason = "no OpenGL render window";
    }
    return false;
  }
  GLint major = 0;
  GLint minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major == 0)
  {
    // before OpenGL 3.0 there is no GL_MAJOR_VERSION: parse "major.minor ..."
    const GLubyte* version = glGetString(GL_VERSION);
    if (version)
    {
      std::istringstream in(reinterpret_cast<const char*>(version));
      char dot = 0;
      in >> major >> dot >> minor;
    }
  }
  if (major > 4 || (major == 4 && minor >= 3))
  {
    if (reason)
    {
      reason->clear();
    }
    return true;
  }
  if (reason)
  {
    const GLubyte* renderer = glGetString(GL_RENDERER);
    std::ostringstream message;
    message << "OpenGL 4.3 is required for compute shaders and shader storage buffers; this "
               "context is "
            << major << "." << minor << " ("
            << (renderer ? reinterpret_cast<const char*>(renderer) : "unknown renderer") << ")";
    *reason = message.str();
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkParticleComputeProgram::GetMaxWorkGroupCount(
  vtkOpenGLRenderWindow* context, unsigned int count[3])
{
  count[0] = count[1] = count[2] = 0;
  if (!vtkParticleComputeProgram::IsSupported(context, nullptr))
  {
    return;
  }
  for (GLuint i = 0; i < 3; ++i)
  {
    GLint value = 0;
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, i, &value);
    count[i] = static_cast<unsigned int>(value > 0 ? value : 0);
  }
}

//------------------------------------------------------------------------------
unsigned long long vtkParticleComputeProgram::GetMaxLinearWorkGroupCount(
  vtkOpenGLRenderWindow* context)
{
  unsigned int count[3];
  vtkParticleComputeProgram::GetMaxWorkGroupCount(context, count);
  return static_cast<unsigned long long>(count[0]) * count[1];
}

//------------------------------------------------------------------------------
void vtkParticleComputeProgram::SetSource(const std::string& source)
{
  if (source != this->Source)
  {
    this->Source = source;
    this->SourceChanged = true;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::Build(vtkOpenGLRenderWindow* context)
{
  if (this->Handle != 0 && !this->SourceChanged && this->Internals->Context == context)
  {
    return true; // (a program of another context is released below and built again)
  }
  std::string reason;
  if (!vtkParticleComputeProgram::IsSupported(context, &reason))
  {
    vtkErrorMacro(<< reason);
    return false;
  }
  if (this->Source.empty())
  {
    vtkErrorMacro(<< "No source set.");
    return false;
  }
  this->ReleaseGraphicsResources(context);
  context->MakeCurrent(); // (releasing made the old program's context current)
  vtkParticleComputeProgram::GetMaxWorkGroupCount(context, this->MaxGroups);

  GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  const char* text = this->Source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE)
  {
    vtkErrorMacro(<< "Compute shader compile error:\n"
                  << ShaderLog(shader) << "\nSource:\n"
                  << NumberedSource(this->Source));
    glDeleteShader(shader);
    return false;
  }
  GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDetachShader(program, shader);
  glDeleteShader(shader);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE)
  {
    vtkErrorMacro(<< "Compute program link error:\n" << ProgramLog(program));
    glDeleteProgram(program);
    return false;
  }
  this->Handle = program;
  this->Internals->Context = context;
  this->SourceChanged = false;
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleComputeProgram::Use()
{
  // VTK's shader cache keeps track of the bound program: tell it that its program is no longer
  // bound, so that the next VTK draw binds its own again
  if (vtkOpenGLRenderWindow* context = this->Internals->Context)
  {
    context->GetShaderCache()->ReleaseCurrentShader();
  }
  glUseProgram(this->Handle);
}

//------------------------------------------------------------------------------
void vtkParticleComputeProgram::UseNone()
{
  glUseProgram(0);
}

//------------------------------------------------------------------------------
int vtkParticleComputeProgram::GetUniformLocation(const char* name)
{
  if (this->Handle == 0 || !name)
  {
    return -1;
  }
  auto it = this->Internals->Locations.find(name);
  if (it == this->Internals->Locations.end())
  {
    it = this->Internals->Locations.emplace(name, glGetUniformLocation(this->Handle, name)).first;
  }
  return it->second;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::SetUniformi(const char* name, int value)
{
  const GLint location = this->GetUniformLocation(name);
  if (location < 0)
  {
    return false;
  }
  glUniform1i(location, value);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::SetUniformui(const char* name, unsigned int value)
{
  const GLint location = this->GetUniformLocation(name);
  if (location < 0)
  {
    return false;
  }
  glUniform1ui(location, value);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::SetUniformf(const char* name, float value)
{
  const GLint location = this->GetUniformLocation(name);
  if (location < 0)
  {
    return false;
  }
  glUniform1f(location, value);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::SetUniform2i(const char* name, int x, int y)
{
  const GLint location = this->GetUniformLocation(name);
  if (location < 0)
  {
    return false;
  }
  glUniform2i(location, x, y);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::SetUniform2f(const char* name, float x, float y)
{
  const GLint location = this->GetUniformLocation(name);
  if (location < 0)
  {
    return false;
  }
  glUniform2f(location, x, y);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::SetUniform3f(const char* name, float x, float y, float z)
{
  const GLint location = this->GetUniformLocation(name);
  if (location < 0)
  {
    return false;
  }
  glUniform3f(location, x, y, z);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::SetUniform4f(const char* name, float x, float y, float z, float w)
{
  const GLint location = this->GetUniformLocation(name);
  if (location < 0)
  {
    return false;
  }
  glUniform4f(location, x, y, z, w);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::SetUniformMatrix4x4(const char* name, const float* matrix)
{
  const GLint location = this->GetUniformLocation(name);
  if (location < 0 || !matrix)
  {
    return false;
  }
  glUniformMatrix4fv(location, 1, GL_FALSE, matrix);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::SetUniformMatrix3x3(const char* name, const float* matrix)
{
  const GLint location = this->GetUniformLocation(name);
  if (location < 0 || !matrix)
  {
    return false;
  }
  glUniformMatrix3fv(location, 1, GL_FALSE, matrix);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::Dispatch(unsigned int x, unsigned int y, unsigned int z)
{
  if (this->Handle == 0)
  {
    vtkErrorMacro(<< "Dispatch() before a successful Build().");
    return false;
  }
  if (x == 0 || y == 0 || z == 0)
  {
    return true;
  }
  const unsigned int* limit = this->MaxGroups;
  if (x > limit[0] && y == 1 && z == 1)
  {
    // split into rows of at most limit[0] groups, balanced so that the waste is < rows groups
    const unsigned long long rows = (static_cast<unsigned long long>(x) + limit[0] - 1) / limit[0];
    if (rows > limit[1])
    {
      vtkErrorMacro(<< "Dispatch of " << x << " work groups exceeds the limit of "
                    << static_cast<unsigned long long>(limit[0]) * limit[1]
                    << " (GL_MAX_COMPUTE_WORK_GROUP_COUNT " << limit[0] << " x " << limit[1]
                    << ").");
      return false;
    }
    const unsigned long long columns = (x + rows - 1) / rows;
    glDispatchCompute(static_cast<GLuint>(columns), static_cast<GLuint>(rows), 1);
    return true;
  }
  if (x > limit[0] || y > limit[1] || z > limit[2])
  {
    vtkErrorMacro(<< "Dispatch of " << x << " x " << y << " x " << z
                  << " work groups exceeds GL_MAX_COMPUTE_WORK_GROUP_COUNT (" << limit[0] << ", "
                  << limit[1] << ", " << limit[2] << ").");
    return false;
  }
  glDispatchCompute(x, y, z);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::MakeCurrentForRelease(vtkOpenGLRenderWindow* context)
{
  if (!context)
  {
    return false;
  }
  context->MakeCurrent();
  return context->IsCurrent();
}

//------------------------------------------------------------------------------
void vtkParticleComputeProgram::ReleaseStorage(
  vtkSmartPointer<vtkOpenGLBufferObject>& buffer, bool current)
{
  if (!buffer || buffer->GetHandle() == 0)
  {
    return;
  }
  if (current)
  {
    buffer->ReleaseGraphicsResources();
    return;
  }
  const vtkOpenGLBufferObject::ObjectType type = buffer->GetType();
  buffer->Register(nullptr); // deliberately never deleted: see the header
  buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  buffer->SetType(type);
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::AllocateStorage(vtkOpenGLBufferObject* buffer, std::size_t bytes)
{
  if (!buffer || (buffer->GetHandle() == 0 && !buffer->GenerateBuffer(buffer->GetType())))
  {
    return false;
  }
  while (glGetError() != GL_NO_ERROR)
  {
    // errors of earlier code are not ours to report; clear them to see our own
  }
  glBindBuffer(GL_COPY_WRITE_BUFFER, static_cast<GLuint>(buffer->GetHandle()));
  glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_COPY);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  return glGetError() == GL_NO_ERROR;
}

//------------------------------------------------------------------------------
void vtkParticleComputeProgram::BindStorage(unsigned int binding, vtkOpenGLBufferObject* buffer)
{
  glBindBufferBase(
    GL_SHADER_STORAGE_BUFFER, binding, buffer ? static_cast<GLuint>(buffer->GetHandle()) : 0);
}

//------------------------------------------------------------------------------
void vtkParticleComputeProgram::BindStorageBlock(
  unsigned int program, const char* block, unsigned int binding, vtkOpenGLBufferObject* buffer)
{
  const GLuint index = glGetProgramResourceIndex(program, GL_SHADER_STORAGE_BLOCK, block);
  if (index != GL_INVALID_INDEX)
  {
    glShaderStorageBlockBinding(program, index, binding);
  }
  BindStorage(binding, buffer);
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::UploadStorage(
  vtkOpenGLBufferObject* buffer, std::size_t offset, std::size_t bytes, const void* data)
{
  if (!buffer || buffer->GetHandle() == 0)
  {
    return false;
  }
  glBindBuffer(GL_COPY_WRITE_BUFFER, static_cast<GLuint>(buffer->GetHandle()));
  glBufferSubData(
    GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::DownloadStorage(
  vtkOpenGLBufferObject* buffer, std::size_t offset, std::size_t bytes, void* data)
{
  if (!buffer || buffer->GetHandle() == 0)
  {
    return false;
  }
  glBindBuffer(GL_COPY_READ_BUFFER, static_cast<GLuint>(buffer->GetHandle()));
  glGetBufferSubData(
    GL_COPY_READ_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleComputeProgram::ClearStorage(
  vtkOpenGLBufferObject* buffer, std::size_t bytes, unsigned int value)
{
  if (!buffer || buffer->GetHandle() == 0)
  {
    return false;
  }
  const GLuint word = value;
  glBindBuffer(GL_COPY_WRITE_BUFFER, static_cast<GLuint>(buffer->GetHandle()));
  glClearBufferSubData(GL_COPY_WRITE_BUFFER, GL_R32UI, 0, static_cast<GLsizeiptr>(bytes),
    GL_RED_INTEGER, GL_UNSIGNED_INT, &word);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleComputeProgram::ReleaseGraphicsResources(vtkWindow*)
{
  if (this->Handle != 0)
  {
    if (MakeCurrentForRelease(this->Internals->Context))
    {
      glDeleteProgram(this->Handle);
    }
    this->Handle = 0;
    this->Internals->Context = nullptr;
  }
  this->Internals->Locations.clear();
  this->SourceChanged = true;
}

//------------------------------------------------------------------------------
void vtkParticleComputeProgram::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Handle: " << this->Handle << "\n";
  os << indent << "Source: " << this->Source.size() << " characters"
     << (this->SourceChanged ? " (not built)" : "") << "\n";
  os << indent << "MaxWorkGroupCount: " << this->MaxGroups[0] << " " << this->MaxGroups[1] << " "
     << this->MaxGroups[2] << "\n";
}
