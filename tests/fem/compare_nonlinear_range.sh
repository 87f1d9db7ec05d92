#!/bin/sh
# `chipflex compare --nonlinear` at the corners of its range: steel cantilevers (2D, nu = 0,
# E = 2e11 Pa) of L/h = 10 and 100 under a dead transverse tip load P L^2/EI = 10 (tip angle
# 82 degrees), reduced with 4 modes, the tip-load static mode and the modal derivatives. Both
# sides must reach their static and transient answers (before, the reduced side's dynamic
# relaxation stopped with "Newton did not converge" and the full trapezoidal transient with
# an internal error). Checked: the full static tip deflection against the elastica,
# w/L = 0.81061 (Mattiasson 1981), within 1 % at L/h = 100 and 3 % at L/h = 10 (a solid of
# L/h = 10 strains 20 % at the clamp there and shears: no longer the elastica's beam), and the
# reduced static tip against the full one within 5 % (docs/nonlinear_bodies.md has the
# figures). A short transient (10 steps) keeps the test near half a minute.
#   usage: compare_nonlinear_range.sh CHIPFLEX
set -e
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
first() { sed -n "s/.*\"$1\": *\[\([^,]*\),.*/\1/p" "$2"; }
value() { sed -n "s/.*\"$1\": *\([0-9.eE+-]*\).*/\1/p" "$2"; }

report=""
for slenderness in 10 100; do
  length=0.1
  h=$(awk -v s="$slenderness" 'BEGIN { printf "%.6g", 0.1 / s }')
  # P = 10 EI / L^2 with EI = E h^3 / 12 per metre of depth (nu = 0: plane strain = stress)
  p=$(awk -v h="$h" 'BEGIN { printf "%.8g", 10 * 2e11 * h * h * h / 12 / (0.1 * 0.1) }')
  size=$(awk -v h="$h" 'BEGIN { printf "%.6g", h / 2 }')
  "$chipflex" mesh gate --length $length --thickness "$h" --size "$size" -o "$dir/s.msh" > /dev/null
  "$chipflex" reduce "$dir/s.msh" -o "$dir/s.h5" --clamp clamp --modes 4 \
    --static-modes force:tip:1,0 --nonlinear --nu 0 --E 2e11 --rho 7800 > /dev/null
  dt=$("$chipflex" info "$dir/s.h5" --json | sed -n 's/.*"frequencies_hz": *\[\([^,]*\),.*/\1/p' |
       awk '{ printf "%.6g", 1 / (40 * $1) }')
  duration=$(awk -v d="$dt" 'BEGIN { printf "%.6g", 10 * d }')
  "$chipflex" compare "$dir/s.msh" "$dir/s.h5" --load "force:tip:$p,0" --nonlinear --json \
    --duration "$duration" > "$dir/c.json" || fail "L/h = $slenderness: compare failed"
  full=$(first static_full_m "$dir/c.json")
  reduced=$(first static_reduced_m "$dir/c.json")
  limit=0.01
  [ "$slenderness" = 10 ] && limit=0.03
  awk -v w="$full" -v l="$limit" 'BEGIN { e = (w / 0.1 - 0.81061) / 0.81061; if (e < 0) e = -e;
    exit !(e <= l) }' || fail "L/h = $slenderness: full tip w/L $full/0.1, elastica 0.81061"
  awk -v a="$full" -v b="$reduced" 'BEGIN { e = (b - a) / a; if (e < 0) e = -e; exit !(e <= 0.05) }' ||
    fail "L/h = $slenderness: reduced tip $reduced against full $full"
  report="$report L/h = $slenderness: w full $full, reduced $reduced m (rho $(value rho_infinity_full "$dir/c.json"), $(value rho_infinity_reduced "$dir/c.json"));"
done
echo "ok: compare --nonlinear range:$report"
