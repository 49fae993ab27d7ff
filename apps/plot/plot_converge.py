"""plot_converge.py - the charts of `ggx converge` from its CSVs:
  PREFIX-<integrand>.png: RMSE against the sample count N, one panel per
      configuration (rows: roughness, columns: view angle), a line per
      method, solid for sobol and dashed for philox, with the N^-1/2 slope
      of plain Monte Carlo as a thin grey guide;
  PREFIX-time.png: RMSE against the time the samples cost (N times the
      method's ns per sample with that sequence, fused estimator), one panel
      per integrand at the middle configuration: lower left is better.
Both axes logarithmic.

Usage: python3 plot_converge.py CURVES.csv SPEEDS.csv PREFIX TITLE
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PALETTE = ["#7f7f7f", "#1f77b4", "#17becf", "#d62728", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#e377c2"]
COLORS = {}  # a colour per method, in the order the methods first appear in the data (main)
STYLES = {"sobol": "-", "philox": "--"}


def rows_of(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def curves(rows):
    """{(method, sequence, integrand, alpha, theta): ([n], [rmse])} in file order."""
    found = {}
    for r in rows:
        key = (r["method"], r["sequence"], r["integrand"], float(r["alpha"]), float(r["theta_degrees"]))
        n, e = found.setdefault(key, ([], []))
        n.append(int(r["n"]))
        e.append(max(float(r["rmse"]), 1e-16))
    return found


def save(fig, path):
    fig.tight_layout()
    temp = path + ".tmp.png"
    fig.savefig(temp)
    os.replace(temp, path)


def legend_handles(ax, methods, sequences):
    for m in methods:
        ax.plot([], [], color=COLORS[m], label=m)
    for s in sequences:
        ax.plot([], [], color="black", linestyle=STYLES[s], label=s)


def integrand_chart(data, integrand, alphas, thetas, methods, sequences, title, path):
    fig, axes = plt.subplots(len(alphas), len(thetas), figsize=(4 * len(thetas), 3.3 * len(alphas)), dpi=90,
                             squeeze=False)
    for i, a in enumerate(alphas):
        for j, t in enumerate(thetas):
            ax = axes[i][j]
            top = 0.0
            for (m, s, g, ca, ct), (n, e) in data.items():
                if g == integrand and ca == a and ct == t:
                    ax.plot(n, e, color=COLORS[m], linestyle=STYLES[s], linewidth=1.2)
                    top = max(top, e[0])
            if top > 0:
                n0 = min(n)
                ax.plot([n0, max(n)], [top, top * (max(n) / n0) ** -0.5], color="#bbbbbb", linewidth=0.8)
            ax.set_xscale("log", base=2)
            ax.set_yscale("log")
            ax.set_title("alpha %g, view %g deg" % (a, t), fontsize=9)
            ax.grid(True, which="both", alpha=0.3)
            if i == len(alphas) - 1:
                ax.set_xlabel("N")
            if j == 0:
                ax.set_ylabel("RMSE")
    legend_handles(axes[0][0], methods, sequences)
    axes[0][0].legend(fontsize=7, ncol=2)
    fig.suptitle("%s: RMSE against N - %s" % (integrand, title), fontsize=10)
    save(fig, path)


def time_chart(data, speeds, integrands, alpha, theta, methods, sequences, title, path):
    fig, axes = plt.subplots(1, len(integrands), figsize=(4.5 * len(integrands), 4), dpi=90, squeeze=False)
    for k, integrand in enumerate(integrands):
        ax = axes[0][k]
        for (m, s, g, ca, ct), (n, e) in data.items():
            if g == integrand and ca == alpha and ct == theta and (m, s) in speeds:
                ax.plot([x * speeds[(m, s)] * 1e-3 for x in n], e, color=COLORS[m], linestyle=STYLES[s], linewidth=1.2)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("microseconds of device time")
        ax.set_ylabel("RMSE")
        ax.set_title("%s, alpha %g, view %g deg" % (integrand, alpha, theta), fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    legend_handles(axes[0][0], methods, sequences)
    axes[0][0].legend(fontsize=7, ncol=2)
    fig.suptitle("RMSE at equal time - " + title, fontsize=10)
    save(fig, path)


def ordered(values):
    seen = []
    for v in values:
        if v not in seen:
            seen.append(v)
    return seen


def main():
    curves_path, speeds_path, prefix, title = sys.argv[1:5]
    rows = rows_of(curves_path)
    data = curves(rows)
    methods = ordered(r["method"] for r in rows)
    COLORS.update({m: PALETTE[k % len(PALETTE)] for k, m in enumerate(methods)})
    sequences = ordered(r["sequence"] for r in rows)
    integrands = ordered(r["integrand"] for r in rows)
    alphas = sorted(set(float(r["alpha"]) for r in rows))
    thetas = sorted(set(float(r["theta_degrees"]) for r in rows))
    for integrand in integrands:
        integrand_chart(data, integrand, alphas, thetas, methods, sequences, title, "%s-%s.png" % (prefix, integrand))
    speeds = {(r["method"], r["sequence"]): float(r["ns_per_sample"]) for r in rows_of(speeds_path)}
    if speeds:
        time_chart(data, speeds, integrands, alphas[len(alphas) // 2], thetas[len(thetas) // 2], methods, sequences,
                   title, prefix + "-time.png")


if __name__ == "__main__":
    main()
