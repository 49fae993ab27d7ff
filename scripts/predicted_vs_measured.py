"""predicted_vs_measured.py - the speed ratios `ggx bench` measured on a device
beside those the PTX instruction counts predict (docs/DEVICES.md, "Predicted
speed ratios"): caps over heitz (write, fused furnace) and caps-iso over caps
with a basis (world space), precise mode.

usage: python3 scripts/predicted_vs_measured.py BENCH_CSV DEVICES_MD [TARGET]"""

import csv
import sys


def measured(path):
    """{(method, job): ns per sample} of the precise, philox rows of conductors (eta 0)."""
    rows = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            conductor = float(row.get("eta") or 0) == 0
            if row["precision"] == "precise" and row.get("sequence", "philox") == "philox" and conductor:
                rows[(row["method"], row["job"])] = float(row["ns_median"])
    return rows


def predicted(path, target):
    """The ratio row of `target` in DEVICES.md's predicted ratios table."""
    for line in open(path):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells and cells[0] == target and len(cells) == 4:
            return cells[1:]
    raise SystemExit(f"no predicted ratios for {target} in {path}")


def main():
    if len(sys.argv) not in (3, 4):
        raise SystemExit(__doc__)
    ns = measured(sys.argv[1])
    target = sys.argv[3] if len(sys.argv) == 4 else "NVPTX sm_80"
    pairs = [("heitz", "caps", "write"), ("heitz", "caps", "furnace"), ("caps", "caps-iso", "world")]
    print(f"| ratio | measured here | predicted ({target}, static) |\n|---|---|---|")
    for (slow, fast, job), prediction in zip(pairs, predicted(sys.argv[2], target)):
        have = (slow, job) in ns and (fast, job) in ns
        value = f"{ns[(slow, job)] / ns[(fast, job)]:.2f}" if have else "not measured"
        print(f"| {fast} over {slow}, {job} | {value} | {prediction} |")


if __name__ == "__main__":
    main()
