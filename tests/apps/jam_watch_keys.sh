#!/bin/sh
# `probes/jam watch` (apps/jam_watch.h) on the 2D drill flute: a reference measured over a
# window equals the mean of probes.csv's rows in it, a running mean shorter than the
# channel's acoustic period is warned about, `stop after` ends the run after the jam, and
# bad keys (a gauge the case lacks, a
# missing reference window, a reference that is not positive) give one line naming the key.
#   usage: jam_watch_keys.sh CHIPFLEX SOURCE_DIR
chipflex=$1
flute=$2/cases/drill_flute/flute_2d.prm
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
grep -q "set reference pressure = 1740" "$flute" || fail "flute_2d.prm has no jam watch"

# The reference from a window (the rows in 0.4 ... 1 ms), a short running mean.
sed -e 's/^    set reference pressure = 1740$/    set reference pressure =/' \
    -e 's/^    set averaging time     = 0.004$/    set averaging time     = 0.0004\n    set reference window   = 0.0004, 0.001/' \
    -e 's/^    set start time         = 0.006$/    set start time         = 0/' "$flute" > "$dir/window.prm"
"$chipflex" run "$dir/window.prm" --out "$dir/window" --end-time 0.002 > "$dir/window.log" 2>&1 ||
  fail "the window run stopped: $(tail -2 "$dir/window.log")"
grep -q "warning: jam watch: the averaging time 0.0004 s is shorter than the channel's acoustic period" \
  "$dir/window.log" || fail "no warning for a running mean shorter than the acoustic period"
mean=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  $1 >= 0.0004 && $1 <= 0.001 { s += $col["p_tip_Pa"]; n++ } END { printf "%.5g", s / n }' "$dir/window/probes.csv")
ref=$(sed -n 's/^jam: p_tip_Pa_reference=\([^ ]*\) .*/\1/p' "$dir/window/summary.txt")
awk -v a="$mean" -v b="$ref" 'BEGIN { exit !(b > 0 && (a - b) ^ 2 <= (1e-4 * b) ^ 2) }' ||
  fail "the window's reference $ref Pa is not the mean of its probe rows, $mean Pa"

# `stop after`: a reference of 1 Pa makes the start-up's pressure a jam at once (0.4 ms
# mean from t = 0); the run must end, finished, 0.2 ms after it, with its last frame.
sed -e 's/^    set reference pressure = 1740$/    set reference pressure = 1/' \
    -e 's/^    set averaging time     = 0.004$/    set averaging time     = 0.0004\n    set stop after         = 0.0002/' \
    -e 's/^    set start time         = 0.006$/    set start time         = 0/' "$flute" > "$dir/stop.prm"
"$chipflex" run "$dir/stop.prm" --out "$dir/stop" > "$dir/stop.log" 2>&1 ||
  fail "the stop-after run failed: $(tail -2 "$dir/stop.log")"
grep -q "^jam watch: the run ends 0.0002 s after the jam" "$dir/stop.log" || fail "the run did not end after the jam"
awk '/^status=finished/ { for (i = 1; i <= NF; ++i) if ($i ~ /^t_s=/) t = substr($i, 5) }
     /^jam:/ { for (i = 1; i <= NF; ++i) if ($i ~ /^time_to_jam_s=/) j = substr($i, 15) }
     END { exit !(j != "" && t >= j + 0.0002 && t < j + 0.0003) }' "$dir/stop/summary.txt" ||
  fail "not finished 0.2 ms after the jam: $(head -c 200 "$dir/stop/summary.txt")"

# The shipped jam study case starts (its eight parked strips, the source, the watch).
"$chipflex" run "$2/cases/drill_flute/flute_2d_jam_study.prm" --out "$dir/study" --end-time 0.0002 \
  > "$dir/study.log" 2>&1 || fail "flute_2d_jam_study.prm: $(tail -2 "$dir/study.log")"

bad() { # $1: sed script, $2: the key the error must name
  sed "$1" "$flute" > "$dir/bad.prm"
  if "$chipflex" run "$dir/bad.prm" --out "$dir/bad" --end-time 0.0001 > "$dir/bad.log" 2>&1; then
    fail "accepted: $1"
  fi
  [ "$(wc -l < "$dir/bad.log")" -le 2 ] || fail "more than one line for $1: $(cat "$dir/bad.log")"
  grep -q "$2" "$dir/bad.log" || fail "the error does not name $2: $(cat "$dir/bad.log")"
}
bad 's/^    set pressure gauge     = tip$/    set pressure gauge     = nose/' "probes/jam watch/pressure gauge: 'nose'"
bad 's/^    set flow gauge         = barrier$/    set flow gauge         = gap/' "probes/jam watch/flow gauge: 'gap'"
bad 's/^    set reference pressure = 1740$/    set reference pressure =/' "probes/jam watch/reference window"
bad 's/^    set reference pressure = 1740$/    set reference pressure = -5/' "probes/jam watch/reference pressure"
bad 's/^    set averaging time     = 0.004$/    set stop after = -1/' "probes/jam watch/stop after"
echo "ok: the window's reference $ref Pa (probe rows: $mean Pa); bad keys refused"
