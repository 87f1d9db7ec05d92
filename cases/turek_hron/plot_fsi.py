#!/usr/bin/env python3
"""The bar's tip displacement in Turek & Hron's FSI benchmark (fsi2.prm, fsi3.prm) against
the published reference values.

    python3 plot_fsi.py OUT [FROM_S] [--benchmark fsi2|fsi3]

reads OUT/probes.csv (`bar_dx_m`, `bar_dy_m`: the displacement of the bar's probe point,
the middle of its free end, point A of the benchmark), takes the periodic part from FROM_S
(default: the last third of the run) and prints one `figures:` line. Turek & Hron (2006)
give each displacement as mean +- amplitude with mean = (max + min) / 2 and amplitude =
(max - min) / 2 over one period; here both are averaged over every whole period of u_y in
the window (periods from its upward crossings of its mean; u_x swings twice per period, its
max and min are taken over each period of u_y). The frequency is one over the mean period
of u_y. Each figure is then checked against its tolerance (u_y amplitude 10 %, frequency
5 %, u_x mean and amplitude 20 %): the script exits with 1 when one is missed and `--check`
is given. OUT/fsi.png (gnuplot, if present) draws u_x and u_y against time.
"""
import csv
import os
import shutil
import subprocess
import sys

# Turek & Hron (2006), their finest mesh level for FSI2 and FSI3: point A's
# displacement, mean +- amplitude [frequency].
REFERENCE = {
    "fsi2": {"ux_mean": -1.4580e-2, "ux_amplitude": 1.2440e-2, "uy_mean": 1.2300e-3,
             "uy_amplitude": 8.0600e-2, "frequency_hz": 2.0},
    "fsi3": {"ux_mean": -2.6900e-3, "ux_amplitude": 2.5300e-3, "uy_mean": 1.4800e-3,
             "uy_amplitude": 3.4380e-2, "frequency_hz": 5.3},
}
# What the validation requires of each figure (relative to the reference).
TOLERANCE = {"uy_amplitude": 0.10, "frequency_hz": 0.05, "ux_mean": 0.20, "ux_amplitude": 0.20}


def periods(t, u, start):
    """The whole periods of u after `start`: (t_begin, t_end, index_begin, index_end) between
    successive upward crossings of u's mean over the window."""
    window = [k for k in range(len(t)) if t[k] >= start]
    mean = sum(u[k] for k in window) / len(window)
    ups = [k for k in window[1:] if u[k - 1] < mean <= u[k]]
    # An upward crossing must follow a swing of at least a tenth of the range, so the
    # particles' noise near the mean does not cut a period into pieces.
    swing = 0.1 * (max(u[k] for k in window) - min(u[k] for k in window))
    kept = []
    for k in ups:
        if not kept or max(u[kept[-1]:k + 1]) - min(u[kept[-1]:k + 1]) > 2 * swing:
            kept.append(k)
    return [(t[a], t[b], a, b) for a, b in zip(kept, kept[1:])]


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    check = "--check" in sys.argv
    benchmark = "fsi2"
    if "--benchmark" in sys.argv:
        benchmark = sys.argv[sys.argv.index("--benchmark") + 1]
        args.remove(benchmark)
    if not args or benchmark not in REFERENCE:
        print(__doc__)
        return 2
    out = args[0]
    with open(os.path.join(out, "probes.csv")) as f:
        rows = list(csv.DictReader(f))
    if not rows or "bar_dy_m" not in rows[0]:
        print(f"{out}/probes.csv: no bar_dy_m column (is this a Turek & Hron FSI run?)")
        return 1
    t = [float(r["time_s"]) for r in rows]
    ux = [float(r["bar_dx_m"]) for r in rows]
    uy = [float(r["bar_dy_m"]) for r in rows]
    start = float(args[1]) if len(args) > 1 else t[-1] - (t[-1] - t[0]) / 3
    cycles = periods(t, uy, start)
    if not cycles:
        print(f"figures: from_s={start:.2f} to_s={t[-1]:.2f} periods=0 "
              "(u_y has no whole period in the window: no oscillation)")
        return 1 if check else 0

    def mean_of(f):
        return sum(f(c) for c in cycles) / len(cycles)

    figures = {
        "ux_mean": mean_of(lambda c: 0.5 * (max(ux[c[2]:c[3]]) + min(ux[c[2]:c[3]]))),
        "ux_amplitude": mean_of(lambda c: 0.5 * (max(ux[c[2]:c[3]]) - min(ux[c[2]:c[3]]))),
        "uy_mean": mean_of(lambda c: 0.5 * (max(uy[c[2]:c[3]]) + min(uy[c[2]:c[3]]))),
        "uy_amplitude": mean_of(lambda c: 0.5 * (max(uy[c[2]:c[3]]) - min(uy[c[2]:c[3]]))),
        "frequency_hz": 1.0 / mean_of(lambda c: c[1] - c[0]),
    }
    print(f"figures: benchmark={benchmark} from_s={start:.2f} to_s={t[-1]:.2f} "
          f"periods={len(cycles)} " + " ".join(f"{k}={v:.5g}" for k, v in figures.items()))
    missed = []
    reference = REFERENCE[benchmark]
    for key, value in figures.items():
        ref = reference[key]
        line = f"  {key}: {value:.5g} against {ref:.5g} ({100 * (value / ref - 1):+.1f} %)"
        if key in TOLERANCE:
            ok = abs(value / ref - 1) <= TOLERANCE[key]
            line += f", tolerance {100 * TOLERANCE[key]:.0f} %: {'met' if ok else 'MISSED'}"
            if not ok:
                missed.append(key)
        print(line)
    if shutil.which("gnuplot"):
        png = os.path.join(out, "fsi.png")
        data = os.path.join(out, "fsi_tip.dat")
        with open(data + ".tmp", "w") as g:
            for k in range(len(t)):
                g.write(f"{t[k]} {ux[k]} {uy[k]}\n")
        os.replace(data + ".tmp", data)
        r = reference
        script = f"""set terminal pngcairo size 1000,600
set output '{png}.tmp'
set multiplot layout 2,1 title 'Turek and Hron {benchmark.upper()}: the bar tip (point A)'
set ylabel 'u_y (m)'
set key outside
plot '{data}' using 1:3 with lines title 'chipflex', \
  {r['uy_mean'] + r['uy_amplitude']} with lines dt 2 lc 'black' title 'reference max', \
  {r['uy_mean'] - r['uy_amplitude']} with lines dt 2 lc 'black' title 'reference min'
set xlabel 't (s)'
set ylabel 'u_x (m)'
plot '{data}' using 1:2 with lines title 'chipflex', \
  {r['ux_mean'] + r['ux_amplitude']} with lines dt 2 lc 'black' title 'reference max', \
  {r['ux_mean'] - r['ux_amplitude']} with lines dt 2 lc 'black' title 'reference min'
unset multiplot
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
        os.replace(png + ".tmp", png)
        print(f"wrote {png}")
    if missed and check:
        print("missed: " + ", ".join(missed))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
