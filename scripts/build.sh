#!/usr/bin/env bash
# Configures and builds chipflex (Release) into build/; the executable is build/bin/chipflex.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
