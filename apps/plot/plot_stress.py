"""plot_stress.py - heat maps of `ggx stress`: for each method one PNG with
a row for the device and a row for the host reference, and a panel per
failure kind; each panel shows the fraction of the cell's cases that fail
that way over roughness alpha (rows, log scale) and view angle theta
(columns).

Usage: python3 plot_stress.py STRESS.csv PREFIX   (writes PREFIX-METHOD.png)
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

KINDS = ["nan_inf", "fallback", "not_unit", "m_below", "wasted", "pdf_nonpositive", "pdf_mismatch"]


def load(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def grid(rows, method, side, kind, alphas, thetas):
    data = np.zeros((len(alphas), len(thetas)))
    for row in rows:
        if row["method"] == method and row["side"] == side:
            r = alphas.index(row["alpha"])
            c = thetas.index(row["theta_degrees"])
            data[r, c] = float(row[kind]) / max(1.0, float(row["cases"]))
    return data


def theta_label(text):
    t = float(text)
    return f"{t:.5f}" if 89.0 < t < 90.0 else f"{t:g}"


def plot_method(rows, method, out_path):
    mine = [r for r in rows if r["method"] == method]
    alphas = sorted({r["alpha"] for r in mine}, key=float)
    thetas = sorted({r["theta_degrees"] for r in mine}, key=float)
    sides = ["device", "host"]
    fig, axes = plt.subplots(len(sides), len(KINDS), figsize=(28, 8.5), dpi=56, squeeze=False,
                             constrained_layout=True)
    for i, side in enumerate(sides):
        for k, kind in enumerate(KINDS):
            ax = axes[i][k]
            data = grid(rows, method, side, kind, alphas, thetas)
            image = ax.imshow(data, origin="lower", aspect="auto", cmap="magma_r", vmin=0.0, vmax=1.0,
                              interpolation="nearest")
            ax.set_title(f"{side}: {kind} ({int(sum(float(r[kind]) for r in mine if r['side'] == side))})",
                         fontsize=9)
            ax.set_xticks(range(len(thetas)))
            ax.set_xticklabels([theta_label(t) for t in thetas], rotation=90, fontsize=6)
            ax.set_yticks(range(len(alphas)))
            ax.set_yticklabels([f"{float(a):.0e}" for a in alphas], fontsize=6)
            if k == 0:
                ax.set_ylabel("alpha")
            if i == len(sides) - 1:
                ax.set_xlabel("view theta (degrees)")
    fig.colorbar(image, ax=axes, shrink=0.6, label="fraction of the cell's cases")
    fig.suptitle(f"{method}: where it fails (roughness pairs incl. anisotropy 1:1000 and one axis 0; "
                 f"edge and random uniforms)", fontsize=12)
    temp = out_path + ".tmp.png"
    fig.savefig(temp)
    plt.close(fig)
    os.replace(temp, out_path)


def main():
    csv_path, prefix = sys.argv[1:3]
    rows = load(csv_path)
    for method in sorted({r["method"] for r in rows}):
        plot_method(rows, method, f"{prefix}-{method}.png")


if __name__ == "__main__":
    main()
