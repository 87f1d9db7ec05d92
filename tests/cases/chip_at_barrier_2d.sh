#!/bin/sh
# One chip held at the barrier in steady flow (cases/drill_flute/flute_2d_chip_at_barrier.prm,
# 30 ms): the strip's load on the barrier (its contact force along the flow) against the
# pressure difference across it times its projected length, (p_front - p_behind) L with
# L = 5 mm, averaged over 10 ... 30 ms: within 10 %. Measured 8.59 N/m against 8.65 N/m
# (-0.7 %; 5 ms windows within -15 ... +8 %), AMD EPYC, native, 2026-12-05. A strip the
# fluid passes through, or a load read from the wrong side, fails.
#   usage: chip_at_barrier_2d.sh CHIPFLEX
chipflex=$1
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$chipflex" run "$here/../../cases/drill_flute/flute_2d_chip_at_barrier.prm" --out "$dir/out" \
  --threads 1 > "$dir/log" 2>&1 || fail "the run stopped: $(tail -3 "$dir/log")"
tail -1 "$dir/log"
awk -F, -v L=0.005 '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  $1 >= 0.01 { n++; f += $col["contact_wall_1_force_x_N"]; dp += $col["p_front_Pa"] - $col["p_behind_Pa"]
               if ($col["chip1_x_m"] > 0.02) { print "FAIL: the strip passed the barrier"; exit 1 } }
  END { if (n == 0) { print "FAIL: no probe rows after 10 ms"; exit 1 }
        printf "barrier load %.3f N/m, (p_front - p_behind) L = %.3f N/m (%+.1f %%)\n", f / n, dp / n * L, 100 * (f / (dp * L) - 1)
        if (!(dp / n > 0) || (f / (dp * L) - 1) ^ 2 > 0.01) { print "FAIL: not within 10 %"; exit 1 } }
' "$dir/out/probes.csv" || exit 1
