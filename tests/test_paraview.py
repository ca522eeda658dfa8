#!/usr/bin/env python3
"""Our HDF5 + XDMF snapshot series opened by ParaView's own reader (make test-paraview; issue 17).

The reader is ParaView's XDMF 3 reader, vtkXdmf3Reader, as Debian's python3-paraview ships it (the module
vtkmodules.vtkIOXdmf3; python3-vtk9 alone has no XDMF reader). Two series are read:
1. a known series written by the library's SnapshotSeries (build/bin/snapshot_sample): three snapshots whose
   fields are closed forms of the particle index and the time (tests/tools/snapshot_sample.cpp); every time,
   every point and every array value must be what was written, exactly (doubles are stored and read as
   doubles), and the positions-only snapshot must carry no particle arrays;
2. optionally (--series DIR) every *.xdmf a driver wrote under DIR (the hexagon's snapshots of H-fig4): the
   reader's times must be the series' <Time> values in order, each step's points the declared particle count,
   and every array finite.
Exit 0 only if every check passed; each failure is printed.
"""
import argparse
import glob
import math
import os
import re
import subprocess
import sys
import tempfile

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL: " + what)
    return cond


def open_series(path):
    from vtkmodules.vtkIOXdmf3 import vtkXdmf3Reader
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
    reader = vtkXdmf3Reader()
    reader.SetFileName(path)
    reader.UpdateInformation()
    times = reader.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    return reader, list(times) if times else []


def step(reader, t):
    """Points (n x 3) and point arrays {name: list of tuples} of the step at time t."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader.UpdateTimeStep(t)
    grid = reader.GetOutputDataObject(0)
    pts = vtk_to_numpy(grid.GetPoints().GetData()).tolist() if grid.GetPoints() else []
    arrays = {}
    pd = grid.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        a = pd.GetArray(i)
        v = vtk_to_numpy(a).tolist()
        arrays[a.GetName()] = [x if isinstance(x, list) else [x] for x in v]
    return pts, arrays


def known_series(sample_bin):
    with tempfile.TemporaryDirectory() as tmp:
        h5 = os.path.join(tmp, "sample.h5")
        subprocess.run([sample_bin, h5], check=True)
        reader, times = open_series(os.path.join(tmp, "sample.xdmf"))
        check(times == [0.0, 0.25, 1.5], f"known series: times {times}, written 0, 0.25, 1.5")
        compared = 0
        for s, t in enumerate(times):
            pts, arrays = step(reader, t)
            check(len(pts) == 7, f"known series t = {t}: {len(pts)} points, written 7")
            for i, p in enumerate(pts):
                check(p == [0.5 * i, -i + t, 0.0], f"known series t = {t}: point {i} = {p}")
            if s == 2:  # positions only
                check(not arrays, f"known series t = {t}: arrays {sorted(arrays)} in a positions-only snapshot")
                continue
            want = {"velocity": lambda i: [t + i, 2.0 * i], "density": lambda i: [1000.0 + i + t],
                    "stress_xx_yy_xy": lambda i: [float(i), float(-i), 0.5 * i + t]}
            check(sorted(arrays) == sorted(want), f"known series t = {t}: arrays {sorted(arrays)}")
            for name, f in want.items():
                got = arrays.get(name, [])
                check(len(got) == 7, f"known series t = {t}: {name} has {len(got)} tuples")
                for i, v in enumerate(got):
                    compared += 1
                    check(v == f(i), f"known series t = {t}: {name}[{i}] = {v}, written {f(i)}")
        print(f"known series: {len(times)} times, {compared} array tuples compared exactly")


def driver_series(folder):
    paths = sorted(glob.glob(os.path.join(folder, "**", "*.xdmf"), recursive=True))
    check(paths, f"no .xdmf under {folder}")
    for path in paths:
        text = open(path).read()
        declared_times = [float(x) for x in re.findall(r'<Time Value="([^"]+)"', text)]
        declared_n = [int(x) for x in re.findall(r'TopologyType="Polyvertex" NumberOfElements="(\d+)"', text)]
        reader, times = open_series(path)
        name = os.path.relpath(path, folder)
        check(times == sorted(declared_times), f"{name}: reader times {times}, series {declared_times}")
        for t, n in zip(sorted(declared_times), declared_n):
            pts, arrays = step(reader, t)
            check(len(pts) == n, f"{name} t = {t}: {len(pts)} points, declared {n}")
            bad = [k for k, v in arrays.items() if not all(math.isfinite(c) for row in v for c in row)]
            check(not bad, f"{name} t = {t}: non-finite values in {bad}")
        print(f"{name}: {len(times)} times read")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sample", required=True, help="the snapshot_sample executable")
    ap.add_argument("--series", help="a folder of a driver's snapshot series to open as well")
    args = ap.parse_args()
    try:
        import vtkmodules.vtkIOXdmf3  # noqa: F401
    except ImportError as e:
        print(f"test_paraview: ParaView's XDMF reader is not importable ({e}): install python3-paraview (make test-paraview does)")
        return 1
    known_series(args.sample)
    if args.series:
        driver_series(args.series)
    print(f"test_paraview: {'FAILED, ' + str(len(failures)) + ' checks' if failures else 'every check passed'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
