// The registry of embedded GLSL sources: each module registers the table CMake generates from its
// folder of Shaders/ (vtkParticleShaderTable.cxx.in) when its library loads.
#include "vtkParticleShaders.h"

#include <iostream>
#include <map>
#include <mutex>
#include <set>

namespace
{
struct Entry
{
  const char* Text;
  std::string Module;
};

std::mutex& TableMutex()
{
  static std::mutex mutex;
  return mutex;
}

std::map<std::string, Entry>& Table()
{
  static std::map<std::string, Entry> table;
  return table;
}

// The registered entry of `name`, or null.
const Entry* Find(const std::string& name)
{
  std::lock_guard<std::mutex> lock(TableMutex());
  const auto it = Table().find(name);
  return it == Table().end() ? nullptr : &it->second;
}

std::string Resolve(const std::string& source, std::set<std::string>& seen)
{
  static const std::string tag = "//PR::Include ";
  std::string out;
  std::size_t pos = 0;
  while (true)
  {
    std::size_t hit = source.find(tag, pos);
    if (hit == std::string::npos)
    {
      out.append(source, pos, std::string::npos);
      return out;
    }
    out.append(source, pos, hit - pos);
    std::size_t end = source.find('\n', hit);
    std::string name = source.substr(
      hit + tag.size(), (end == std::string::npos ? source.size() : end) - hit - tag.size());
    while (!name.empty() && (name.back() == ' ' || name.back() == '\r'))
    {
      name.pop_back();
    }
    const Entry* entry = Find(name);
    if (!entry)
    {
      std::cerr << "ParticleRendering: unknown GLSL include '" << name << "'\n";
      out += "#error unknown include " + name + "\n";
    }
    else if (seen.insert(name).second)
    {
      out += "// ---- begin " + name + ".glsl\n" + Resolve(entry->Text, seen) + "// ---- end " +
        name + ".glsl\n";
    }
    pos = (end == std::string::npos ? source.size() : end + 1);
  }
}
}

std::string vtkParticleShaders::Get(const std::string& name)
{
  const Entry* entry = Find(name);
  if (!entry)
  {
    std::cerr << "ParticleRendering: unknown GLSL source '" << name << "'\n";
    return "#error unknown shader " + name + "\n";
  }
  return ResolveIncludes(entry->Text);
}

bool vtkParticleShaders::Register(const char* module, const Source* sources, std::size_t count)
{
  std::lock_guard<std::mutex> lock(TableMutex());
  bool unique = true;
  for (std::size_t i = 0; i < count; ++i)
  {
    const auto added = Table().emplace(sources[i].Name, Entry{ sources[i].Text, module });
    if (!added.second && added.first->second.Module != module)
    {
      std::cerr << "ParticleRendering: the GLSL source '" << sources[i].Name << "' of " << module
                << " is also in " << added.first->second.Module << "; " << module
                << "'s is ignored\n";
      unique = false;
    }
  }
  return unique;
}

std::string vtkParticleShaders::GetModule(const std::string& name)
{
  const Entry* entry = Find(name);
  return entry ? entry->Module : std::string();
}

std::string vtkParticleShaders::ResolveIncludes(const std::string& source)
{
  std::set<std::string> seen;
  return Resolve(source, seen);
}

bool vtkParticleShaders::ReplaceHook(
  std::string& source, const std::string& hook, const std::string& replacement)
{
  std::size_t pos = 0;
  while ((pos = source.find(hook, pos)) != std::string::npos)
  {
    std::size_t lineStart = source.rfind('\n', pos);
    lineStart = lineStart == std::string::npos ? 0 : lineStart + 1;
    if (source.find_first_not_of(" \t", lineStart) == pos)
    {
      source.replace(pos, hook.size(), replacement);
      return true;
    }
    pos += hook.size();
  }
  return false;
}
