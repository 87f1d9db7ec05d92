#!/bin/sh
# The body keys `weight` and `probe point`, on the SPH-solid gate hanging in air (the water
# is a small block far downstream, so only gravity loads the gate):
# - weight = true: the strip hangs under its own weight; its free end moves down, on mean
#   over the axial oscillations, by the static stretch of a hanging plane-strain strip,
#   rho g L^2 (1 - nu^2) / (2 E) = 2.36e-6 m (within 10 %; measured 2.24e-6 m);
# - weight = false: nothing loads it, the free end does not move at all;
# - probe point = 0.105, 0: the probe starts at the downstream lower corner's skin node,
#   half a spacing outside the corner particle: (0.105, 0.0).
#   usage: gate_body_keys.sh CHIPFLEX
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
write_case() { # $1 file, $2 weight, $3 probe point
  cat > "$1" <<CASE
set dimension = 2
subsection fluid
  set particle spacing = 0.002
  set gravity          = 0, -9.81
end
subsection time
  set end time = 0.02
  set scheme   = symplectic
  set cfl      = 0.2
end
subsection output
  set frame interval = 0.02
  set probe interval = 0.0001
end
subsection geometry
  set fluid blocks = 0.4, 0, 0.45, 0.02
  subsection tank
    set min corner = 0, 0
    set max corner = 0.5, 0.3
  end
end
subsection bodies
  subsection body 1
    set name        = gate
    set kind        = sph solid
    set density     = 1100
    set youngs modulus = 1.2e7
    set poisson ratio  = 0.4
    set position    = 0.1025, 0.079
    set length      = 0.079
    set thickness   = 0.005
    set weight      = $2
    set probe point = $3
  end
end
CASE
}
write_case "$dir/heavy.prm" true ""
write_case "$dir/weightless.prm" false ""
write_case "$dir/corner.prm" true "0.105, 0"
for c in heavy weightless corner; do
  "$chipflex" run "$dir/$c.prm" --out "$dir/$c" > "$dir/$c.log" 2>&1 ||
    fail "$c: $(tail -3 "$dir/$c.log")"
done
column() { # $1 run, $2 column name: prints "time value" rows
  awk -F, -v name="$2" 'NR == 1 { for (k = 1; k <= NF; ++k) if ($k == name) c = k; next }
                        { print $1, $c }' "$dir/$1/probes.csv"
}
mean_dy=$(column heavy gate_dy_m | awk '$1 >= 0.005 { s += $2; n += 1 } END { print s / n }')
expected=$(awk 'BEGIN { print -1100 * 9.81 * 0.079^2 * (1 - 0.16) / (2 * 1.2e7) }')
echo "weight on: mean free-end dy $mean_dy m, hanging strip $expected m"
awk -v a="$mean_dy" -v b="$expected" 'BEGIN { d = a / b - 1; exit !(d < 0.1 && d > -0.1) }' ||
  fail "the hanging gate's stretch $mean_dy m is not within 10 % of $expected m"
largest=$(column weightless gate_dy_m | awk '{ v = $2 < 0 ? -$2 : $2; if (v > m) m = v } END { print m + 0 }')
echo "weight off: largest free-end |dy| $largest m"
[ "$largest" = 0 ] || fail "the weightless gate moved ($largest m)"
start=$(column corner gate_x_m | head -1 | cut -d' ' -f2),$(column corner gate_y_m | head -1 | cut -d' ' -f2)
echo "probe point 0.105, 0: the probe starts at $start"
echo "$start" | awk -F, '{ exit !(($1 - 0.105)^2 + $2^2 < 1e-18) }' ||
  fail "the probe does not start at the corner node (0.105, 0): $start"
echo "ok"
