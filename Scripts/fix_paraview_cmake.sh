#!/usr/bin/env bash
# Works around a packaging bug of Debian 13's ParaView 5.13 and Debian unstable's ParaView 6.1
# (run as root; Scripts/install_dependencies.sh calls it). Their CMake exports (ParaView's, its
# bundled VTK's and the external VTK's) name the Python extension modules without the ABI suffix,
# e.g. .../dist-packages/paraview/modules/vtkRemotingClientServerStream.so
# while the file installed is vtkRemotingClientServerStream.cpython-313-x86_64-linux-gnu.so, so
# find_package(ParaView) stops with "The imported target ... references the file ... but this
# file does not exist". This rewrites each such name in those *-targets-*.cmake files to
# the one file that exists beside it, and changes nothing else: a name whose file exists, or
# that has no single suffixed file, stays. Running it again (e.g. after a package upgrade
# restored the files) does the same; on Debian 12 it finds nothing to change.
set -euo pipefail
shopt -s nullglob
dirs=(/usr/lib/*/cmake/paraview-* /usr/lib/*/cmake/paraview-*/vtk /usr/lib/*/cmake/vtk-*)
[ ${#dirs[@]} -gt 0 ] || exit 0
python3 - "${dirs[@]}" <<'EOF'
import glob, os, re, sys

location = re.compile(r'"\$\{_IMPORT_PREFIX\}(/[^"]*/dist-packages/[^"]*)\.so"')
for directory in sys.argv[1:]:
    # The export's prefix: the directory above lib/ (lib/<triplet>/cmake/paraview-X.Y[/vtk]).
    prefix = directory[: directory.index("/lib/")]
    for path in sorted(glob.glob(os.path.join(directory, "*-targets-*.cmake"))):
        with open(path) as f:
            text = f.read()
        fixed = []

        def repair(match):
            stem = match.group(1)
            if os.path.exists(prefix + stem + ".so"):
                return match.group(0)
            candidates = glob.glob(glob.escape(prefix + stem) + ".cpython-*.so")
            if len(candidates) != 1:
                return match.group(0)
            fixed.append(os.path.basename(candidates[0]))
            return '"${_IMPORT_PREFIX}%s"' % candidates[0][len(prefix):]

        new_text = location.sub(repair, text)
        if fixed:
            with open(path, "w") as f:
                f.write(new_text)
            print("fix_paraview_cmake: %s: %d Python module name(s) given their ABI suffix (%s, ...)"
                  % (path, len(fixed), fixed[0]))
EOF
