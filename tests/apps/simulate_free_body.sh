#!/bin/sh
# `chipflex simulate`: a free-floating reduced gate (no clamp) under a constant total
# force F on its tip node set, no gravity. Newton's second law for the whole body: the
# linear momentum is F t at every step (to 1e-9 relative; the force passes through the
# centre of mass's vertical, so there is no spin), and the frame falls F t^2 / (2 m)
# (1e-6 relative: the elastic modes are mass-orthogonal to the rigid motions). Then a bad
# load history gives one error line, exit 2, and no output file.
#   usage: simulate_free_body.sh CHIPFLEX
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$chipflex" mesh gate -o "$dir/gate.msh" > /dev/null || fail "mesh"
"$chipflex" reduce "$dir/gate.msh" -o "$dir/free.h5" --modes 6 --E 1.2e7 --nu 0.4 --rho 1100 > /dev/null ||
  fail "reduce"
mass=$("$chipflex" info "$dir/free.h5" --json | sed -n 's/.*"mass": *\([0-9.e+-]*\).*/\1/p' | head -1)
[ -n "$mass" ] || fail "info --json gives no mass"
"$chipflex" simulate "$dir/free.h5" --end-time 0.02 --dt 1e-4 --load force:tip:0,-2 \
  -o "$dir/free.csv" > "$dir/log" 2>&1 || fail "simulate: $(cat "$dir/log")"
head -1 "$dir/free.csv" | grep -q "^time_s,load_factor,frame_x_m,frame_y_m,frame_angle_rad,momentum_x_Ns,momentum_y_Ns" ||
  fail "header: $(head -1 "$dir/free.csv")"
awk -F, -v m="$mass" 'NR > 1 {
    t = $1; p = -2 * t; y = -2 * t * t / (2 * m)
    ep = $7 - p; if (ep < 0) ep = -ep; if (ep > 1e-9 * (p < 0 ? -p : p) + 1e-15) { print "momentum at t = " t ": " $7 " against " p; bad = 1 }
    ey = $4 - y; if (ey < 0) ey = -ey; if (ey > 1e-6 * (y < 0 ? -y : y) + 1e-15) { print "frame y at t = " t ": " $4 " against " y; bad = 1 }
    n++ }
  END { if (n != 201) { print "rows: " n; bad = 1 } exit bad }' "$dir/free.csv" ||
  fail "Newton's second law"
printf 'time_s,factor\n0,0\n0.01,1\n0.005,1\n' > "$dir/bad.csv"
"$chipflex" simulate "$dir/free.h5" --end-time 0.02 --load force:tip:0,-2 --history "$dir/bad.csv" \
  -o "$dir/bad_out.csv" > /dev/null 2> "$dir/err"
rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < "$dir/err")" -eq 1 ] && grep -q "bad.csv:4" "$dir/err" ||
  fail "bad history: exit $rc, $(cat "$dir/err")"
[ ! -e "$dir/bad_out.csv" ] || fail "a failed simulate left its output"
echo "ok: free body momentum F t to 1e-9 and fall F t^2/(2m) to 1e-6 (m = $mass kg/m); bad history: $(cat "$dir/err")"
