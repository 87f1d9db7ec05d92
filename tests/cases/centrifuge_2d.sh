#!/bin/sh
# The 2D centrifuge (cases/centrifuge_2d.prm) to its end, 1 s: water at rest in a closed
# tank turning at 20 rad/s, a block twice and one half as dense as the water released
# 50 mm from the axis. Checks that `subsection rotating frame` reaches the fluid and the
# bodies of a `chipflex run`:
#   - the fluid: p(80 mm) - p(axis) over the second half within 20 % of rho Omega^2 r^2 / 2
#     = 1280 Pa (measured 1163 Pa, -9 %: the blocks stir the water; the undisturbed forced
#     vortex is within 1 %, tests/sph/test_rotating_frame.cc). Without the fluid's
#     centrifugal acceleration it would be 0.
#   - the bodies: the heavy block ends more than 90 mm from the axis (measured 119 mm, in a
#     corner of the tank) and the light one less than 30 mm (measured 9 mm). Without the
#     bodies' centrifugal force the fluid's pressure gradient would push both inwards.
#   - nothing is lost.
#   usage: centrifuge_2d.sh CHIPFLEX
chipflex=$1
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$chipflex" run "$here/../../cases/centrifuge_2d.prm" --out "$dir/out" --threads 2 > "$dir/log" 2>&1 ||
  fail "the run stopped: $(tail -3 "$dir/log")"
tail -1 "$dir/log"
grep -q 'lost_particles=0 ' "$dir/log" || fail "fluid particles were lost"
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { if ($1 >= 0.5) { n++; dp += $col["p_r80_Pa"] - $col["p_axis_Pa"] }
    rh = sqrt($col["heavy_x_m"]^2 + $col["heavy_y_m"]^2); rl = sqrt($col["light_x_m"]^2 + $col["light_y_m"]^2) }
  END { if (n == 0) { print "FAIL: no probe rows in the second half"; exit 1 }
        printf "p(80 mm) - p(axis) %.0f Pa (rho Omega^2 r^2 / 2 = 1280 Pa, %+.1f %%); heavy block at r = %.1f mm, light at %.1f mm\n", dp / n, 100 * (dp / n / 1280 - 1), 1e3 * rh, 1e3 * rl
        if (dp / n < 1024 || dp / n > 1536) { print "FAIL: the pressure rise left 1280 Pa +- 20 %"; exit 1 }
        if (rh < 0.09) { print "FAIL: the heavy block did not move outwards"; exit 1 }
        if (rl > 0.03) { print "FAIL: the light block did not move inwards"; exit 1 } }
' "$dir/out/probes.csv" || exit 1
