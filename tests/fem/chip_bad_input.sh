#!/bin/sh
# `chipflex mesh chip` with impossible parameters: each case must exit with status 2, print
# exactly one line on stderr naming the option at fault, and leave no mesh file behind.
# usage: chip_bad_input.sh CHIPFLEX
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0
out="$dir/chip.msh"

# expect NAME EXPECTED_IN_MESSAGE ARGUMENTS...
expect() {
  name=$1 needle=$2
  shift 2
  "$chipflex" mesh chip -o "$out" "$@" > "$dir/stdout" 2> "$dir/stderr"
  status=$?
  lines=$(wc -l < "$dir/stderr")
  if [ "$status" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -q -- "$needle" "$dir/stderr" ||
     ls "$out"* > /dev/null 2>&1; then
    echo "FAIL $name: status $status, $lines stderr lines:"
    cat "$dir/stderr"
    ls "$out"* 2> /dev/null
    failures=$((failures + 1))
  else
    echo "ok   $name: $(cat "$dir/stderr")"
  fi
}

expect "thickness 0" "--thickness" --shape arc --thickness 0
expect "thickness < 0" "--thickness" --shape helical --thickness -0.001
expect "width 0" "--width" --shape ribbon --width 0
# helical, R = 2 mm, 2 x 0.2 mm: a turn spans just over 0.2 mm along the axis
expect "helical pitch 0" "intersects itself" --shape helical --pitch 0
expect "helical pitch = thickness" "intersects itself" --shape helical --pitch 0.0002
expect "negative pitch" "--pitch" --shape helical --pitch -0.001
expect "spiral pitch below width" "--pitch" --shape spiral --pitch 0.0015
expect "curl radius below width/2" "--curl-radius" --shape arc --curl-radius 0.0009
expect "curl radius = width/2" "--curl-radius" --shape helical --curl-radius 0.001
expect "spiral curl radius" "--curl-radius" --shape spiral --curl-radius 0.0005
expect "size larger than the chip" "larger than the chip" --shape ribbon --length 0.001 --size 0.002
expect "size larger than the arc" "larger than the chip" --shape arc --arc-angle 10 --size 0.001
expect "size 0" "--size" --shape arc --size 0
expect "one layer" "--layers" --shape arc --layers 1
expect "arc over 360" "--arc-angle" --shape arc --arc-angle 400
expect "arc 0" "--arc-angle" --shape arc --arc-angle 0
expect "turns 0" "--turns" --shape helical --turns 0
expect "order 3" "--order" --shape arc --order 3
expect "unknown shape" "cone" --shape cone

# A good chip still works, and a mesh that is already there is left alone by a bad run.
"$chipflex" mesh chip --shape helical -o "$dir/good.msh" > /dev/null || {
  echo "FAIL good helical chip"
  failures=$((failures + 1))
}
cp "$dir/good.msh" "$dir/keep.msh"
"$chipflex" mesh chip --shape helical --pitch 0 -o "$dir/good.msh" 2> /dev/null
cmp -s "$dir/good.msh" "$dir/keep.msh" || {
  echo "FAIL a bad run changed an existing mesh"
  failures=$((failures + 1))
}

[ "$failures" -eq 0 ]
