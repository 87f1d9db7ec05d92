"""Opens the outputs of a `chipflex run` the way a user would (docs/output.md).

    check_outputs.py DIR [--stopped] [--no-bodies] [--paraview]

    check_outputs.py --body-xdmf OUT.xdmf BODY.h5

With h5py: every XDMF grid's topology, geometry and attributes name existing HDF5
datasets of the stated shapes, the particles' vertex cells are 0..n-1, (kind, id) is
unique in every frame, array names have no spaces and carry a unit (in the name
ParaView shows, e.g. pressure_Pa for the dataset pressure, and as Information), every
wall or body keeps one grid name through time, the three series share their frame
times, and summary.txt has its status line (status=stopped and a frame at the stop time
with --stopped); skins.xdmf is expected unless --no-bodies. The particles' global ids
(the XDMF's GlobalId attribute) are unique in every frame and follow the particle: a
fluid particle found by its id in two frames has moved no further than twice the
fastest fluid speed of the two frames allows, (kind, id) and the global id name the same
particle in every frame, and the body array is -1 for the fluid and names a wall or body
for every dummy particle; with bodies, the tank's dummy particles stay where they were
while a body's move. With --paraview (run under pvpython) the same files are also read
with ParaView's three XDMF readers: every frame gives cells, the id, global id and kind
arrays, the surface arrays, and the legacy reader's block names stay the same in every
frame.

--body-xdmf: the file of `chipflex info BODY.h5 --xdmf OUT.xdmf` parses, its geometry is
the body's n_nodes x 3 reference nodes, its cells the skin faces, and it has one point
vector array (n_nodes x 3) per mode, named mode_K_F_Hz, holding the body file's psi_K.
Exit status 0: all good; 1: a failure (printed); 77: neither h5py nor ParaView found.
"""

import os
import sys
import xml.etree.ElementTree as ET

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
    return condition


def parse(path):
    return ET.parse(path).getroot().find("Domain")


def item_info(item):
    dims = [int(d) for d in item.get("Dimensions").split()]
    file, dataset = item.text.strip().split(":", 1)
    return dims, file, dataset


def temporal_collections(domain):
    return [g for g in domain.findall("Grid") if g.get("CollectionType") == "Temporal"]


def grid_time(grid):
    return float(grid.find("Time").get("Value"))


def name_with_unit(name, unit):
    """The name ParaView shows for dataset `name` (apps/array_names.h)."""
    if unit in ("", "-"):
        return name
    spelt = ""
    for c in unit:
        if c.isalnum():
            spelt += c
        elif c != "^" and spelt and not spelt.endswith("_"):
            spelt += "_"
    return name + "_" + spelt


# The particles' arrays by dataset (what scripts read) and by the name ParaView shows.
PARTICLE_ARRAYS = {"velocity": "velocity_m_s", "pressure": "pressure_Pa",
                   "density": "density_kg_m3", "kind": "kind", "id": "id",
                   "global_id": "GlobalIds", "body": "body"}


# --- XDMF + HDF5 (h5py) --------------------------------------------------------------
def check_grid(directory, name, grid, h5py):
    """One Uniform grid: datasets exist with the shapes the XDMF states."""
    where = "%s t=%g" % (name, grid_time(grid))
    topology = grid.find("Topology")
    n_cells = int(topology.get("NumberOfElements"))
    item = topology.find("DataItem")
    if not check(item is not None, where + ": topology without connectivity"):
        return None
    dims, file, dataset = item_info(item)
    check(dims[0] == n_cells, where + ": connectivity rows %d != cells %d" % (dims[0], n_cells))
    with h5py.File(os.path.join(directory, file), "r") as h5:
        cells = h5[dataset][()]
        check(list(cells.shape) == dims, where + ": connectivity shape %s" % (cells.shape,))
        gitem = grid.find("Geometry").find("DataItem")
        gdims, gfile, gset = item_info(gitem)
        check(gfile == file, where + ": geometry in another file")
        n_points = h5[gset].shape[0]
        check(list(h5[gset].shape) == gdims, where + ": geometry shape")
        check(n_cells == 0 or (cells.min() >= 0 and cells.max() < n_points),
              where + ": connectivity out of range")
        arrays = {}
        for attribute in grid.findall("Attribute"):
            aname = attribute.get("Name")
            check(" " not in aname, where + ": array name with a space: '%s'" % aname)
            unit = attribute.find("Information")
            check(unit is not None and unit.get("Name") == "unit" and unit.get("Value"),
                  where + ": array '%s' has no unit" % aname)
            adims, afile, aset = item_info(attribute.find("DataItem"))
            # Keyed by the dataset's own name, which scripts read; ParaView shows the
            # name with its unit (the global id goes by VTK's name for global ids).
            bare = aset.rsplit("/", 1)[-1]
            if unit is not None and bare != "global_id":
                check(aname == name_with_unit(bare, unit.get("Value", "")),
                      where + ": array '%s' (unit %s) is not named with its unit"
                      % (aname, unit.get("Value")))
            aname = bare
            check(adims[0] == n_points, where + ": '%s' rows %d != points %d"
                  % (aname, adims[0], n_points))
            check(aset in h5 and list(h5[aset].shape) == adims,
                  where + ": '%s' dataset %s missing or misshapen" % (aname, aset))
            if aset in h5:
                arrays[aname] = h5[aset][()]
        return {"cells": cells, "n_points": n_points, "arrays": arrays}


def check_with_h5py(directory, stopped, series_expected):
    import h5py
    import numpy

    series_times = {}
    # particles.xdmf: one temporal collection, one grid per frame, one vertex per particle.
    domain = parse(os.path.join(directory, "particles.xdmf"))
    (collection,) = temporal_collections(domain)
    frames = collection.findall("Grid")
    check(len(frames) >= 2, "particles: fewer than two frames")
    check(len({f.get("Name") for f in frames}) == 1, "particles: grid name changes")
    times = [grid_time(f) for f in frames]
    check(all(a < b for a, b in zip(times, times[1:])), "particles: times not increasing")
    series_times["particles"] = times
    for f in frames:
        g = check_grid(directory, "particles", f, h5py)
        if g is None:
            continue
        check(f.find("Topology").get("TopologyType") == "Polyvertex", "particles: not Polyvertex")
        check(numpy.array_equal(g["cells"], numpy.arange(g["n_points"])),
              "particles t=%g: cells are not 0..n-1" % grid_time(f))
        for a in PARTICLE_ARRAYS:
            check(a in g["arrays"], "particles t=%g: no '%s'" % (grid_time(f), a))
        if "id" in g["arrays"] and "kind" in g["arrays"]:
            kind, ident = g["arrays"]["kind"], g["arrays"]["id"]
            check(set(numpy.unique(kind)) <= {0, 1}, "particles: kind not 0/1")
            for k in (0, 1):
                ids = ident[kind == k]
                check(len(numpy.unique(ids)) == len(ids),
                      "particles t=%g: kind %d ids not unique" % (grid_time(f), k))
        global_ids = [a for a in f.findall("Attribute") if a.get("Name") == "GlobalIds"]
        check(len(global_ids) == 1 and global_ids[0].get("AttributeType") == "GlobalId",
              "particles t=%g: no attribute GlobalIds of AttributeType GlobalId" % grid_time(f))
    print("h5py: particles.xdmf %d frames, %s particles" % (
        len(frames), [int(f.find("Topology").get("NumberOfElements")) for f in frames]))
    check_particle_identity(directory, frames, "skins" in series_expected, h5py, numpy)

    # walls.xdmf, skins.xdmf: one temporal collection per surface, named after it.
    expected = {"walls": ["velocity", "fluid_force"],
                "skins": ["displacement", "velocity", "fluid_force", "contact_force"]}
    for series, arrays in expected.items():
        if series not in series_expected:
            continue
        path = os.path.join(directory, series + ".xdmf")
        if not check(os.path.exists(path), "no %s.xdmf" % series):
            continue
        collections = temporal_collections(parse(path))
        check(collections, series + ": no surfaces")
        names = []
        for c in collections:
            name = c.get("Name")
            names.append(name)
            frames = c.findall("Grid")
            check({f.get("Name") for f in frames} == {name},
                  "%s/%s: grid names change over time" % (series, name))
            series_times["%s/%s" % (series, name)] = [grid_time(f) for f in frames]
            for f in frames:
                g = check_grid(directory, series + "/" + name, f, h5py)
                if g is None:
                    continue
                check(len(g["cells"]) > 0, "%s/%s: no cells" % (series, name))
                for a in arrays:
                    check(a in g["arrays"], "%s/%s: no '%s'" % (series, name, a))
                if series == "skins" and f is frames[0] and "displacement" in g["arrays"]:
                    check(abs(g["arrays"]["displacement"]).max() == 0,
                          "skins/%s: displacement at the first frame is not 0" % name)
        print("h5py: %s.xdmf surfaces %s, %d frames" % (series, names, len(frames)))
    reference = series_times["particles"]
    for name, times in series_times.items():
        check(times == reference, "%s: frame times differ from the particles'" % name)

    with open(os.path.join(directory, "summary.txt")) as f:
        status = f.readline()
    check(status.startswith("status=" + ("stopped" if stopped else "finished")),
          "summary.txt status line: " + status.strip())
    if stopped:
        check('reason="' in status, "summary.txt: stopped without a reason")
        t_stop = float(status.split(" t_s=")[1].split()[0])
        check(abs(reference[-1] - t_stop) <= 1e-8 * max(1.0, t_stop),
              "no frame at the stop time %g (last %g)" % (t_stop, reference[-1]))
    for f in ("probes.csv",):
        check(os.path.exists(os.path.join(directory, f)), "no " + f)


def read_particles(directory, frame, h5py):
    """One frame's datasets by name, and its wall and body names."""
    _, file, _ = item_info(frame.find("Geometry").find("DataItem"))
    with h5py.File(os.path.join(directory, file), "r") as h5:
        data = {k: h5[k][()] for k in ("position", "velocity", "kind", "id", "global_id", "body")
                if k in h5}
        names = [n.decode() if isinstance(n, bytes) else n for n in h5["body_names"][()]] \
            if "body_names" in h5 else []
    return data, names


def check_particle_identity(directory, frames, with_bodies, h5py, numpy):
    """Global ids: unique, following the particle from frame to frame; the body array."""
    first_names, pairs, tracked, origin = None, 0, [], {}
    previous = None
    for f in frames:
        t = grid_time(f)
        p, names = read_particles(directory, f, h5py)
        if not check(all(k in p for k in ("global_id", "body")),
                     "particles t=%g: no global_id or body dataset" % t):
            return
        gid, kind, body = p["global_id"], p["kind"], p["body"]
        check(len(numpy.unique(gid)) == len(gid), "particles t=%g: global ids not unique" % t)
        # (kind, id) and the global id name the same particle in every frame, and a
        # dummy particle stays with its wall or body.
        for g, k, i, b in zip(gid.tolist(), kind.tolist(), p["id"].tolist(), body.tolist()):
            if origin.setdefault(g, (k, i, b)) != (k, i, b):
                check(False, "particles t=%g: global id %d was (kind, id, body) %s, now %s"
                      % (t, g, origin[g], (k, i, b)))
                break
        if first_names is None:
            first_names = names
        check(names == first_names, "particles t=%g: body names %s, first frame %s"
              % (t, names, first_names))
        check(numpy.all(body[kind == 1] == -1), "particles t=%g: a fluid particle's body is not -1" % t)
        check(numpy.all((body[kind == 0] >= 0) & (body[kind == 0] < len(names))),
              "particles t=%g: a dummy particle's body is not one of %s" % (t, names))
        if previous is not None:
            # A fluid particle found by its global id in both frames moved continuously:
            # no further than twice the fastest fluid speed of the two frames allows. A
            # global id that stood for another particle in the next frame would jump by
            # the size of the water body.
            tp, q = previous
            fluid_now, fluid_then = kind == 1, q["kind"] == 1
            common, i_now, i_then = numpy.intersect1d(
                gid[fluid_now], q["global_id"][fluid_then], return_indices=True)
            x_now = p["position"][fluid_now][i_now]
            x_then = q["position"][fluid_then][i_then]
            speeds = numpy.concatenate([numpy.linalg.norm(p["velocity"][fluid_now], axis=1),
                                        numpy.linalg.norm(q["velocity"][fluid_then], axis=1)])
            finite = numpy.all(numpy.isfinite(x_now)) and numpy.all(numpy.isfinite(x_then)) \
                and numpy.all(numpy.isfinite(speeds))
            n_before = int(numpy.count_nonzero(fluid_then))
            check(len(common) >= 0.9 * n_before,
                  "particles t=%g..%g: only %d of %d fluid particles found again by id"
                  % (tp, t, len(common), n_before))
            if finite and len(common):
                step = numpy.linalg.norm(x_now - x_then, axis=1)
                bound = 2 * speeds.max() * (t - tp) + 1e-9
                worst = int(numpy.argmax(step))
                check(step[worst] <= bound,
                      "particles t=%g..%g: fluid particle %d jumped %.4g m (bound %.4g m)"
                      % (tp, t, common[worst], step[worst], bound))
                tracked.append(float(numpy.median(step)))
            pairs += 1
        previous = (t, p)
    # The tank's dummy particles stay put; a body's move with it (first to last frame).
    first, _ = read_particles(directory, frames[0], h5py)
    last, _ = read_particles(directory, frames[-1], h5py)
    moved = {}
    for b, name in enumerate(first_names or []):
        ids, i_first, i_last = numpy.intersect1d(first["global_id"][first["body"] == b],
                                                 last["global_id"][last["body"] == b],
                                                 return_indices=True)
        if len(ids):
            x0 = first["position"][first["body"] == b][i_first]
            x1 = last["position"][last["body"] == b][i_last]
            moved[name] = float(numpy.linalg.norm(x1 - x0, axis=1).max())
    if "tank" in moved:
        check(moved["tank"] == 0, "the tank's dummy particles moved %g m" % moved["tank"])
    if with_bodies:
        skins = [c.get("Name") for c in temporal_collections(parse(os.path.join(directory,
                                                                                "skins.xdmf")))]
        bodies = [n for n in moved if n in skins]
        check(bodies, "no body has dummy particles of its own (body names %s, skins %s)"
              % (first_names, skins))
        check(any(moved[n] > 0 for n in bodies),
              "no body's dummy particles moved: %s" % {n: moved[n] for n in bodies})
    print("h5py: global ids unique, %d frame pairs tracked (median step %s m); bodies %s, "
          "dummy particles moved %s m" % (pairs, ["%.2g" % s for s in tracked], first_names,
                                         {n: "%.3g" % v for n, v in moved.items()}))


def check_body_xdmf(xdmf, body_file):
    """`chipflex info BODY.h5 --xdmf OUT.xdmf`: mesh and mode shapes of the body file."""
    import h5py
    import numpy

    directory = os.path.dirname(os.path.abspath(xdmf))
    grids = parse(xdmf).findall("Grid")
    if not check(len(grids) == 1, "%s: %d grids, expected 1" % (xdmf, len(grids))):
        return
    grid = grids[0]
    with h5py.File(body_file, "r") as body:
        nodes = body["mesh/nodes"][()]
        faces = body["mesh/skin/faces"][()]
        psi = body["modes/psi"][()]
        frequencies = body["modes/frequencies_hz"][()]
    n, dim = nodes.shape
    m = psi.shape[1]
    topology = grid.find("Topology")
    check(topology.get("TopologyType") == ("Polyline" if dim == 2 else "Triangle"),
          "body xdmf: topology %s for a %dD body" % (topology.get("TopologyType"), dim))
    tdims, tfile, tset = item_info(topology.find("DataItem"))
    gdims, gfile, gset = item_info(grid.find("Geometry").find("DataItem"))
    check(gdims == [n, 3], "body xdmf: geometry dimensions %s, expected [%d, 3]" % (gdims, n))
    check(tdims == list(faces.shape), "body xdmf: cells %s, skin faces %s" % (tdims, faces.shape))
    attributes = grid.findall("Attribute")
    check(len(attributes) == m, "body xdmf: %d arrays for %d modes" % (len(attributes), m))
    with h5py.File(os.path.join(directory, gfile), "r") as h5:
        xyz = h5[gset][()]
        check(xyz.shape == (n, 3), "body xdmf: nodes dataset %s, expected (%d, 3)" % (xyz.shape, n))
        if xyz.shape == (n, 3):
            check(numpy.array_equal(xyz[:, :dim], nodes) and not xyz[:, dim:].any(),
                  "body xdmf: nodes differ from the body file's")
        cells = h5[tset][()] if tfile == gfile and tset in h5 else None
        check(cells is not None and numpy.array_equal(cells, faces),
              "body xdmf: cells differ from the body file's skin faces")
        names = []
        for k, attribute in enumerate(attributes):
            name = attribute.get("Name")
            names.append(name)
            check(attribute.get("AttributeType") == "Vector" and attribute.get("Center") == "Node",
                  "body xdmf: %s is not a point vector" % name)
            check(name.startswith("mode_%d_" % (k + 1)) and name.endswith("_Hz") and " " not in name,
                  "body xdmf: array %d named %s" % (k + 1, name))
            f = float(name[len("mode_%d_" % (k + 1)):-len("_Hz")])
            check(abs(f - frequencies[k]) <= 1e-3 * abs(frequencies[k]) + 1e-3,
                  "body xdmf: %s, the body file's frequency is %g Hz" % (name, frequencies[k]))
            adims, afile, aset = item_info(attribute.find("DataItem"))
            check(adims == [n, 3] and afile == gfile, "body xdmf: %s dimensions %s" % (name, adims))
            shape = h5[aset][()] if aset in h5 else None
            if check(shape is not None and shape.shape == (n, 3),
                     "body xdmf: %s dataset %s missing or not %d x 3" % (name, aset, n)):
                check(numpy.array_equal(shape[:, :dim], psi[:, k].reshape(n, dim))
                      and not shape[:, dim:].any(),
                      "body xdmf: %s is not the body file's psi_%d" % (name, k + 1))
    print("h5py: %s: %d nodes x 3, %d cells, arrays %s" % (os.path.basename(xdmf), n,
                                                            len(faces), names))


# --- ParaView ----------------------------------------------------------------------------
def leaves(data, name=None):
    """(block name, dataset) of every leaf of a composite data set."""
    if data is None:
        return []
    if data.IsA("vtkDataSet"):
        return [(name, data)]
    out = []
    if data.IsA("vtkMultiPieceDataSet"):
        for i in range(data.GetNumberOfPieces()):
            out += leaves(data.GetPiece(i), name)
        return out
    for i in range(data.GetNumberOfBlocks()):
        child_name = None
        if data.HasMetaData(i) and data.GetMetaData(i).Has(data.NAME()):
            child_name = data.GetMetaData(i).Get(data.NAME())
        out += leaves(data.GetBlock(i), child_name)
    return out


def check_with_paraview(directory, series_expected):
    from paraview import servermanager
    from paraview import simple

    readers = {
        "XDMFReader": lambda f: simple.XDMFReader(FileNames=[f]),
        "Xdmf3ReaderS": lambda f: simple.Xdmf3ReaderS(FileName=f),
        "Xdmf3ReaderT": lambda f: simple.Xdmf3ReaderT(FileName=f),
    }
    # The names ParaView shows; a force is in N/m in 2D, N in 3D.
    force = lambda a: [a + "_N_m", a + "_N"]
    expected = {"particles": [[n] for n in PARTICLE_ARRAYS.values()],
                "walls": [["velocity_m_s"], force("fluid_force")],
                "skins": [["displacement_m"], ["velocity_m_s"], force("fluid_force"),
                          force("contact_force")]}
    for series, arrays in expected.items():
        if series not in series_expected:
            continue
        path = os.path.abspath(os.path.join(directory, series + ".xdmf"))
        for reader_name, make in readers.items():
            reader = make(path)
            times = list(reader.TimestepValues)
            report, names_per_frame = [], []
            for t in times:
                reader.UpdatePipeline(t)
                blocks = leaves(servermanager.Fetch(reader))
                names_per_frame.append([n for n, _ in blocks])
                where = "%s %s t=%g" % (reader_name, series, t)
                check(blocks, where + ": no data")
                for name, data in blocks:
                    n_cells, n_points = data.GetNumberOfCells(), data.GetNumberOfPoints()
                    check(n_cells > 0, "%s %s: 0 cells (%d points)" % (where, name, n_points))
                    if series == "particles":
                        check(n_cells == n_points, "%s: %d cells for %d particles"
                              % (where, n_cells, n_points))
                    point_data = data.GetPointData()
                    for a in arrays:
                        check(any(point_data.GetArray(b) is not None for b in a),
                              "%s %s: no '%s'" % (where, name, " or ".join(a)))
                    if series == "particles":
                        ids = point_data.GetGlobalIds()
                        check(ids is not None and ids.GetName() == "GlobalIds",
                              "%s: GlobalIds are not the point data's global ids" % where)
                report.append("/".join("%s:%dc" % (n, d.GetNumberOfCells()) for n, d in blocks))
            if reader_name == "XDMFReader" and series != "particles":
                check(all(n == names_per_frame[0] for n in names_per_frame),
                      "%s %s: block names change: %s" % (reader_name, series, names_per_frame))
            if series != "particles":
                check(all(len(n) == len(names_per_frame[0]) for n in names_per_frame),
                      "%s %s: block count changes" % (reader_name, series))
            point_arrays = sorted(reader.PointData.keys())
            simple.Delete(reader)
            if not check(report, "%s %s: no time steps" % (reader_name, series)):
                continue
            print("paraview %s %s: %d times, first %s, last %s, arrays %s" % (
                reader_name, series, len(times), report[0], report[-1], point_arrays))


def main():
    args = sys.argv[1:]
    if args and args[0] == "--body-xdmf":
        try:
            check_body_xdmf(args[1], args[2])
        except ImportError:
            print("h5py not found: body XDMF checks skipped")
            sys.exit(77)
        for f in failures:
            print("FAIL:", f)
        sys.exit(1 if failures else 0)
    directory = [a for a in args if not a.startswith("--")][0]
    stopped = "--stopped" in args
    series = ["particles", "walls"] + ([] if "--no-bodies" in args else ["skins"])
    ran = False
    try:
        import h5py  # noqa: F401
        check_with_h5py(directory, stopped, series)
        ran = True
    except ImportError:
        print("h5py not found: HDF5 checks skipped")
    if "--paraview" in args:
        check_with_paraview(directory, series)
        ran = True
    if not ran:
        sys.exit(77)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
