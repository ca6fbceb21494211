// TestParticleShaders: the GLSL registry vtkParticleShaders, without OpenGL.
//   a) every Shaders/<Module>/<Name>.glsl on disk is registered by the library of <Module> (the
//      test links every module) and resolves without an unknown include;
//   b) an unknown name gives a source that cannot compile and no module;
//   c) a name that another module registered already is refused and the first text kept; the
//      same module registering again is accepted;
//   d) an include is pasted once per shader, however often it is named.
#include "vtkMetaballMapper.h"
#include "vtkNew.h"
#include "vtkParticleShaders.h"
#include "vtkPointAOPass.h"
#include "vtkSNDFRenderPass.h"
#include "vtkTransparentSphereMapper.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <iostream>
#include <string>

namespace
{
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++Failures;
  }
}

std::size_t Count(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for (std::size_t pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1))
  {
    ++n;
  }
  return n;
}

// a) returns the number of files checked
int CheckFolders(const std::string& shaders)
{
  int files = 0;
  vtksys::Directory top;
  Check(static_cast<bool>(top.Load(shaders)), "the Shaders directory " + shaders + " opens");
  for (unsigned long i = 0; i < top.GetNumberOfFiles(); ++i)
  {
    const std::string module = top.GetFile(i);
    const std::string folder = shaders + "/" + module;
    if (module[0] == '.' || !vtksys::SystemTools::FileIsDirectory(folder))
    {
      continue;
    }
    vtksys::Directory files_of;
    files_of.Load(folder);
    for (unsigned long j = 0; j < files_of.GetNumberOfFiles(); ++j)
    {
      const std::string file = files_of.GetFile(j);
      if (vtksys::SystemTools::GetFilenameLastExtension(file) != ".glsl")
      {
        continue;
      }
      const std::string name = vtksys::SystemTools::GetFilenameWithoutLastExtension(file);
      Check(vtkParticleShaders::GetModule(name) == module,
        name + " registered by " + module + " (is: '" + vtkParticleShaders::GetModule(name) + "')");
      Check(vtkParticleShaders::Get(name).find("#error unknown") == std::string::npos,
        name + " resolves every include");
      ++files;
    }
  }
  return files;
}
}

int TestParticleShaders(int argc, char* argv[])
{
  // one object of every technique: the linker keeps a library only where its symbols are used,
  // and a module's shaders are registered where its library is loaded
  vtkNew<vtkTransparentSphereMapper> translucency;
  vtkNew<vtkPointAOPass> ambientOcclusion;
  vtkNew<vtkMetaballMapper> metaballs;
  vtkNew<vtkSNDFRenderPass> sndf;

  // the source tree's Shaders/: beside Testing/ of the data directory given with -D
  std::string data;
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-D")
    {
      data = argv[i + 1];
    }
  }
  const std::string shaders = data + "/../../Shaders";
  const int files = CheckFolders(shaders);
  Check(files > 0, "GLSL files found under " + shaders);

  // b)
  Check(vtkParticleShaders::GetModule("NoSuchShader").empty(), "an unknown name has no module");
  Check(vtkParticleShaders::Get("NoSuchShader").rfind("#error", 0) == 0,
    "an unknown name gives #error");

  // c)
  const std::string raySphere = vtkParticleShaders::Get("RaySphere");
  const vtkParticleShaders::Source clash[] = { { "RaySphere", "// another module's text\n" } };
  std::cerr << "(expected: one message about RaySphere registered twice)\n";
  Check(!vtkParticleShaders::Register("SomeTechnique", clash, 1),
    "a name of another module is refused");
  Check(vtkParticleShaders::GetModule("RaySphere") == "Core", "the first module keeps the name");
  Check(vtkParticleShaders::Get("RaySphere") == raySphere, "the first text is kept");
  const vtkParticleShaders::Source own[] = { { "TestParticleShadersOwn", "float prOwn;\n" } };
  Check(vtkParticleShaders::Register("SomeTechnique", own, 1) &&
      vtkParticleShaders::Register("SomeTechnique", own, 1),
    "a module registering its own name again is accepted");
  Check(vtkParticleShaders::GetModule("TestParticleShadersOwn") == "SomeTechnique",
    "a new module's name is found");

  // d)
  const std::string twice = vtkParticleShaders::ResolveIncludes(
    "//PR::Include TestParticleShadersOwn\n//PR::Include TestParticleShadersOwn\n");
  Check(Count(twice, "float prOwn;") == 1, "an include named twice is pasted once");

  std::cout << files << " GLSL files checked, " << Failures << " failures\n";
  return Failures == 0 ? 0 : 1;
}
