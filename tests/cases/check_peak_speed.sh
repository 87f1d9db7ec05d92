#!/bin/sh
# Checks a finished run's peak fluid speed (summary.txt: the largest speed of any fluid
# particle at any step) against Mach 0.3, the limit of weakly compressible water (beyond
# it the density varies by more than M^2/2 = 4.5 %; c0 is chosen for Mach 0.1 in the
# flow), and, given the water depth or column height H, against the flow bound
# 2 sqrt(2 g H) (shipped_case_runs_through.sh says why that bound).
#   usage: check_peak_speed.sh OUT_DIR LOG [H_m]
out=$1
log=$2
height=$3
fail() { echo "FAIL: $*"; exit 1; }
peak=$(head -1 "$out/summary.txt" | sed -n 's/.*peak_fluid_speed_m_s=\([0-9.e+-]*\).*/\1/p')
[ -n "$peak" ] || fail "$out/summary.txt lacks peak_fluid_speed_m_s"
c0=$(grep -o 'c0 = [0-9.e+-]* m/s' "$log" | head -1 | cut -d' ' -f3)
[ -n "$c0" ] || fail "$log does not give c0"
if [ -n "$height" ]; then
  bound=$(awk "BEGIN { print 2 * sqrt(2 * 9.81 * $height) }")
  awk "BEGIN { exit !($peak < $bound) }" ||
    fail "a fluid particle reached $peak m/s, above 2 sqrt(2 g H) = $bound m/s"
  echo "peak fluid speed $peak m/s below 2 sqrt(2 g H) = $bound m/s"
fi
mach_bound=$(awk "BEGIN { print 0.3 * $c0 }")
awk "BEGIN { exit !($peak < $mach_bound) }" ||
  fail "a fluid particle reached $peak m/s, above Mach 0.3 = $mach_bound m/s"
echo "peak fluid speed $peak m/s over the run below Mach 0.3 = $mach_bound m/s (c0 $c0 m/s)"
