#!/bin/sh
# Turek & Hron's FSI2 at the shipped resolution (D/20) over the shipped 15 s, through
# cases/turek_hron/run_fsi.sh, and its figures against the benchmark with plot_fsi.py's
# tolerances (--check: the tip's u_y amplitude within 10 % of 0.0806 m, its frequency
# within 5 % of 2.0 Hz, u_x's mean and amplitude within 20 % of -0.01458 and 0.01244 m),
# over the last 3 s; the channel whole the whole run (`torn=no`) and nothing lost.
# Label `long`: about an hour on 2 cores (docs/turek_hron.md).
#   usage: fsi2_long.sh CHIPFLEX
chipflex=$1
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
CHIPFLEX=$chipflex "$here/../../cases/turek_hron/run_fsi.sh" "$dir" > "$dir/log" 2>&1 ||
  fail "run_fsi.sh: $(tail -3 "$dir/log")"
grep '^status=' "$dir/fsi2/summary.txt"
grep -q ' lost_particles=0 ' "$dir/fsi2/summary.txt" || fail "fluid lost"
grep -q '^continuity:.*torn=no' "$dir/fsi2/summary.txt" || fail "the channel tore"
python3 "$here/../../cases/turek_hron/plot_fsi.py" "$dir/fsi2" 12 --check ||
  fail "FSI2's figures missed the benchmark"
echo "ok: FSI2 meets the benchmark"
