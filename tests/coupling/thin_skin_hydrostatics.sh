#!/bin/sh
# Thin skins hold water (2D, dp 2 mm, h = 2.83 mm; docs/sph.md "Thin skins"). A fixed
# plate (a `moving wall` at rest, `wall model` automatic) stands across a tank at
# x = 0.1 m:
#   zero   - zero thickness (an open polyline), 0.10 m of water on its left, air on its right;
#   quarter - a closed outline dp/4 = 0.5 mm thick, the same water;
#   levels  - zero thickness, 0.10 m of water on the left and 0.04 m on the right;
#   fixed   - the levels case with the plate as a fixed polyline wall (walls' `wall
#             model = thin skin`): the levels stay apart.
# Checked over 0.15 ... 0.4 s: the plate's horizontal load against hydrostatics,
# rho g H^2 / 2 = 49.05 N/m (levels: rho g (H1^2 - H2^2) / 2 = 41.20 N/m), within 3 %;
# the left level falls by less than dp; the right side stays dry (zero, quarter) or
# keeps its level within dp (levels); no particle had to be put back by the guard
# (guarded_particles=0), and no fluid particle ends on the wrong side. Before thin
# skins the two-level case threw 35 particles out of the tank at 13 m/s.
# Last, a restart: the 2D drill flute (moving thin-skin chips, the guard at work) run to
# 6 ms, restarted from its checkpoint to 12 ms, ends bitwise as the run straight to 12 ms
# (the particles' sides and the guard's count are in the checkpoint).
#   usage: thin_skin_hydrostatics.sh CHIPFLEX [REPO]
set -e
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

run_case() { # name, outline, fluid blocks, expected load
  name=$1
  cat > "$dir/$name.prm" <<EOF
set dimension = 2
subsection fluid
  set particle spacing     = 0.002
  set gravity              = 0, -9.81
  set speed of sound       = 20
  set artificial viscosity = 0.02
  set density diffusion    = fourtakas
end
subsection time
  set end time = 0.4
end
subsection output
  set frame interval = 0.4
  set probe interval = 0.005
end
subsection geometry
  set fluid blocks = $3
  subsection tank
    set min corner = 0, 0
    set max corner = 0.2, 0.16
    set wall model = dummy particles
  end
end
subsection probes
  set water height = left: 0.05, 0; right: 0.15, 0
end
subsection bodies
  set count = 1
  subsection body 1
    set name    = plate
    set kind    = moving wall
    set outline = $2
  end
end
EOF
  "$chipflex" run "$dir/$name.prm" --out "$dir/$name" > "$dir/$name.log" 2>&1 ||
    { cat "$dir/$name.log"; fail "$name: run failed"; }
  grep -q "thin-skin wall (automatic" "$dir/$name.log" || fail "$name: the plate is not a thin skin"
  grep -q "guarded_particles=0" "$dir/$name/summary.txt" ||
    fail "$name: the guard had to put particles back ($(grep -o 'guarded_particles=[0-9]*' "$dir/$name/summary.txt"))"
  # Mean load and levels over 0.15 ... 0.4 s; the levels at the end.
  awk -F, -v name="$name" -v load="$4" '
    NR == 1 { for (k = 1; k <= NF; ++k) col[$k] = k; next }
    NR == 2 { left0 = $col["h_left_m"]; right0 = $col["h_right_m"] }
    $1 >= 0.15 { f = $col["plate_force_x_N"]; sum += (f < 0 ? -f : f); ++n }
    { left = $col["h_left_m"]; right = $col["h_right_m"] }
    END {
      mean = sum / n; e = (mean - load) / load
      printf "%s: load %.2f N/m against %.2f (%+.2f %%), left level %.4f -> %.4f m, right %.4f -> %.4f m\n",
             name, mean, load, 100 * e, left0, left, right0, right
      if (e > 0.03 || e < -0.03) { print "FAIL: " name ": load off by more than 3 %"; exit 1 }
      if (left0 - left > 0.002) { print "FAIL: " name ": the left level fell by more than dp"; exit 1 }
      if (right - right0 > 0.002 || right0 - right > 0.002) {
        print "FAIL: " name ": the right level moved by more than dp"; exit 1 }
    }' "$dir/$name/probes.csv" || exit 1
}

run_case zero "0.1, -0.01, 0.1, 0.15" "0, 0, 0.1, 0.1" 49.05
run_case quarter "0.1, -0.01, 0.1005, -0.01, 0.1005, 0.15, 0.1, 0.15, 0.1, -0.01" \
  "0, 0, 0.1, 0.1" 49.05
run_case levels "0.1, -0.01, 0.1, 0.15" "0, 0, 0.1, 0.1; 0.1, 0, 0.2, 0.04" 41.20
# A fixed wall: the zero-thickness plate as a polyline of the case's walls with `wall
# model = thin skin`, the two levels (a fixed wall's load goes to walls.xdmf, not to the
# probes: the levels and the guard are checked).
sed -e 's|^  subsection tank|  subsection walls\n    set polylines  = 0.1, -0.01, 0.1, 0.15\n    set wall model = thin skin\n  end\n  subsection tank|' \
    -e '/^subsection bodies/,$d' "$dir/levels.prm" > "$dir/fixed.prm"
"$chipflex" run "$dir/fixed.prm" --out "$dir/fixed" > "$dir/fixed.log" 2>&1 ||
  { cat "$dir/fixed.log"; fail "fixed: run failed"; }
grep -q "guarded_particles=0" "$dir/fixed/summary.txt" || fail "fixed: the guard put particles back"
awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) col[$k] = k; next }
  NR == 2 { l0 = $col["h_left_m"]; r0 = $col["h_right_m"] }
  { l = $col["h_left_m"]; r = $col["h_right_m"] }
  END { printf "fixed: left level %.4f -> %.4f m, right %.4f -> %.4f m\n", l0, l, r0, r
        d1 = l - l0; d2 = r - r0
        exit !(d1 < 0.002 && d1 > -0.002 && d2 < 0.002 && d2 > -0.002) }' "$dir/fixed/probes.csv" ||
  fail "fixed: the levels did not stay apart"

repo=${2:-$(cd "$(dirname "$0")/../.." && pwd)}
flute=$repo/cases/drill_flute/flute_2d.prm
"$chipflex" run "$flute" --out "$dir/first" --end-time 0.006 --checkpoint-every 0.006 > "$dir/first.log" 2>&1 ||
  fail "flute to 6 ms: $(tail -2 "$dir/first.log")"
"$chipflex" run "$flute" --out "$dir/first" --end-time 0.012 --restart "$dir/first/checkpoint.h5" \
  > "$dir/restart.log" 2>&1 || fail "flute restart: $(tail -2 "$dir/restart.log")"
"$chipflex" run "$flute" --out "$dir/straight" --end-time 0.012 > "$dir/straight.log" 2>&1 ||
  fail "flute to 12 ms: $(tail -2 "$dir/straight.log")"
grep -q "thin-skin wall" "$dir/straight.log" || fail "the flute's chips are not thin skins"
cmp -s "$dir/first/probes.csv" "$dir/straight/probes.csv" ||
  fail "the restarted flute differs from the straight run"
grep -o "guarded_particles=[0-9]*" "$dir/first/summary.txt" > "$dir/g1"
grep -o "guarded_particles=[0-9]*" "$dir/straight/summary.txt" > "$dir/g2"
cmp -s "$dir/g1" "$dir/g2" || fail "guard counts differ: $(cat "$dir/g1") / $(cat "$dir/g2")"
echo "ok: the restarted flute ends bitwise as the straight run ($(cat "$dir/g2"))"
echo "ok: thin skins hold water"
