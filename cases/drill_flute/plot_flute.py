#!/usr/bin/env python3
"""Post-processing of the drill-flute runs (docs/drill_flute.md).

    plot_flute.py OUT [VARIANT ...]      (default: rigid flexible)

For each OUT/VARIANT/probes.csv it writes
  OUT/VARIANT/<chip>.csv  time, position (x, y, z), rotation vector (rx, ry, rz), maximum
                          elastic deflection, elastic strain energy of every chip
  OUT/VARIANT/drill.csv   time, contact force on the barrier and on the flute's flanks
                          (the drill body) and on the borehole wall, the friction torque of
                          the contacts on the drill (flanks + barrier) and on the borehole
                          about the drill axis, the pressure drop tip - top, inflow, outflow
prints one line of figures per variant (means over the last third of the run), and draws
OUT/drill_flute.png (gnuplot): deflection, barrier contact force and drill torque against
time for every variant.
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
            min(float(r[f"{c}_z_m"]) for c in chips) if chips else 0])
    header = ["time_s", "barrier_force_N", "barrier_force_z_N", "flank_force_N",
              "borehole_force_N", "drill_torque_Nm", "borehole_torque_Nm", "pressure_drop_Pa",
              "inflow_kg_s", "outflow_kg_s", "max_deflection_m", "strain_energy_J", "lowest_chip_z_m"]
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
          f"peak_deflection_um={peak_deflection * 1e6:.2f}")
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
    script = f"""set terminal pngcairo size 900,1000 font ',10'
set output '{png}.tmp'
set datafile separator ','
set multiplot layout 3,1 title 'Drill flute: chips against the barrier (D = 20 mm, 120 deg flute)'
set grid
set ylabel 'largest chip deflection (um)'
plot {plots(11, 1e6)}
set ylabel 'barrier contact force (N)'
plot {plots(2, 1)}
set ylabel 'contact torque on the drill (N mm)'
set xlabel 'time (s)'
plot {plots(6, 1e3)}
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    os.replace(png + ".tmp", png)
    print(f"wrote {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
