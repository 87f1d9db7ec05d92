#!/usr/bin/env bash
# Installs the dependencies, builds, and runs every test (Catch2 unit tests and the
# CTest validation cases). `ctest -LE validation` skips the long validation runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
bash scripts/build.sh
cd build
# OpenMPI refuses to run as root unless told; the MPI tests run mpirun.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest --output-on-failure -j"$(nproc)" --timeout 1500
