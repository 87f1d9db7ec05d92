#!/bin/sh
# `chipflex info BODY.h5 --xdmf OUT.xdmf`: the mesh and mode shapes of a 2D gate and a 3D
# plate open as XDMF (tests/apps/check_outputs.py --body-xdmf: the XML parses, n_nodes x
# 3 nodes, the skin faces as cells, one n_nodes x 3 array per mode equal to the body
# file's psi); `info --help` names the option; a bad path gives one error line, exit 2,
# and no file. Without python3 + h5py: exit 77 (CTest SKIP).
#   usage: info_xdmf.sh CHIPFLEX
chipflex=$1
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
python=$(sh "$(dirname "$0")/../python_with_h5py.sh")
[ -n "$python" ] || { echo "SKIP: python3 with h5py not installed"; exit 77; }

"$chipflex" info --help | grep -q -- "--xdmf OUT.xdmf" || fail "info --help lacks --xdmf"
"$chipflex" mesh gate -o "$dir/gate.msh" > /dev/null || fail "mesh gate"
"$chipflex" reduce "$dir/gate.msh" -o "$dir/gate.h5" --clamp clamp --modes 4 \
  --E 1.2e7 --nu 0.4 --rho 1100 --static-modes pressure:xmin > /dev/null || fail "reduce gate"
"$chipflex" mesh plate -o "$dir/plate.msh" --length 0.06 --thickness 0.03 --width 0.03 \
  --size 0.01 > /dev/null || fail "mesh plate"
"$chipflex" reduce "$dir/plate.msh" -o "$dir/plate.h5" --clamp clamp --modes 3 \
  --E 1.2e7 --nu 0.4 --rho 1100 > /dev/null || fail "reduce plate"
mkdir "$dir/view"
for body in gate plate; do
  "$chipflex" info "$dir/$body.h5" --xdmf "$dir/view/$body.xdmf" > "$dir/$body.log" 2>&1 ||
    fail "info $body --xdmf: $(cat "$dir/$body.log")"
  grep -q "written .*$body.xdmf" "$dir/$body.log" || fail "info $body: no 'written' line"
  "$python" "$here/check_outputs.py" --body-xdmf "$dir/view/$body.xdmf" "$dir/$body.h5" ||
    fail "$body.xdmf"
done
# --json stays one JSON object with --xdmf.
"$chipflex" info "$dir/gate.h5" --json --xdmf "$dir/view/json.xdmf" |
  "$python" -c "import json, sys; json.load(sys.stdin)" || fail "info --json --xdmf: not JSON"

# bad PATH NEEDLE: one line on stderr naming the path, exit 2, nothing written.
bad() {
  "$chipflex" info "$dir/gate.h5" --xdmf "$1" > "$dir/out" 2> "$dir/err"
  rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l < "$dir/err")" -eq 1 ] && grep -q -- "$2" "$dir/err" ||
    fail "--xdmf $1: exit $rc, stderr: $(cat "$dir/err")"
  [ ! -s "$dir/out" ] || fail "--xdmf $1: printed a summary: $(head -1 "$dir/out")"
  echo "ok: $(cat "$dir/err")"
}
bad "$dir/missing/gate.xdmf" "no folder"
bad "$dir/view/gate.vtu" "ending in .xdmf"
mkdir "$dir/view/folder.xdmf"
bad "$dir/view/folder.xdmf" "is a folder"
[ ! -e "$dir/view/folder.modes.h5" ] || fail "a folder as OUT.xdmf left folder.modes.h5"
ls "$dir/missing" > /dev/null 2>&1 && fail "a bad path created a folder"
[ ! -e "$dir/view/gate.vtu" ] && [ ! -e "$dir/view/gate.modes.h5.vtu" ] || fail "a bad path left a file"
echo "ok: info --xdmf for a 2D gate and a 3D plate"
