#!/bin/sh
# Turek & Hron's FSI2 benchmark (cases/turek_hron/fsi2.prm, docs/turek_hron.md): meshes
# the bar and reduces it to a geometrically nonlinear floating-frame body (OUT/bar.h5),
# runs the case and prints the tip's figures against the benchmark (plot_fsi.py, which
# also draws OUT/fsi2/fsi.png).
#
#   cases/turek_hron/run_fsi.sh OUT [END_TIME_S]
#     END_TIME_S  simulated time (default: the case's 10 s)
#   Environment: CHIPFLEX (default build/bin/chipflex), THREADS (default: all cores).
set -e
if [ $# -lt 1 ]; then
  sed -n '2,9p' "$0"
  exit 2
fi
repo=$(cd "$(dirname "$0")/../.." && pwd)
chipflex=${CHIPFLEX:-$repo/build/bin/chipflex}
chipflex=$(cd "$(dirname "$chipflex")" && pwd)/$(basename "$chipflex")
mkdir -p "$1"
out=$(cd "$1" && pwd)
cd "$out"
# The bar: 0.02 m thick, 0.351 m from the cylinder's surface at y = +-0.01 m (x = 0.249 m)
# to point A, elements of 5 mm (second degree). Turek & Hron's FSI2 material.
[ -f bar.msh ] || "$chipflex" mesh gate -o bar.msh --length 0.351 --thickness 0.02 --size 0.005
[ -f bar.h5 ] || "$chipflex" reduce bar.msh -o bar.h5 --clamp clamp --modes 6 \
  --static-modes pressure:xmin --nonlinear --E 1.4e6 --nu 0.4 --rho 10000
"$chipflex" run "$repo/cases/turek_hron/fsi2.prm" --out fsi2 ${THREADS:+--threads $THREADS} \
  ${2:+--end-time $2}
python3 "$repo/cases/turek_hron/plot_fsi.py" fsi2
