#include "vtkParticleGLDebugLog.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSmartPointer.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <iostream>

vtkStandardNewMacro(vtkParticleGLDebugLog);

namespace
{
void GLAPIENTRY Report(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
  const GLchar* message, const void* log)
{
  static_cast<vtkParticleGLDebugLog*>(const_cast<void*>(log))
    ->Add(source, type, id, severity, message);
}
}

//------------------------------------------------------------------------------
vtkParticleGLDebugLog* vtkParticleGLDebugLog::GetInstance()
{
  // lives until the process ends: contexts keep calling it
  static vtkSmartPointer<vtkParticleGLDebugLog> instance =
    vtkSmartPointer<vtkParticleGLDebugLog>::New();
  return instance;
}

//------------------------------------------------------------------------------
bool vtkParticleGLDebugLog::Watch(vtkRenderWindow* window)
{
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!context || context->GetNeverRendered())
  {
    return false;
  }
  // (a window deleted since leaves a null pointer: a new one at its address is watched anew)
  this->Watched.erase(
    std::remove(this->Watched.begin(), this->Watched.end(), nullptr), this->Watched.end());
  if (std::find(this->Watched.begin(), this->Watched.end(), window) != this->Watched.end())
  {
    return true;
  }
  context->MakeCurrent();
  if (!glDebugMessageCallback || !glDebugMessageControl)
  {
    return false;
  }
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
  glDebugMessageCallback(Report, this);
  this->Watched.emplace_back(window);
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleGLDebugLog::StartFrame(vtkRenderWindow* window)
{
  this->Watch(window);
  this->FrameStartErrors = this->NumberOfErrors;
}

//------------------------------------------------------------------------------
bool vtkParticleGLDebugLog::EndFrame(const char* name)
{
  const int errors = this->NumberOfErrors - this->FrameStartErrors;
  if (errors > 0)
  {
    std::cout << "REPEAT " << (name ? name : "picture") << ": " << errors
              << " OpenGL error(s) reported while the frame was drawn (the last: "
              << this->LastError << ")\n";
    std::cout.flush();
  }
  return errors == 0;
}

//------------------------------------------------------------------------------
void vtkParticleGLDebugLog::Add(unsigned int source, unsigned int type, unsigned int id,
  unsigned int severity, const char* message)
{
  ++this->NumberOfMessages;
  if (type != GL_DEBUG_TYPE_ERROR && type != GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR)
  {
    return;
  }
  ++this->NumberOfErrors;
  this->LastError = message ? message : "";
  std::cout << "GL DEBUG " << (type == GL_DEBUG_TYPE_ERROR ? "ERROR" : "UNDEFINED BEHAVIOUR")
            << " (source 0x" << std::hex << source << ", id 0x" << id << ", severity 0x" << severity
            << std::dec << "): " << this->LastError << "\n";
  std::cout.flush();
}

//------------------------------------------------------------------------------
void vtkParticleGLDebugLog::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfErrors: " << this->NumberOfErrors << "\n";
  os << indent << "NumberOfMessages: " << this->NumberOfMessages << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
  os << indent << "Watched windows: " << this->Watched.size() << "\n";
}
