#!/bin/sh
# `subsection contact` and a permeable barrier (`geometry/walls/fluid passes`) in a
# `chipflex run` case (docs/contact.md): a free rigid box (2500 kg/m^3, 30 x 8 mm)
# dropped into 6 cm of water sinks and comes to rest flat on a barrier across the tank at
# y = 25 mm, which the water passes: its centre ends at 25 + 4 mm, so its probe falls
# 46 mm (within 0.5 mm: the contact overlap is ~0.1 mm, a box that fell through would
# fall to the floor, 71 mm). Then bad keys give one error line and exit 2.
#   usage: contact_case.sh CHIPFLEX
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
write_case() { # $1: fluid passes, $2: contact enabled, $3: restitution
  cat > "$dir/case.prm" <<CASE
set dimension = 2
subsection fluid
  set particle spacing = 0.003
  set gravity = 0, -9.81
end
subsection time
  set end time = 0.4
  set scheme = symplectic
end
subsection output
  set frame interval = 0.1
end
subsection geometry
  set fluid blocks = 0, 0, 0.15, 0.06
  subsection tank
    set min corner = 0, 0
    set max corner = 0.15, 0.12
  end
  subsection walls
    set polylines = 0.15, 0.025, 0, 0.025
    set fluid passes = $1
  end
end
subsection bodies
  set count = 1
  subsection body 1
    set name = box
    set kind = rigid
    set clamped = false
    set size = 0.03, 0.008
    set skin spacing = 0.002
    set density = 2500
    set position = 0.07, 0.075
  end
end
subsection contact
  set enabled = $2
  set restitution = $3
  set friction coefficient = 0.4
end
CASE
}
write_case 1 true 0.3
"$chipflex" run "$dir/case.prm" --out "$dir/out" > "$dir/log" 2>&1 || fail "run: $(tail -3 "$dir/log")"
grep -q "contact: restitution 0.3, friction 0.4" "$dir/log" || fail "no contact line in the log"
tail -1 "$dir/out/box_displacement.csv" | awk -F, '{ d = $3 + 0.046; if (d < 0) d = -d; exit !(d < 5e-4) }' ||
  fail "box rests at dy = $(tail -1 "$dir/out/box_displacement.csv" | cut -d, -f3) m, expected -0.046"
check_error() { # $1: what, $2: expected text
  "$chipflex" run "$dir/case.prm" --out "$dir/bad" > /dev/null 2> "$dir/err"
  rc=$?
  [ $rc -eq 2 ] && [ "$(wc -l < "$dir/err")" -eq 1 ] && grep -q "case.prm" "$dir/err" &&
    grep -q "$2" "$dir/err" || fail "$1: exit $rc, $(cat "$dir/err")"
}
write_case 3 true 0.3
check_error "a missing polyline" "no polyline 3"
write_case 1 false 0.3
check_error "a barrier without contact" "set .enabled = true."
write_case 1 true 0
check_error "restitution 0" "contact/restitution: must lie in (0, 1]"
echo "ok: the box rests on the barrier, dy = $(tail -1 "$dir/out/box_displacement.csv" | cut -d, -f3) m (expected -0.046); bad keys refused"
