#!/usr/bin/env python3
"""The elastic gate's flow account: per run folder of run_benchmark.sh, at the
experiment's frames, the free end's dx (mm; the experiment's beside it), the upstream water
level h_upstream (mm, mid-column), the flow towards the gate q_under_gate through
x = 0.095 m (the discharge under the gate plus what the moving gate sweeps; litres per
second per metre, mean over +-5 ms), and the volume that has passed the section, integral
of q dt, against the volume the tank has lost, 0.1 m * (h0 - h_upstream) (litres per
metre; equal for a level surface).

  cases/elastic_gate/flow_table.py RUN_DIR [RUN_DIR ...]
"""
import csv
import os
import sys


def read(path):
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    head, body = rows[0], [[float(v) for v in r] for r in rows[1:] if r]
    return {name: [r[k] for r in body] for k, name in enumerate(head)}


def at(t, ts, vs):
    """Linear interpolation of vs(ts) at t."""
    for k in range(1, len(ts)):
        if ts[k] >= t:
            w = (t - ts[k - 1]) / (ts[k] - ts[k - 1])
            return vs[k - 1] + w * (vs[k] - vs[k - 1])
    return vs[-1]


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    here = os.path.dirname(os.path.abspath(__file__))
    exp = read(os.path.join(here, "../../data/antoci2007/experiment_merged.csv"))
    for run in sys.argv[1:]:
        p = read(os.path.join(run, "probes.csv"))
        t = p["time_s"]
        dx = p["gate_dx_m"]
        h, q = p["h_upstream_m"], p["q_under_gate_m2_s"]
        passed = [0.0]
        for k in range(1, len(t)):
            passed.append(passed[-1] + 0.5 * (q[k] + q[k - 1]) * (t[k] - t[k - 1]))
        print(f"{run}:")
        print("  t_s   dx_mm (exp)    h_up_mm  q_l_s_m  passed_l_m  tank_loss_l_m")
        for frame in range(1, 10):
            tf = 0.04 * frame
            if tf > t[-1]:
                break
            qm = [q[k] for k in range(len(t)) if abs(t[k] - tf) <= 0.005]
            print(f"  {tf:.2f}  {1e3 * at(tf, t, dx):6.1f} ({1e3 * at(tf, exp['time_s'], exp['dx_m']):5.1f})"
                  f"  {1e3 * at(tf, t, h):7.1f}  {1e3 * sum(qm) / len(qm):7.2f}"
                  f"  {1e3 * at(tf, t, passed):10.2f}  {1e3 * 0.1 * (h[0] - at(tf, t, h)):12.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
