#!/bin/sh
# The `fmu` body kind: the elastic gate at dp 2 mm for 0.03 s, once with its reduced body
# as a `flexible` body and once exported (`chipflex export fmu`) and coupled as an `fmu`
# body, both from the same linear body file (reduced here without --nonlinear). The FMU
# runs the same body and integrator behind the FMI calls, so the free-end curves must
# agree within 0.1 mm (they agree to the last digit); the gate must have moved (> 1 mm)
# for the comparison to mean anything. Then an `fmu file` that is not an FMU: one error
# line naming it, exit 2. With MPIEXEC the fmu case also runs on 2 MPI ranks (every rank
# steps its own copy of the FMU, unpacked into a folder of its own) and must agree with
# the one-process flexible curve within the same 0.1 mm (the ranks' sums round
# differently, so not to the last digit).
#   usage: fmu_body_gate.sh CHIPFLEX REPO [MPIEXEC]
chipflex=$1
repo=$2
mpiexec=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cd "$dir" || fail "no temporary folder"
"$chipflex" mesh gate -o gate.msh > /dev/null || fail "mesh"
"$chipflex" reduce gate.msh -o gate.h5 --clamp clamp --modes 8 --static-modes pressure:xmin \
  --E 1.2e7 --nu 0.4 --rho 1100 \
  > /dev/null 2>&1 || fail "reduce"
"$chipflex" export fmu gate.h5 -o gate.fmu > /dev/null || fail "export fmu"
"$repo/scripts/flatten_case.sh" "$repo/cases/elastic_gate/flexible.prm" |
  sed -e "s|^\(  set particle spacing *=\).*|\1 0.002|" -e "s|^\(  set end time *=\).*|\1 0.03|" \
    -e "s|^\(  set reference *=\).*|\1 $repo/data/antoci2007/experiment_merged.csv|" \
    > flexible.prm
sed -e "s|^\(    set kind *=\).*|\1 fmu|" -e "s|^    set body file *=.*|    set fmu file = gate.fmu|" \
    flexible.prm > fmu.prm
grep -q "set kind *= fmu" fmu.prm && grep -q "set fmu file = gate.fmu" fmu.prm || fail "fmu.prm"
for v in flexible fmu; do
  "$chipflex" run $v.prm --out $v > $v.log 2>&1 || { tail -3 $v.log; fail "run $v"; }
  grep -q "kind=$v" $v.log || fail "$v: no summary of kind $v"
done
compare() { # compare RUN_A RUN_B: the free-end curves
paste -d, "$1/gate_displacement.csv" "$2/gate_displacement.csv" | awk -F, 'NR > 1 {
    n++; if ($1 != $4) { print "time " $1 " against " $4; bad = 1 }
    dx = $2 - $5; dy = $3 - $6; if (dx < 0) dx = -dx; if (dy < 0) dy = -dy
    if (dx > mx) mx = dx; if (dy > my) my = dy
    a = $2 < 0 ? -$2 : $2; if (a > moved) moved = a }
  END { printf "rows %d, max |dx| difference %.3g mm, |dy| %.3g mm, largest dx %.2f mm\n", n, 1000 * mx, 1000 * my, 1000 * moved
        exit bad || n < 100 || mx > 1e-4 || my > 1e-4 || moved < 1e-3 }'
}
compare flexible fmu > diff.txt || fail "free-end curves: $(cat diff.txt)"
if [ -n "$mpiexec" ]; then
  "$mpiexec" -np 2 "$chipflex" run fmu.prm --out fmu_np2 --threads 1 > fmu_np2.log 2>&1 ||
    { tail -3 fmu_np2.log; fail "run fmu on 2 ranks"; }
  compare flexible fmu_np2 > diff_np2.txt || fail "free-end curves, 2 ranks: $(cat diff_np2.txt)"
  echo "flexible vs fmu on 2 ranks: $(cat diff_np2.txt)"
fi
sed -e "s|set fmu file = gate.fmu|set fmu file = gate.h5|" fmu.prm > bad.prm
"$chipflex" run bad.prm --out bad > /dev/null 2> err.txt
rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q "gate.h5" err.txt ||
  fail "not an FMU: exit $rc, $(cat err.txt)"
echo "ok: flexible vs fmu: $(cat diff.txt); not an FMU: $(cat err.txt)"
