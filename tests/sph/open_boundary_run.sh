#!/bin/sh
# `chipflex run` with open boundaries (docs/sph.md, "Open boundaries"), on the shipped
# cases/channel_2d.prm cut short:
#  1. the run writes the zones' columns to probes.csv and inflow/outflow to summary.txt;
#  2. a run restarted from a checkpoint (written after creations and removals) ends with
#     the same probe history as the uninterrupted one, to the last digit;
#  3. bad open-boundary keys give one line naming the key and exit status 2;
#  4. the continuity check: the steady channel is not torn, a channel that drains is (with
#     a background pressure the warning states the pressure error of an even thinning);
#  5. the channel-acoustics warning for a watched frequency near c0 / (4 L).
#   usage: open_boundary_run.sh CHIPFLEX SOURCE_DIR
chipflex=$1
case_file=$2/cases/channel_2d.prm
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$chipflex" run "$case_file" --out "$dir/full" --threads 1 --end-time 0.06 > "$dir/full.log" 2>&1 ||
  fail "run: $(tail -2 "$dir/full.log")"
head -1 "$dir/full/probes.csv" | grep -q "inlet_created,inlet_removed,inlet_mass_flow,outlet_created,outlet_removed,outlet_mass_flow,inflow_particles,outflow_particles,lost_particles" ||
  fail "probes.csv header: $(head -1 "$dir/full/probes.csv")"
grep -q "inflow_particles=[1-9][0-9]* outflow_particles=[1-9]" "$dir/full/summary.txt" ||
  fail "summary.txt: $(cat "$dir/full/summary.txt")"
grep -q "^continuity: start_fluid_particles=[1-9].* torn=no$" "$dir/full/summary.txt" ||
  fail "the steady channel: no continuity line or torn: $(cat "$dir/full/summary.txt")"
echo "ok: $(head -1 "$dir/full/summary.txt")"
echo "ok: $(grep '^continuity:' "$dir/full/summary.txt")"

# A channel whose inlet is shut while the fluid runs on to the outlet at 0.3 m/s empties
# from its upstream end (18 % of its length in 0.06 s): the run must say the fluid tore,
# once in the log and as torn=yes in summary.txt; with the warning off it must not.
sed -e '0,/set enabled   = true/s//set enabled   = false/' \
  -e 's/set initial velocity = 0.1, 0/set initial velocity = 0.3, 0/' "$case_file" > "$dir/drain.prm"
"$chipflex" run "$dir/drain.prm" --out "$dir/drain" --threads 1 --end-time 0.06 > "$dir/drain.log" 2>&1 ||
  fail "draining channel: $(tail -2 "$dir/drain.log")"
[ "$(grep -c "warning: the fluid is tearing" "$dir/drain.log")" -eq 1 ] ||
  fail "draining channel: no single tearing warning in the log"
grep -q "^continuity: .* torn=yes$" "$dir/drain/summary.txt" ||
  fail "draining channel: summary.txt does not say torn: $(cat "$dir/drain/summary.txt")"
echo "ok: $(grep "warning: the fluid is tearing" "$dir/drain.log")"
# Under a background pressure the warning also reads the drop as an even thinning and
# states the gauge-pressure error it brings, 2 P x drop (about 100 Pa at 1 kPa and 5 %).
sed 's/^subsection fluid$/subsection fluid\n  set background pressure = 1000/' "$dir/drain.prm" \
  > "$dir/drain_p.prm"
"$chipflex" run "$dir/drain_p.prm" --out "$dir/drain_p" --threads 1 --end-time 0.06 \
  > "$dir/drain_p.log" 2>&1 || fail "draining channel at 1 kPa: $(tail -2 "$dir/drain_p.log")"
grep -q "warning: the fluid is tearing: .*background pressure of 1000 Pa.* by about 1[0-9][0-9] Pa" \
  "$dir/drain_p.log" || fail "draining channel at 1 kPa: $(grep tearing "$dir/drain_p.log")"
echo "ok: $(grep "warning: the fluid is tearing" "$dir/drain_p.log")"
sed 's/^subsection open boundaries$/subsection open boundaries\n  set tear warning fraction = 1/' \
  "$dir/drain.prm" > "$dir/drain_off.prm"
"$chipflex" run "$dir/drain_off.prm" --out "$dir/drain_off" --threads 1 --end-time 0.06 \
  > "$dir/drain_off.log" 2>&1 || fail "draining channel, warning off: $(tail -2 "$dir/drain_off.log")"
! grep -q "tearing" "$dir/drain_off.log" && grep -q "torn=no$" "$dir/drain_off/summary.txt" ||
  fail "draining channel with the warning off still warns"

"$chipflex" run "$case_file" --out "$dir/part" --threads 1 --end-time 0.03 --checkpoint-every 0.03 \
  > "$dir/part.log" 2>&1 || fail "run to 0.03 s: $(tail -2 "$dir/part.log")"
"$chipflex" run "$case_file" --out "$dir/part" --threads 2 --end-time 0.06 \
  --restart "$dir/part/checkpoint.h5" > "$dir/restart.log" 2>&1 ||
  fail "restart: $(tail -2 "$dir/restart.log")"
grep -q "restarted from" "$dir/restart.log" || fail "restart did not say so"
cmp -s "$dir/full/probes.csv" "$dir/part/probes.csv" ||
  fail "restarted run differs: $(tail -1 "$dir/full/probes.csv") / $(tail -1 "$dir/part/probes.csv")"
echo "ok: restart with open boundaries is bitwise: $(tail -1 "$dir/part/probes.csv")"

# Channel acoustics: c0 = 4 m/s over L = 0.1 m rings at c0 / (4 L) = 10 Hz; a watched
# frequency within a factor of 3 of it draws a warning, one further away does not.
for f in 25 40; do
  sed "s/^subsection open boundaries$/subsection open boundaries\n  set watched frequencies = $f/" \
    "$case_file" > "$dir/watch_$f.prm"
  "$chipflex" run "$dir/watch_$f.prm" --out "$dir/watch_$f" --threads 1 --end-time 0.001 \
    > "$dir/watch_$f.log" 2>&1 || fail "watched frequency $f Hz: $(tail -2 "$dir/watch_$f.log")"
done
grep -q "warning: the channel's acoustic frequency c0 / (4 L) = 10 Hz.* 25 Hz" "$dir/watch_25.log" ||
  fail "no acoustic warning for 25 Hz against 10 Hz"
! grep -q "acoustic" "$dir/watch_40.log" || fail "an acoustic warning for 40 Hz against 10 Hz"
echo "ok: $(grep "acoustic frequency" "$dir/watch_25.log")"

sed 's/set velocity  = 0.1/set velocity  = 0.1\n    set flow rate = 0.002/' "$case_file" > "$dir/both.prm"
"$chipflex" run "$dir/both.prm" --out "$dir/both" > "$dir/both.out" 2> "$dir/both.err"
[ $? -eq 2 ] || fail "velocity and flow rate together: not exit status 2"
[ "$(wc -l < "$dir/both.err")" -eq 1 ] && grep -q "open boundaries/inlet" "$dir/both.err" ||
  fail "velocity and flow rate together: $(cat "$dir/both.err")"
sed 's/set layers.*//; s/box min   = -0.004, 0/box min   = -0.002, 0/' "$case_file" > "$dir/thin.prm"
"$chipflex" run "$dir/thin.prm" --out "$dir/thin" > "$dir/thin.out" 2> "$dir/thin.err"
[ $? -eq 2 ] && grep -q "layers" "$dir/thin.err" || fail "a 2-layer-deep box: $(cat "$dir/thin.err")"
echo "ok: $(cat "$dir/both.err")"
echo "ok: $(cat "$dir/thin.err")"
