#!/bin/sh
# MPI equals serial: `mpirun -np 2 chipflex reduce` writes the same body (modes, sign
# included) as one process, for a clamped 2D gate with a static mode and a free-free 3D
# plate on quadratic tetrahedra.   usage: mpi_equals_serial.sh CHIPFLEX COMPARE_BODY_FILES
set -e
chipflex=$1
compare=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mpi="mpirun --allow-run-as-root --oversubscribe -np 2"

"$chipflex" mesh gate -o "$dir/gate.msh" --size 0.0025 > /dev/null
set -- "$dir/gate.msh" --clamp clamp --modes 6 --E 1.2e7 --nu 0.4 --rho 1100 --static-modes pressure:xmin,force:tip:0,-1
"$chipflex" reduce "$@" -o "$dir/gate_serial.h5" > /dev/null
$mpi "$chipflex" reduce "$@" -o "$dir/gate_mpi.h5" > /dev/null
"$compare" "$dir/gate_serial.h5" "$dir/gate_mpi.h5"

"$chipflex" mesh plate -o "$dir/plate.msh" --length 0.03 --width 0.008 --thickness 0.003 \
  --size 0.003 --simplex > /dev/null
set -- "$dir/plate.msh" --modes 5 --E 2.1e11 --nu 0.3 --rho 7850 --static-modes pressure:zmax
"$chipflex" reduce "$@" -o "$dir/plate_serial.h5" > /dev/null
$mpi "$chipflex" reduce "$@" -o "$dir/plate_mpi.h5" > /dev/null
"$compare" "$dir/plate_serial.h5" "$dir/plate_mpi.h5"
