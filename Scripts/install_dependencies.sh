#!/usr/bin/env bash
# Installs the Debian 12 packages ParticleRendering needs (run as root). Skips apt entirely when
# everything is already installed.
set -euo pipefail
packages=(
  # ParaView 5.11 and everything its CMake config asks for
  paraview paraview-dev python3-paraview
  qtbase5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools libqt5opengl5-dev
  libhdf5-openmpi-dev libnetcdf-dev libgdal-dev libutfcpp-dev libdouble-conversion-dev
  zlib1g-dev libtiff-dev libtheora-dev python3-dev libpng-dev libxml2-dev liblzma-dev
  liblz4-dev libjpeg-dev libgl2ps-dev libfreetype-dev libavcodec-dev libavformat-dev
  libavutil-dev libswscale-dev libexpat1-dev libboost-dev libopenmpi-dev python3-mpi4py
  libx11-dev libgl-dev libxt-dev libglew-dev
  # build tools
  cmake g++ make
  # headless OpenGL 4.5 (Mesa llvmpipe) under a virtual X server
  xvfb xauth mesa-utils libgl1-mesa-dri
  # data generation, plots, MPI runs
  lammps python3-numpy python3-matplotlib openmpi-bin
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_dependencies: all ${#packages[@]} packages already installed"
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "install_dependencies: missing packages (${missing[*]}); run as root" >&2
  exit 1
fi
echo "install_dependencies: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
