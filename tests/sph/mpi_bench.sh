#!/bin/bash
# `chipflex bench sph-dambreak2d` under mpirun -np 2: it runs over the ranks, reports the
# global particle count and the time split; `chipflex run` under mpirun stops on an input
# error with its line. Usage: mpi_bench.sh CHIPFLEX MPIEXEC
set -euo pipefail
chipflex=$1
mpiexec=$2
export OMP_NUM_THREADS=1
out=$("$mpiexec" -np 2 --oversubscribe "$chipflex" bench sph-dambreak2d --end-time 0.002 --threads 1)
echo "$out"
grep -q '^ranks=2$' <<<"$out"
grep -q '^particles=21002 (fluid 20000, boundary 1002)$' <<<"$out"
grep -q '^slowest_rank_seconds: halo=' <<<"$out"
grep -q '^particle_steps_per_s=' <<<"$out"
err=$(mktemp)
trap 'rm -f "$err"' EXIT
# An error on the ranks (here a missing case file) ends the job with the error line, at once.
if "$mpiexec" -np 2 --oversubscribe "$chipflex" run /nonexistent.prm --out /tmp/never 2>"$err"; then
  echo "FAILED: chipflex run under mpirun ran a missing case"
  exit 1
fi
grep -q 'chipflex run: error: .*nonexistent.prm' "$err"
echo passed
