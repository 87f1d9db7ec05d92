#!/usr/bin/env python3
"""Drag, lift and Strouhal number of the Re-100 cylinder (cylinder_re100.prm) against the
bounds of Schaefer & Turek (1996), benchmark 2D-2.

    python3 plot_cylinder.py OUT [FROM_S]

reads OUT/probes.csv (the moving wall's `cylinder_force_x_N`, `cylinder_force_y_N`, per
metre of depth), takes the periodic part from FROM_S (default: the last half of the run),
and prints one `figures:` line: the drag and lift coefficients
c_D = 2 F_x / (rho U^2 D), c_L = 2 F_y / (rho U^2 D) (rho = 1000 kg/m^3, U = 1 m/s,
D = 0.1 m); the shedding frequency f, the lift's strongest Fourier component between 0.5
and 10 Hz (the wall forces of SPH carry noise far above it), and St = f D / U; the lift's
amplitude at f and the drag's at 2 f, and their largest values as mean + amplitude (the
benchmark's c_D max and c_L max). OUT/cylinder.png (gnuplot, if present) draws c_D and c_L
against time, as running means over a tenth of the shedding period.
"""
import csv
import math
import os
import shutil
import subprocess
import sys

RHO, U, D = 1000.0, 1.0, 0.1
PUBLISHED = {"cd_max": (3.22, 3.24), "cl_max": (0.99, 1.01), "st": (0.295, 0.305)}


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    out = sys.argv[1]
    with open(os.path.join(out, "probes.csv")) as f:
        rows = list(csv.DictReader(f))
    if not rows or "cylinder_force_x_N" not in rows[0]:
        print(f"{out}/probes.csv: no cylinder_force_x_N column (is this cylinder_re100.prm's output?)")
        return 1
    t = [float(r["time_s"]) for r in rows]
    scale = 2.0 / (RHO * U * U * D)
    cd = [scale * float(r["cylinder_force_x_N"]) for r in rows]
    cl = [scale * float(r["cylinder_force_y_N"]) for r in rows]
    start = float(sys.argv[2]) if len(sys.argv) > 2 else 0.5 * t[-1]
    k0 = next(k for k, x in enumerate(t) if x >= start)
    window = range(k0, len(t))
    n = len(window)
    cd_mean = sum(cd[k] for k in window) / n
    cl_mean = sum(cl[k] for k in window) / n

    def amplitude(values, mean, freq):
        """The amplitude of `values` at `freq` (a discrete Fourier sum over the window)."""
        re = sum((values[k] - mean) * math.cos(2 * math.pi * freq * t[k]) for k in window)
        im = sum((values[k] - mean) * math.sin(2 * math.pi * freq * t[k]) for k in window)
        return 2 * math.hypot(re, im) / n

    # The shedding frequency: the lift's strongest component between 0.5 and 10 Hz (the
    # particles' noise and the channel's acoustics lie far above; St 0.3 gives 3 Hz).
    span = t[-1] - t[k0]
    freqs = [0.5 + k / (8 * span) for k in range(int(9.5 * 8 * span))]
    f = max(freqs, key=lambda q: amplitude(cl, cl_mean, q))
    cl_amplitude = amplitude(cl, cl_mean, f)
    cd_amplitude = amplitude(cd, cd_mean, 2 * f)  # drag oscillates at twice the shedding
    # Curves for the plot: a running mean over a tenth of the shedding period.
    width = max(1, int(round(0.1 / f / (t[1] - t[0]))))
    smooth = [sum(cl[max(0, k - width + 1):k + 1]) / len(cl[max(0, k - width + 1):k + 1])
              for k in range(len(cl))]
    smooth_cd = [sum(cd[max(0, k - width + 1):k + 1]) / len(cd[max(0, k - width + 1):k + 1])
                 for k in range(len(cd))]
    figures = {
        "cd_max": cd_mean + cd_amplitude,
        "cl_max": cl_mean + cl_amplitude,
        "st": f * D / U,
    }
    line = (f"figures: from_s={start:.2f} to_s={t[-1]:.2f} cd_mean={cd_mean:.3f} "
            f"cd_amplitude={cd_amplitude:.3f} cd_max={figures['cd_max']:.3f} "
            f"cl_mean={cl_mean:.3f} cl_amplitude={cl_amplitude:.3f} "
            f"cl_max={figures['cl_max']:.3f} frequency_hz={f:.3f} st={figures['st']:.4f}")
    print(line)
    for key, (lo, hi) in PUBLISHED.items():
        mid = 0.5 * (lo + hi)
        print(f"  {key}: {figures[key]:.4f} against {lo} ... {hi} "
              f"({100 * (figures[key] / mid - 1):+.1f} % from the middle)")
    if shutil.which("gnuplot"):
        png = os.path.join(out, "cylinder.png")
        data = os.path.join(out, "cylinder_coefficients.dat")
        with open(data + ".tmp", "w") as g:
            for k in range(len(t)):
                g.write(f"{t[k]} {smooth_cd[k]} {smooth[k]}\n")
        os.replace(data + ".tmp", data)
        script = f"""set terminal pngcairo size 1000,500
set output '{png}.tmp'
set xlabel 't (s)'
set ylabel 'coefficient'
set key outside
set title 'cylinder at Re 100, running means over a tenth of the shedding period (Schaefer and Turek 2D-2: c_D max 3.22-3.24, c_L max 0.99-1.01, St 0.295-0.305)'
plot '{data}' using 1:2 with lines title 'c_D', '' using 1:3 with lines title 'c_L'
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
        os.replace(png + ".tmp", png)
        print(f"wrote {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
