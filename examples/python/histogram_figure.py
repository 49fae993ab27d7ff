"""histogram_figure.py - the figure `ggx demo` draws for each method, from
Python: the reflected directions of caps binned on the device over
(cos theta, phi), the counts its pdf predicts, and the normalized residuals
(observed - expected) / sqrt(expected), side by side.

Usage: python3 examples/python/histogram_figure.py [METHOD] [OUT.png]
(with the module built: PYTHONPATH=build/python, or installed).
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ggxcl  # noqa: E402


def main():
    method = sys.argv[1] if len(sys.argv) > 1 else "caps"
    out = sys.argv[2] if len(sys.argv) > 2 else method + "-histogram.png"
    sampler = ggxcl.Sampler()
    h = sampler.histogram(method, 10 ** 7, alpha=0.3, theta=60, seed=1, bins_z=32, bins_phi=64)
    observed, expected = h["counts"].astype(np.float64), h["expected"]
    residual = np.where(expected > 0, (observed - expected) / np.sqrt(np.maximum(expected, 1e-300)), 0.0)
    fig, axes = plt.subplots(1, 3, figsize=(12.8, 4.0), dpi=100)
    extent = (0.0, 360.0, -1.0, 1.0)  # phi in degrees, cos theta
    for ax, data, title in zip(axes, (observed, expected, residual),
                               ("observed", "expected from the pdf", "(observed - expected) / sqrt(expected)")):
        image = ax.imshow(data, origin="lower", aspect="auto", extent=extent,
                          cmap="coolwarm" if data is residual else "viridis")
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("phi (degrees)")
        ax.set_ylabel("cos theta")
        fig.colorbar(image, ax=ax)
    fig.suptitle("%s, alpha 0.3, view 60 degrees, 1e7 samples on %s: chi-square %.1f on %d dof, p = %.3g"
                 % (method, sampler.device_name, h["chi_square"], h["dof"], h["p_value"]), fontsize=10)
    fig.tight_layout()
    fig.savefig(out)
    print(out)


if __name__ == "__main__":
    main()
