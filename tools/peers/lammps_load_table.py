"""A load history for LAMMPS MACHDYN inputs (tools/peers/lammps_wave.in, lammps_hole.in), read by LAMMPS's `python`
command: load(t, path) interpolates linearly in the table `path` (CSV t,value with '#' comment lines, as
build/bin/peer_tl --action layout writes it from our own load function) and holds its last value beyond its end."""
import bisect

_tables = {}


def load(t, path):
    tab = _tables.get(path)
    if tab is None:
        ts, vs = [], []
        with open(path) as f:
            for line in f:
                if line.startswith("#") or not line[:1].isdigit() and not line[:1] in "-.":
                    continue
                a, b = line.split(",")
                ts.append(float(a))
                vs.append(float(b))
        if len(ts) < 2 or any(b <= a for a, b in zip(ts, ts[1:])):
            raise ValueError(f"lammps_load_table: {path}: needs >= 2 rows with increasing t")
        tab = _tables[path] = (ts, vs)
    ts, vs = tab
    if t <= ts[0]:
        return vs[0]
    if t >= ts[-1]:
        return vs[-1]
    k = bisect.bisect_right(ts, t) - 1
    w = (t - ts[k]) / (ts[k + 1] - ts[k])
    return vs[k] + w * (vs[k + 1] - vs[k])
