#!/bin/sh
# A short run (0.5 ms) of both 3D drill-flute variants through cases/drill_flute/run_flute.sh:
# the geometry script, `chipflex mesh chip` + `reduce`, the two runs and plot_flute.py.
# Checks that the generated surfaces face the flute (their normals), that every output exists (particles, skins, per-chip CSVs, drill.csv, the PNG),
# that the probes carry the chips' strain energy and the walls' contact torques, that the
# rigid chips report no deflection and no strain energy while the flexible ones do (they
# are loaded by the starting flow), and that no fluid is lost. Then the rigid chip-source
# variant (flute_3d_rigid_chip_source.prm) with a chip due every 0.14 ms from 0.1 ms: the
# first is released at the cutting edge in its pose and starts to move; the next waits,
# since the first is still at the edge (delayed=1), so the three others stay parked inside
# the drill body; nothing is lost and the mass balances.
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
# The surfaces face the right way: flanks and borehole into the flute (towards a point on
# its bisector), the barrier towards the tip (-z), the fluid region outwards.
python3 - "$dir" <<'PY' || fail "a surface faces the wrong way"
import os, sys
def faces(name):
    t, n, cur = [], [], []
    for line in open(os.path.join(sys.argv[1], name)):
        w = line.split()
        if w[:2] == ["facet", "normal"]: n.append([float(v) for v in w[2:5]])
        if w[:1] == ["vertex"]:
            cur.append([float(v) for v in w[1:4]])
            if len(cur) == 3: t.append(cur); cur = []
    return [([sum(p[i] for p in f) / 3 for i in range(3)], m) for f, m in zip(t, n)]
inside = (0.005, 0.0, 0.015)  # on the bisector, mid-depth, mid-length
into = lambda c, m: sum(m[i] * (inside[i] - c[i]) for i in range(2)) > 0
bad = sum(not into(c, m) for c, m in faces("flute_walls.stl") + faces("borehole.stl"))
bad += sum(not m[2] < -0.999 for c, m in faces("barrier.stl"))
bad += sum(not sum(m[i] * (c[i] - inside[i]) for i in range(3)) > 0 for c, m in faces("flute_region.stl"))
print("surfaces facing the wrong way:", bad)
sys.exit(bad > 0)
PY
head -1 "$dir/flexible/probes.csv" | grep -q 'contact_borehole_torque_Nm' || fail "no borehole contact torque column"
head -1 "$dir/flexible/probes.csv" | grep -q 'contact_surface_2_force_z_N' || fail "no barrier contact force column"
grep -q 'lost_particles=0' "$dir/flexible.log" || fail "fluid lost: $(grep lost_particles "$dir/flexible.log" | tail -1)"
awk -F, 'NR > 1 { if ($8 != 0 || $9 != 0) bad = 1 } END { exit bad }' "$dir/rigid/chip1.csv" ||
  fail "a rigid chip reports a deflection or strain energy"
awk -F, 'NR > 1 && $8 > 0 && $9 > 0 { ok = 1 } END { exit !ok }' "$dir/flexible/chip1.csv" ||
  fail "the flexible chip never deflects"
# The jam watch runs in both (0.5 ms is before it looks: no jam yet) and the mass balances.
for v in rigid flexible; do
  grep -q '^jam: p_tip_Pa_reference=2330.8.* jammed=no' "$dir/$v/summary.txt" ||
    fail "$v: no jam watch line, or a jam at 0.5 ms: $(grep '^jam:' "$dir/$v/summary.txt")"
  grep -q '^mass_balance: .* residual_particles=0$' "$dir/$v/summary.txt" || fail "$v: the mass does not balance"
done
# The film, where ffmpeg is installed (CI has none).
if command -v ffmpeg > /dev/null && command -v h5dump > /dev/null; then
  [ -s "$dir/jam_flexible.mp4" ] && [ -s "$dir/jam_flexible_frames/frame_0000.png" ] || fail "no film"
fi
# The chip source in 3D: releases due at 0.1, 0.24 and 0.38 ms. Without the wait the second
# and third chip land on the first (81 particles lost, the run stopped at 0.46 ms).
CHIPFLEX=$chipflex THREADS=2 VARIANTS=rigid_chip_source CHIP_FIRST_RELEASE=0.0001 CHIP_REVOLUTIONS=0.00075 \
  sh "$here/../../cases/drill_flute/run_flute.sh" "$dir" 0.0005 > "$dir/source.log" 2>&1 ||
  fail "run_flute.sh (chip source) failed: $(tail -5 "$dir/source.log")"
grep '^summary: chip_source' "$dir/rigid_chip_source/summary.txt"
grep -q '^summary: chip_source released=1 removed=0 skipped=0 in_segment=1 delayed=1$' \
  "$dir/rigid_chip_source/summary.txt" || fail "not one chip released and one delayed"
grep -q 'lost_particles=0' "$dir/rigid_chip_source.log" || fail "chip source: fluid lost"
grep -q '^mass_balance: .* residual_particles=0$' "$dir/rigid_chip_source/summary.txt" ||
  fail "chip source: the mass does not balance"
# At the last probe row (0.4 ms): chip1 carries chip 1 within 0.5 mm of the release point
# (x = 5.5 mm, z = 3.75 mm) and has moved off it; chip k = 2 ... 4 is parked (chip number
# 0) at x = -6 mm, z = 5k mm, where the case put it.
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  { for (k = 1; k <= 4; ++k) { n[k] = $c["chip" k "_chip"]; x[k] = $c["chip" k "_x_m"]; z[k] = $c["chip" k "_z_m"] } }
  END {
    printf "chip1: chip %d at x %.5f z %.5f m\n", n[1], x[1], z[1]
    d2 = (z[1] - 0.00375) ^ 2 + (x[1] - 0.0055) ^ 2
    if (n[1] != 1 || d2 > 0.25e-6 || d2 < 1e-14) { print "FAIL: chip 1 is not released where it should be"; exit 1 }
    for (k = 2; k <= 4; ++k)
      if (n[k] != 0 || (x[k] + 0.006) ^ 2 > 1e-12 || (z[k] - 0.005 * k) ^ 2 > 1e-12) { print "FAIL: chip" k " left its park"; exit 1 }
  }' "$dir/rigid_chip_source/probes.csv" || exit 1
echo "ok: both variants and the chip source ran with every output"
