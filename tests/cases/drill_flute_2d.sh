#!/bin/sh
# The 2D drill-flute case (cases/drill_flute/flute_2d.prm) to its end, 0.03 s: the coolant carries
# three rigid steel strips from the tip to the permeable barrier at x = 20 mm. Checks:
#   - no chip passes the barrier: every chip's centre stays at least its half thickness
#     (0.25 mm, less 0.1 mm for the contact overlap: the penalty contact gives way under
#     the pressure behind the strips, 0.06 mm measured in a pressure surge of 38 kPa)
#     before x = 20 mm, at every probe row;
#   - the chips reach it and rest on it: every chip within 1.5 mm of it at the end, and the
#     contact force on the barrier (along the flow) positive over the last third;
#   - the pressure falls along the flow: p(tip) - p(top) > 0 over the last third;
#   - mass is conserved through the channel: the outlet's mean mass flow over the last
#     third within 7 % of the inlet's. Until about 16 ms the channel behind the barrier
#     empties and refills as the chips arrive (the outflow swings between 0.76 and 1.6
#     times the inflow in 4 ms windows); from then on every 4 ms window is within 4 %. The
#     test used to stop at 0.02 s, where that swing was still in its last third and the
#     balance depended on the CPU (+20 % on one machine).
# The key figures hold bands (docs/drill_flute.md): the barrier's contact force over the
# last third 40 ... 500 N/m and the pressure drop 5 ... 70 kPa. With particle shifting
# (on for internal flows) and the channel held whole by its background pressure (50 kPa):
# 125.4 N/m and 13.3 kPa, and 110.5 N/m and 15.2 kPa on an earlier build of the
# same method (AMD EPYC, native, 2026-12-05); the drop's 2 ms means over the
# last third run from 8 to 38 kPa as the strips settle, shift and clatter, so its mean
# moves with the trajectory. Without shifting 109 N/m and 30.7 kPa (2 ms means 6.6 to
# 47 kPa), and 253 N/m and 37.5 kPa in a run with slightly different open-boundary walls.
# The channel must stay whole (summary.txt `torn=no`). Before the background pressure,
# with the channel behind the strips partly empty: 61.6 N/m and 12.1 kPa with the strips as thin
# skins (AMD EPYC, native, 2026-12-04); with the former
# Lennard-Jones strips 68.6 N/m and 13.6 kPa (Intel Xeon, native), 73.8 N/m and 13.9 kPa
# (AMD EPYC, native), 41.9 N/m and 10.6 kPa (AMD EPYC, portable). The force is a train of chip impacts on the barrier, so its
# mean over 10 ms moves with the trajectory; a lost contact (0) or a reversed one fails.
# The jam watch (apps/jam_watch.h) must see the jam: the tip's 4 ms mean reaches 4 times
# the dynamic pressure (measured at 13.6 ms, AMD EPYC, native, 2026-12-05; the chips reach
# the barrier from about 9 ms); held to 8 ... 28 ms. The fluid's mass balances exactly
# (inflow = outflow + stored change, residual 0 particles).
# A barrier the chips slipped through, a contact reaction with the wrong sign or lost, a
# pressure probe on the wrong side or an outlet that drains the channel fails it.
# With MPIEXEC and N it runs on N MPI ranks (the thin skins' guard and sides, the open
# boundaries and the chips over the ranks; docs/parallel.md) and must pass the same
# checks: the chips' paths part from one process's by rounding within 2 ms and are
# chaotic from 4 ms on, so only the bands can be compared.
#   usage: drill_flute_2d.sh CHIPFLEX [MPIEXEC N]
chipflex=$1
launcher=""
[ -z "$2" ] || launcher="$2 -np $3 --oversubscribe"
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cp "$here/../../cases/drill_flute/flute_2d.prm" "$dir/flute_2d.prm"
$launcher "$chipflex" run "$dir/flute_2d.prm" --out "$dir/out" --threads 1 > "$dir/log" 2>&1 ||
  fail "the run stopped: $(tail -3 "$dir/log")"
tail -1 "$dir/log"
awk -F, -v barrier=0.02 -v half=0.00025 -v end=0.03 '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { for (c = 1; c <= 3; ++c) { x = $col["chip" c "_x_m"]
      if (x + half - barrier > overlap) overlap = x + half - barrier
      if (x + half - 1e-4 > barrier) { printf "FAIL: chip%d at x = %.5f m at t = %s s, past the barrier\n", c, x, $1; bad = 1 }
      last[c] = x }
    if ($1 >= 2 * end / 3) { n++; force += $col["contact_wall_1_force_x_N"]
      drop += $col["p_tip_Pa"] - $col["p_top_Pa"]; fin += $col["inlet_mass_flow"]; fout += $col["outlet_mass_flow"] } }
  END { if (bad) exit 1
        if (n == 0) { print "FAIL: no probe rows in the last third"; exit 1 }
        for (c = 1; c <= 3; ++c) if (barrier - last[c] > 0.0015) { printf "FAIL: chip%d ends at x = %.5f m, not at the barrier\n", c, last[c]; exit 1 }
        printf "chips at %.3f %.3f %.3f mm (barrier 20 mm, largest overlap %.3f mm); last third: barrier contact force %.2f N/m, pressure drop %.0f Pa, inflow %.3f outflow %.3f kg/(s m) (%+.1f %%)\n",
               1e3 * last[1], 1e3 * last[2], 1e3 * last[3], 1e3 * overlap, force / n, drop / n, fin / n, fout / n, 100 * (fout / fin - 1)
        if (!(force / n > 40 && force / n < 500)) { print "FAIL: the barrier force left its band 40 ... 500 N/m"; exit 1 }
        if (!(drop / n > 5000 && drop / n < 70000)) { print "FAIL: the pressure drop left its band 5 ... 70 kPa"; exit 1 }
        if (fout / fin > 1.07 || fout / fin < 0.93) { print "FAIL: outflow differs from inflow by more than 7 %"; exit 1 } }
' "$dir/out/probes.csv" || exit 1
grep '^continuity:' "$dir/out/summary.txt"
grep -q '^continuity:.*torn=no' "$dir/out/summary.txt" ||
  fail "the channel tore (summary.txt: $(grep '^continuity:' "$dir/out/summary.txt"))"
grep '^jam:' "$dir/out/summary.txt"
awk '/^jam:/ { for (i = 1; i <= NF; ++i) if ($i ~ /^time_to_jam_s=/) t = substr($i, 15) }
     END { if (t == "" || t < 0.008 || t > 0.028) { print "FAIL: no jam at 8 ... 28 ms"; exit 1 } }' \
  "$dir/out/summary.txt" || exit 1
# The watch's time to jam, recomputed from probes.csv: the 4 ms running mean of p_tip over
# the rows from 6 ms on, first at or above 4 x 1740 Pa once it spans 4 ms (at t >= 10 ms).
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  $1 >= 0.006 { n++; t[n] = $1; p[n] = $col["p_tip_Pa"]
    if (found == "" && $1 >= 0.01 - 1e-12) { s = 0; c = 0
      for (k = n; k >= 1 && t[k] > $1 - 0.004; --k) { s += p[k]; c++ }
      if (s / c >= 4 * 1740) found = $1 } }
  END { print found }' "$dir/out/probes.csv" > "$dir/recomputed"
awk -v r="$(cat "$dir/recomputed")" '/^jam:/ { for (i = 1; i <= NF; ++i) if ($i ~ /^time_to_jam_s=/) t = substr($i, 15) }
     END { if (r == "" || (t - r) > 1e-6 || (r - t) > 1e-6) { printf "FAIL: time to jam %s, from probes.csv %s\n", t, r; exit 1 } }' \
  "$dir/out/summary.txt" || exit 1
grep -q '^mass_balance: .* residual_particles=0$' "$dir/out/summary.txt" ||
  fail "the fluid's mass does not balance: $(grep '^mass_balance:' "$dir/out/summary.txt")"
echo "ok: the chips stop at the barrier and jam the channel, which stays whole"
