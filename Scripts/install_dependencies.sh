#!/usr/bin/env bash
# Installs the Debian packages ParticleRendering needs (run as root), for the release it runs on:
#   Debian 12 (bookworm): ParaView 5.11, bundled VTK 9.2, Qt 5, Python 3.11
#   Debian 13 (trixie):   ParaView 5.13, bundled VTK 9.3, Qt 6, Python 3.13
#   Debian unstable (sid): ParaView 6.1, external VTK 9.6, Qt 6, Python 3.14
# ParaView's CMake config calls find_package for every third-party library it was built with, so
# each -dev package below is needed even where the plugin never uses it. Skips apt entirely when
# everything is already installed. Then applies Scripts/fix_paraview_cmake.sh (a packaging bug of
# Debian 13 and unstable; does nothing elsewhere).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)

# The release: VERSION_CODENAME from os-release; unstable reports the next release's name
# there, and "<name>/sid" in /etc/debian_version.
. /etc/os-release
release=${VERSION_CODENAME:-unknown}
case "$(cat /etc/debian_version 2>/dev/null)" in */sid) release=sid ;; esac

common=(
  paraview paraview-dev python3-paraview
  libhdf5-openmpi-dev libnetcdf-dev libgdal-dev libutfcpp-dev libdouble-conversion-dev
  zlib1g-dev libtiff-dev libtheora-dev python3-dev libpng-dev libxml2-dev liblzma-dev
  liblz4-dev libjpeg-dev libgl2ps-dev libfreetype-dev libavcodec-dev libavformat-dev
  libavutil-dev libswscale-dev libexpat1-dev libboost-dev libopenmpi-dev python3-mpi4py
  libx11-dev libgl-dev libxt-dev libglew-dev
  # build tools
  cmake g++ make
  # headless OpenGL 4.5 (Mesa llvmpipe) under a virtual X server
  xvfb xauth mesa-utils libgl1-mesa-dri x11-apps
  # data generation, plots, MPI runs
  lammps python3-numpy python3-matplotlib openmpi-bin
)
# Debian 13 and unstable: Qt 6 and the further -dev packages their ParaView's CMake config asks for
newer=(qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-svg-dev qt6-5compat-dev libcgns-dev
  libprotobuf-dev protobuf-compiler libpugixml-dev libfmt-dev libexprtk-dev libcli11-dev
  libfast-float-dev libeigen3-dev)
case "$release" in
  bookworm)
    what="Debian 12 (bookworm): ParaView 5.11, Qt 5"
    # (clang-format 14: the version the tree is formatted with, checked by CTest's
    # ParticleRendering.Format; other releases' versions format differently and skip the check)
    packages=("${common[@]}" qtbase5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools
      libqt5opengl5-dev clang-format) ;;
  trixie)
    what="Debian 13 (trixie): ParaView 5.13, Qt 6"
    packages=("${common[@]}" "${newer[@]}" libadios2-mpi-c++11-dev) ;;
  sid)
    what="Debian unstable (sid): ParaView 6.1, external VTK 9.6, Qt 6"
    packages=("${common[@]}" "${newer[@]}" libvtk9-dev python3-vtk9) ;;
  *)
    echo "install_dependencies: unsupported release '$release' ($PRETTY_NAME); supported:" \
      "Debian 12 (bookworm), Debian 13 (trixie), Debian unstable (sid)" >&2
    exit 1 ;;
esac
echo "install_dependencies: found $what"

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_dependencies: all ${#packages[@]} packages already installed"
else
  if [ "$(id -u)" -ne 0 ]; then
    echo "install_dependencies: missing packages (${missing[*]}); run as root" >&2
    exit 1
  fi
  echo "install_dependencies: installing ${#missing[@]} of ${#packages[@]} packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
bash "$top/Scripts/fix_paraview_cmake.sh"
