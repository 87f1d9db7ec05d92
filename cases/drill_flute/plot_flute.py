#!/usr/bin/env python3
"""Post-processing of the drill-flute runs (docs/drill_flute.md).

    plot_flute.py OUT [VARIANT ...]      (default: rigid flexible)

For each OUT/VARIANT/probes.csv it writes
  OUT/VARIANT/<chip>.csv  time, position (x, y, z), rotation vector (rx, ry, rz), maximum
                          elastic deflection, elastic strain energy of every chip
  OUT/VARIANT/drill.csv   time, contact force on the barrier and on the flute's flanks
                          (the drill body) and on the borehole wall, the friction torque of
                          the contacts on the drill (flanks + barrier) and on the borehole
                          about the drill axis, the pressure drop tip - top, inflow, outflow,
                          the pressures in front of and behind the barrier (where the chips
                          block) and the coolant's volume flow through it (l/min)
prints one line of figures per variant (means over the last third of the run), and draws
OUT/drill_flute.png (gnuplot): deflection, barrier contact force, drill torque and the
pressures in front of and behind the barrier against time for every variant.
"""
import csv
import math
import os
import subprocess
import sys

# Wall names as the case files define them: `surfaces = flute_walls.stl; barrier.stl
# barrier` (walls "surface 1" and "surface 2") and the moving wall body `borehole`.
FLANKS, BARRIER, BOREHOLE = "contact_surface_1", "contact_surface_2", "contact_borehole"


def atomic_csv(path, header, rows):
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)
    os.replace(tmp, path)


def rotation_matrix(v):
    """Rodrigues: the rotation by |v| about v."""
    angle = math.sqrt(sum(x * x for x in v))
    if angle < 1e-15:
        return [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]
    k = [x / angle for x in v]
    c, s = math.cos(angle), math.sin(angle)
    skew = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    return [[c * (i == j) + s * skew[i][j] + (1 - c) * k[i] * k[j] for j in range(3)]
            for i in range(3)]


def rotation_between(v0, v1):
    """Angle (degrees) of the rotation R1 R0^T that takes orientation v0 to v1."""
    r0, r1 = rotation_matrix(v0), rotation_matrix(v1)
    trace = sum(r1[i][k] * r0[i][k] for i in range(3) for k in range(3))
    return math.degrees(math.acos(max(-1.0, min(1.0, (trace - 1) / 2))))


def norm(r, prefix):
    return math.sqrt(sum(float(r[f"{prefix}_force_{a}_N"]) ** 2 for a in "xyz"))


def process(out, variant):
    folder = os.path.join(out, variant)
    rows = list(csv.DictReader(open(os.path.join(folder, "probes.csv"))))
    if len(rows) < 2:
        raise SystemExit(f"plot_flute.py: {folder}/probes.csv has no rows")
    chips = sorted({k[:-len("_strain_energy_J")] for k in rows[0] if k.endswith("_strain_energy_J")}
                   - {"borehole"})
    for c in chips:
        cols = [f"{c}_{q}" for q in ("x_m", "y_m", "z_m", "rx_rad", "ry_rad", "rz_rad",
                                     "deflection_m", "strain_energy_J")]
        atomic_csv(os.path.join(folder, f"{c}.csv"), ["time_s"] + [q[len(c) + 1:] for q in cols],
                   [[r["time_s"]] + [r[k] for k in cols] for r in rows])
    # Gauges the older case files lack read as 0 (the columns stay).
    value = lambda r, k: float(r[k]) if k in r else 0.0
    drill = []
    for r in rows:
        drill.append([
            float(r["time_s"]), norm(r, BARRIER), float(r[f"{BARRIER}_force_z_N"]), norm(r, FLANKS),
            norm(r, BOREHOLE),
            float(r[f"{FLANKS}_torque_Nm"]) + float(r[f"{BARRIER}_torque_Nm"]),
            float(r[f"{BOREHOLE}_torque_Nm"]),
            float(r["p_tip_Pa"]) - float(r["p_top_Pa"]),
            float(r["inlet_mass_flow"]), float(r["outlet_mass_flow"]),
            max(float(r[f"{c}_deflection_m"]) for c in chips),
            sum(float(r[f"{c}_strain_energy_J"]) for c in chips),
            min(float(r[f"{c}_z_m"]) for c in chips) if chips else 0,
            value(r, "p_before_barrier_Pa"), value(r, "p_behind_barrier_Pa"),
            value(r, "q_barrier_m3_s") * 6e4])
    header = ["time_s", "barrier_force_N", "barrier_force_z_N", "flank_force_N",
              "borehole_force_N", "drill_torque_Nm", "borehole_torque_Nm", "pressure_drop_Pa",
              "inflow_kg_s", "outflow_kg_s", "max_deflection_m", "strain_energy_J", "lowest_chip_z_m",
              "p_before_barrier_Pa", "p_behind_barrier_Pa", "barrier_flow_l_min"]
    atomic_csv(os.path.join(folder, "drill.csv"), header, drill)
    t_end = drill[-1][0]
    tail = [d for d in drill if d[0] >= 2 * t_end / 3]
    mean = [sum(d[k] for d in tail) / len(tail) for k in range(len(header))]
    peak_deflection = max(d[10] for d in drill)
    print(f"figures: variant={variant} t_end_s={t_end:.4f} last_third_mean: "
          f"max_deflection_um={mean[10] * 1e6:.2f} strain_energy_uJ={mean[11] * 1e6:.4f} "
          f"barrier_force_N={mean[1]:.4f} flank_force_N={mean[3]:.4f} "
          f"borehole_force_N={mean[4]:.4f} drill_torque_Nmm={mean[5] * 1e3:.4f} "
          f"borehole_torque_Nmm={mean[6] * 1e3:.4f} pressure_drop_Pa={mean[7]:.0f} "
          f"inflow_kg_s={mean[8]:.4f} outflow_kg_s={mean[9]:.4f} "
          f"peak_deflection_um={peak_deflection * 1e6:.2f} "
          f"p_before_barrier_Pa={mean[13]:.0f} p_behind_barrier_Pa={mean[14]:.0f} "
          f"barrier_flow_l_min={mean[15]:.2f}")
    # Each chip's rotation from its start (angle of the rotation vector) and its deflection
    # at the end.
    for c in chips:
        angle = rotation_between([float(rows[0][f"{c}_r{a}_rad"]) for a in "xyz"],
                                 [float(rows[-1][f"{c}_r{a}_rad"]) for a in "xyz"])
        print(f"figures: variant={variant} chip={c} end: z_mm={float(rows[-1][f'{c}_z_m']) * 1e3:.2f} "
              f"rotation_deg={angle:.1f} deflection_um={float(rows[-1][f'{c}_deflection_m']) * 1e6:.2f}")
    return os.path.join(folder, "drill.csv")


def main():
    if len(sys.argv) < 2:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    out = sys.argv[1]
    variants = sys.argv[2:] or ["rigid", "flexible"]
    files = {v: process(out, v) for v in variants}
    png = os.path.join(out, "drill_flute.png")
    plots = lambda col, scale: ", ".join(
        f"'{f}' using 1:(${col}*{scale}) every ::1 with lines lw 2 title '{v}'" for v, f in files.items())
    pressures = ", ".join(
        f"'{f}' using 1:(${col}*1e-3) every ::1 with lines lw 2 dt {dt} title '{v}, {where}'"
        for v, f in files.items() for col, dt, where in ((14, 1, "in front"), (15, 2, "behind")))
    script = f"""set terminal pngcairo size 900,1300 font ',10'
set output '{png}.tmp'
set datafile separator ','
set multiplot layout 4,1 title 'Drill flute: chips against the barrier (D = 20 mm, 120 deg flute)'
set grid
set ylabel 'largest chip deflection (um)'
plot {plots(11, 1e6)}
set ylabel 'barrier contact force (N)'
plot {plots(2, 1)}
set ylabel 'contact torque on the drill (N mm)'
plot {plots(6, 1e3)}
set ylabel 'pressure (kPa): in front of / behind the barrier'
set xlabel 'time (s)'
plot {pressures}
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    os.replace(png + ".tmp", png)
    print(f"wrote {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
