#!/usr/bin/env bash
# Installs chipflex's build and run dependencies from Debian 12's packages (as root).
# OpenBLAS is installed deliberately: through Debian's alternatives it replaces the
# reference BLAS under MUMPS and makes the factorisations ~3.5x faster (docs/performance.md).
# libzip-dev, libpugixml-dev: FMUs (zip archives, common/zip_archive.cc; modelDescription.xml,
# common/fmi2_model_description.cc). python3-h5py: tests/apps opens the run outputs with it
# (ParaView's python3-paraview does more, but is too large to install here; the test uses it
# where present).
# Further packages given as arguments are installed with them (scripts/sanitize.sh: clang).
set -euo pipefail
packages=(
  cmake g++ make pkg-config
  libdeal.ii-dev petsc-dev slepc-dev libhdf5-openmpi-dev libeigen3-dev
  gmsh libgmsh-dev catch2 openmpi-bin libopenblas0-pthread gnuplot-nox python3-h5py
  libzip-dev libpugixml-dev
  "$@"
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
