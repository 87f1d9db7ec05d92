#!/bin/sh
# Failure behaviour of `chipflex run` (issue: restart and failure):
#  1. A run killed with SIGKILL after its first checkpoint and restarted from that
#     checkpoint ends in the same final state as an uninterrupted run (same thread count:
#     the whole probe history, 9 significant digits, identical to the last digit).
#  2. A run whose particles leave the domain stops with exit status 1 and one message
#     naming the step, the time and the particle, and its last good checkpoint stays
#     readable (a restart from it starts).
#   usage: kill_restart_blowup.sh CHIPFLEX
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
[ -n "$KEEP" ] && trap - EXIT && echo "keeping $dir"
fail() { echo "FAIL: $*"; exit 1; }

cat > "$dir/dam.prm" <<'CASE'
set dimension = 2
subsection fluid
  set particle spacing = 0.01
  set gravity          = 0, -9.81
end
subsection time
  set end time = 0.3
end
subsection output
  set frame interval = 0.1
  set probe interval = 0.01
end
subsection geometry
  set fluid blocks = 0, 0, 0.3, 0.4
  subsection tank
    set min corner = 0, 0
    set max corner = 1.0, 0.6
  end
end
subsection probes
  set pressure     = wall: 0.995, 0.02
  set water height = gauge: 0.6, 0
end
CASE

"$chipflex" run "$dir/dam.prm" --out "$dir/full" --threads 2 > "$dir/full.log" 2>&1 ||
  fail "uninterrupted run: $(tail -2 "$dir/full.log")"

"$chipflex" run "$dir/dam.prm" --out "$dir/killed" --threads 2 --checkpoint-every 0.05 \
  > "$dir/killed.log" 2>&1 &
pid=$!
i=0
while [ ! -f "$dir/killed/checkpoint.h5" ] && [ $i -lt 600 ]; do
  sleep 0.1
  i=$((i + 1))
done
kill -9 $pid 2> /dev/null
wait $pid 2> /dev/null
[ -f "$dir/killed/checkpoint.h5" ] || fail "no checkpoint before the kill"
grep -q "^finished" "$dir/killed.log" && echo "note: the run finished before the kill"
cp "$dir/killed/checkpoint.h5" "$dir/first_checkpoint.h5"
"$chipflex" run "$dir/dam.prm" --out "$dir/killed" --threads 2 --restart "$dir/first_checkpoint.h5" \
  > "$dir/restart.log" 2>&1 || fail "restart: $(tail -2 "$dir/restart.log")"
grep -q "restarted from" "$dir/restart.log" || fail "restart did not say so"
tail -1 "$dir/full/probes.csv" > "$dir/a"
tail -1 "$dir/killed/probes.csv" > "$dir/b"
cmp -s "$dir/a" "$dir/b" || fail "final probe rows differ: $(cat "$dir/a") / $(cat "$dir/b")"
[ "$(wc -l < "$dir/full/probes.csv")" -eq "$(wc -l < "$dir/killed/probes.csv")" ] ||
  fail "probe histories differ in length"
cmp -s "$dir/full/probes.csv" "$dir/killed/probes.csv" || fail "probe histories differ"
echo "ok: killed + restarted run ends as the uninterrupted one: $(cat "$dir/a")"

# 2. No tank and a tight domain: the water falls out of it.
cat > "$dir/falls.prm" <<'CASE'
set dimension = 2
subsection fluid
  set particle spacing = 0.01
  set gravity          = 0, -9.81
end
subsection time
  set end time = 1.0
end
subsection geometry
  set domain min   = -0.1, -0.05
  set domain max   = 0.4, 0.5
  set fluid blocks = 0, 0, 0.3, 0.2
  subsection tank
    set enabled = false
  end
end
CASE
"$chipflex" run "$dir/falls.prm" --out "$dir/falls" --threads 2 --checkpoint-every 0.02 \
  > "$dir/falls.out" 2> "$dir/falls.err"
status=$?
[ $status -ne 0 ] || fail "a run whose water leaves the domain exited 0"
grep -i "particle" "$dir/falls.err" | grep -i "step" | grep -q -i "t = \|time" ||
  fail "the failure message does not name particle, step and time: $(cat "$dir/falls.err")"
[ -f "$dir/falls/checkpoint.h5" ] || fail "the last good checkpoint is gone"
"$chipflex" run "$dir/falls.prm" --out "$dir/falls_again" --threads 2 \
  --restart "$dir/falls/checkpoint.h5" --end-time 0.001 > "$dir/again.log" 2>&1
grep -q "restarted from" "$dir/again.log" || fail "the kept checkpoint cannot be restarted: $(cat "$dir/again.log")"
echo "ok: blow-up stops with: $(head -1 "$dir/falls.err")"

# 3. A few stray particles (a 2 x 2 droplet beside the tank, with no floor under it) fall
#    out of the domain: they are removed and counted, the run goes on to its end, and a
#    run restarted from a checkpoint written after the removals ends bitwise as the
#    uninterrupted one.
cat > "$dir/stray.prm" <<'CASE'
set dimension = 2
subsection fluid
  set particle spacing = 0.01
  set gravity          = 0, -9.81
  set sound coefficient = 10
end
subsection time
  set end time = 0.4
end
subsection output
  set frame interval = 0.1
  set probe interval = 0.01
end
subsection geometry
  set domain min   = -0.1, -0.1
  set domain max   = 0.8, 0.5
  set fluid blocks = 0, 0, 0.3, 0.2; 0.6, 0.3, 0.62, 0.32
  subsection tank
    set min corner = 0, 0
    set max corner = 0.3, 0.3
  end
end
CASE
"$chipflex" run "$dir/stray.prm" --out "$dir/stray" --threads 2 > "$dir/stray.log" 2>&1 ||
  fail "a run losing 4 of 604 particles stopped: $(tail -2 "$dir/stray.log")"
[ "$(grep -c '^removed: .*left the domain box' "$dir/stray.log")" -eq 4 ] ||
  fail "expected 4 removals in the log: $(grep removed "$dir/stray.log")"
grep -q "lost_particles=4 " "$dir/stray.log" || fail "the final line does not count 4 lost particles"
[ "$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "lost_particles") c = i; next }
              END { print $c }' "$dir/stray/probes.csv")" = 4 ] ||
  fail "probes.csv does not count the lost particles: $(tail -1 "$dir/stray/probes.csv")"
"$chipflex" run "$dir/stray.prm" --out "$dir/stray_part" --threads 2 --end-time 0.35 \
  --checkpoint-every 0.35 > "$dir/stray_part.log" 2>&1 || fail "run to 0.35 s failed"
"$chipflex" run "$dir/stray.prm" --out "$dir/stray_part" --threads 1 \
  --restart "$dir/stray_part/checkpoint.h5" > "$dir/stray_restart.log" 2>&1 ||
  fail "restart after removals: $(tail -2 "$dir/stray_restart.log")"
grep -q "lost_particles=4 " "$dir/stray_restart.log" || fail "the restarted run lost its count"
cmp -s "$dir/stray/probes.csv" "$dir/stray_part/probes.csv" ||
  fail "restart after removals differs: $(tail -1 "$dir/stray/probes.csv") / $(tail -1 "$dir/stray_part/probes.csv")"
echo "ok: 4 stray particles removed and counted; restart after the removals is bitwise: $(tail -1 "$dir/stray/probes.csv")"
