#!/bin/sh
# `chipflex export fmu` on a reduced elastic gate (clamped, 6 modes): the FMU is a zip with
# modelDescription.xml, binaries/linux64/chipflex_body.so and resources/body.h5 (the body
# file byte for byte); exporting twice gives the same bytes (same GUID). Run by the test's
# FMI master under a step tip load, its |q| and energies equal `chipflex simulate
# --clamped` at equal steps to 1e-9 of their largest value (simulate writes 12 digits, so
# the difference seen is ~1e-12; the same integrator on the same equations). Bad input: a
# file that is not a body file, a bad model identifier: one error line, exit 2, no FMU.
# The FMU repacked with deflate (python3's zipfile) runs the same.
# `chipflex export sid` of the same body: the SID layout's frame (one node per FE node, or
# per node of --nodes SET), and an unknown node set refused.
#   usage: export_gate.sh CHIPFLEX FMU_STEP_RESPONSE
chipflex=$1
master=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$chipflex" mesh gate -o "$dir/gate.msh" > /dev/null || fail "mesh"
"$chipflex" reduce "$dir/gate.msh" -o "$dir/gate.h5" --clamp clamp --modes 6 \
  --E 1.2e7 --nu 0.4 --rho 1100 > /dev/null 2>&1 ||
  fail "reduce"
"$chipflex" export fmu "$dir/gate.h5" -o "$dir/gate.fmu" > "$dir/log" 2>&1 ||
  fail "export: $(cat "$dir/log")"
grep -q "FMI 2.0 co-simulation, GUID {" "$dir/log" || fail "export summary: $(cat "$dir/log")"
"$chipflex" export fmu "$dir/gate.h5" -o "$dir/again.fmu" > /dev/null || fail "second export"
cmp -s "$dir/gate.fmu" "$dir/again.fmu" || fail "two exports of one body differ"

end=0.05
dt=1e-4
"$chipflex" simulate "$dir/gate.h5" --clamped --load force:tip:0,-2 --dt $dt --end-time $end \
  -o "$dir/simulate.csv" > /dev/null || fail "simulate"
"$master" "$dir/gate.fmu" "$dir/unpacked" tip 0 -2 $dt $end 1 "$dir/fmu.csv" ||
  fail "the FMU under the step load"
cmp -s "$dir/unpacked/resources/body.h5" "$dir/gate.h5" || fail "resources/body.h5 is not the body file"
[ -f "$dir/unpacked/binaries/linux64/chipflex_body.so" ] || fail "no binaries/linux64/chipflex_body.so"
grep -q 'fmiVersion="2.0"' "$dir/unpacked/modelDescription.xml" || fail "modelDescription.xml"
# simulate: time_s,load_factor,frame_x,frame_y,angle,px,py,q_norm,kinetic_J,strain_J
# fmu:      time_s,q_norm,kinetic_J,strain_J
paste -d, "$dir/simulate.csv" "$dir/fmu.csv" | awk -F, 'NR > 1 {
    if ($1 - $11 > 1e-12 || $11 - $1 > 1e-12) { print "times " $1 " " $11; bad = 1 }
    for (k = 0; k < 3; ++k) { a = $(8 + k); b = $(12 + k); d = a - b; if (d < 0) d = -d
      if (d > dmax[k]) dmax[k] = d; if (a < 0) a = -a; if (a > amax[k]) amax[k] = a }
    n++ }
  END { for (k = 0; k < 3; ++k) { r = dmax[k] / amax[k]; printf "relative difference %s %.3e\n", (k == 0 ? "q_norm" : k == 1 ? "kinetic" : "strain"), r
          if (!(amax[k] > 0) || r > 1e-9) bad = 1 }
        if (n != 501) { print "rows " n; bad = 1 } exit bad }' > "$dir/diff" ||
  fail "FMU against chipflex simulate: $(cat "$dir/diff")"

# The same FMU repacked with deflate (as most zip tools and FMU exporters write it), where
# python3 is at hand: the same response, bit for bit.
if command -v python3 > /dev/null; then
  python3 -c 'import sys, zipfile
src = zipfile.ZipFile(sys.argv[1])
with zipfile.ZipFile(sys.argv[2], "w", zipfile.ZIP_DEFLATED) as dst:
    for i in src.infolist(): dst.writestr(i.filename, src.read(i.filename))' "$dir/gate.fmu" "$dir/deflated.fmu" ||
    fail "repacking with python3"
  "$master" "$dir/deflated.fmu" "$dir/unpacked_deflated" tip 0 -2 $dt $end 1 "$dir/deflated.csv" ||
    fail "the deflated FMU"
  cmp -s "$dir/fmu.csv" "$dir/deflated.csv" || fail "the deflated FMU responds differently"
fi

printf 'not a body file' > "$dir/bad.h5"
"$chipflex" export fmu "$dir/bad.h5" -o "$dir/bad.fmu" > /dev/null 2> "$dir/err"
rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < "$dir/err")" -eq 1 ] && grep -q "bad.h5" "$dir/err" ||
  fail "bad body: exit $rc, $(cat "$dir/err")"
[ ! -e "$dir/bad.fmu" ] || fail "a failed export left its output"
cp "$dir/err" "$dir/bad_body_err"
"$chipflex" export fmu "$dir/gate.h5" -o "$dir/bad.fmu" --model-identifier 9x > /dev/null 2> "$dir/err"
rc=$?
[ $rc -eq 2 ] && grep -q "model-identifier" "$dir/err" || fail "bad identifier: exit $rc, $(cat "$dir/err")"
[ ! -e "$dir/bad.fmu" ] || fail "a failed export left its output"
"$chipflex" export sid "$dir/gate.h5" -o "$dir/gate.SID_FEM" > /dev/null || fail "export sid"
head -3 "$dir/gate.SID_FEM" | tr '\n' ' ' | grep -q "^part new modal refmod" || fail "SID header"
nodes=$(grep -c "^new node" "$dir/gate.SID_FEM")
[ "$nodes" -eq 1161 ] || fail "SID has $nodes nodes, not 1161"
"$chipflex" export sid "$dir/gate.h5" -o "$dir/tip.SID_FEM" --nodes tip > /dev/null || fail "export sid --nodes"
[ "$(grep -c "^new node" "$dir/tip.SID_FEM")" -eq 9 ] || fail "SID of the tip set"
"$chipflex" export sid "$dir/gate.h5" -o "$dir/bad.SID_FEM" --nodes nowhere > /dev/null 2> "$dir/err"
rc=$?
[ $rc -eq 2 ] && grep -q "nowhere" "$dir/err" && [ ! -e "$dir/bad.SID_FEM" ] || fail "bad SID node set: exit $rc"
echo "ok: FMU vs chipflex simulate: $(tr '\n' ' ' < "$dir/diff"); bad body: $(cat "$dir/bad_body_err")"
