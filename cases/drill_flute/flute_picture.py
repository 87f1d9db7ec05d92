#!/usr/bin/env python3
"""A picture of a 3D drill-flute run in the manner of the seed paper's Fig. 1: the
coolant's fluid particles blue, the chips red, the barrier grey, seen perpendicular to the
flute (left: from the borehole side, along -x, onto the flute's opening; right: along +y,
across the flute's depth), the drill axis z upwards and the coolant flowing up.

    flute_picture.py OUT/VARIANT PNG [FRAME]

OUT/VARIANT is a `chipflex run` output folder of the 3D flute (particles/, skins/, walls/
frames); FRAME is the frame number (default: the last). Reads the HDF5 frames with
h5dump (Debian: hdf5-tools) and draws with gnuplot.
"""
import os
import re
import subprocess
import sys
import tempfile


def dataset(path, name):
    """The values of one HDF5 dataset, flat, as floats (h5dump's text output)."""
    text = subprocess.run(["h5dump", "-y", "-w", "0", "-d", name, path], check=True,
                          capture_output=True, text=True).stdout
    start = text.index("DATA {") + 6
    body = text[start:text.index("}", start)]
    return [float(v) for v in body.replace("\n", " ").split(",") if v.strip()]


def triangles(path, group):
    """The faces of a skin or wall surface, each as three (x, y, z) points."""
    x = dataset(path, f"/{group}/vertices")
    faces = [int(v) for v in dataset(path, f"/{group}/faces")]
    points = [x[3 * i:3 * i + 3] for i in range(len(x) // 3)]
    return [[points[faces[3 * f + k]] for k in range(3)] for f in range(len(faces) // 3)]


def main():
    if len(sys.argv) < 3:
        print(__doc__.strip().splitlines()[4].strip(), file=sys.stderr)
        return 2
    folder, png = sys.argv[1], sys.argv[2]
    frames = sorted(f for f in os.listdir(os.path.join(folder, "particles")) if f.endswith(".h5"))
    if not frames:
        raise SystemExit(f"flute_picture.py: {folder}/particles has no frames")
    frame = frames[-1] if len(sys.argv) < 4 else f"frame_{int(sys.argv[3]):06d}.h5"
    particles = os.path.join(folder, "particles", frame)
    # The frame's time from particles.xdmf (one Time per grid, in frame order).
    xdmf = open(os.path.join(folder, "particles.xdmf")).read()
    times = {m.group(2): m.group(1)
             for m in re.finditer(r'Time Value="([^"]+)".*?(frame_\d+\.h5)', xdmf, re.DOTALL)}
    label = f"t = {float(times[frame]) * 1e3:.1f} ms" if frame in times else frame
    kind = dataset(particles, "/kind")
    x = dataset(particles, "/position")
    fluid = [x[3 * i:3 * i + 3] for i, k in enumerate(kind) if k == 1]
    skins = os.path.join(folder, "skins", frame)
    names = subprocess.run(["h5dump", "-y", "-w", "0", "-d", "/names", skins], check=True,
                           capture_output=True, text=True).stdout
    chips = [n for n in ("chip1", "chip2", "chip3", "chip4") if f'"{n}"' in names]
    walls = os.path.join(folder, "walls", frame)

    with tempfile.TemporaryDirectory() as tmp:
        fluid_file, chip_file, barrier_file = (os.path.join(tmp, n) for n in
                                               ("fluid.dat", "chips.dat", "barrier.dat"))
        with open(fluid_file, "w") as f:
            f.writelines(f"{p[0]} {p[1]} {p[2]}\n" for p in fluid)
        with open(chip_file, "w") as f:
            for c in chips:
                for t in triangles(skins, c):
                    f.writelines(f"{p[0]} {p[1]} {p[2]}\n" for p in t + [t[0]])
                    f.write("\n")
        with open(barrier_file, "w") as f:
            for t in triangles(walls, "surface_2"):
                f.writelines(f"{p[0]} {p[1]} {p[2]}\n" for p in t + [t[0]])
                f.write("\n")
        mm = "($1*1e3)", "($2*1e3)", "($3*1e3)"

        def view(axis):
            """One panel: the coordinate `axis` (0 x, 1 y) across, z up."""
            u = f"{mm[axis]}:{mm[2]}"
            return (f"plot '{fluid_file}' using {u} with points pt 7 ps 0.25 lc rgb '#3060d0' notitle, "
                    f"'{barrier_file}' using {u} with lines lw 1 lc rgb '#808080' notitle, "
                    f"'{chip_file}' using {u} with filledcurves closed lc rgb '#d01010' notitle, "
                    f"'{chip_file}' using {u} with lines lw 1.5 lc rgb '#d01010' notitle\n")

        script = f"""set terminal pngcairo size 1100,900 font ',10'
set output '{png}.tmp'
set multiplot layout 1,2 title 'Drill flute, {os.path.basename(folder)} chips, {label}: coolant blue, chips red, barrier grey' noenhanced
set size ratio -1
set xlabel 'y (mm), across the flute'
set ylabel 'z (mm), drill axis (coolant flows up)'
set xrange [-9:9]
set yrange [-0.5:31]
{view(1)}set xlabel 'x (mm), flute depth (axis at 0, borehole wall at 10)'
set xrange [-0.5:10.5]
{view(0)}unset multiplot
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
    os.replace(png + ".tmp", png)
    print(f"wrote {png} ({len(fluid)} fluid particles, chips {', '.join(chips)})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
