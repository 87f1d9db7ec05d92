#!/bin/sh
# The elastic-gate benchmark (Antoci, Gallati & Sibilla 2007): meshes and reduces the
# gate once, runs every variant, prints each run's summary line (wall time, lost particles,
# peak fluid speed), draws OUT/elastic_gate.png and prints each run's RMS dx / dy against
# the experiment (`rms: run=VARIANT ...`, from chipflex plot).
#
#   cases/elastic_gate/run_benchmark.sh OUT [DP_MM] [VARIANT ...]
#     DP_MM    fluid particle spacing in mm (default 1; the SPH solid keeps Table 1's 1 mm)
#     VARIANT  flexible fe chain1 chain2 chain3 sph_solid (default: all; fe is the full
#              nonlinear FE gate, minutes per run at dp 2 mm)
#   Environment: CHIPFLEX (default build/bin/chipflex), THREADS (default: all cores),
#   MODES (modes kept of the 8 normal + 1 static correction mode + modal derivatives of
#   the nonlinear gate; default all).
set -e
if [ $# -lt 1 ]; then
  sed -n '2,12p' "$0"
  exit 2
fi
repo=$(cd "$(dirname "$0")/../.." && pwd)
chipflex=${CHIPFLEX:-$repo/build/bin/chipflex}
chipflex=$(cd "$(dirname "$chipflex")" && pwd)/$(basename "$chipflex")
out=$1
dp_mm=${2:-1}
shift $(( $# >= 2 ? 2 : 1 ))
variants=${*:-flexible fe chain1 chain2 chain3 sph_solid}
threads=${THREADS:+--threads $THREADS}
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"
if [ ! -f gate.h5 ] || [ ! -f gate.msh ]; then
  "$chipflex" mesh gate -o gate.msh
  "$chipflex" reduce gate.msh -o gate.h5 --clamp clamp --modes 8 --static-modes pressure:xmin \
    --nonlinear
fi
dp=$(awk "BEGIN { print $dp_mm / 1000 }")
for v in $variants; do
  case_file=$repo/cases/elastic_gate/$v.prm
  [ -f "$case_file" ] || { echo "no variant $v ($case_file)" >&2; exit 2; }
  sed -e "s|^\(  set particle spacing *=\).*|\1 $dp|" \
      -e "s|^\(    set modes *=\).*|\1 ${MODES:--1}|" "$case_file" > "$v.prm"
  "$chipflex" run "$v.prm" --out "$v" $threads > "$v.log" 2>&1 || { tail -3 "$v.log" >&2; exit 1; }
  grep '^summary:' "$v.log" | sed "s|^summary:|summary: variant=$v|"
done
"$chipflex" plot $variants --out elastic_gate.png
echo "plot: $out/elastic_gate.png"
