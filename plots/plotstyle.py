"""Shared plumbing for the plot scripts: command line, reading the drivers' CSVs, saving figures.

Every plot script reads CSV only (never runs a simulation) and is called as
    plots/<target>.py --results results/<target> --figures figures
writing figures/<target>.png (and .pdf, plus any figures/<target>_<panel>.png it needs).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

plt.rcParams.update({"figure.dpi": 110, "savefig.dpi": 150, "font.size": 9, "axes.grid": True,
                     "grid.alpha": 0.3, "legend.fontsize": 8, "figure.constrained_layout.use": True})


def parse_args(description):
    ap = argparse.ArgumentParser(description=description)
    ap.add_argument("--results", required=True, help="the target's results directory")
    ap.add_argument("--figures", required=True, help="where to write the figures")
    return ap.parse_args()


def read(results_dir, name):
    """A driver CSV as a DataFrame; its '# key = value' header lines in df.attrs['meta']."""
    path = os.path.join(results_dir, name)
    meta = {}
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            if " = " in line:
                k, v = line[2:].rstrip("\n").split(" = ", 1)
                meta[k] = v
    df = pd.read_csv(path, comment="#")
    df.attrs["meta"] = meta
    return df


def save(fig, figures_dir, name, source_df=None):
    """Writes <name>.png and <name>.pdf, stamped with the code version of the data."""
    os.makedirs(figures_dir, exist_ok=True)
    if source_df is not None and "meta" in source_df.attrs:
        m = source_df.attrs["meta"]
        fig.text(0.995, 0.003, f"{m.get('driver', '')} {m.get('code_version', '')}", ha="right", va="bottom",
                 fontsize=5, color="0.5")
    for ext in ("png", "pdf"):
        fig.savefig(os.path.join(figures_dir, f"{name}.{ext}"))
    plt.close(fig)
