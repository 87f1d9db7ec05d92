#!/bin/sh
# Turek & Hron's FSI2 at the shipped resolution (D/20) over the shipped 15 s, through
# cases/turek_hron/run_fsi.sh, over its last 3 s (the flapping saturates by about 7 s):
#   - the flapping frequency within 4 % of chipflex's documented 1.961 Hz, and the tip's u_y
#     amplitude within 15 % of its documented 0.0559 m. These hold the figures
#     docs/turek_hron.md reports, NOT the benchmark's: its 2.0 Hz lies 2 % above (within the
#     issue's 5 %), its 0.0806 m 44 % above (D/20 misses it by 31 %: the wake drives the
#     bar too weakly);
#   - the channel whole the whole run (`torn=no`), and at most 5 of the about 230,000
#     particles that pass lost (measured: none).
# Label `long`: about 75 minutes on 2 cores.
#   usage: fsi2_long.sh CHIPFLEX
chipflex=$1
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
CHIPFLEX=$chipflex "$here/../../cases/turek_hron/run_fsi.sh" "$dir" > "$dir/log" 2>&1 ||
  fail "run_fsi.sh: $(tail -3 "$dir/log")"
grep '^status=' "$dir/fsi2/summary.txt"
lost=$(sed -n 's/^status=.* lost_particles=\([0-9]*\) .*/\1/p' "$dir/fsi2/summary.txt")
[ "${lost:-99}" -le 5 ] || fail "$lost fluid particles lost"
grep -q '^continuity:.*torn=no' "$dir/fsi2/summary.txt" || fail "the channel tore"
python3 "$here/../../cases/turek_hron/plot_fsi.py" "$dir/fsi2" 12 > "$dir/figures" 2>&1 ||
  fail "plot_fsi.py: $(cat "$dir/figures")"
cat "$dir/figures"
grep '^figures: ' "$dir/figures" | tr ' ' '\n' | awk -F= '
  $1 == "frequency_hz" { f = $2 } $1 == "uy_amplitude" { a = $2 }
  END { if (!(f > 1.883 && f < 2.039)) { print "FAIL: the frequency " f " Hz left 1.961 Hz +- 4 %"; exit 1 }
        if (!(a > 0.0475 && a < 0.0643)) { print "FAIL: the u_y amplitude " a " m left 0.0559 m +- 15 %"; exit 1 } }' ||
  exit 1
echo "ok: FSI2 flaps with its documented frequency and amplitude"
