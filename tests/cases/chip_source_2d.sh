#!/bin/sh
# The chip source (coupling/chip_source.h) in `chipflex run`, on the 2D drill flute with
# its chips produced as the drill cuts (cases/drill_flute/flute_2d_chip_source.prm) and the
# barrier taken out, so that the chips leave through the top. Checks:
#   - releases come every 3 ms from 1 ms: by 24 ms, 8 are due (released + skipped = 8);
#   - chips leave: a chip whose centre passes x = 28 mm is removed and counted, and its
#     body is released again as a later chip (a chip number above the pool's 3 appears);
#   - no chip goes past the outlet (x < 31.6 mm) and none is lost;
#   - a restart from the checkpoint at 12 ms continues bitwise as the uninterrupted run
#     (its probe rows after 12 ms, with four releases and chips leaving, are identical):
#     the pool's parked and released chips are part of the checkpoint;
#   - without the barrier the chips pass: the jam watch (apps/jam_watch.h) reports no jam
#     (measured: the tip's running mean at most -0.06 of the dynamic pressure, against 4
#     for a jam and 8 with the barrier), and its line and the mass balance (residual 0) of
#     the restarted run equal the uninterrupted run's.
#   usage: chip_source_2d.sh CHIPFLEX
chipflex=$1
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cp "$here/../../cases/drill_flute/flute_2d.prm" "$dir/"
cat "$here/../../cases/drill_flute/flute_2d_chip_source.prm" - > "$dir/case.prm" <<'CASE'
subsection geometry
  subsection walls
    set polylines    =
    set fluid passes =
  end
end
CASE
"$chipflex" run "$dir/case.prm" --out "$dir/full" --threads 1 --end-time 0.024 \
  --checkpoint-every 0.012 > "$dir/full.log" 2>&1 || fail "the run stopped: $(tail -3 "$dir/full.log")"
grep '^summary: chip_source' "$dir/full.log" || fail "no chip source summary"
awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
  { for (c = 1; c <= 3; ++c) { x = $col["chip" c "_x_m"]; if (x > 0.0316) { printf "FAIL: chip%d at x = %.4f m at t = %s s\n", c, x, $1; bad = 1 }
      if ($col["chip" c "_chip"] > top) top = $col["chip" c "_chip"] }
    released = $col["chips_released"]; removed = $col["chips_removed"]; skipped = $col["chips_skipped"] }
  END { if (bad) exit 1
        printf "released %d, removed %d, skipped %d, highest chip number %d\n", released, removed, skipped, top
        if (released + skipped != 8) { print "FAIL: 8 releases are due by 24 ms"; exit 1 }
        if (removed < 1) { print "FAIL: no chip left through the exit plane"; exit 1 }
        if (top <= 3) { print "FAIL: no pool body was released a second time"; exit 1 } }
' "$dir/full/probes.csv" || exit 1
grep -q 'lost_particles=0 ' "$dir/full.log" || fail "fluid particles were lost"
grep -q '^jam: .* jammed=no' "$dir/full/summary.txt" ||
  fail "the jam watch saw a jam without the barrier: $(grep '^jam:' "$dir/full/summary.txt")"
grep -q '^mass_balance: .* residual_particles=0$' "$dir/full/summary.txt" ||
  fail "the fluid's mass does not balance: $(grep '^mass_balance:' "$dir/full/summary.txt")"
# The restart: the checkpoint of 12 ms lies in a second folder, continued to 24 ms.
"$chipflex" run "$dir/case.prm" --out "$dir/first" --threads 1 --end-time 0.012 \
  --checkpoint-every 0.012 \
  > "$dir/first.log" 2>&1 || fail "the first half stopped: $(tail -3 "$dir/first.log")"
"$chipflex" run "$dir/case.prm" --out "$dir/second" --threads 1 --end-time 0.024 \
  --restart "$dir/first/checkpoint.h5" > "$dir/second.log" 2>&1 ||
  fail "the restart stopped: $(tail -3 "$dir/second.log")"
# The restarted probes.csv holds the rows after the checkpoint: the uninterrupted run's last ones.
rows=$(($(wc -l < "$dir/second/probes.csv") - 1))
[ "$rows" -gt 10 ] || fail "the restarted run wrote $rows probe rows"
tail -n "$rows" "$dir/full/probes.csv" > "$dir/full_tail.csv"
tail -n "$rows" "$dir/second/probes.csv" > "$dir/second_tail.csv"
cmp "$dir/full_tail.csv" "$dir/second_tail.csv" ||
  fail "the restarted run's probes differ from the uninterrupted run's"
for line in jam mass_balance continuity; do
  [ "$(grep "^$line:" "$dir/full/summary.txt")" = "$(grep "^$line:" "$dir/second/summary.txt")" ] ||
    fail "the restarted run's $line line differs: $(grep "^$line:" "$dir/second/summary.txt")"
done
echo "restart from 12 ms: the $rows probe rows after it identical"
