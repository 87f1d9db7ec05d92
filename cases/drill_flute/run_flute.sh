#!/bin/sh
# The drill-flute jamming case (docs/drill_flute.md): generates the flute's surfaces,
# meshes and reduces the chip once, runs the rigid and the flexible chip variants of the
# 3D case, writes per-chip CSVs and the drill's contact history, and draws
# OUT/drill_flute.png and the jam pictures OUT/jam_VARIANT.png.
#
#   cases/drill_flute/run_flute.sh OUT [END_TIME]
#     END_TIME  simulated time in s (default: the case files' 0.02)
#   Environment: CHIPFLEX (default build/bin/chipflex), THREADS (default 2),
#   VARIANTS (default "rigid flexible"), DP (particle spacing, m; default the case's
#   0.00075; the open boundaries' layers follow so that layers * dp stays 3 mm),
#   SCALE (the similitude's speed scale k, default the case files' 4: coolant 50/k l/min,
#   drill 133/k rad/s, chips' E 210/k^2 GPa, c0 120/k m/s, chips released at 0.44/k m/s;
#   1: the full-scale process), CHIP_REVOLUTIONS and CHIP_FIRST_RELEASE (the chip source
#   variants, e.g. VARIANTS="rigid_chip_source flexible_chip_source": a chip every this
#   many revolutions from this time; default the case files' 1 and 0.01 s).
set -e
if [ $# -lt 1 ]; then
  sed -n '2,17p' "$0"
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
chipflex=${CHIPFLEX:-$repo/build/bin/chipflex}
chipflex=$(cd "$(dirname "$chipflex")" && pwd)/$(basename "$chipflex")
out=$1
end_time=${2:-}
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"
# The flute of a D = 20 mm single-lip drill: 120-degree V, apex on the axis, a 30 mm
# segment with the barrier at 20 mm (the case files' boxes and probes match these).
python3 "$here/make_flute_geometry.py" --diameter 0.02 --flute-angle 120 --length 0.03 \
  --barrier 0.02 --out "$out" > geometry.log
scale=${SCALE:-4}
num() { awk "BEGIN { printf \"%.6g\", $1 }"; }
modulus=$(num "2.1e11 / ($scale * $scale)")
if [ ! -f chip.h5 ] || [ "$(cat chip.modulus 2>/dev/null)" != "$modulus" ]; then
  # A ribbon chip, 10 x 2 x 0.1 mm, of 42CrMo4 steel (E 210 GPa, nu 0.3, rho 7850 kg/m^3),
  # its E divided by k^2 (the similitude keeps the Cauchy number).
  "$chipflex" mesh chip --shape ribbon --length 0.01 --width 0.002 --thickness 0.0001 \
    --size 0.0005 -o chip.msh > chip.log
  "$chipflex" reduce chip.msh -o chip.h5 --E "$modulus" --nu 0.3 --rho 7850 --modes 10 >> chip.log
  echo "$modulus" > chip.modulus
fi
omega=$(num "133 / $scale")
flow=$(num "8.3333e-4 / $scale")
c0=$(num "120 / $scale")
chip_speed=$(num "0.44 / $scale")
# The jam watch's references: rho U^2 / 2 with U over the 90 mm^2 the fluid fills, and
# the flow fed.
pref=$(num "0.5 * 870 * ($flow / 9.0e-5)^2")
layers=""
if [ -n "$DP" ]; then
  layers=$(awk "BEGIN { printf \"%d\", 0.003 / $DP + 0.5 }")
fi
# A case file, scaled, resolved and with END_TIME, into OUT.
scaled_case() {
  sed -e "${end_time:+s|^\(  set end time *=\).*|\1 $end_time|}" \
      -e "s|^\(  set angular velocity *=\).*|\1 0, 0, $omega|" \
      -e "s|^\(    set angular velocity *=\).*|\1 0, 0, -$omega|" \
      -e "s|^\(    set flow rate *=\).*|\1 $flow|" \
      -e "s|^\(    set reference flow *=\).*|\1 $flow|" \
      -e "s|^\(    set reference pressure *=\).*|\1 $pref|" \
      -e "s|^\(  set speed of sound *=\).*|\1 $c0|" \
      -e "${DP:+s|^\(  set particle spacing *=\).*|\1 $DP|}" \
      -e "${layers:+s|^\(    set layers *=\).*|\1 $layers|}" \
      -e "s|^\(    set velocity *=\).*|\1 0, 0, $chip_speed|" \
      -e "${CHIP_REVOLUTIONS:+s|^\(    set revolutions *=\).*|\1 $CHIP_REVOLUTIONS|}" \
      -e "${CHIP_FIRST_RELEASE:+s|^\(    set first release *=\).*|\1 $CHIP_FIRST_RELEASE|}" "$1" > "$2"
}
for v in ${VARIANTS:-rigid flexible}; do
  case_file=$here/flute_3d_$v.prm
  [ -f "$case_file" ] || { echo "no variant $v ($case_file)" >&2; exit 2; }
  scaled_case "$case_file" "flute_3d_$v.prm"
  # A chip-source variant includes its base case: scale that too, beside it.
  included=$(sed -n 's|^include *||p' "$case_file")
  [ -z "$included" ] || scaled_case "$here/$included" "$included"
  "$chipflex" run "flute_3d_$v.prm" --out "$v" --threads "${THREADS:-2}" > "$v.log" 2>&1 ||
    { tail -3 "$v.log" >&2; exit 1; }
  grep '^summary:' "$v.log" | sed "s|^summary:|summary: variant=$v|"
done
python3 "$here/plot_flute.py" "$out" ${VARIANTS:-rigid flexible}
# The jam as a picture, per variant at the last frame (needs h5dump: hdf5-tools).
if command -v h5dump > /dev/null; then
  for v in ${VARIANTS:-rigid flexible}; do
    python3 "$here/flute_picture.py" "$out/$v" "$out/jam_$v.png"
  done
  # And as a film with its PNG frame series (needs ffmpeg).
  if command -v ffmpeg > /dev/null; then
    for v in ${VARIANTS:-rigid flexible}; do
      sh "$here/flute_video.sh" "$out/$v" "$out/jam_$v.mp4"
    done
  fi
fi
