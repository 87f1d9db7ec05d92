#!/usr/bin/env bash
# Installs the dependencies, builds, and runs every test (Catch2 unit tests and the
# CTest validation cases). `ctest -LE validation` skips the validation runs. Tests labelled
# `long` (several minutes each; docs/testing.md lists them) are left out unless
# CHIPFLEX_LONG_TESTS=1; `ctest -L long` runs only them.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
bash scripts/build.sh
cd build
# The spin count that chipflex and the test programs would set for themselves by starting
# again (common/openmp_waiting.h): set here, it spares each of the suite's hundreds of
# processes that second start, about 0.4 s of loading 200 shared libraries each.
export GOMP_SPINCOUNT=${GOMP_SPINCOUNT:-1000}
# OpenMPI refuses to run as root unless told; the MPI tests run mpirun.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
skip_long=(-LE long)
[ "${CHIPFLEX_LONG_TESTS:-0}" = 1 ] && skip_long=()
ctest --output-on-failure -j"$(nproc)" --timeout 1500 "${skip_long[@]}"
