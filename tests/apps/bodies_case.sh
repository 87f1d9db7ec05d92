#!/bin/sh
# Bodies in case files (docs/bodies.md), through `chipflex run`:
# 1. A 3D case with a rigid sphere dropped into water, a paddle from an STL file turning
#    as a moving wall and a fixed wall from the same STL: it runs, the sphere falls
#    (z drops by about g t^2 / 2 in the first 0.03 s, before it meets the water), the
#    paddle, standing in the water, turns by omega t and reports its torque; the fluid
#    particles the blocks put inside the paddle are removed at the start, so none is
#    thrown about.
# 2. A restart from a checkpoint halfway ends bitwise as the uninterrupted run.
# 3. Bad bodies: each exits with status 2 and one line on stderr naming the case, the
#    body and the key (or the file) at fault.
#   usage: bodies_case.sh CHIPFLEX
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# STL files: a 0.06 x 0.06 m square at z = 0.12 facing down (a fixed wall above the
# water), and a closed 0.06 x 0.02 x 0.06 m plate centred on the origin (the paddle: a
# Lennard-Jones wall is one-sided, so a paddle in water needs both faces).
facet() { echo " facet normal 0 0 0"; echo "  outer loop"
          echo "   vertex $1"; echo "   vertex $2"; echo "   vertex $3"
          echo "  endloop"; echo " endfacet"; }
{ echo "solid square"
  facet "0.12 0.07 0.12" "0.12 0.13 0.12" "0.18 0.13 0.12"
  facet "0.12 0.07 0.12" "0.18 0.13 0.12" "0.18 0.07 0.12"
  echo "endsolid square"; } > "$dir/square.stl"
{ echo "solid plate"
  # corner k of the box: x = +-0.03, y = +-0.01, z = +-0.03 by the bits of k
  c() { x=$(( ($1 & 1) * 2 - 1 )) y=$(( (($1 >> 1) & 1) * 2 - 1 )) z=$(( (($1 >> 2) & 1) * 2 - 1 ))
        echo "$(awk "BEGIN { print 0.03 * $x, 0.01 * $y, 0.03 * $z }")"; }
  for q in "0 2 3 1" "4 5 7 6" "0 1 5 4" "2 6 7 3" "0 4 6 2" "1 3 7 5"; do
    set -- $q
    facet "$(c $1)" "$(c $2)" "$(c $3)"
    facet "$(c $1)" "$(c $3)" "$(c $4)"
  done
  echo "endsolid plate"; } > "$dir/plate.stl"

# A flexible 3D block (0.06 x 0.03 x 0.03 m, clamped at x = 0, 4 modes), stood up on
# the floor in the water: rotated by -pi/2 about y, its length runs along +z. (Thick: a
# skin thinner than the kernel support lets the fluid interact through it.)
"$chipflex" mesh plate -o "$dir/plate.msh" --length 0.06 --thickness 0.03 --width 0.03 \
  --size 0.01 > /dev/null || fail "mesh plate"
"$chipflex" reduce "$dir/plate.msh" -o "$dir/plate.h5" --clamp clamp --modes 4 --E 2e6 \
  --nu 0.4 --rho 1100 > /dev/null || fail "reduce plate"

cat > "$dir/case.prm" <<'PRM'
set dimension = 3
subsection fluid
  set particle spacing = 0.01
  set gravity          = 0, 0, -9.81
end
subsection time
  set end time = 0.03
  set scheme   = symplectic
end
subsection output
  set frame interval = 0.01
  set probe interval = 0.001
end
subsection geometry
  set fluid blocks = 0, 0, 0, 0.2, 0.2, 0.05
  subsection tank
    set min corner = 0, 0, 0
    set max corner = 0.2, 0.2, 0.2
  end
  subsection walls
    set surfaces = square.stl
  end
end
subsection bodies
  subsection body 1
    set name     = sphere
    set kind     = rigid
    set shape    = sphere
    set radius   = 0.02
    set density  = 800
    set position = 0.05, 0.1, 0.15
    set clamped  = false
  end
  subsection body 2
    set name             = paddle
    set kind             = moving wall
    set surface          = plate.stl
    set position         = 0.15, 0.1, 0.03 # in the water: the fluid inside it is removed
    set angular velocity = 0, 0, 2
  end
  subsection body 3
    set name          = plate
    set kind          = flexible
    set body file     = plate.h5
    set position      = 0.1, 0.085, 0 # faces between particle columns
    set rotation axis = 0, 1, 0
    set angle         = -1.5707963267948966
    set clamped       = true
    set wall model    = dummy particles
  end
end
PRM
"$chipflex" run "$dir/case.prm" --out "$dir/out" > "$dir/log" 2>&1 || fail "run: $(tail -3 "$dir/log")"
grep "^summary: body=" "$dir/out/summary.txt"
peak=$(sed -n 's/.*peak_fluid_speed_m_s=\([0-9.e+-]*\).*/\1/p' "$dir/out/summary.txt" | head -1)
awk "BEGIN { exit !($peak < 0.5) }" || fail "a fluid particle reached $peak m/s in water at rest"
[ -f "$dir/out/skins.xdmf" ] || fail "no skins.xdmf"
grep -q "body 'paddle'.* fluid particles inside it removed" "$dir/log" ||
  fail "the fluid inside the paddle was not removed: $(grep "body 'paddle'" "$dir/log")"
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { t = $1; dz = $col["sphere_dz_m"]; rz = $col["paddle_rz_rad"]; torque = $col["paddle_torque_Nm"]
    bend = $col["plate_deflection_m"]; top = $col["plate_z_m"] }
  END { fall = 0.5 * 9.81 * t * t
        printf "t = %.4f s: sphere dz %.5f m (free fall %.5f m), paddle turned %.4f rad (omega t %.4f), torque %.3g N m\n",
               t, dz, -fall, rz, 2 * t, torque
        if (dz > -0.9 * fall || dz < -1.1 * fall) { print "FAIL: the sphere does not fall freely"; exit 1 }
        if (rz < 0.999 * 2 * t || rz > 1.001 * 2 * t) { print "FAIL: the paddle does not turn at 2 rad/s"; exit 1 }
        if (!(torque < 0)) { print "FAIL: the water does not resist the paddle (torque " torque ")"; exit 1 }
        printf "plate: tip at z = %.4f m (stood up: 0.06), deflection %.3g m\n", top, bend
        if (top < 0.0599 || top > 0.0601) { print "FAIL: the plate is not stood up"; exit 1 }
        if (!(bend >= 0 && bend < 0.005)) { print "FAIL: the plate deflection is off"; exit 1 } }
' "$dir/out/probes.csv" || exit 1
awk -F, 'NR == 1 { exit !(index($0, "paddle_torque_Nm") && index($0, "sphere_rx_rad") && index($0, "plate_deflection_m")) }' \
  "$dir/out/probes.csv" || fail "probes.csv lacks the per-body columns"

# A restart halfway (checkpoint at 0.015 s) ends bitwise as the uninterrupted run: the
# bodies' states (rigid sphere, moving wall's clock and impulse) are in the checkpoint.
"$chipflex" run "$dir/case.prm" --out "$dir/part" --end-time 0.015 --checkpoint-every 0.015 \
  > "$dir/part.log" 2>&1 || fail "run to 0.015 s: $(tail -2 "$dir/part.log")"
"$chipflex" run "$dir/case.prm" --out "$dir/part" --restart "$dir/part/checkpoint.h5" \
  > "$dir/restart.log" 2>&1 || fail "restart: $(tail -2 "$dir/restart.log")"
cmp -s "$dir/out/probes.csv" "$dir/part/probes.csv" ||
  fail "the restarted 3D run differs: $(tail -1 "$dir/out/probes.csv") / $(tail -1 "$dir/part/probes.csv")"
echo "ok: the 3D run restarted at 0.015 s ends bitwise as the uninterrupted one"

failures=0
# bad NAME NEEDLE: replaces the first body by the lines on stdin, expects status 2 and
# one stderr line containing NEEDLE.
bad() {
  name=$1 needle=$2
  { sed '/subsection bodies/,$d' "$dir/case.prm"; echo "subsection bodies"; echo "  subsection body 1"
    cat; echo "  end"; echo "end"; } > "$dir/bad.prm"
  "$chipflex" run "$dir/bad.prm" --out "$dir/bad_out" > /dev/null 2> "$dir/stderr"
  status=$? lines=$(wc -l < "$dir/stderr")
  if [ "$status" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -q -- "$needle" "$dir/stderr"; then
    echo "FAIL $name: status $status, $lines lines:"; cat "$dir/stderr"; failures=$((failures + 1))
  else
    echo "ok   $name: $(cat "$dir/stderr")"
  fi
}
printf '    set kind = rigid\n    set links = 2\n    set density = 1000\n' | bad "key of another kind" "body 1, links: does not apply to a body of kind rigid"
printf '    set kind = chain\n' | bad "2D-only kind in 3D" "chain kind exists in 2D cases only"
printf '    set kind = rigid\n    set shape = mesh\n    set mesh = nothing.stl\n    set density = 1000\n' | bad "missing mesh" "nothing.stl"
printf '    set kind = rigid\n    set shape = mesh\n    set mesh = square.stl\n    set density = 1000\n' | bad "open surface as a rigid body" "not closed"
printf '    set kind = rigid\n    set size = 0.1, 0.1\n    set density = 1000\n' | bad "box size of a 2D box" "size"
printf '    set kind = rigid\n    set position = 0.1, 0.1\n    set density = 1000\n' | bad "2D position in 3D" "position"
printf '    set kind = flexible\n    set body file = none.h5\n' | bad "missing body file" "none.h5"
printf '    set kind = moving wall\n' | bad "moving wall without a surface" "needs either an outline or a surface"
printf '    set kind = rigid\n    set density = -5\n' | bad "negative density" "density"
printf '    set kind = rigid\n' | bad "rigid body without density" "body 1, density: required"
[ "$failures" -eq 0 ] || exit 1
echo "ok"
