#!/bin/sh
# `fluid/particle shifting`: automatic switches it on for an internal flow (a case with an
# open boundary: the log states it and summary.txt reports the closest fluid pair, and no
# pair beside thin skins, which it has none of) and
# leaves a tank alone; `on` switches it on for a tank too; an unknown value is refused
# with one line naming the key.
#   usage: particle_shifting.sh CHIPFLEX SOURCE_DIR
chipflex=$1
cases=$2/cases
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$chipflex" run "$cases/channel_2d.prm" --out "$dir/channel" --end-time 0.001 > "$dir/channel.log" 2>&1 ||
  fail "channel: $(tail -2 "$dir/channel.log")"
grep -q "^particle shifting: D = 2 h |v| dt" "$dir/channel.log" || fail "the channel's log does not state the shifting"
grep -q "closest_fluid_pair_dp=" "$dir/channel/summary.txt" || fail "no closest pair in the channel's summary.txt"
grep -q "closest_skin_side_pair_dp=" "$dir/channel/summary.txt" &&
  fail "a closest pair beside thin skins in a channel without any"

"$chipflex" run "$cases/dam_break_2d.prm" --out "$dir/tank" --end-time 0.001 > "$dir/tank.log" 2>&1 ||
  fail "tank: $(tail -2 "$dir/tank.log")"
grep -q "particle shifting" "$dir/tank.log" && fail "automatic shifted a tank without open boundaries"
grep -q "closest_fluid_pair_dp=" "$dir/tank/summary.txt" && fail "a closest pair without shifting"

sed 's/^subsection fluid$/subsection fluid\n  set particle shifting = on/' "$cases/dam_break_2d.prm" > "$dir/on.prm"
"$chipflex" run "$dir/on.prm" --out "$dir/on" --end-time 0.001 > "$dir/on.log" 2>&1 ||
  fail "tank with shifting: $(tail -2 "$dir/on.log")"
grep -q "^particle shifting: D = 2 h |v| dt" "$dir/on.log" || fail "'on' did not switch it on"

sed 's/^subsection fluid$/subsection fluid\n  set particle shifting = maybe/' "$cases/dam_break_2d.prm" > "$dir/bad.prm"
if "$chipflex" run "$dir/bad.prm" --out "$dir/bad" > "$dir/bad.log" 2>&1; then
  fail "'maybe' was accepted"
fi
grep -q "particle shifting" "$dir/bad.log" || fail "the error does not name the key: $(cat "$dir/bad.log")"
[ "$(wc -l < "$dir/bad.log")" -le 2 ] || fail "the error is not one line: $(cat "$dir/bad.log")"
echo "ok: shifting on for internal flows, off for a tank unless asked, bad values refused"
