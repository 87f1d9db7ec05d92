#!/bin/sh
# Checks a finished run's fluid speed against Mach 0.3 over the whole run, the limit of
# weakly compressible water (beyond it the density varies by more than M^2/2 = 4.5 %; c0
# is chosen for Mach 0.1 in the flow), and, given the water depth or column height H,
# against the flow bound 2 sqrt(2 g H) (shipped_case_runs_through.sh says why that bound):
# over the whole run (summary.txt's peak_fluid_speed_m_s, the largest speed of any fluid
# particle at any step), or up to UNTIL_s where a front meets a wall then (probes.csv's
# running peak_fluid_speed_m_s at the last row up to that time).
#   usage: check_peak_speed.sh OUT_DIR LOG [H_m [UNTIL_s]]
out=$1
log=$2
height=$3
until=$4
fail() { echo "FAIL: $*"; exit 1; }
peak=$(head -1 "$out/summary.txt" | sed -n 's/.*peak_fluid_speed_m_s=\([0-9.e+-]*\).*/\1/p')
[ -n "$peak" ] || fail "$out/summary.txt lacks peak_fluid_speed_m_s"
c0=$(grep -o 'c0 = [0-9.e+-]* m/s' "$log" | head -1 | cut -d' ' -f3)
[ -n "$c0" ] || fail "$log does not give c0"
if [ -n "$height" ]; then
  bound=$(awk "BEGIN { print 2 * sqrt(2 * 9.81 * $height) }")
  if [ -z "$until" ]; then
    awk "BEGIN { exit !($peak < $bound) }" ||
      fail "a fluid particle reached $peak m/s, above 2 sqrt(2 g H) = $bound m/s"
    echo "peak fluid speed $peak m/s below 2 sqrt(2 g H) = $bound m/s"
  else
    before=$(awk -F, -v until="$until" '
      NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "peak_fluid_speed_m_s") c = i; next }
      c && $1 <= until + 0 { p = $c } END { print p }' "$out/probes.csv")
    [ -n "$before" ] || fail "probes.csv has no peak_fluid_speed_m_s up to t = $until s"
    awk "BEGIN { exit !($before < $bound) }" ||
      fail "a fluid particle reached $before m/s by t = $until s, above 2 sqrt(2 g H) = $bound m/s"
    echo "peak fluid speed $before m/s up to the impact (t = $until s) below 2 sqrt(2 g H) = $bound m/s"
  fi
fi
mach_bound=$(awk "BEGIN { print 0.3 * $c0 }")
awk "BEGIN { exit !($peak < $mach_bound) }" ||
  fail "a fluid particle reached $peak m/s, above Mach 0.3 = $mach_bound m/s"
echo "peak fluid speed $peak m/s over the run below Mach 0.3 = $mach_bound m/s (c0 $c0 m/s)"
