#!/bin/sh
# The `fe` body kind (the full nonlinear FE gate) through `chipflex run`: the elastic gate at
# dp 4 mm for 12 ms with the FE model sub-cycled (fe time step 0.2 ms, ~4 fluid steps per FE
# step). A run stopped at 6 ms (inside an FE step) and restarted from its checkpoint must
# reproduce the uninterrupted run's probes bitwise, and the gate must have moved downstream.
# Bad keys stop the run with one line and status 2.
#   usage: fe_body_restart.sh CHIPFLEX REPO
chipflex=$1
repo=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
[ -n "$KEEP" ] && trap - EXIT && echo "keeping $dir"
fail() { echo "FAIL: $*"; exit 1; }

"$chipflex" mesh gate -o "$dir/gate.msh" > /dev/null || fail "mesh gate"
"$repo/scripts/flatten_case.sh" "$repo/cases/elastic_gate/fe.prm" |
  sed -e "s|^\(  set particle spacing *=\).*|\1 0.004|" \
    -e "s|^\(  set reference *=\).*|\1 $repo/data/antoci2007/experiment_merged.csv|" \
    -e "s|^\(  set frame interval *=\).*|\1 0.006|" \
    > "$dir/fe.prm"

"$chipflex" run "$dir/fe.prm" --out "$dir/full" --threads 2 --end-time 0.012 > "$dir/full.log" 2>&1 ||
  fail "uninterrupted run: $(tail -2 "$dir/full.log")"
grep -q "body 'gate': fe" "$dir/full.log" || fail "no fe body in the log: $(head -5 "$dir/full.log")"
"$chipflex" run "$dir/fe.prm" --out "$dir/parts" --threads 2 --end-time 0.006 \
  --checkpoint-every 0.006 > "$dir/first.log" 2>&1 || fail "first part: $(tail -2 "$dir/first.log")"
cp "$dir/parts/checkpoint.h5" "$dir/checkpoint.h5"
"$chipflex" run "$dir/fe.prm" --out "$dir/parts" --threads 2 --end-time 0.012 \
  --restart "$dir/checkpoint.h5" > "$dir/second.log" 2>&1 || fail "restart: $(tail -2 "$dir/second.log")"
grep -q "restarted from" "$dir/second.log" || fail "the restart did not say so"
cmp -s "$dir/full/probes.csv" "$dir/parts/probes.csv" ||
  fail "probe histories differ: $(tail -1 "$dir/full/probes.csv") / $(tail -1 "$dir/parts/probes.csv")"
# The water pushes the gate's free end downstream (+x) by a fraction of a millimetre by 12 ms.
dx=$(sed -n 's/.*max_abs_dx_mm=\([0-9.eE+-]*\).*/\1/p' "$dir/full.log" | head -1)
awk -v d="$dx" 'BEGIN { exit !(d > 0.01 && d < 5) }' || fail "free-end dx $dx mm after 12 ms"
# Bad input: one line naming the case, the body and the problem, exit status 2.
sed 's/^\(    set clamp group *=\).*/\1 nogroup/' "$dir/fe.prm" > "$dir/bad.prm"
"$chipflex" run "$dir/bad.prm" --out "$dir/bad" > "$dir/bad.log" 2>&1
[ $? -eq 2 ] || fail "a missing clamp group: exit status not 2"
grep -q "body 1.*nogroup" "$dir/bad.log" || fail "the error does not name the group: $(cat "$dir/bad.log")"
sed 's/^\(    set material model *=\).*/\1 neo-hooke\n    set plane stress = true/' "$dir/fe.prm" > "$dir/bad.prm"
"$chipflex" run "$dir/bad.prm" --out "$dir/bad" > "$dir/bad.log" 2>&1
[ $? -eq 2 ] || fail "neo-Hooke in plane stress: exit status not 2"
echo "ok: fe gate restarted at 6 ms = uninterrupted run, bitwise (max dx $dx mm)"
