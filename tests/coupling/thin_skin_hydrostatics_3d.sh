#!/bin/sh
# Thin skins hold water in 3D (dp 3 mm, h = 5.2 mm; docs/sph.md "Thin skins"): a fixed
# plate (a `moving wall` at rest from an STL file, `wall model` automatic) spans a
# 0.1 x 0.03 x 0.1 m tank at x = 0.051 m and dips into its walls:
#   zero    - zero thickness (two triangles), 0.06 m of water on its left, air on its right;
#   quarter - a closed box dp/4 = 0.75 mm thick (12 triangles), the same water;
#   levels  - zero thickness, 0.06 m of water on the left and 0.03 m on the right.
# Checked over 0.05 ... 0.2 s: the plate's horizontal load against hydrostatics times
# the width, rho g H^2 W / 2 = 0.5297 N (levels: rho g (H1^2 - H2^2) W / 2 = 0.3973 N),
# within 3 %; the left level falls by less than dp and the right one moves by less than
# dp; the guard put no particle back (guarded_particles=0).
#   usage: thin_skin_hydrostatics_3d.sh CHIPFLEX
set -e
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

facet() { # three vertices "x y z"
  printf 'facet normal 0 0 0\n outer loop\n  vertex %s\n  vertex %s\n  vertex %s\n endloop\nendfacet\n' \
    "$1" "$2" "$3"
}
# The plate's extent: y and z reach 1 cm into the tank's walls and floor.
y0=-0.01 y1=0.04 z0=-0.01 z1=0.1
{
  echo "solid zero"
  facet "0.051 $y0 $z0" "0.051 $y1 $z0" "0.051 $y1 $z1"
  facet "0.051 $y0 $z0" "0.051 $y1 $z1" "0.051 $y0 $z1"
  echo "endsolid zero"
} > "$dir/zero.stl"
x0=0.051 x1=0.05175 # dp/4 thick, outward normals
{
  echo "solid quarter"
  facet "$x0 $y0 $z0" "$x0 $y0 $z1" "$x0 $y1 $z1"; facet "$x0 $y0 $z0" "$x0 $y1 $z1" "$x0 $y1 $z0"
  facet "$x1 $y0 $z0" "$x1 $y1 $z0" "$x1 $y1 $z1"; facet "$x1 $y0 $z0" "$x1 $y1 $z1" "$x1 $y0 $z1"
  facet "$x0 $y0 $z0" "$x1 $y0 $z0" "$x1 $y0 $z1"; facet "$x0 $y0 $z0" "$x1 $y0 $z1" "$x0 $y0 $z1"
  facet "$x0 $y1 $z0" "$x0 $y1 $z1" "$x1 $y1 $z1"; facet "$x0 $y1 $z0" "$x1 $y1 $z1" "$x1 $y1 $z0"
  facet "$x0 $y0 $z0" "$x0 $y1 $z0" "$x1 $y1 $z0"; facet "$x0 $y0 $z0" "$x1 $y1 $z0" "$x1 $y0 $z0"
  facet "$x0 $y0 $z1" "$x1 $y0 $z1" "$x1 $y1 $z1"; facet "$x0 $y0 $z1" "$x1 $y1 $z1" "$x0 $y1 $z1"
  echo "endsolid quarter"
} > "$dir/quarter.stl"

run_case() { # name, surface, fluid blocks, expected load
  name=$1
  cat > "$dir/$name.prm" <<EOF2
set dimension = 3
subsection fluid
  set particle spacing     = 0.003
  set gravity              = 0, 0, -9.81
  set speed of sound       = 20
  set artificial viscosity = 0.02
  set density diffusion    = fourtakas
end
subsection time
  set end time = 0.2
end
subsection output
  set frame interval = 0.2
  set probe interval = 0.005
end
subsection geometry
  set fluid blocks = $3
  subsection tank
    set min corner = 0, 0, 0
    set max corner = 0.1, 0.03, 0.1
    set wall model = dummy particles
  end
end
subsection probes
  set water height = left: 0.025, 0.015, 0; right: 0.078, 0.015, 0
end
subsection bodies
  set count = 1
  subsection body 1
    set name    = plate
    set kind    = moving wall
    set surface = $2
  end
end
EOF2
  "$chipflex" run "$dir/$name.prm" --out "$dir/$name" > "$dir/$name.log" 2>&1 ||
    { cat "$dir/$name.log"; fail "$name: run failed"; }
  grep -q "thin-skin wall (automatic" "$dir/$name.log" || fail "$name: the plate is not a thin skin"
  grep -q "guarded_particles=0" "$dir/$name/summary.txt" ||
    fail "$name: the guard had to put particles back ($(grep -o 'guarded_particles=[0-9]*' "$dir/$name/summary.txt"))"
  awk -F, -v name="$name" -v load="$4" '
    NR == 1 { for (k = 1; k <= NF; ++k) col[$k] = k; next }
    NR == 2 { left0 = $col["h_left_m"]; right0 = $col["h_right_m"] }
    $1 >= 0.05 { f = $col["plate_force_x_N"]; sum += (f < 0 ? -f : f); ++n }
    { left = $col["h_left_m"]; right = $col["h_right_m"] }
    END {
      mean = sum / n; e = (mean - load) / load
      printf "%s: load %.4f N against %.4f (%+.2f %%), left level %.4f -> %.4f m, right %.4f -> %.4f m\n",
             name, mean, load, 100 * e, left0, left, right0, right
      if (e > 0.03 || e < -0.03) { print "FAIL: " name ": load off by more than 3 %"; exit 1 }
      if (left0 - left > 0.003) { print "FAIL: " name ": the left level fell by more than dp"; exit 1 }
      if (right - right0 > 0.003 || right0 - right > 0.003) {
        print "FAIL: " name ": the right level moved by more than dp"; exit 1 }
    }' "$dir/$name/probes.csv" || exit 1
}

run_case zero zero.stl "0, 0, 0, 0.051, 0.03, 0.06" 0.5297
run_case quarter quarter.stl "0, 0, 0, 0.051, 0.03, 0.06" 0.5297
run_case levels zero.stl "0, 0, 0, 0.051, 0.03, 0.06; 0.051, 0, 0, 0.1, 0.03, 0.03" 0.3973
echo "ok: thin skins hold water in 3D"
