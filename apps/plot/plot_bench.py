"""plot_bench.py - the two charts of `ggx bench` from its CSV:
  SPEED_ERROR.png: ns per sample (x, write job) against the 99th percentile
                   angle error of m and o against the reference (y);
  SPEED_RMSE.png:  ns per sample (x, fused estimator) against the RMSE of the
                   albedo table at equal time (y).
One point per method and precision mode (color: method, marker: mode), and
in precise mode one per sequence of uniforms (filled: philox, hollow: sobol,
whose RMSE is the measured one: the variance model holds for independent
uniforms only); both axes logarithmic.  Lower left is better.  Conductor rows
only: a dielectric's rows (eta set, `ggx bench --eta`) are in the report's tables.

Usage: python3 plot_bench.py BENCH.csv SPEED_ERROR.png SPEED_RMSE.png TITLE
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PALETTE = ["#7f7f7f", "#1f77b4", "#17becf", "#d62728", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#e377c2"]
MARKERS = {"precise": "o", "relaxed": "^", "native": "x"}


def rows_of(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def y_of(row, y_column):
    """The row's y: Sobol rows' RMSE is measured, the others' from the variance model."""
    if row.get("sequence") == "sobol" and y_column == "rmse_at_budget":
        return row.get("rmse_measured", "")
    return row[y_column]


def conductor(row):
    """Whether the row is a conductor's (eta 0; CSVs without the column hold only conductors)."""
    return float(row.get("eta") or 0) == 0


def method_colors(rows):
    """A colour per method, in the order the methods first appear in the data (the library's order)."""
    methods = []
    for row in rows:
        if row["method"] not in methods and row["method"] != "all":
            methods.append(row["method"])
    return {m: PALETTE[k % len(PALETTE)] for k, m in enumerate(methods)}


def chart(rows, job, y_column, y_label, title, out_path):
    colors = method_colors(rows)
    fig, ax = plt.subplots(figsize=(8, 5.5), dpi=100)
    for row in rows:
        y_text = y_of(row, y_column)
        if row["job"] != job or not y_text or row["precision"] not in MARKERS or not conductor(row):
            continue
        x, y = float(row["ns_median"]), max(float(y_text), 1e-9)
        hollow = row.get("sequence") == "sobol"
        if hollow:
            ax.scatter(x, y, marker=MARKERS[row["precision"]], s=55, facecolors="none", edgecolors=colors[row["method"]])
        else:
            ax.scatter(x, y, marker=MARKERS[row["precision"]], s=55, color=colors[row["method"]])
        ax.annotate(row["method"] + (" sobol" if hollow else ""), (x, y), textcoords="offset points", xytext=(5, 4),
                    fontsize=7)
    for method, color in colors.items():
        ax.scatter([], [], color=color, marker="o", label=method)
    for mode, marker in MARKERS.items():
        ax.scatter([], [], color="black", marker=marker, label=mode)
    ax.scatter([], [], facecolors="none", edgecolors="black", marker="o", label="precise, sobol")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("ns per sample (median)")
    ax.set_ylabel(y_label)
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, ncol=2, loc="best")
    fig.tight_layout()
    temp = out_path + ".tmp.png"
    fig.savefig(temp)
    os.replace(temp, out_path)


def main():
    csv_path, speed_error, speed_rmse, title = sys.argv[1:5]
    rows = rows_of(csv_path)
    chart(rows, "write", "angle_p99", "angle error of m and o, 99th percentile (rad)",
          "Speed against numerical error (m + pdf_m written) - " + title, speed_error)
    chart(rows, "furnace", "rmse_at_budget", "RMSE per cell of the albedo table at equal time",
          "Speed against statistical error (fused estimator) - " + title, speed_rmse)


if __name__ == "__main__":
    main()
