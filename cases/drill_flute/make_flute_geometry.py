#!/usr/bin/env python3
"""Surface meshes (ASCII STL, metres) of a straight segment of a single-lip drill's flute.

The drill axis is z, the coolant flows along +z (tip at z = 0, top at z = length); the
flute's bisector is +x. The flute is a V of opening angle `--flute-angle` whose apex lies
`--flute-depth` in from the borehole wall along the bisector (depth = radius: the apex on
the axis, as in the classic 120-degree single-lip profile). Writes into `--out`:

  flute_walls.stl   the two flanks of the V (the drill body), normals into the flute
  borehole.stl      the borehole wall over the flute (the flute's angle and --bore-margin
                    each side), radius D/2, normals inwards; it turns in place (a moving
                    wall with `in place = true`), so it need not be a full cylinder
  barrier.stl       the permeable barrier across the flute at z = --barrier, normal -z
                    (chips coming from the tip are stopped)
  flute_region.stl  the closed flute section swept along z (the fluid region), normals out

The walls and the region reach --margin beyond both ends so that they span the inlet and
outlet buffers. Everything is deterministic (the same arguments give the same bytes).
"""
import argparse
import math
import os
import sys


def write_stl(path, name, triangles):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(f"solid {name}\n")
        for a, b, c in triangles:
            u = [b[i] - a[i] for i in range(3)]
            v = [c[i] - a[i] for i in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            l = math.sqrt(sum(x * x for x in n)) or 1.0
            f.write("  facet normal %.9e %.9e %.9e\n    outer loop\n" % tuple(x / l for x in n))
            for p in (a, b, c):
                f.write("      vertex %.9e %.9e %.9e\n" % tuple(p))
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {name}\n")
    os.replace(tmp, path)


def quad(t, p00, p10, p11, p01):
    """Two triangles with the normal of (p10 - p00) x (p01 - p00)."""
    t.append((p00, p10, p11))
    t.append((p00, p11, p01))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--diameter", type=float, default=0.02, help="drill (= borehole) diameter D, m")
    ap.add_argument("--flute-angle", type=float, default=120, help="opening angle of the V, degrees")
    ap.add_argument("--flute-depth", type=float, default=None,
                    help="borehole wall to the V's apex along the bisector, m (default D/2)")
    ap.add_argument("--length", type=float, default=0.03, help="segment length along the axis, m")
    ap.add_argument("--barrier", type=float, default=0.02, help="barrier position z, m")
    ap.add_argument("--margin", type=float, default=0.004, help="walls beyond both ends, m")
    ap.add_argument("--bore-margin", type=float, default=15,
                    help="borehole wall beyond the flute's edges, degrees")
    ap.add_argument("--size", type=float, default=0.001, help="triangle edge, m")
    ap.add_argument("--out", default=".", help="output folder")
    a = ap.parse_args()
    R = a.diameter / 2
    depth = R if a.flute_depth is None else a.flute_depth
    half = math.radians(a.flute_angle) / 2
    bad = None
    if not (a.diameter > 0 and a.length > 0 and a.size > 0 and a.margin >= 0):
        bad = "diameter, length and size must be positive, margin >= 0"
    elif not (0 < a.flute_angle < 180):
        bad = "--flute-angle must lie in (0, 180) degrees"
    elif not (0 < depth <= a.diameter):
        bad = "--flute-depth must lie in (0, D]"
    elif not (0 < a.barrier < a.length):
        bad = "--barrier must lie inside (0, length)"
    if bad:
        print(f"make_flute_geometry.py: {bad}", file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    apex = (R - depth, 0.0)

    def flank_end(sign):
        # apex + s (cos, sin) on the circle |p| = R
        d = (math.cos(half), sign * math.sin(half))
        b = apex[0] * d[0] + apex[1] * d[1]
        c = apex[0] ** 2 + apex[1] ** 2 - R * R
        s = -b + math.sqrt(b * b - c)
        return (apex[0] + s * d[0], apex[1] + s * d[1])

    top, bottom = flank_end(+1), flank_end(-1)
    z0, z1 = -a.margin, a.length + a.margin
    nz = max(1, math.ceil((z1 - z0) / a.size))
    zs = [z0 + (z1 - z0) * k / nz for k in range(nz + 1)]

    def line(p, q, n):
        return [(p[0] + (q[0] - p[0]) * k / n, p[1] + (q[1] - p[1]) * k / n) for k in range(n + 1)]

    # Flanks: fluid between them (normal towards the bisector).
    walls = []
    for end, sign in ((top, +1), (bottom, -1)):
        n = max(1, math.ceil(math.dist(apex, end) / a.size))
        pts = line(apex, end, n)
        for i in range(n):
            for k in range(nz):
                p00 = (*pts[i], zs[k]); p10 = (*pts[i + 1], zs[k])
                p11 = (*pts[i + 1], zs[k + 1]); p01 = (*pts[i], zs[k + 1])
                # (p10 - p00) along the flank outwards, (p01 - p00) along +z: their cross
                # product on the upper flank (sign +1) points towards the bisector.
                if sign > 0:
                    quad(walls, p00, p10, p11, p01)
                else:
                    quad(walls, p00, p01, p11, p10)
    write_stl(os.path.join(a.out, "flute_walls.stl"), "flute_walls", walls)

    # The flute section as a polygon: apex, bottom flank end, the arc, top flank end.
    phi0, phi1 = math.atan2(bottom[1], bottom[0]), math.atan2(top[1], top[0])
    narc = max(2, math.ceil(R * (phi1 - phi0) / a.size))
    arc = [(R * math.cos(phi0 + (phi1 - phi0) * j / narc), R * math.sin(phi0 + (phi1 - phi0) * j / narc))
           for j in range(narc + 1)]
    section = [apex] + arc  # counter-clockwise

    # Borehole wall over the flute and a margin, normals inwards.
    b0, b1 = phi0 - math.radians(a.bore_margin), phi1 + math.radians(a.bore_margin)
    nphi = max(2, math.ceil(R * (b1 - b0) / a.size))
    ring = [(R * math.cos(b0 + (b1 - b0) * j / nphi), R * math.sin(b0 + (b1 - b0) * j / nphi))
            for j in range(nphi + 1)]
    bore = []
    for j in range(nphi):
        p, q = ring[j], ring[j + 1]
        for k in range(nz):
            # counter-clockwise p -> q and +z: (q - p) x z points outwards; reverse it.
            quad(bore, (*p, zs[k]), (*p, zs[k + 1]), (*q, zs[k + 1]), (*q, zs[k]))
    write_stl(os.path.join(a.out, "borehole.stl"), "borehole", bore)

    # Barrier: the section grown by half a triangle edge (so a chip's corner at a wall
    # still meets it), fanned from its centroid in rings, normal -z.
    cx = sum(p[0] for p in section) / len(section)
    cy = sum(p[1] for p in section) / len(section)
    grow = 0.5 * a.size
    outline = []
    for p in section:
        d = math.hypot(p[0] - cx, p[1] - cy)
        outline.append((cx + (p[0] - cx) * (d + grow) / d, cy + (p[1] - cy) * (d + grow) / d))
    nr = max(1, math.ceil(max(math.hypot(p[0] - cx, p[1] - cy) for p in outline) / a.size))
    barrier = []
    for j in range(len(outline)):
        p, q = outline[j], outline[(j + 1) % len(outline)]
        for i in range(nr):
            r0, r1 = i / nr, (i + 1) / nr
            a0 = (cx + r0 * (p[0] - cx), cy + r0 * (p[1] - cy), a.barrier)
            b0 = (cx + r0 * (q[0] - cx), cy + r0 * (q[1] - cy), a.barrier)
            a1 = (cx + r1 * (p[0] - cx), cy + r1 * (p[1] - cy), a.barrier)
            b1 = (cx + r1 * (q[0] - cx), cy + r1 * (q[1] - cy), a.barrier)
            # counter-clockwise p -> q seen from +z: (b1 - a0) x (a1 - a0) points -z.
            if i == 0:
                barrier.append((a0, b1, a1))
            else:
                barrier.append((a0, b1, a1))
                barrier.append((a0, b0, b1))
    write_stl(os.path.join(a.out, "barrier.stl"), "barrier", barrier)

    # Fluid region: the section swept from z0 to z1, closed, normals outwards.
    region = []
    m = len(section)
    for j in range(m):
        p, q = section[j], section[(j + 1) % m]
        quad(region, (*p, z0), (*q, z0), (*q, z1), (*p, z1))
    for j in range(1, m - 1):
        region.append(((*section[0], z0), (*section[j + 1], z0), (*section[j], z0)))
        region.append(((*section[0], z1), (*section[j], z1), (*section[j + 1], z1)))
    write_stl(os.path.join(a.out, "flute_region.stl"), "flute_region", region)

    area = 0.5 * sum(section[j][0] * section[(j + 1) % m][1] - section[(j + 1) % m][0] * section[j][1]
                     for j in range(m))
    xs, ys = [p[0] for p in section], [p[1] for p in section]
    print(f"flute section area {area:.6e} m^2, box x {min(xs):.6f} .. {max(xs):.6f}, "
          f"y {min(ys):.6f} .. {max(ys):.6f} m")
    return 0


if __name__ == "__main__":
    sys.exit(main())
