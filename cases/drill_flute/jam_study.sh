#!/bin/sh
# When does the 2D flute jam? flute_2d_jam_study.prm (a chip source with a pool of eight
# strips) run once per release interval; prints each run's time to jam and the largest
# loss coefficient its tip pressure reached (summary.txt's `jam:` line; docs/drill_flute.md,
# "When the flute jams").
#   jam_study.sh OUT [INTERVALS (s, default "0.0015 0.003 0.006 0.012")]
# CHIPFLEX (default build/bin/chipflex), THREADS (default 1 per run; two runs at a time).
set -e
[ $# -ge 1 ] || { sed -n '2,8p' "$0" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
chipflex=${CHIPFLEX:-$here/../../build/bin/chipflex}
out=$1
intervals=${2:-0.0015 0.003 0.006 0.012}
mkdir -p "$out"
cp "$here/flute_2d.prm" "$out/"
run() {
  sed "s|^    set interval      = .*|    set interval      = $1|" "$here/flute_2d_jam_study.prm" \
    > "$out/jam_study_$1.prm"
  "$chipflex" run "$out/jam_study_$1.prm" --out "$out/interval_$1" --threads "${THREADS:-1}" \
    > "$out/interval_$1.log" 2>&1 || { echo "interval $1 s: the run stopped: $(tail -1 "$out/interval_$1.log")"; return 0; }
}
set -- $intervals
while [ $# -gt 0 ]; do
  run "$1" &
  if [ $# -gt 1 ]; then run "$2" & fi
  wait
  shift; [ $# -gt 0 ] && shift
done
for i in $intervals; do
  awk -v i="$i" '
    /^jam:/ { for (k = 1; k <= NF; ++k) { split($k, kv, "="); v[kv[1]] = kv[2] } }
    /^summary: chip_source/ { for (k = 1; k <= NF; ++k) { split($k, kv, "="); c[kv[1]] = kv[2] } }
    END { printf "jam_study: interval_s=%s jammed=%s time_to_jam_s=%s largest_zeta=%.2f chips_released=%s chips_skipped=%s\n",
                 i, v["jammed"], (v["jammed"] == "yes" ? v["time_to_jam_s"] : "-"), v["p_tip_Pa_largest_ratio"], c["released"], c["skipped"] }
  ' "$out/interval_$i/summary.txt"
done
