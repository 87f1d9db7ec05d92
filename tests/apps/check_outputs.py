"""Opens the outputs of a `chipflex run` the way a user would (docs/output.md).

    check_outputs.py DIR [--stopped] [--no-bodies] [--paraview]

With h5py: every XDMF grid's topology, geometry and attributes name existing HDF5
datasets of the stated shapes, the particles' vertex cells are 0..n-1, (kind, id) is
unique in every frame, array names have no spaces and carry a unit, every wall or body
keeps one grid name through time, the three series share their frame times, and
summary.txt has its status line (status=stopped and a frame at the stop time with
--stopped); skins.xdmf is expected unless --no-bodies. With --paraview (run under pvpython) the same files are also read with
ParaView's three XDMF readers: every frame gives cells, the id and kind arrays, the
surface arrays, and the legacy reader's block names stay the same in every frame.
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
        for a in ("velocity", "pressure", "density", "kind", "id"):
            check(a in g["arrays"], "particles t=%g: no '%s'" % (grid_time(f), a))
        if "id" in g["arrays"] and "kind" in g["arrays"]:
            kind, ident = g["arrays"]["kind"], g["arrays"]["id"]
            check(set(numpy.unique(kind)) <= {0, 1}, "particles: kind not 0/1")
            for k in (0, 1):
                ids = ident[kind == k]
                check(len(numpy.unique(ids)) == len(ids),
                      "particles t=%g: kind %d ids not unique" % (grid_time(f), k))
    print("h5py: particles.xdmf %d frames, %s particles" % (
        len(frames), [int(f.find("Topology").get("NumberOfElements")) for f in frames]))

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
    expected = {"particles": ["velocity", "pressure", "density", "kind", "id"],
                "walls": ["velocity", "fluid_force"],
                "skins": ["displacement", "velocity", "fluid_force", "contact_force"]}
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
                        check(point_data.GetArray(a) is not None, "%s %s: no '%s'" % (where, name, a))
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
