#!/bin/sh
# The tension watch: a run under a background pressure that does not cover its flow's
# suction says so. A 2D channel 1.0 x 0.2 m past a square block of 0.04 m (Re 40, mean
# inflow 0.5 m/s, c0 10 m/s, dp 10 mm, summation density, no-slip walls, shifting), to
# 0.6 s, at two background pressures:
#   - 1 kPa: the suction above the block and the pressure waves of the inflow's start
#     take the absolute pressure below 0; a tenth of the fluid is in tension (11.8 %
#     measured, AMD EPYC, native, 2026-12-07) and particles pair up (0.0004 dp). The run
#     must report tension_peak_percent > 1 in summary.txt and warn in summary.txt and
#     the log, of the tension and of the clumped pair (closer than 0.1 dp; 0.0089 dp on
#     the portable build);
#   - 5 kPa: no lasting tension (0.002 %), the closest pair 0.58 dp: no warning, and a
#     tension_peak_percent below 1.
# A watch that never fires, fires on a sound run or counts gauge instead of absolute
# pressures fails it; so does a clumping warning that never fires or fires at 0.58 dp.
#   usage: tension_warning.sh CHIPFLEX
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
write_case() { # $1: background pressure, Pa
  cat <<END
set dimension = 2
subsection fluid
  set particle spacing    = 0.01
  set gravity             = 0, 0
  set viscosity           = laminar
  set kinematic viscosity = 0.0005
  set speed of sound      = 10
  set hydrostatic start   = false
  set no slip walls       = true
  set density             = summation
  set background pressure = $1
end
subsection time
  set end time = 0.6
end
subsection output
  set frame interval = 0.6
  set probe interval = 0.01
end
subsection geometry
  set fluid blocks     = 0, 0, 1.0, 0.2
  set initial velocity = 0, 0
  subsection tank
    set min corner = -0.04, 0
    set max corner = 1.04, 0.2
    set open top   = false
    set open ends  = x
    set wall model = dummy particles
  end
end
subsection open boundaries
  subsection inlet
    set enabled   = true
    set box min   = -0.04, 0
    set box max   = 0, 0.2
    set direction = +x
    set velocity  = 0.5
    set profile   = parabolic
    set ramp time = 0.3
  end
  subsection outlet
    set enabled   = true
    set box min   = 1.0, 0
    set box max   = 1.04, 0.2
    set direction = +x
    set pressure  = 0
  end
end
subsection bodies
  subsection body 1
    set name       = block
    set kind       = moving wall
    set position   = 0.3, 0.1
    set wall model = dummy particles
    set outline    = -0.02, -0.02, 0.02, -0.02, 0.02, 0.02, -0.02, 0.02, -0.02, -0.02
  end
end
END
}
peak() { sed -n 's/.* tension_peak_percent=\([^ ]*\).*/\1/p' "$1"; }
for p in 1000 5000; do
  write_case $p > "$dir/p$p.prm"
  "$chipflex" run "$dir/p$p.prm" --out "$dir/p$p" --threads 1 > "$dir/p$p.log" 2>&1 ||
    fail "P = $p Pa: the run stopped: $(tail -2 "$dir/p$p.log")"
  echo "P = $p Pa: $(grep -o 'closest_fluid_pair_dp=[^ ]*\|tension_peak_percent=[^ ]*' "$dir/p$p/summary.txt" | tr '\n' ' ')"
done
low=$(peak "$dir/p1000/summary.txt")
high=$(peak "$dir/p5000/summary.txt")
[ -n "$low" ] && [ -n "$high" ] || fail "summary.txt has no tension_peak_percent"
awk -v a="$low" 'BEGIN { exit !(a > 1) }' || fail "1 kPa: tension_peak_percent=$low, expected above 1"
grep -q "^warning: .* % of the fluid was in tension" "$dir/p1000/summary.txt" ||
  fail "1 kPa: no warning in summary.txt"
grep -q "^warning: .* % of the fluid was in tension" "$dir/p1000.log" || fail "1 kPa: no warning in the log"
awk -v a="$high" 'BEGIN { exit !(a < 1) }' || fail "5 kPa: tension_peak_percent=$high, expected below 1"
grep -q "in tension" "$dir/p5000/summary.txt" && fail "5 kPa: a warning on a sound run"
clumped="^warning: two fluid particles came within .* dp of each other"
grep -q "$clumped" "$dir/p1000/summary.txt" || fail "1 kPa: no clumping warning in summary.txt"
grep -q "$clumped" "$dir/p1000.log" || fail "1 kPa: no clumping warning in the log"
grep -q "warning" "$dir/p5000/summary.txt" && fail "5 kPa: a warning on a sound run"
echo "ok: tension at 1 kPa ($low %) warned, none at 5 kPa ($high %)"
