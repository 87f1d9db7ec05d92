#!/usr/bin/env bash
# Configures and builds chipflex (Release) into build/; the executable is build/bin/chipflex.
# Arguments name the targets to build (default: all, tests included), e.g.
#   bash scripts/build.sh chipflex      # the command alone, as scripts/demo.sh does
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
targets=()
(($#)) && targets=(--target "$@")
cmake --build build -j"$(nproc)" "${targets[@]}"
