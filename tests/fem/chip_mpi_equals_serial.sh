#!/bin/sh
# MPI equals serial for a curved chip: `mpirun -np 2 chipflex reduce` of a free helical chip
# (27-node hexahedra, the isoparametric mapping on the gmsh nodes, a static mode on its
# skin) writes the same body as one process.
#   usage: chip_mpi_equals_serial.sh CHIPFLEX COMPARE_BODY_FILES
set -e
chipflex=$1
compare=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mpi="mpirun --allow-run-as-root --oversubscribe -np 2"

"$chipflex" mesh chip --shape helical --turns 1.5 --size 0.001 -o "$dir/chip.msh" > /dev/null
set -- "$dir/chip.msh" --modes 6 --E 2.1e11 --nu 0.3 --rho 7850 --static-modes pressure:skin
"$chipflex" reduce "$@" -o "$dir/chip_serial.h5" > /dev/null
$mpi "$chipflex" reduce "$@" -o "$dir/chip_mpi.h5" > /dev/null
"$compare" "$dir/chip_serial.h5" "$dir/chip_mpi.h5"
