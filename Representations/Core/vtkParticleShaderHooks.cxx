#include "vtkParticleShaderHooks.h"

#include "vtkObject.h"
#include "vtkParticleShaders.h"

namespace
{
const char* StageName(vtkParticleShaderHooks::Stage stage)
{
  switch (stage)
  {
    case vtkParticleShaderHooks::Vertex:
      return "vertex";
    case vtkParticleShaderHooks::Geometry:
      return "geometry";
    default:
      return "fragment";
  }
}
}

//------------------------------------------------------------------------------
vtkParticleShaderHooks::vtkParticleShaderHooks(vtkObject* owner)
  : Owner(owner)
{
}

//------------------------------------------------------------------------------
void vtkParticleShaderHooks::Begin(
  std::string& vertexShader, std::string& geometryShader, std::string& fragmentShader)
{
  this->Sources[Vertex] = &vertexShader;
  this->Sources[Geometry] = &geometryShader;
  this->Sources[Fragment] = &fragmentShader;
}

//------------------------------------------------------------------------------
bool vtkParticleShaderHooks::Insert(Stage stage, const std::string& hook, const std::string& code)
{
  std::string* source = this->Sources[stage];
  if (source && vtkParticleShaders::ReplaceHook(*source, hook, code + "\n" + hook))
  {
    return true;
  }
  const std::string key = std::string(StageName(stage)) + " " + hook;
  if (this->Warned.insert(key).second && this->Owner)
  {
    vtkWarningWithObjectMacro(
      this->Owner, << "The " << StageName(stage) << " shader being built has no hook " << hook
                   << (source ? "" : " (no shader: Begin() was not called)") << "; "
                   << this->Owner->GetClassName()
                   << " cannot add its code there, and its effect is missing from the picture.");
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkParticleShaderHooks::AddSphereVarying(const std::string& type, const std::string& name)
{
  const std::string vs = name + "VSOutput";
  const std::string gs = name + "GSOutput";
  bool ok = this->Insert(Vertex, "//PR::Sphere::Dec", "flat out " + type + " " + vs + ";");
  ok = this->Insert(Geometry, "//PR::Sphere::Dec",
         "flat in " + type + " " + vs + "[];\nflat out " + type + " " + gs + ";") &&
    ok;
  ok = this->Insert(Geometry, "//PR::Sphere::Impl", "    " + gs + " = " + vs + "[0];") && ok;
  ok = this->Insert(Fragment, "//PR::Sphere::Dec", "flat in " + type + " " + vs + ";") && ok;
  return ok;
}

//------------------------------------------------------------------------------
const std::set<std::string>& vtkParticleShaderHooks::GetHookNames(Stage stage)
{
  static const std::set<std::string> vertex = { "//PR::Sphere::Dec", "//PR::Sphere::Impl" };
  static const std::set<std::string> geometry = { "//PR::Sphere::Dec", "//PR::Sphere::Cull",
    "//PR::Sphere::Impl" };
  static const std::set<std::string> fragment = { "//PR::Sphere::Dec", "//PR::Surface::Impl",
    "//PR::Coverage::Impl", "//PR::Surface::Normal", "//PR::AmbientOcclusion::Impl",
    "//PR::Shading::Impl" };
  return stage == Vertex ? vertex : (stage == Geometry ? geometry : fragment);
}
