#!/usr/bin/env bash
# The main job on its default case: installs the dependencies, builds, then runs the
# Antoci et al. (2007) elastic-gate benchmark with the reduced flexible gate: meshes the
# gate (gmsh), reduces it (deal.II + SLEPc: 8 modes + 1 static pressure mode + modal
# derivatives, geometrically nonlinear), couples it to
# the SPH water column for 0.4 s, prints the summary (RMS error of the free-end dx, dy
# against the experiment, wall time) and draws out/elastic_gate/elastic_gate.png.
#   VARIANTS="flexible chain1 chain2 chain3 sph_solid" DP_MM=1 bash scripts/demo.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
bash scripts/build.sh chipflex   # the command only: the tests are not needed here
out=out/elastic_gate
mkdir -p "$out"
build/bin/chipflex mesh gate -o "$out/gate.msh"
build/bin/chipflex reduce "$out/gate.msh" -o "$out/gate.h5" --clamp clamp --modes 8 \
  --static-modes pressure:xmin --nonlinear --E 1.2e7 --nu 0.4 --rho 1100
build/bin/chipflex info "$out/gate.h5"
build/bin/chipflex compare "$out/gate.msh" "$out/gate.h5" --load force:tip:1,0
# shellcheck disable=SC2086
CHIPFLEX=build/bin/chipflex cases/elastic_gate/run_benchmark.sh "$out" "${DP_MM:-1}" \
  ${VARIANTS:-flexible}
