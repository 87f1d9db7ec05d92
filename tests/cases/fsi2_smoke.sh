#!/bin/sh
# Turek & Hron's FSI2 (cases/turek_hron, docs/turek_hron.md) coarse and short: the bar
# meshed and reduced to a nonlinear body by run_fsi.sh, the case at D/10 (buffers, tank
# and particle spacing edited to match) for 1 s. The benchmark's own figures need the
# whole run at D/20 (the long test case_fsi2); this one checks what must hold at any
# resolution and time:
#   - the bar's body file: its first frequency within 1 % of beam theory (0.3386 Hz for
#     the 0.351 m plane-strain bar: 1.875^2 / (2 pi) sqrt(E I / ((1 - nu^2) rho A L^4)));
#   - the run goes through with the bar as a thin skin: nothing lost, the channel whole
#     (`torn=no`), no two fluid particles closer than dp/10, neither among the shifted
#     ones (`closest_fluid_pair_dp`) nor beside the bar (`closest_skin_side_pair_dp`);
#   - the bar is loaded and bends, but stays within 2 cm (its first swings; the full
#     oscillation, 8 cm, takes 10 s to grow);
#   - plot_fsi.py reads the run.
#   usage: fsi2_smoke.sh CHIPFLEX
chipflex=$1
here=$(cd "$(dirname "$0")" && pwd)
case_dir=$here/../../cases/turek_hron
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cd "$dir" || fail "no folder"
# The bar as run_fsi.sh makes it (0 s: mesh and reduce only).
"$chipflex" mesh gate -o bar.msh --length 0.351 --thickness 0.02 --size 0.005 > /dev/null || fail "mesh"
"$chipflex" reduce bar.msh -o bar.h5 --clamp clamp --modes 6 --static-modes pressure:xmin \
  --nonlinear --E 1.4e6 --nu 0.4 --rho 10000 > reduce.log 2>&1 || fail "reduce: $(tail -2 reduce.log)"
f1=$(sed -n 's/^ *mode  1 *\([0-9.e+-]*\) Hz.*/\1/p' reduce.log)
awk -v f="$f1" 'BEGIN { e = f / 0.3386 - 1; printf "bar: first frequency %.4f Hz (beam theory 0.3386 Hz, %+.2f %%)\n", f, 100 * e
  exit !(e > -0.01 && e < 0.01) }' || fail "the bar's first frequency is off"
sed -e 's/^\(  set particle spacing *=\).*/\1 0.01/' -e 's/-0.02, 0/-0.04, 0/' -e 's/2.22, 0.41/2.24, 0.41/' \
  "$case_dir/fsi2.prm" > fsi2_d10.prm
"$chipflex" run fsi2_d10.prm --out out --end-time 1 --threads 1 > run.log 2>&1 ||
  fail "the run stopped: $(tail -3 run.log)"
grep "body 'bar'" run.log
grep -q "body 'bar': flexible.*thin-skin wall" run.log || fail "the bar is not a thin skin"
status=$(grep '^status=' out/summary.txt)
echo "$status"
echo "$status" | grep -q ' lost_particles=0 ' || fail "fluid lost"
grep -q '^continuity:.*torn=no' out/summary.txt || fail "the channel tore"
# Both records: the shifted fluid, and the fluid beside the bar's thin skin (not shifted).
for key in closest_fluid_pair_dp closest_skin_side_pair_dp; do
  echo "$status" | awk -v key="$key" '{ for (i = 1; i <= NF; ++i) if (index($i, key "=") == 1) { split($i, a, "="); c = a[2]; seen = 1 } }
    END { exit !(seen && c >= 0.1) }' || fail "fluid particles clumped (closer than dp/10: $key)"
done
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { y = $col["bar_dy_m"]; if (y < 0) y = -y; if (y > m) m = y }
  END { printf "bar tip: largest |u_y| %.2f mm over 1 s\n", 1000 * m
        exit !(m > 0.5e-3 && m < 0.02) }' out/probes.csv || fail "the bar's tip left 0.5 ... 20 mm"
python3 "$case_dir/plot_fsi.py" out 0 > figures.txt 2>&1 || fail "plot_fsi.py: $(cat figures.txt)"
grep '^figures: ' figures.txt || fail "plot_fsi.py printed no figures"
echo "ok: FSI2 coarse runs through, the channel whole, the bar bends"
