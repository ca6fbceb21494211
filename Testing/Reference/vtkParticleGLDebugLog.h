/**
 * @class   vtkParticleGLDebugLog
 * @brief   the OpenGL debug output (KHR_debug) of a render window's context, for the tests
 *
 * Watch(window) enables the context's debug output (GL_DEBUG_OUTPUT, synchronous, every source
 * and type) with a callback that counts and keeps the messages. Errors (GL_DEBUG_TYPE_ERROR) and
 * undefined behaviour (GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: e.g. a texture sampled while it is a
 * render target, on drivers that detect it) are printed at once as "GL DEBUG ERROR: ..." and
 * counted in GetNumberOfErrors(); other messages (performance notes, portability) only in
 * GetNumberOfMessages(). The suite's repeatability checks (vtkParticleImageComparison::
 * TestRepeatable, the Python harnesses) draw their second frame between StartFrame and EndFrame,
 * so a GL error during any image test's frame fails that test. One log per process (GetInstance());
 * a context is watched once. Needs OpenGL 4.3 or KHR_debug (Watch returns false without it).
 */
#ifndef vtkParticleGLDebugLog_h
#define vtkParticleGLDebugLog_h

#include "vtkObject.h"
#include "vtkParticleRenderingReferenceModule.h" // for export macro

#include "vtkWeakPointer.h" // for vtkWeakPointer

#include <string> // for std::string
#include <vector> // for std::vector

class vtkRenderWindow;

class VTKPARTICLERENDERINGREFERENCE_EXPORT vtkParticleGLDebugLog : public vtkObject
{
public:
  static vtkParticleGLDebugLog* New();
  vtkTypeMacro(vtkParticleGLDebugLog, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The process's log. */
  static vtkParticleGLDebugLog* GetInstance();

  /**
   * Enable the debug output of the window's context (made current) into this log. False when
   * the context has no debug output (or no window); true when it is watched, also already.
   */
  bool Watch(vtkRenderWindow* window);

  ///@{
  /** Errors and undefined behaviour reported, and all messages, since the log was made. */
  vtkGetMacro(NumberOfErrors, int);
  vtkGetMacro(NumberOfMessages, int);
  ///@}

  /** The text of the last error ("" when none). */
  const char* GetLastError() { return this->LastError.c_str(); }

  ///@{
  /**
   * A frame under the debug output, as the repeatability checks draw it: StartFrame watches the
   * window and marks the error count; EndFrame returns whether no error came since, printing
   * "REPEAT name: N OpenGL error(s) reported while the frame was drawn (the last: ...)" if one did.
   */
  void StartFrame(vtkRenderWindow* window);
  bool EndFrame(const char* name);
  ///@}

#ifndef __VTK_WRAP__
  /** The callback's entry (public for the C callback only). */
  void Add(unsigned int source, unsigned int type, unsigned int id, unsigned int severity,
    const char* message);
#endif

protected:
  vtkParticleGLDebugLog() = default;
  ~vtkParticleGLDebugLog() override = default;

private:
  vtkParticleGLDebugLog(const vtkParticleGLDebugLog&) = delete;
  void operator=(const vtkParticleGLDebugLog&) = delete;

  int NumberOfErrors = 0;
  int NumberOfMessages = 0;
  int FrameStartErrors = 0;
  std::string LastError;
  std::vector<vtkWeakPointer<vtkRenderWindow>> Watched; // the windows reporting here
};

#endif
