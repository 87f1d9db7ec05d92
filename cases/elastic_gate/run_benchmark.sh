#!/bin/sh
# The elastic-gate benchmark (Antoci, Gallati & Sibilla 2007): meshes and reduces the
# gate once, runs every variant, prints each run's summary line (wall time, lost particles,
# peak fluid speed), draws OUT/elastic_gate.png and prints each run's RMS dx / dy against
# the experiment (`rms: run=VARIANT ...`, from chipflex plot).
#
#   cases/elastic_gate/run_benchmark.sh OUT [DP_MM] [VARIANT ...]
#     DP_MM    fluid particle spacing in mm (default 1; the SPH solid keeps Table 1's 1 mm)
#     VARIANT  flexible fe chain1 chain2 chain3 sph_solid (default: all; fe is the
#              full nonlinear FE gate, minutes per run at dp 2 mm), or
#              flexible_sphinxsys fe_sphinxsys sph_solid_sphinxsys (SPHinXsys' gate material,
#              7.8 MPa, nu 0.47, weightless, observer at the downstream lower corner); a variant may
#              carry modifiers, each ':NAME': ':noweight' / ':weight' (the gate's own weight
#              off / on), ':gap' (the gate lifted GAP_MM off the floor, the wall above with
#              it), ':dummy' / ':lj' / ':thin' (the gate's wall model: dummy particles / Lennard-Jones / thin skin),
#              ':ljthin' (the gate's Lennard-Jones wall with half its reach: r0 = dp/4, R = dp/2),
#              ':uncorrected' (sph solid: the seed's GMS-2001 solid); its run folder is the
#              name with '_' for ':'.
#   Environment: CHIPFLEX (default build/bin/chipflex), THREADS (default: all cores),
#   MODES (modes kept of the 8 normal + 1 static correction mode + modal derivatives of
#   the nonlinear gate; default all),
#   GAP_MM (default 1).
set -e
if [ $# -lt 1 ]; then
  sed -n '2,22p' "$0"
  exit 2
fi
repo=$(cd "$(dirname "$0")/../.." && pwd)
chipflex=${CHIPFLEX:-$repo/build/bin/chipflex}
chipflex=$(cd "$(dirname "$chipflex")" && pwd)/$(basename "$chipflex")
out=$1
dp_mm=${2:-1}
shift $(( $# >= 2 ? 2 : 1 ))
variants=${*:-flexible fe chain1 chain2 chain3 sph_solid}
threads=${THREADS:+--threads $THREADS}
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"
[ -f gate.msh ] || "$chipflex" mesh gate -o gate.msh
reduce="--clamp clamp --modes 8 --static-modes pressure:xmin --nonlinear"
# Antoci et al. (2007), Table 1: the gate's rubber. `reduce` has no material defaults.
[ -f gate.h5 ] || "$chipflex" reduce gate.msh -o gate.h5 $reduce --E 1.2e7 --nu 0.4 --rho 1100
case " $variants" in
  *" flexible_sphinxsys"*)
    [ -f gate_sphinxsys.h5 ] ||
      "$chipflex" reduce gate.msh -o gate_sphinxsys.h5 $reduce --E 7.8e6 --nu 0.47 --rho 1100 ;;
esac
dp=$(awk "BEGIN { print $dp_mm / 1000 }")
gap=$(awk "BEGIN { print ${GAP_MM:-1} / 1000 }")
runs=
for spec in $variants; do
  v=${spec%%:*}
  run=$(echo "$spec" | tr ':' '_')
  case_file=$repo/cases/elastic_gate/$v.prm
  [ -f "$case_file" ] || { echo "no variant $v ($case_file)" >&2; exit 2; }
  # The variant with the shared tank written out (its include), so that sed reaches every key.
  "$repo/scripts/flatten_case.sh" "$case_file" |
    sed -e "s|^\(  set particle spacing *=\).*|\1 $dp|" \
        -e "s|^\(    set modes *=\).*|\1 ${MODES:--1}|" > "$run.prm"
  mods=${spec#"$v"}
  for m in $(echo "$mods" | tr ':' ' '); do
    case $m in
      noweight | weight)
        w=$([ "$m" = weight ] && echo true || echo false)
        sed -i -e '/^    set weight *=/d' \
            -e "s|^\(    set name *= gate\)\$|\1\n    set weight = $w|" "$run.prm" ;;
      gap)
        # The gate and the wall above it move up by the gap; the gate keeps its length.
        sed -i -e "s|^\(    set position *= 0.1, \)0 |\1$gap |" \
            -e "s|^\(    set position *= 0.1025, \)0.079|\1$(awk "BEGIN { print 0.079 + $gap }")|" \
            -e "s|^\(    set probe point *= 0.105, \)0 |\1$gap |" \
            -e "/^    set polylines/s|0.079|$(awk "BEGIN { print 0.079 + $gap }")|g" "$run.prm" ;;
      dummy | lj | thin)
        wm=$(case $m in dummy) echo "dummy particles" ;; lj) echo "lennard jones" ;;
             *) echo "thin skin" ;; esac)
        sed -i -e '/^    set wall model *=/d' \
            -e "s|^\(    set name *= gate\)\$|\1\n    set wall model = $wm|" "$run.prm" ;;
      ljthin)
        sed -i -e "s|^\(    set name *= gate\)\$|\1\n    set lennard jones r0 = $(awk "BEGIN { print $dp / 4 }")\n    set lennard jones R = $(awk "BEGIN { print $dp / 2 }")|" "$run.prm" ;;
      uncorrected)
        sed -i -e "s|^\(    set name *= gate\)\$|\1\n    set formulation = updated lagrangian\n    set kernel gradient correction = false|" "$run.prm" ;;
      *) echo "unknown modifier :$m in $spec" >&2; exit 2 ;;
    esac
  done
  "$chipflex" run "$run.prm" --out "$run" $threads > "$run.log" 2>&1 || { tail -3 "$run.log" >&2; exit 1; }
  grep '^summary:' "$run.log" | sed "s|^summary:|summary: variant=$spec|"
  runs="$runs $run"
done
"$chipflex" plot $runs --out elastic_gate.png
echo "plot: $out/elastic_gate.png"
