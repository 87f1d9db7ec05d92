#!/bin/sh
# The time scheme a case gets when it names none (`time/scheme = automatic`): Verlet for a
# fluid alone, position Verlet for a case with bodies (the coupling's momentum exchange is
# exact only with the symplectic schemes; docs/coupling.md); a case with bodies that asks
# for Verlet explicitly is refused with one line naming the key.
#   usage: time_scheme.sh CHIPFLEX SOURCE_DIR
chipflex=$1
tank=$2/cases/hydrostatic_tank_2d.prm
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

sed '/set scheme/d' "$tank" > "$dir/fluid.prm"
cat "$dir/fluid.prm" - > "$dir/body.prm" <<'BODY'
subsection bodies
  subsection body 1
    set kind     = rigid
    set shape    = box
    set size     = 0.1, 0.05
    set density  = 500
    set position = 0.2, 0.35
    set clamped  = false
  end
end
BODY
sed 's/^subsection time$/subsection time\n  set scheme = verlet/' "$dir/body.prm" > "$dir/verlet_body.prm"

"$chipflex" run "$dir/fluid.prm" --out "$dir/fluid" --end-time 0.002 > "$dir/fluid.log" 2>&1 ||
  fail "fluid alone: $(tail -2 "$dir/fluid.log")"
grep -q "scheme verlet$" "$dir/fluid.log" || fail "fluid alone: not Verlet: $(head -1 "$dir/fluid.log")"
"$chipflex" run "$dir/body.prm" --out "$dir/body" --end-time 0.002 > "$dir/body.log" 2>&1 ||
  fail "with a body: $(tail -2 "$dir/body.log")"
grep -q "scheme position verlet$" "$dir/body.log" ||
  fail "with a body: not position Verlet: $(head -1 "$dir/body.log")"
"$chipflex" run "$dir/verlet_body.prm" --out "$dir/verlet_body" > "$dir/verlet.out" 2> "$dir/verlet.err"
[ $? -eq 2 ] || fail "Verlet with a body: not exit status 2"
[ "$(wc -l < "$dir/verlet.err")" -eq 1 ] && grep -q "verlet_body.prm: time/scheme" "$dir/verlet.err" ||
  fail "Verlet with a body: $(cat "$dir/verlet.err")"
echo "ok: a fluid alone runs Verlet, a case with a body position Verlet; $(cat "$dir/verlet.err")"
