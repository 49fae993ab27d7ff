"""plot_stress.py - heat maps of `ggx stress`: for each method one PNG with
a row for the device and a row for the host reference, and a panel per
failure kind (the CSV's columns after `cases`); each panel shows the
fraction of the cell's cases that fail that way over roughness alpha (rows,
log scale) and view angle theta (columns).  A dielectric's CSV (`ggx stress
--eta`, with an eta column) sums each cell over the indices and adds
PREFIX-eta.png: the same fractions over eta (rows) and theta, every method
and roughness together.

Usage: python3 plot_stress.py STRESS.csv PREFIX   (writes PREFIX-METHOD.png)
"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SIDES = ["device", "host"]


def load(path):
    with open(path) as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        fields = reader.fieldnames
    return rows, fields[fields.index("cases") + 1:]


def sums(rows, key):
    """Cases and failures summed per key(row)."""
    totals = defaultdict(lambda: defaultdict(float))
    for row in rows:
        cell = totals[key(row)]
        for name, value in row.items():
            if name == "cases" or name in KIND_SET:
                cell[name] += float(value)
    return totals


def grid(totals, side, kind, ys, thetas):
    data = np.zeros((len(ys), len(thetas)))
    for r, y in enumerate(ys):
        for c, theta in enumerate(thetas):
            cell = totals.get((side, y, theta))
            if cell:
                data[r, c] = cell[kind] / max(1.0, cell["cases"])
    return data


def theta_label(text):
    t = float(text)
    return f"{t:.5f}" if 89.0 < t < 91.0 and t != 90.0 else f"{t:g}"


def draw(rows, kinds, y_name, y_label, y_format, title, out_path):
    """One figure: device and host rows, a panel per kind, y_name against theta."""
    ys = sorted({r[y_name] for r in rows}, key=float)
    thetas = sorted({r["theta_degrees"] for r in rows}, key=float)
    totals = sums(rows, lambda r: (r["side"], r[y_name], r["theta_degrees"]))
    sides = [side for side in SIDES if any(r["side"] == side for r in rows)]  # a user sampler: the device alone
    fig, axes = plt.subplots(len(sides), len(kinds), figsize=(4 * len(kinds), 4.25 * len(sides)), dpi=56, squeeze=False,
                             constrained_layout=True)
    for i, side in enumerate(sides):
        for k, kind in enumerate(kinds):
            ax = axes[i][k]
            image = ax.imshow(grid(totals, side, kind, ys, thetas), origin="lower", aspect="auto", cmap="magma_r",
                              vmin=0.0, vmax=1.0, interpolation="nearest")
            count = int(sum(float(r[kind]) for r in rows if r["side"] == side))
            ax.set_title(f"{side}: {kind} ({count})", fontsize=9)
            ax.set_xticks(range(len(thetas)))
            ax.set_xticklabels([theta_label(t) for t in thetas], rotation=90, fontsize=6)
            ax.set_yticks(range(len(ys)))
            ax.set_yticklabels([y_format(float(y)) for y in ys], fontsize=6)
            if k == 0:
                ax.set_ylabel(y_label)
            if i == len(sides) - 1:
                ax.set_xlabel("view theta (degrees)")
    fig.colorbar(image, ax=axes, shrink=0.6, label="fraction of the cell's cases")
    fig.suptitle(title, fontsize=12)
    temp = out_path + ".tmp.png"
    fig.savefig(temp)
    plt.close(fig)
    os.replace(temp, out_path)


def main():
    global KIND_SET
    csv_path, prefix = sys.argv[1:3]
    rows, kinds = load(csv_path)
    KIND_SET = set(kinds)
    dielectric = "eta" in rows[0] if rows else False
    what = "every index summed; " if dielectric else ""
    for method in sorted({r["method"] for r in rows}):
        mine = [r for r in rows if r["method"] == method]
        draw(mine, kinds, "alpha", "alpha", lambda a: f"{a:.0e}",
             f"{method}: where it fails ({what}roughness pairs incl. anisotropy 1:1000 and one axis 0; "
             f"edge and random uniforms)", f"{prefix}-{method}.png")
    if dielectric:
        draw(rows, kinds, "eta", "eta", lambda e: f"{e:.9g}",
             "rough dielectric: where it fails per index (every method and roughness summed)", f"{prefix}-eta.png")


KIND_SET = set()

if __name__ == "__main__":
    main()
