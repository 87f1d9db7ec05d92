#!/bin/sh
# A free 3D rigid box floats at Archimedes' draft (hydrostatics: buoyancy = weight of the
# displaced water, so a box of density rho_b and height H_b floats upright with draft
# d = (rho_b / rho_w) H_b). The case (cases/floating_box_3d.prm):
# a 0.06 x 0.06 x 0.03 m box of 500 kg/m^3, d = 15 mm, dummy-particle skin, in a 3D basin
# 45 mm deep, started at its draft with the water around it. Checked through the whole
# `chipflex run` path (case file, body registry, 3D coupling): the mean draft over
# 0.2 ... 0.4 s (water level, unchanged, minus the box bottom) within 2 % of 15 mm, and the
# box upright and centred, and the fluid below 2 sqrt(2 g H) at every step. A wall that
# let particles through, a lost or doubled force or a wrong mass would move the draft by
# more than that. The run stops at 0.4 s of the case's
# 0.6 s (-0.14 % there, 2026-12-03), to keep the test under 1.5 minutes on 2 cores.
#   usage: floating_box_3d.sh CHIPFLEX
chipflex=$1
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$chipflex" run "$here/../../cases/floating_box_3d.prm" --out "$dir/out" --end-time 0.4 \
  > "$dir/log" 2>&1 ||
  fail "the run stopped: $(tail -3 "$dir/log")"
head -1 "$dir/out/summary.txt"
awk -F, -v level=0.045 -v half=0.015 -v expected=0.015 '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  $1 >= 0.2 { n++; draft += level - ($col["box_z_m"] - half)
              tilt = sqrt($col["box_rx_rad"]^2 + $col["box_ry_rad"]^2)
              if (tilt > worst) worst = tilt
              off = sqrt(($col["box_x_m"] - 0.06)^2 + ($col["box_y_m"] - 0.06)^2)
              if (off > drift) drift = off }
  END { if (n == 0) { print "FAIL: no probe rows after 0.2 s"; exit 1 }
        d = draft / n
        printf "mean draft %.3f mm over %d rows (Archimedes %.1f mm, %+.2f %%); largest tilt %.4f rad, drift %.2f mm\n",
               1e3 * d, n, 1e3 * expected, 100 * (d / expected - 1), worst, 1e3 * drift
        if (d < 0.98 * expected || d > 1.02 * expected) { print "FAIL: draft off by more than 2 %"; exit 1 }
        if (worst > 0.05) { print "FAIL: the box tipped"; exit 1 }
        if (drift > 0.003) { print "FAIL: the box drifted off the basin centre"; exit 1 } }' \
  "$dir/out/probes.csv" || exit 1
# The water around the box is nearly at rest: its speed stays below the flow bound for the
# basin's depth, 45 mm, at every step.
"$here/../cases/check_peak_speed.sh" "$dir/out" "$dir/log" 0.045 || exit 1
echo "ok"
