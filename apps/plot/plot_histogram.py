"""plot_histogram.py - renders a `ggx histogram` result as one PNG: observed
counts, expected counts and the standardized residual
(observed - expected) / sqrt(expected), side by side over (phi, cos theta),
each with a color bar, axes and a title naming the method, alpha and view.

Usage: python3 plot_histogram.py SUMMARY.json OUT.png
The summary names the .npy files of counts and expectations (bins_z x bins_phi).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402


def load(summary_path):
    with open(summary_path) as f:
        summary = json.load(f)
    folder = os.path.dirname(os.path.abspath(summary_path))
    observed = np.load(os.path.join(folder, summary["observed"])).astype(float)
    expected = np.load(os.path.join(folder, summary["expected"])).astype(float)
    return summary, observed, expected


def title_of(s):
    alpha = s["alpha"]
    a = f"{alpha[0]:g}" if alpha[0] == alpha[1] else f"({alpha[0]:g}, {alpha[1]:g})"
    glass = f", eta {s['eta']:g} ({s['transport']})" if "eta" in s else ""
    return (f"{s['method']}{glass}: alpha {a}, view theta {s['theta_degrees']:g}°, phi {s['phi_degrees']:g}° — "
            f"{s['count']:.3g} samples of {s['direction']}; chi² {s['chi_square']:.1f} on {s['dof']} dof, "
            f"p = {s['p_value']:.3g}")


def panel(ax, data, extent, title, **style):
    image = ax.imshow(data, origin="lower", extent=extent, aspect="auto", interpolation="nearest", **style)
    ax.set_title(title, fontsize=10)
    ax.set_xlabel("phi (degrees)")
    ax.set_ylabel("cos theta")
    ax.set_xticks([0, 90, 180, 270, 360])
    return image


def main(summary_path, png_path):
    s, observed, expected = load(summary_path)
    extent = [0.0, 360.0, -1.0, 1.0]
    top = max(observed.max(), expected.max(), 1.0)
    norm = LogNorm(vmin=0.5, vmax=top)
    with np.errstate(divide="ignore", invalid="ignore"):
        residual = np.where(expected > 0, (observed - expected) / np.sqrt(expected), 0.0)
    fig, axes = plt.subplots(1, 3, figsize=(16, 5), constrained_layout=True)
    cmap = plt.get_cmap("viridis").copy()
    cmap.set_bad(cmap(0.0))
    image = panel(axes[0], np.ma.masked_less_equal(observed, 0), extent, "observed counts", cmap=cmap, norm=norm)
    fig.colorbar(image, ax=axes[0], label="samples per bin")
    image = panel(axes[1], np.ma.masked_less_equal(expected, 0), extent, "expected counts (pdf integrated per bin)",
                  cmap=cmap, norm=norm)
    fig.colorbar(image, ax=axes[1], label="samples per bin")
    image = panel(axes[2], residual, extent, "(observed - expected) / sqrt(expected)", cmap="RdBu_r", vmin=-5, vmax=5)
    fig.colorbar(image, ax=axes[2], label="standard deviations")
    fig.suptitle(title_of(s), fontsize=11)
    temp = png_path + ".tmp.png"
    fig.savefig(temp, dpi=80)
    os.replace(temp, png_path)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_histogram.py SUMMARY.json OUT.png")
    main(sys.argv[1], sys.argv[2])
