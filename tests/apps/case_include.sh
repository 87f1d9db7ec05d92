#!/bin/sh
# `include FILE` in a case file: FILE is read relative to the including case file (not the
# working folder), a key set after the include overrides the included value, the body
# subsections of an included file count, and a missing file or an include inside an
# included file is refused in one line naming the file and line, before any output.
# Also checks scripts/flatten_case.sh, which the gate scripts use to edit included keys.
#   usage: case_include.sh CHIPFLEX SOURCE_DIR
chipflex=$1
src=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
mkdir -p "$dir/cases" "$dir/elsewhere"
cp "$src/cases/hydrostatic_tank_2d.prm" "$dir/cases/tank.prm"
# The including case sets the end time again, and adds a body in an included file.
cat > "$dir/cases/body.prm" <<'BODY'
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
cat > "$dir/cases/main.prm" <<'CASE'
include tank.prm
subsection time
  set end time = 0.002
end
CASE
# The tank names the Verlet scheme, which a case with bodies may not use.
printf 'subsection time\n  set scheme = automatic\nend\ninclude body.prm\n' |
  cat "$dir/cases/main.prm" - > "$dir/cases/with_body.prm"
cd "$dir/elsewhere" || fail "no folder"
"$chipflex" run ../cases/main.prm --out main > main.log 2>&1 || fail "main.prm: $(tail -2 main.log)"
grep -q "^finished at t = 0.002" main.log || fail "the end time set after the include did not count: $(tail -1 main.log)"
# with_body.prm includes two files; a body counts from an included file.
"$chipflex" run ../cases/with_body.prm --out body > body.log 2>&1 ||
  fail "with_body.prm: $(tail -2 body.log)"
grep -q "body 'body1': rigid" body.log || fail "the included body is missing: $(grep body body.log)"
# The flattened case is the same case.
"$src/scripts/flatten_case.sh" ../cases/main.prm > flat.prm || fail "flatten_case.sh"
grep -q '^include' flat.prm && fail "flatten_case.sh left an include"
"$chipflex" run flat.prm --out flat > flat.log 2>&1 || fail "flat.prm: $(tail -2 flat.log)"
cmp -s main/probes.csv flat/probes.csv || fail "the flattened case runs differently"
# Errors: one line, the file and line, a non-zero exit, no output folder.
printf 'include absent.prm\n' > ../cases/missing.prm
"$chipflex" run ../cases/missing.prm --out missing > missing.log 2>&1 && fail "a missing include ran"
[ "$(wc -l < missing.log)" -eq 1 ] || fail "more than one line: $(cat missing.log)"
grep -q "missing.prm: line 1: include absent.prm: cannot open" missing.log ||
  fail "unclear error: $(cat missing.log)"
printf 'include main.prm\n' > ../cases/nested.prm
"$chipflex" run ../cases/nested.prm --out nested > nested.log 2>&1 && fail "a nested include ran"
grep -q "main.prm: include inside an included file" nested.log || fail "unclear error: $(cat nested.log)"
[ -e missing ] || [ -e nested ] && fail "a refused case left an output folder"
echo "ok: include reads relative to the case, overrides count, errors are one line"
