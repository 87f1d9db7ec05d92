#!/bin/sh
# `fluid/background pressure`: the log states it (and that outputs stay gauge), warns for
# a Lennard-Jones wall, which has no particles to carry it, and stays quiet with
# dummy-particle walls; a negative value is refused with one line naming the key.
#   usage: background_pressure.sh CHIPFLEX SOURCE_DIR
chipflex=$1
flute=$2/cases/drill_flute/flute_2d.prm
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

grep -q "set background pressure = 50000" "$flute" || fail "flute_2d.prm sets no background pressure"
sed 's/^    set open ends  = x$/    set open ends  = x\n    set wall model = lennard jones/' "$flute" > "$dir/lj.prm"
sed 's/set background pressure = 50000/set background pressure = -1/' "$flute" > "$dir/negative.prm"

"$chipflex" run "$flute" --out "$dir/dummy" --end-time 0.0001 > "$dir/dummy.log" 2>&1 ||
  fail "dummy walls: $(tail -2 "$dir/dummy.log")"
grep -q "^background pressure 50000 Pa" "$dir/dummy.log" || fail "the log does not state the background pressure"
grep -q "warning: background pressure" "$dir/dummy.log" && fail "a warning with dummy-particle walls"

"$chipflex" run "$dir/lj.prm" --out "$dir/lj" --end-time 0.0001 > "$dir/lj.log" 2>&1 ||
  fail "Lennard-Jones tank: $(tail -2 "$dir/lj.log")"
grep -q "warning: background pressure with the Lennard-Jones wall 'tank'" "$dir/lj.log" ||
  fail "no warning for the Lennard-Jones tank"

if "$chipflex" run "$dir/negative.prm" --out "$dir/negative" > "$dir/negative.log" 2>&1; then
  fail "a negative background pressure was accepted"
fi
grep -q "background pressure" "$dir/negative.log" || fail "the error does not name the key: $(cat "$dir/negative.log")"
echo "ok: background pressure stated, warned for Lennard-Jones walls, negative refused"
