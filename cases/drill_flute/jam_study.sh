#!/bin/sh
# When does the 2D flute jam? flute_2d_jam_study.prm (a chip source with a pool of eight
# strips) run once per release interval; prints each run's time to jam and the largest
# loss coefficient its tip pressure reached (summary.txt's `jam:` line; docs/drill_flute.md,
# "When the flute jams").
#   jam_study.sh OUT [INTERVALS (s, default "0.0015 0.003 0.006 0.012"; 0.189 is one chip per
#   revolution of the scaled drill)]
# CHIPFLEX (default build/bin/chipflex), THREADS (default 1 per run; two runs at a time).
set -e
[ $# -ge 1 ] || { sed -n '2,9p' "$0" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
chipflex=${CHIPFLEX:-$here/../../build/bin/chipflex}
out=$1
intervals=${2:-0.0015 0.003 0.006 0.012}
mkdir -p "$out"
cp "$here/flute_2d.prm" "$out/"
run() {
  # Long enough for the first release and four more (the flute has jammed on three strips
  # in every run so far); the jam watch stops the run 5 ms after the jam.
  end=$(awk -v i="$1" 'BEGIN { e = 0.001 + 4 * i + 0.03; printf "%.6g", (e > 0.06 ? e : 0.06) }')
  sed -e "s|^    set interval      = .*|    set interval      = $1|" \
      -e "s|^  set end time = .*|  set end time = $end|" "$here/flute_2d_jam_study.prm" \
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
# The tip's loss coefficient against time, as the jam watch sees it (the trailing mean of
# p_tip over its averaging time, divided by its reference): OUT/interval_I/zeta.csv per run and OUT/jam_study.png.
plot=""
for i in $intervals; do
  d=$out/interval_$i
  [ -f "$d/probes.csv" ] || continue
  ref=$(sed -n 's/^jam: p_tip_Pa_reference=\([^ ]*\).*/\1/p' "$d/summary.txt")
  window=$(sed -n 's/^jam: .* averaging_s=\([^ ]*\).*/\1/p' "$d/summary.txt")
  awk -F, -v ref="${ref:-1740}" -v window="${window:-0.004}" '
    NR == 1 { for (k = 1; k <= NF; ++k) col[$k] = k; first = 2
              print "time_s,zeta_mean,q_barrier_m2_s"; next }
    { t[NR] = $col["time_s"]; p[NR] = $col["p_tip_Pa"]; sum += p[NR]
      while (t[NR] - t[first] > window) { sum -= p[first]; delete t[first]; delete p[first]; ++first }
      printf "%s,%.4f,%s\n", t[NR], sum / (NR - first + 1) / ref, $col["q_barrier_m2_s"] }
  ' "$d/probes.csv" > "$d/zeta.csv.tmp" && mv "$d/zeta.csv.tmp" "$d/zeta.csv"
  plot="$plot${plot:+, }'$d/zeta.csv' using (\$1*1000):2 with lines title 'a chip every $i s'"
done
if [ -n "$plot" ] && command -v gnuplot > /dev/null; then
  gnuplot <<GNUPLOT
set terminal pngcairo size 900,500
set output '$out/jam_study.png.tmp'
set datafile separator ','
set key top left
set xlabel 'time (ms)'
set ylabel 'tip loss coefficient zeta (4 ms mean)'
set yrange [-5:*]
plot $plot, 4 with lines dashtype 2 lc rgb 'black' title 'jam (zeta = 4)'
GNUPLOT
  mv "$out/jam_study.png.tmp" "$out/jam_study.png"
fi
