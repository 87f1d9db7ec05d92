#!/bin/sh
# A short run (0.5 ms) of both 3D drill-flute variants through cases/drill_flute/run_flute.sh:
# the geometry script, `chipflex mesh chip` + `reduce`, the two runs and plot_flute.py.
# Checks that every output exists (particles, skins, per-chip CSVs, drill.csv, the PNG),
# that the probes carry the chips' strain energy and the walls' contact torques, that the
# rigid chips report no deflection and no strain energy while the flexible ones do (they
# are loaded by the starting flow), and that no fluid is lost.
#   usage: drill_flute_3d_smoke.sh CHIPFLEX
chipflex=$1
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
CHIPFLEX=$chipflex THREADS=2 sh "$here/../../cases/drill_flute/run_flute.sh" "$dir" 0.0005 > "$dir/log" 2>&1 ||
  fail "run_flute.sh failed: $(tail -5 "$dir/log")"
cat "$dir/log" | grep '^figures:'
for f in rigid/particles.xdmf rigid/skins.xdmf flexible/skins.xdmf rigid/chip1.csv flexible/chip2.csv \
         flexible/drill.csv drill_flute.png flute_walls.stl borehole.stl barrier.stl flute_region.stl chip.h5; do
  [ -s "$dir/$f" ] || fail "no $f"
done
head -1 "$dir/flexible/probes.csv" | grep -q 'contact_borehole_torque_Nm' || fail "no borehole contact torque column"
head -1 "$dir/flexible/probes.csv" | grep -q 'contact_surface_2_force_z_N' || fail "no barrier contact force column"
grep -q 'lost_particles=0' "$dir/flexible.log" || fail "fluid lost: $(grep lost_particles "$dir/flexible.log" | tail -1)"
awk -F, 'NR > 1 { if ($8 != 0 || $9 != 0) bad = 1 } END { exit bad }' "$dir/rigid/chip1.csv" ||
  fail "a rigid chip reports a deflection or strain energy"
awk -F, 'NR > 1 && $8 > 0 && $9 > 0 { ok = 1 } END { exit !ok }' "$dir/flexible/chip1.csv" ||
  fail "the flexible chip never deflects"
echo "ok: both variants ran with every output"
