#!/bin/sh
# The 3D drill flute without chips (cases/drill_flute/flute_3d_chip_free.prm, docs/drill_flute.md
# "The flute without chips"), 30 ms: the coolant stays whole in the turning frame beside
# the borehole wall that slides in place (`continuity: ... torn=no`, at most 3 particles
# lost, the mass balance's residual 0), it does not jam (`jammed=no`), and over the steady
# 20 ... 30 ms the outflow matches the feed within 3 % and the pressure falls along the
# flow. The pressure drop between the probes at z = 3 and 27 mm is printed against Shah's
# estimate for developing laminar duct flow (902 Pa); at dp 0.75 mm the boundary layer is
# 2 ... 3 spacings thick and the drop is about half of it (documented, not held). With
# DP = 0.0005 (the open boundaries' layers follow, 6) the check holds the drop to 15 % of
# the estimate as well (820 Pa measured; about 19 minutes on one core, label `long`).
#   usage: drill_flute_3d_chip_free.sh CHIPFLEX [DP]
chipflex=$1
dp=$2
here=$(cd "$(dirname "$0")" && pwd)
cases=$here/../../cases/drill_flute
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
python3 "$cases/make_flute_geometry.py" --diameter 0.02 --flute-angle 120 --length 0.03 \
  --barrier 0.02 --out "$dir" > "$dir/geometry.log" || fail "make_flute_geometry.py failed"
if [ -n "$dp" ]; then
  layers=$(awk "BEGIN { printf \"%d\", 0.003 / $dp + 0.5 }")
  sed -e "s|^\(  set particle spacing *=\).*|\1 $dp|" -e "s|^\(    set layers *=\).*|\1 $layers|" \
    "$cases/flute_3d_chip_free.prm" > "$dir/flute_3d_chip_free.prm"
else
  cp "$cases/flute_3d_chip_free.prm" "$dir/"
fi
(cd "$dir" && "$chipflex" run flute_3d_chip_free.prm --out out --threads 2 > run.log 2>&1) ||
  fail "the run failed: $(tail -3 "$dir/run.log")"
s=$dir/out/summary.txt
grep -E '^(continuity|mass_balance|jam|status)' "$s"
grep -q '^continuity:.* torn=no' "$s" || fail "the flute tore"
lost=$(sed -n 's/^status=.* lost_particles=\([0-9]*\) .*/\1/p' "$s")
[ -n "$lost" ] && [ "$lost" -le 3 ] || fail "lost particles: '$lost' (at most 3)"
grep -q '^mass_balance:.* residual_particles=0$' "$s" || fail "the mass balance does not close"
grep -q '^jam:.* jammed=no' "$s" || fail "the chip-free flute jammed"
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  $c["time_s"] >= 0.02 { n++; tip += $c["p_tip_Pa"]; top += $c["p_top_Pa"];
                         before += $c["p_before_barrier_Pa"]; q += $c["q_barrier_m3_s"] }
  END { tip /= n; top /= n; before /= n; q /= n;
        printf "20 ... 30 ms: p(tip) %.0f Pa, p(before barrier) %.0f Pa, p(top) %.0f Pa, drop %.0f Pa (%.2f x Shah 902 Pa), q_barrier %.4g m^3/s (%.3f x the feed)\n",
               tip, before, top, tip - top, (tip - top) / 902, q, q / 2.0833e-4
        if (!(tip > before && before > top)) { print "FAIL: the pressure does not fall along the flow"; exit 1 }
        if (q / 2.0833e-4 < 0.97 || q / 2.0833e-4 > 1.03) { print "FAIL: the flow through the barrier is not the feed within 3 %"; exit 1 }
        if (fine && ((tip - top) / 902 < 0.85 || (tip - top) / 902 > 1.15)) { print "FAIL: the drop is not within 15 % of the estimate"; exit 1 } }' \
  fine=$([ -n "$dp" ] && echo 1 || echo 0) "$dir/out/probes.csv" || exit 1
echo "PASS"
