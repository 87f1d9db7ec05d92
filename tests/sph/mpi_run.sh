#!/bin/sh
# `mpirun -np N chipflex run`: a coarse 2D dam break (dp 0.02 m, 5000 particles, 0.3 s)
# run on 1, 2 and 3 ranks, and restarted from an np-2 checkpoint on 1 and on 3 ranks. Every
# run must give the one-process answer to the rounding that the ranks' other summation
# order brings (docs/parallel.md):
#   - the last frame holds every fluid particle once; their RMS displacement from the
#     one-process positions < 0.05 dp (measured 0.0025-0.0044 dp) and the surge front
#     within 0.5 %;
#   - every wall particle's density within 1 kg/m^3 of the one-process one (measured
#     0.05; a rank that wrote its stale copies of the other slabs' walls is 17 off);
#   - the gauges (a pressure in the column, three water heights) within 1 % of their
#     range, and the same step count to within 1 %.
# Then a case with bodies, a channel with open boundaries and no-slip walls, and the fe
# and sph solid body kinds (below).
#   usage: mpi_run.sh CHIPFLEX MPIEXEC SOURCE_DIR
chipflex=$1
mpiexec=$2
src=$(cd "$3" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
python=$(sh "$(dirname "$0")/../python_with_h5py.sh")
[ -n "$python" ] || { echo "SKIP: python3 with h5py not installed"; exit 77; }
cat > "$dir/dam.prm" <<CASE
include $src/cases/dam_break_2d.prm
subsection fluid
  set particle spacing = 0.02
end
subsection time
  set end time = 0.3
end
subsection output
  set frame interval = 0.1
  set probe interval = 0.01
end
subsection probes
  set pressure     = column: 0.3, 0.2
  set water height = x050: 0.5, 0; x100: 1.0, 0; x150: 1.5, 0
end
CASE
run() { # run NAME RANKS [options]
  name=$1 ranks=$2
  shift 2
  if [ "$ranks" = 1 ]; then
    "$chipflex" run "$dir/dam.prm" --out "$dir/$name" --threads 1 "$@" > "$dir/$name.log" 2>&1
  else
    "$mpiexec" -np "$ranks" --oversubscribe "$chipflex" run "$dir/dam.prm" --out "$dir/$name" \
      --threads 1 "$@" > "$dir/$name.log" 2>&1
  fi || fail "$name: $(tail -3 "$dir/$name.log")"
}
run np1 1
run np2 2
run np3 3
grep -q "^MPI: 2 ranks, slabs along x" "$dir/np2.log" || fail "np2: the log does not state the slabs"
[ "$(grep -c '^finished at' "$dir/np2.log")" = 1 ] || fail "np2: more than one rank printed"
run checkpoint 2 --end-time 0.15 --checkpoint-every 0.15
for n in 1 3; do
  cp -r "$dir/checkpoint" "$dir/restart$n"
  run "restart$n" "$n" --restart "$dir/checkpoint/checkpoint.h5"
done

"$python" - "$dir" <<'PY' || fail "the ranks' answers differ"
import glob, sys
import h5py, numpy as np
d = sys.argv[1]
dp = 0.02

def last_frame(run):
    f = h5py.File(sorted(glob.glob(f"{d}/{run}/particles/frame_*.h5"))[-1], "r")
    kind, ids = f["kind"][:], f["id"][:]
    out = {}
    for k, name in ((1, "fluid"), (0, "walls")):
        order = np.argsort(ids[kind == k])
        out[name] = (ids[kind == k][order], f["position"][:][kind == k][order],
                     f["density"][:][kind == k][order])
    return out

def probes(run):
    return np.genfromtxt(f"{d}/{run}/probes.csv", delimiter=",", names=True)

def summary(run):
    line = open(f"{d}/{run}/summary.txt").readline().split()
    return dict(kv.split("=", 1) for kv in line if "=" in kv)

ref, ref_probes, ref_summary = last_frame("np1"), probes("np1"), summary("np1")
ok = True
for run in ("np2", "np3", "restart1", "restart3"):
    f, p, s = last_frame(run), probes(run), summary(run)
    ids, x, _ = f["fluid"]
    if len(ids) != 5000 or not np.array_equal(ids, ref["fluid"][0]):
        print(f"{run}: {len(ids)} fluid particles, not the one-process 5000 once each")
        ok = False
        continue
    rms = np.sqrt(((x - ref["fluid"][1]) ** 2).sum(axis=1).mean()) / dp
    front, ref_front = x[:, 0].max(), ref["fluid"][1][:, 0].max()
    wall = np.abs(f["walls"][2] - ref["walls"][2]).max()
    steps = abs(int(s["steps"]) - int(ref_summary["steps"])) / int(ref_summary["steps"])
    gauges = 0.0
    for c in ("p_column_Pa", "h_x050_m", "h_x100_m", "h_x150_m"):
        n = min(len(p[c]), len(ref_probes[c]))
        span = np.ptp(ref_probes[c]) or 1.0
        gauges = max(gauges, np.abs(p[c][:n] - ref_probes[c][:n]).max() / span)
    print(f"{run}: RMS {rms:.4f} dp, front {front:.5f} m against {ref_front:.5f} m, "
          f"wall density within {wall:.3f} kg/m^3, gauges within {100 * gauges:.3f} % of their "
          f"range, steps {s['steps']} against {ref_summary['steps']}, lost {s['lost_particles']}")
    ok &= rms < 0.05 and abs(front / ref_front - 1) < 0.005 and wall < 1.0 and gauges < 0.01
    ok &= steps < 0.01 and s["status"] == "finished" and s["lost_particles"] == ref_summary["lost_particles"]
sys.exit(0 if ok else 1)
PY

# Bodies: the centrifuge (two rigid blocks in a turning frame, the heavy one in contact
# with the tank wall by 0.3 s) on 2 ranks, and its np-2 checkpoint restarted on 3. Every
# rank steps its own copy of the blocks under the fluid forces summed over the ranks: the
# blocks' paths within 0.1 mm of one process (measured 0.011 mm; dp is 4 mm), the fluid's
# RMS displacement below 0.05 dp (measured 0.001), the gauge at 80 mm within 2 %.
run_case() { # run_case CASE.prm NAME RANKS [options]: to 0.3 s unless the options say
  run_file=$1 run_name=$2 run_ranks=$3
  shift 3
  "$mpiexec" -np "$run_ranks" --oversubscribe "$chipflex" run "$run_file" \
    --out "$dir/$run_name" --threads 1 --end-time 0.3 "$@" > "$dir/$run_name.log" 2>&1 ||
    fail "$run_name: $(tail -3 "$dir/$run_name.log")"
}
run_and_restart() { # run_and_restart CASE.prm NAME RESTART_RANKS RANKS...: NAMEn on n ranks
  # for each of RANKS, and NAME_checkpoint (2 ranks, to 0.15 s) restarted on RESTART_RANKS
  # as NAME_restart
  series_file=$1 series=$2 restart_ranks=$3
  shift 3
  for n in "$@"; do
    run_case "$series_file" "$series$n" "$n"
  done
  run_case "$series_file" "${series}_checkpoint" 2 --end-time 0.15 --checkpoint-every 0.15
  cp -r "$dir/${series}_checkpoint" "$dir/${series}_restart"
  run_case "$series_file" "${series}_restart" "$restart_ranks" \
    --restart "$dir/${series}_checkpoint/checkpoint.h5"
}
run_and_restart "$src/cases/centrifuge_2d.prm" spin 3 1 2
"$python" - "$dir" <<'PY' || fail "the bodies' answers differ"
import glob, sys
import h5py, numpy as np
d = sys.argv[1]

def fluid(run):
    f = h5py.File(sorted(glob.glob(f"{d}/{run}/particles/frame_*.h5"))[-1], "r")
    k = f["kind"][:] == 1
    order = np.argsort(f["id"][:][k])
    return f["id"][:][k][order], f["position"][:][k][order]

def csv(path):
    return np.genfromtxt(path, delimiter=",", names=True)

ids, x = fluid("spin1")
p = csv(f"{d}/spin1/probes.csv")
ok = True
for run in ("spin2", "spin_restart"):
    i2, x2 = fluid(run)
    if not np.array_equal(ids, i2):
        print(f"{run}: not every fluid particle once")
        ok = False
        continue
    rms = np.sqrt(((x2 - x) ** 2).sum(axis=1).mean()) / 0.004
    path = 0.0
    for body in ("heavy", "light"):
        a, b = csv(f"{d}/spin1/{body}_displacement.csv"), csv(f"{d}/{run}/{body}_displacement.csv")
        n = min(len(a), len(b))
        path = max(path, np.abs(a["dx_m"][:n] - b["dx_m"][:n]).max(), np.abs(a["dy_m"][:n] - b["dy_m"][:n]).max())
    q = csv(f"{d}/{run}/probes.csv")
    gauge = abs(q["p_r80_Pa"][-1] / p["p_r80_Pa"][-1] - 1)
    print(f"{run}: blocks' paths within {1e3 * path:.4f} mm, fluid RMS {rms:.4f} dp, "
          f"p_r80 {q['p_r80_Pa'][-1]:.1f} Pa against {p['p_r80_Pa'][-1]:.1f} Pa, heavy block at "
          f"dx {1e3 * q['heavy_dx_m'][-1]:.2f} mm against {1e3 * p['heavy_dx_m'][-1]:.2f} mm")
    ok &= path < 1e-4 and rms < 0.05 and gauge < 0.02
sys.exit(0 if ok else 1)
PY

# Open boundaries and no-slip walls: the Poiseuille channel (a parabolic inlet, a 0 Pa
# outlet, no-slip plates; 2,160 particles) on 1 and 3 ranks to 0.3 s, and an np-2
# checkpoint at 0.15 s restarted on 1 rank. The inlets number their new particles across
# the ranks, so the same ids end in the domain; the fluid's RMS displacement below 0.05
# dp (measured 4e-6), the no-slip plates' particle velocities (taken from the fluid at
# their mirror points, on the rank that owns them) within 1 mm/s (measured 1e-6 m/s),
# the pressure gauges within 1 % of their range, and the inflow and outflow counts equal.
run_and_restart "$src/cases/channel_2d.prm" channel 1 1 3
"$python" - "$dir" <<'PY' || fail "the channel's answers differ"
import glob, sys
import h5py, numpy as np
d = sys.argv[1]

def frame(run):
    f = h5py.File(sorted(glob.glob(f"{d}/{run}/particles/frame_*.h5"))[-1], "r")
    out = {}
    for k, name in ((1, "fluid"), (0, "walls")):
        m = f["kind"][:] == k
        order = np.argsort(f["id"][:][m])
        out[name] = (f["id"][:][m][order], f["position"][:][m][order], f["velocity"][:][m][order])
    return out

def csv(run):
    return np.genfromtxt(f"{d}/{run}/probes.csv", delimiter=",", names=True)

ref, p = frame("channel1"), csv("channel1")
ok = True
for run in ("channel3", "channel_restart"):
    f, q = frame(run), csv(run)
    if not np.array_equal(f["fluid"][0], ref["fluid"][0]):
        print(f"{run}: other fluid particles ({len(f['fluid'][0])}) than one process's "
              f"({len(ref['fluid'][0])})")
        ok = False
        continue
    rms = np.sqrt(((f["fluid"][1] - ref["fluid"][1]) ** 2).sum(axis=1).mean()) / 0.001
    wall_v = np.abs(f["walls"][2] - ref["walls"][2]).max()
    n = min(len(p), len(q))
    gauges = max(np.abs(q[c][:n] - p[c][:n]).max() / np.ptp(p[c])
                 for c in ("p_inlet_Pa", "p_middle_Pa", "p_outlet_Pa"))
    counts = (q["inflow_particles"][-1], q["outflow_particles"][-1])
    print(f"{run}: RMS {rms:.2e} dp, plate velocities within {wall_v:.1e} m/s, gauges within "
          f"{100 * gauges:.4f} % of their range, inflow/outflow {counts[0]:.0f}/{counts[1]:.0f} "
          f"against {p['inflow_particles'][-1]:.0f}/{p['outflow_particles'][-1]:.0f}")
    ok &= rms < 0.05 and wall_v < 1e-3 and gauges < 0.01
    ok &= counts == (p["inflow_particles"][-1], p["outflow_particles"][-1])
sys.exit(0 if ok else 1)
PY

# Bodies with state of their own, stepped alike by every rank, in the elastic-gate tank on
# 1 and 2 ranks: the free end's paths must agree.
gate_paths() { # gate_paths CASE.prm END_TIME MIN_ROWS TOLERANCE_M
  gate=$(basename "$1" .prm)
  for n in 1 2; do
    run_case "$dir/gate/$1" "$gate$n" "$n" --end-time "$2"
  done
  paste -d, "$dir/${gate}1/gate_displacement.csv" "$dir/${gate}2/gate_displacement.csv" |
    awk -F, -v name="$gate" -v rows="$3" -v tolerance="$4" '
    NR > 1 { n++; d = $2 - $5; if (d < 0) d = -d; e = $3 - $6; if (e < 0) e = -e
             if (d > m) m = d; if (e > m) m = e; a = $2 < 0 ? -$2 : $2; if (a > moved) moved = a }
    END { printf "%s gate on 2 ranks: free end within %.2g mm of one process over %d rows, largest dx %.3f mm\n", name, 1e3 * m, n, 1e3 * moved
          exit n < rows || m > tolerance || moved < 1e-5 }' || fail "the $gate gate's paths differ"
}
mkdir "$dir/gate"
cp "$src/cases/elastic_gate/fe.prm" "$src/cases/elastic_gate/sph_solid.prm" \
  "$src/cases/elastic_gate/tank.prm" "$dir/gate/"
(cd "$dir/gate" && "$chipflex" mesh gate -o gate.msh > /dev/null) || fail "chipflex mesh gate"
# The fe kind (the full nonlinear FE gate, a serial deal.II solver) to 0.02 s: within 0.01
# mm (measured 1e-6 mm at 0.03 s; the gate has moved 5 mm by 0.02 s).
gate_paths fe.prm 0.02 100 1e-5
# The SPH solid (its own particle set, loaded through its skin like every kind) to 5 ms:
# within 0.001 mm (measured 1.3e-7 mm at 20 ms, where it has moved 4.3 mm).
gate_paths sph_solid.prm 0.005 40 1e-6
echo "mpi_run: OK"
