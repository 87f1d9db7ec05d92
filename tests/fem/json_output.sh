#!/bin/sh
# The machine-readable outputs scripts rely on: `chipflex info --json` and
# `chipflex compare --json` print one JSON object with the documented keys, and the
# values agree with the body (2D gate: mass = rho t L per metre; 3 elastic modes listed,
# ascending; the compare errors small for a body with the load's static mode: static
# to round-off, transient within 2 %).
#   usage: json_output.sh CHIPFLEX
set -e
chipflex=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$chipflex" mesh gate -o "$dir/gate.msh" --size 0.0025 > /dev/null
"$chipflex" reduce "$dir/gate.msh" -o "$dir/gate.h5" --clamp clamp --modes 3 \
  --E 1.2e7 --nu 0.4 --rho 1100 --static-modes force:tip:1,0 > /dev/null

"$chipflex" info "$dir/gate.h5" --json > "$dir/info.json"
[ "$(wc -l < "$dir/info.json")" -ge 1 ] || fail "info --json printed nothing"
for key in dim mass center_of_mass inertia frequencies_hz mode_kinds n_nodes n_skin_nodes \
           node_sets; do
  grep -q "\"$key\"" "$dir/info.json" || fail "info --json lacks \"$key\": $(cat "$dir/info.json")"
done
grep -q '"dim": *2' "$dir/info.json" || fail "dim is not 2"
# Numbers are the shortest decimals that read back to the same double: the default
# nu = 0.4 and E = 1.2e7 print as such, not as 0.40000000000000002.
grep -q '"poisson_ratio": 0.4,' "$dir/info.json" ||
  fail "poisson_ratio not printed as 0.4: $(grep poisson_ratio "$dir/info.json")"
grep -q '"youngs_modulus": 1.2e+07,' "$dir/info.json" ||
  fail "youngs_modulus not printed as 1.2e+07: $(grep youngs_modulus "$dir/info.json")"
# Mass per metre of the Antoci gate: 1100 kg/m^3 * 0.005 m * 0.079 m = 0.4345 kg/m.
mass=$(sed -n 's/.*"mass": *\([0-9.eE+-]*\).*/\1/p' "$dir/info.json")
awk -v m="$mass" 'BEGIN { exit !(m > 0.43445 && m < 0.43455) }' || fail "mass $mass, expected 0.4345"
# Three normal modes and one static mode, frequencies ascending.
freqs=$(sed -n 's/.*"frequencies_hz": *\[\([^]]*\)\].*/\1/p' "$dir/info.json")
echo "$freqs" | awk -F, '{ if (NF < 3) exit 1; for (i = 2; i <= NF; ++i) if ($i + 0 < $(i - 1) + 0) exit 1 }' ||
  fail "frequencies not ascending or too few: $freqs"

"$chipflex" compare "$dir/gate.msh" "$dir/gate.h5" --load force:tip:1,0 --json > "$dir/compare.json"
for key in static_rel_error transient_rel_error full_seconds reduced_seconds; do
  grep -q "\"$key\"" "$dir/compare.json" || fail "compare --json lacks \"$key\": $(cat "$dir/compare.json")"
done
err=$(sed -n 's/.*"static_rel_error": *\([0-9.eE+-]*\).*/\1/p' "$dir/compare.json")
awk -v e="$err" 'BEGIN { exit !(e < 1e-3) }' || fail "static_rel_error $err with the load's own static mode"
# The clamped reduced body under a step tip load follows the full FE transient (Newmark,
# same step) within 2 % (its 3 normal modes and the load's static mode).
terr=$(sed -n 's/.*"transient_rel_error": *\([0-9.eE+-]*\).*/\1/p' "$dir/compare.json")
awk -v e="$terr" 'BEGIN { exit !(e < 0.02) }' || fail "transient_rel_error $terr above 2 %"
echo "ok: info --json and compare --json (static $err, transient $terr)"
