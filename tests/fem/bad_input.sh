#!/bin/sh
# Bad input: each case must exit with status 2, print exactly one line on stderr naming the
# file or option at fault, and leave no output file behind.   usage: bad_input.sh CHIPFLEX
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0

# expect NAME EXPECTED_IN_MESSAGE OUTPUT_FILE COMMAND...
expect() {
  name=$1 needle=$2 output=$3
  shift 3
  "$@" > "$dir/stdout" 2> "$dir/stderr"
  status=$?
  lines=$(wc -l < "$dir/stderr")
  if [ "$status" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -q -- "$needle" "$dir/stderr" ||
     { [ -n "$output" ] && ls "$output"* > /dev/null 2>&1; }; then
    echo "FAIL $name: status $status, $lines stderr lines:"
    cat "$dir/stderr"
    ls "$output"* 2> /dev/null
    failures=$((failures + 1))
  else
    echo "ok   $name: $(cat "$dir/stderr")"
  fi
}

"$chipflex" mesh gate -o "$dir/gate.msh" --size 0.0025 > /dev/null || exit 1
# The gate's rubber: `reduce` has no material defaults. Unquoted below (three options).
rubber="--E 1.2e7 --nu 0.4 --rho 1100"
"$chipflex" reduce "$dir/gate.msh" -o "$dir/gate.h5" $rubber \
  --clamp clamp --modes 2 > /dev/null || exit 1
out="$dir/out.h5"

expect "missing mesh" "nothing.msh" "$out" "$chipflex" reduce "$dir/nothing.msh" -o "$out" $rubber
printf 'this is not a mesh\n' > "$dir/garbage.msh"
expect "malformed mesh" "garbage.msh" "$out" "$chipflex" reduce "$dir/garbage.msh" -o "$out" $rubber
# Damaged headers that libgmsh 4.8 itself fails on (found by tests/fuzz): a node count of
# 1e16 (it would allocate that much) and a physical name without its quotes (it crashes).
sed '0,/^\$Nodes/{/^\$Nodes/{n;s/^\([0-9]*\) [0-9]*/\1 10000000000000000/}}' "$dir/gate.msh" > "$dir/huge.msh"
expect "huge count" "larger than a file of this size" "$out" \
  "$chipflex" reduce "$dir/huge.msh" -o "$out" $rubber
# A 9-digit largest node tag: gmsh sizes its tag cache by it (gigabytes).
sed '0,/^\$Nodes/{/^\$Nodes/{n;s/^\([0-9]* [0-9]* [0-9]*\) [0-9]*$/\1 999999999/}}' \
  "$dir/gate.msh" > "$dir/huge_tag.msh"
expect "huge node tag" "the count or tag 999999999 is larger" "$out" \
  "$chipflex" reduce "$dir/huge_tag.msh" -o "$out" $rubber
# An entity line whose counts do not match its tags (gmsh reads a count out of the next
# number and allocates by it): the first point's line with a stray number at its end.
sed '0,/^\$Entities/{/^\$Entities/{n;n;s/$/ 7/}}' "$dir/gate.msh" > "$dir/entity.msh"
expect "damaged entity line" "not a point entity" "$out" \
  "$chipflex" reduce "$dir/entity.msh" -o "$out" $rubber
# The structure check (meshes/msh_text_check.cc), one damage each: gmsh 4.8 itself would
# misread these (an allocation by a wrong count, its binary reader on text, a heap
# corrupted by a damaged section) or silently read something else.
damaged() { # NAME SED_SCRIPT EXPECTED_IN_MESSAGE
  sed "$2" "$dir/gate.msh" > "$dir/$1.msh"
  expect "mesh: $1" "$3" "$out" "$chipflex" reduce "$dir/$1.msh" -o "$out" $rubber
  rm -f "$out"* # a damage that went through must not fail the cases after it
}
damaged binary '2s/^4.1 0 8$/4.1 1 8/' "binary .msh"
damaged format_40 '2s/^4.1 0 8$/4.0 0 8/' "mesh format 4.0 is not read"
damaged control_character '5s/$/\x01/' "control character"
damaged unknown_section 's/^\$\(End\)\{0,1\}PhysicalNames$/$\1NodeData/' "not a section"
damaged unclosed_section '/^\$EndNodes$/d' "expected \$EndNodes"
damaged short_element '0,/^\$Elements/{/^\$Elements/{n;n;n;s/ [0-9]* *$//}}' "needs"
damaged element_count '/^\$Elements/{n;s/^\([0-9]*\) [0-9]*/\1 1/}' "the element blocks hold"
damaged node_line '0,/^\$Nodes/{/^\$Nodes/{n;n;n;n;s/$/ 0/}}' "coordinates"
sed 's/^1 2 "clamp"$/1 2 clamp/' "$dir/gate.msh" > "$dir/unquoted.msh"
expect "unquoted physical name" "not a physical name" "$out" \
  "$chipflex" reduce "$dir/unquoted.msh" -o "$out" $rubber
head -c 3000 "$dir/gate.msh" > "$dir/truncated.msh"
expect "truncated mesh" "truncated.msh" "$out" \
  "$chipflex" reduce "$dir/truncated.msh" -o "$out" $rubber
expect "missing group" "nosuch" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" $rubber --clamp nosuch
expect "missing static group" "nosuch" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" $rubber --static-modes pressure:nosuch
expect "bad static kind" "twist" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" $rubber --static-modes twist:tip
expect "nu = 0.5" "--nu" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" --E 1.2e7 --rho 1100 --nu 0.5
expect "nu = -1" "--nu" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" --E 1.2e7 --rho 1100 --nu -1
expect "E = 0" "--E" "$out" "$chipflex" reduce "$dir/gate.msh" -o "$out" --nu 0.4 --rho 1100 --E 0
expect "rho < 0" "--rho" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" --E 1.2e7 --nu 0.4 --rho -1
expect "E missing" "--E: required" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" --nu 0.4 --rho 1100
expect "nu missing" "--nu: required" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" --E 1.2e7 --rho 1100
expect "rho missing" "--rho: required" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" --E 1.2e7 --nu 0.4
expect "modes = 0" "--modes" "$out" "$chipflex" reduce "$dir/gate.msh" -o "$out" $rubber --modes 0
expect "degree 3" "--degree" "$out" "$chipflex" reduce "$dir/gate.msh" -o "$out" $rubber --degree 3
expect "derivatives without --nonlinear" "--modal-derivatives" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" $rubber --modal-derivatives 2
expect "more derivatives than modes" "--modal-derivatives" "$out" \
  "$chipflex" reduce "$dir/gate.msh" -o "$out" $rubber --modes 2 --nonlinear --modal-derivatives 3
expect "bad mesh size" "--size" "$dir/m.msh" "$chipflex" mesh gate -o "$dir/m.msh" --size -1
expect "unknown mesh kind" "sphere" "$dir/m.msh" "$chipflex" mesh sphere -o "$dir/m.msh"

printf 'garbage garbage garbage\n' > "$dir/garbage.h5"
expect "info: corrupted body" "garbage.h5" "" "$chipflex" info "$dir/garbage.h5"
head -c 20000 "$dir/gate.h5" > "$dir/truncated.h5"
expect "info: truncated body" "truncated.h5" "" "$chipflex" info "$dir/truncated.h5"
expect "info: missing body" "none.h5" "" "$chipflex" info "$dir/none.h5"
expect "compare: corrupted body" "garbage.h5" "$dir/c.csv" \
  "$chipflex" compare "$dir/gate.msh" "$dir/garbage.h5" --load force:tip:1,0 -o "$dir/c.csv"
expect "compare: missing group" "nosuch" "$dir/c.csv" \
  "$chipflex" compare "$dir/gate.msh" "$dir/gate.h5" --load force:nosuch:1,0 -o "$dir/c.csv"
expect "compare: wrong force size" "--load" "$dir/c.csv" \
  "$chipflex" compare "$dir/gate.msh" "$dir/gate.h5" --load force:tip:1,0,0 -o "$dir/c.csv"
"$chipflex" mesh gate -o "$dir/other.msh" --size 0.005 > /dev/null
expect "compare: other mesh" "other.msh" "$dir/c.csv" \
  "$chipflex" compare "$dir/other.msh" "$dir/gate.h5" --load force:tip:1,0 -o "$dir/c.csv"

[ "$failures" -eq 0 ] && echo "all bad-input cases handled" && exit 0
echo "$failures bad-input cases failed"
exit 1
