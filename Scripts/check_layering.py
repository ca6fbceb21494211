#!/usr/bin/env python3
"""Checks the layering of ParticleRendering's C++ modules (issue "One shape per technique").

    python3 Scripts/check_layering.py [REPRESENTATIONS_DIR [SHADERS_DIR]]  # check (default: ours)
    python3 Scripts/check_layering.py --self-test                         # must-fail cases

The modules are the folders of Representations/, one vtk.module each:
  layer 0  Core                                       includes no other module of ours
  layer 1  Translucency, AmbientOcclusion, Metaballs,  include the core and themselves only
           SNDF (any other folder with a vtk.module)
  layer 2  ParaView                                   the integration: may include anything

Checked, from the #include "..." lines of every .h, .cxx and .cxx.in and from the vtk.module files:
  1. no file includes a header of a module its layer may not see (above);
  2. no vtk.module names a ParticleRendering module its layer may not see;
  3. the include graph between classes (a class = its .h and .cxx) has no cycle;
  4. every folder of Shaders/ is a module's (its GLSL, embedded in its library), and names are
     unique across folders;
  5. a module's GLSL includes (`//PR::Include Name`) only GLSL its layer may see, and so does its
     C++ (the `//PR::Include Name` lines it inserts and the names it passes to
     vtkParticleShaders::Get): a technique's shaders are registered only where its library is.
Exit status 0 when the tree is clean, 1 with one line per violation otherwise.
"""
import os
import re
import sys
import tempfile

CORE = "Core"
INTEGRATION = {"ParaView"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
GLSL_INCLUDE = re.compile(r"^\s*//PR::Include (\w+)", re.M)
CXX_GLSL_INCLUDE = re.compile(r'(?:"|\\n)//PR::Include (\w+)')  # in a string literal
GLSL_GET = re.compile(r'vtkParticleShaders::Get\(\s*"(\w+)"')
SOURCE_SUFFIXES = (".h", ".cxx", ".cxx.in")


def class_name(file_name):
    for suffix in (".cxx.in",) + SOURCE_SUFFIXES:
        if file_name.endswith(suffix):
            return file_name[: -len(suffix)]
    return None


def scan(root):
    """Returns {module: {class: set(included headers)}}, {header: module}, {module: deps}."""
    modules, owner, declared = {}, {}, {}
    for module in sorted(os.listdir(root)):
        folder = os.path.join(root, module)
        if not os.path.isfile(os.path.join(folder, "vtk.module")):
            continue
        with open(os.path.join(folder, "vtk.module")) as f:
            declared[module] = set(re.findall(r"ParticleRendering::(\w+)", f.read())) - {module}
        classes = modules.setdefault(module, {})
        for name in sorted(os.listdir(folder)):
            cls = class_name(name)
            if cls is None:
                continue
            if name.endswith(".h"):
                owner[name] = module
            with open(os.path.join(folder, name), errors="replace") as f:
                classes.setdefault(cls, set()).update(INCLUDE.findall(f.read()))
    return modules, owner, declared


def scan_glsl(root, shaders):
    """Returns {glsl name: folder} of SHADERS_DIR, [duplicate names], and per module of root the
    GLSL names its C++ uses: {module: {(file, name)}}, and per GLSL file its includes."""
    folder_of, duplicates, includes = {}, [], {}
    for folder in sorted(os.listdir(shaders)) if os.path.isdir(shaders) else []:
        path = os.path.join(shaders, folder)
        if not os.path.isdir(path):
            continue
        for name in sorted(os.listdir(path)):
            if not name.endswith(".glsl"):
                continue
            glsl = name[: -len(".glsl")]
            if glsl in folder_of:
                duplicates.append(f"{folder}/{name} (also in {folder_of[glsl]}/)")
            folder_of[glsl] = folder
            with open(os.path.join(path, name), errors="replace") as f:
                includes[(folder, glsl)] = set(GLSL_INCLUDE.findall(f.read()))
    used = {}
    for module in sorted(os.listdir(root)):
        folder = os.path.join(root, module)
        if not os.path.isfile(os.path.join(folder, "vtk.module")):
            continue
        for name in sorted(os.listdir(folder)):
            if class_name(name) is None:
                continue
            with open(os.path.join(folder, name), errors="replace") as f:
                text = f.read()
            for glsl in CXX_GLSL_INCLUDE.findall(text) + GLSL_GET.findall(text):
                used.setdefault(module, set()).add((name, glsl))
    return folder_of, duplicates, includes, used


def check_glsl(root, shaders, modules):
    folder_of, duplicates, includes, used = scan_glsl(root, shaders)
    problems = [f"GLSL name twice: {d}" for d in duplicates]
    for folder in sorted(set(folder_of.values())):
        if folder not in modules:
            problems.append(f"Shaders/{folder}/ is no module's folder")
    for (folder, glsl), names in sorted(includes.items()):
        for name in sorted(names):
            other = folder_of.get(name)
            if other is None:
                problems.append(f"Shaders/{folder}/{glsl}.glsl includes unknown {name}")
            elif not visible(folder, other):
                problems.append(f"Shaders/{folder}/{glsl}.glsl includes {other}/{name}.glsl")
    for module, pairs in sorted(used.items()):
        for file_name, name in sorted(pairs):
            other = folder_of.get(name)
            if other is None:
                problems.append(f"{module}/{file_name} uses unknown GLSL {name}")
            elif not visible(module, other):
                problems.append(f"{module}/{file_name} uses GLSL {other}/{name}.glsl")
    return problems


def visible(module, other):
    """Whether a file of `module` may include a header of `other`."""
    if module == other or module in INTEGRATION:
        return True
    if module == CORE:
        return False
    return other == CORE


def find_cycle(graph):
    """One cycle of the directed graph {node: set(nodes)} as a list, or None."""
    state, stack = {}, []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for succ in sorted(graph.get(node, ())):
            if state.get(succ) == 1:
                return stack[stack.index(succ):] + [succ]
            if succ not in state:
                cycle = visit(succ)
                if cycle:
                    return cycle
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state:
            cycle = visit(node)
            if cycle:
                return cycle
    return None


def check(root, shaders=None):
    modules, owner, declared = scan(root)
    problems = []
    graph = {}
    for module, classes in modules.items():
        for other in sorted(declared[module]):
            if other in modules and not visible(module, other):
                problems.append(f"{module}/vtk.module depends on ParticleRendering::{other}")
        for cls, includes in sorted(classes.items()):
            for header in sorted(includes):
                other = owner.get(header)
                if other is None:
                    continue  # VTK's, the standard library's, generated
                if not visible(module, other):
                    problems.append(f"{module}/{cls} includes {other}/{header}")
                target = class_name(header)
                if target != cls:
                    graph.setdefault(cls, set()).add(target)
    cycle = find_cycle(graph)
    if cycle:
        problems.append("include cycle: " + " -> ".join(cycle))
    if shaders is not None:
        problems += check_glsl(root, shaders, modules)
    return problems, modules


def self_test():
    """The checker must reject each broken tree and accept the clean one."""
    def tree(files):
        root = tempfile.mkdtemp(prefix="pr_layering_")
        for path, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
            with open(os.path.join(root, path), "w") as f:
                f.write(text)
        return root

    base = {
        "Core/vtk.module": "NAME\n  ParticleRendering::Core\n",
        "Core/vtkA.h": '#include "vtkObject.h"\n',
        "Core/vtkA.cxx": '#include "vtkA.h"\n',
        "Tech/vtk.module": "NAME\n  ParticleRendering::Tech\nDEPENDS\n  ParticleRendering::Core\n",
        "Tech/vtkT.h": '#include "vtkA.h"\n',
        "Tech/vtkT.cxx": '#include "vtkT.h"\n',
        "Other/vtk.module": "NAME\n  ParticleRendering::Other\nDEPENDS\n  ParticleRendering::Core\n",
        "Other/vtkO.h": '#include "vtkA.h"\n',
        "Other/vtkO.cxx": '#include "vtkO.h"\n',
        "ParaView/vtk.module": "NAME\n  ParticleRendering::ParaView\n",
        "ParaView/vtkP.cxx": '#include "vtkT.h"\n#include "vtkO.h"\n',
        "Shaders/Core/A.glsl": "",
        "Shaders/Tech/T.glsl": "//PR::Include A\n",
        "Shaders/Other/O.glsl": "//PR::Include A\n",
    }
    cases = {
        "clean": ({}, None),
        "core includes a technique": ({"Core/vtkA.cxx": '#include "vtkT.h"\n'}, "Core/vtkA includes"),
        "technique includes a technique": (
            {"Tech/vtkT.cxx": '#include "vtkO.h"\n'}, "Tech/vtkT includes Other/vtkO.h"),
        "technique module depends on a technique": (
            {"Tech/vtk.module": "DEPENDS\n  ParticleRendering::Core\n  ParticleRendering::Other\n"},
            "Tech/vtk.module depends on ParticleRendering::Other"),
        "cycle inside the core": (
            {"Core/vtkB.h": '#include "vtkA.h"\n', "Core/vtkA.cxx": '#include "vtkB.h"\n'},
            "include cycle"),
        "core shader includes a technique's": (
            {"Shaders/Core/A.glsl": "//PR::Include T\n"}, "Shaders/Core/A.glsl includes Tech/T.glsl"),
        "technique shader includes another's": (
            {"Shaders/Tech/T.glsl": "//PR::Include O\n"}, "Shaders/Tech/T.glsl includes Other/O.glsl"),
        "technique C++ gets another's shader": (
            {"Tech/vtkT.cxx": 'auto s = vtkParticleShaders::Get("O");\n'},
            "Tech/vtkT.cxx uses GLSL Other/O.glsl"),
        "core C++ inserts a technique's include": (
            {"Core/vtkA.cxx": 'hooks.Insert("//PR::Include T");\n'}, "Core/vtkA.cxx uses GLSL Tech/T.glsl"),
        "shader folder of no module": ({"Shaders/Gone/G.glsl": ""}, "Shaders/Gone/ is no module's folder"),
        "one name in two folders": ({"Shaders/Other/T.glsl": ""}, "GLSL name twice"),
    }
    failures = 0
    for name, (changes, expected) in cases.items():
        root = tree({**base, **changes})
        problems, _ = check(root, os.path.join(root, "Shaders"))
        ok = (not problems) if expected is None else any(expected in p for p in problems)
        print(f"self-test {name}: {'ok' if ok else 'WRONG'} {problems}")
        failures += not ok
    return 1 if failures else 0


def main(argv):
    if "--self-test" in argv:
        return self_test()
    top = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    root = argv[1] if len(argv) > 1 else os.path.join(top, "Representations")
    shaders = argv[2] if len(argv) > 2 else os.path.join(top, "Shaders")
    problems, modules = check(root, shaders)
    for problem in problems:
        print("layering:", problem)
    counted = ", ".join(f"{m} ({len(c)} classes)" for m, c in modules.items())
    glsl = sum(1 for _, _, files in os.walk(shaders) for f in files if f.endswith(".glsl"))
    print(f"layering: {len(problems)} violations in {counted}; {glsl} GLSL files")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
