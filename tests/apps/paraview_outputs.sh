#!/bin/sh
# The outputs of `chipflex run` open in ParaView with their cells, ids, units, walls and
# bodies (docs/output.md), for a run that finishes and for one the solver stops:
#  1. a coarse elastic gate (a one-link chain with dummy particles, no body file needed)
#     under a water column, in a dummy-particle tank with the Lennard-Jones wall above the
#     gate, 0.03 s, then restarted from its checkpoint to 0.04 s: the global ids follow
#     the particles across the restart, and the body array tells the tank's dummy
#     particles (still) from the gate's (moving);
#  2. water falling out of a tight domain: exit status 3, a frame at the stop time,
#     probes.csv and summary.txt with status=stopped.
#  3. with MPIEXEC: the gate of 1. on 2 MPI ranks and restarted on 2, whose particle
#     frames the ranks write together through parallel HDF5.
# tests/apps/check_outputs.py checks them with python3 + h5py and, where pvpython is
# installed, with ParaView's three XDMF readers. Neither available: exit 77 (CTest SKIP).
#   usage: paraview_outputs.sh CHIPFLEX [MPIEXEC]
chipflex=$1
mpiexec=$2
here=$(cd "$(dirname "$0")" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
[ -n "$KEEP" ] && trap - EXIT && echo "keeping $dir"
fail() { echo "FAIL: $*"; exit 1; }

python=$(sh "$(dirname "$0")/../python_with_h5py.sh")
pvpython=""
command -v pvpython > /dev/null 2>&1 && pvpython=pvpython
if [ -z "$python" ] && [ -z "$pvpython" ]; then
  echo "SKIP: neither python3 with h5py nor pvpython installed"
  exit 77
fi

cat > "$dir/gate.prm" <<'CASE'
set dimension = 2
subsection fluid
  set particle spacing     = 0.004
  set gravity              = 0, -9.81
  set sound coefficient    = 20
  set viscosity            = artificial
  set artificial viscosity = 0.02
  set density diffusion    = fourtakas
end
subsection time
  set end time = 0.03
  set scheme   = symplectic
  set cfl      = 0.2
end
subsection output
  set frame interval = 0.01
  set probe interval = 0.001
end
subsection geometry
  set fluid blocks = 0, 0, 0.1, 0.14
  subsection tank
    set min corner = 0, 0
    set max corner = 0.5, 0.3
    set wall model = dummy particles
  end
  subsection walls
    set polylines  = 0.105, 0.079, 0.105, 0.3, 0.1, 0.3, 0.1, 0.079
    set wall model = lennard jones
  end
end
subsection probes
  set pressure = bottom: 0.05, 0.01
end
subsection bodies
  set count = 1
  subsection body 1
    set name     = gate
    set kind     = chain
    set links       = 1
    set position    = 0.1025, 0.079
    set length      = 0.079
    set thickness   = 0.005
    set density     = 1100
    set spring rate = 3.95
    set implicit = false
    set wall model  = dummy particles
  end
end
CASE
"$chipflex" run "$dir/gate.prm" --out "$dir/gate" --threads 2 --checkpoint-every 0.02 \
  > "$dir/gate.log" 2>&1 || fail "gate run: $(tail -3 "$dir/gate.log")"
# A restart continues every series (particles, walls, skins) from the checkpoint's time.
"$chipflex" run "$dir/gate.prm" --out "$dir/gate" --threads 2 --end-time 0.04 \
  --restart "$dir/gate/checkpoint.h5" > "$dir/restart.log" 2>&1 ||
  fail "gate restart: $(tail -3 "$dir/restart.log")"

# No tank, a tight domain: the water leaves it and the solver stops the run.
cat > "$dir/falls.prm" <<'CASE'
set dimension = 2
subsection fluid
  set particle spacing = 0.02
  set gravity          = 0, -9.81
end
subsection time
  set end time = 1.0
end
subsection output
  set frame interval = 0.5
  set probe interval = 0.01
end
subsection geometry
  set domain min   = -0.1, -0.05
  set domain max   = 0.4, 0.5
  set fluid blocks = 0, 0, 0.3, 0.2
  subsection tank
    set enabled = false
  end
  subsection walls
    set polylines  = 0.3, 0, 0.3, 0.2
  end
end
subsection probes
  set pressure = middle: 0.15, 0.05
end
CASE
"$chipflex" run "$dir/falls.prm" --out "$dir/falls" --threads 2 > "$dir/falls.log" 2>&1
status=$?
[ $status -eq 3 ] || fail "stopped run: exit status $status, expected 3: $(tail -3 "$dir/falls.log")"
grep -q "stopped:" "$dir/falls.log" || fail "stopped run: no 'stopped:' message"

# Both checkers where both are installed: CI has h5py only, a ParaView user has pvpython.
check() {
  if [ -n "$python" ]; then
    "$python" "$here/check_outputs.py" "$@" > "$dir/check.log" 2>&1 ||
      { cat "$dir/check.log"; return 1; }
    cat "$dir/check.log"
  fi
  if [ -n "$pvpython" ]; then
    "$pvpython" --force-offscreen-rendering "$here/check_outputs.py" "$@" --paraview \
      > "$dir/check.log" 2>&1 || { cat "$dir/check.log"; return 1; }
    grep "^paraview" "$dir/check.log"
  fi
}
check "$dir/gate" || fail "gate outputs"
check "$dir/falls" --stopped --no-bodies || fail "stopped run outputs"
if [ -n "$mpiexec" ]; then
  "$mpiexec" -np 2 "$chipflex" run "$dir/gate.prm" --out "$dir/gate_np2" --threads 1 \
    --checkpoint-every 0.03 > "$dir/gate_np2.log" 2>&1 ||
    fail "gate run on 2 ranks: $(tail -3 "$dir/gate_np2.log")"
  "$mpiexec" -np 2 "$chipflex" run "$dir/gate.prm" --out "$dir/gate_np2" --threads 1 \
    --end-time 0.04 --restart "$dir/gate_np2/checkpoint.h5" > "$dir/restart_np2.log" 2>&1 ||
    fail "gate restart on 2 ranks: $(tail -3 "$dir/restart_np2.log")"
  check "$dir/gate_np2" || fail "gate outputs on 2 ranks"
fi
echo "ok: $(head -1 "$dir/falls/summary.txt")"
