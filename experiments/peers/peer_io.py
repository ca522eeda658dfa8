"""The files make peers passes between our tools and the peers' scripts (issue 44): one reader of each.

read_table(path)    a CSV with '#' comment lines first (our layout.csv, settings.csv, values files) -> list of dicts
settings(folder)    settings.csv of a layout folder -> {name: float}
header(path)        the '# key = value' lines at the top of a file -> {key: value} (our files and the traces)
values(path)        a values file (quantity,value,note) -> {quantity: float}
FrameWriter         writes the frames format of experiments/peers/frames_reader.hpp (t,id,x,y,u,v)
machdyn_plugin()    where tools/peers/build_machdyn.sh leaves LAMMPS's MACHDYN plugin (its MACHDYN_OUT, or its default)
"""
import csv
import os


ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def machdyn_plugin():
    """The plugin tools/peers/build_machdyn.sh builds: $MACHDYN_OUT, else <repository>/build/peers/machdynplugin.so."""
    return os.environ.get("MACHDYN_OUT") or os.path.join(ROOT, "build", "peers", "machdynplugin.so")


def read_table(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def settings(folder):
    return {r["name"]: float(r["value"]) for r in read_table(os.path.join(folder, "settings.csv"))}


def header(path):
    meta = {}
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            k, sep, v = line[1:].partition("=")
            if sep:
                meta[k.strip()] = v.strip()
    return meta


def values(path):
    return {r["quantity"]: float(r["value"]) for r in read_table(path)}


def write_header(f, meta):
    for k, v in meta.items():
        f.write(f"# {k} = {v}\n")


class FrameWriter:
    """Frames of every particle (frames_reader.hpp): ids are our layout's row indices, given once."""

    def __init__(self, path, ids, meta):
        self.f = open(path, "w")
        self.ids = list(ids)
        write_header(self.f, meta)
        self.f.write("t,id,x,y,u,v\n")

    def frame(self, t, x, y, u, v):
        w = self.f.write
        for i, xa, ya, ua, va in zip(self.ids, x, y, u, v):
            w(f"{t!r},{i},{xa!r},{ya!r},{ua!r},{va!r}\n")

    def close(self):
        self.f.close()
