#!/usr/bin/env python3
"""check_targets.py - the project's own speed targets, checked against the CSV
of a `ggx bench` run (its --csv) and, with --limits, of a `ggx-limits` run
(bench/limits): speed against the device's limits and between methods, the precision modes and guards, the jobs, the native C++
baseline, start-up, the commands' whole-process cost and small enqueues.
Prints the targets as a Markdown section; with --into it also writes that
section into the project's benchmark document (docs/BENCHMARKS.md),
replacing the one there, so the document holds the bench's report for users
and, apart, what the project expects of itself.  A target without the rows
it needs (a bench run with --no-native, --no-startup, fewer methods) is left
out.  Exits 0 whether targets are met or not: they are measurements to read,
not a gate; exits 1 naming the problem when the CSV is not a bench CSV.

Usage: python3 bench/check_targets.py BENCH.csv [--limits LIMITS.csv] [--into docs/BENCHMARKS.md]
"""
import argparse
import csv
import os
import sys

BEGIN = "<!-- project targets: written by bench/check_targets.py from the bench's CSV -->"
END = "<!-- end of project targets -->"
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "scripts"))
from method_table import names  # noqa: E402  (the one table of methods, ggx_contract.h)
METHODS = names()


class Rows:
    """The CSV's rows, found by method, precision and job (philox conductors unless said)."""

    def __init__(self, path):
        with open(path, newline="") as f:
            self.rows = list(csv.DictReader(f))
        needed = {"method", "precision", "job", "ns_median"}
        if not self.rows or not needed <= set(self.rows[0]):
            sys.exit(f"check_targets: {path} is not the CSV of `ggx bench --csv` (needs columns {sorted(needed)})")
        # A run on several APIs: the targets are the first device's (its rows, the native ones).
        first = self.rows[0].get("api", "")
        self.rows = [row for row in self.rows if row.get("api", "") in (first, "native", "")]

    def find(self, method, precision, job, sequence="philox"):
        for row in self.rows:
            if (row["method"], row["precision"], row["job"]) == (method, precision, job) and \
                    row.get("sequence", "philox") in ("", sequence) and float(row.get("eta") or 0) == 0:
                return row
        return None

    def ns(self, method, precision, job):
        row = self.find(method, precision, job)
        return float(row["ns_median"]) if row else None


def target(what, measured, met):
    return {"what": what, "measured": measured, "met": met}


def worst_ratio(pairs):
    """The largest slow/fast over (who, slow, fast) with both measured: (ratio, who), or None."""
    ratios = [(slow / fast, who) for who, slow, fast in pairs if slow is not None and fast is not None]
    return max(ratios) if ratios else None


def limit_targets(limits_csv):
    """The 2x target on ggx-limits' CSV (its precise write and furnace rows with a compute limit)."""
    if not limits_csv:
        return []
    with open(limits_csv, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or "percent_of_limit" not in rows[0]:
        sys.exit(f"check_targets: {limits_csv} is not the CSV of `ggx-limits --csv` (needs percent_of_limit)")
    percents = [(float(row["percent_of_limit"]), f"{row['method']} {row['job']}") for row in rows
                if row["job"] in ("write", "furnace") and row.get("compute_limit_ns") and row.get("percent_of_limit")]
    out = []
    if percents:
        worst, who = min(percents)
        out.append(target("every method within 2x of its limit (precise write and fused)",
                          f"slowest {who}: {worst:.0f}% of its limit", worst >= 50))
    return out


def rate_targets(r):
    out = []
    for job in ("write", "furnace"):
        caps, heitz = r.ns("caps", "precise", job), r.ns("heitz", "precise", job)
        if caps and heitz:
            out.append(target(f"caps / heitz speed >= 1.35, {job} (paper: 1.38 on a CPU)", f"{heitz / caps:.2f}",
                              heitz / caps >= 1.35))
    caps = r.ns("caps", "precise", "write")
    worst = worst_ratio((m, r.ns(m, "precise", "write"), caps) for m in METHODS)
    if caps and worst:
        out.append(target("every method within 2x of caps", f"slowest {worst[1]}: {worst[0]:.2f}x", worst[0] <= 2))
    return out


def mode_and_job_targets(r):
    out = []
    worst = worst_ratio((f"{m} {job}", r.ns(m, "precise", job), r.ns(m, "relaxed", job))
                        for m in METHODS for job in ("write", "furnace"))
    if worst:
        out.append(target("the default (precise) within 1.15x of the fastest mode (relaxed)",
                          f"largest {worst[1]}: {worst[0]:.2f}x", worst[0] <= 1.15))
    worst = worst_ratio((m, r.ns(m, "precise", "write"), r.ns(m, "precise-unguarded", "write")) for m in METHODS)
    if worst:
        out.append(target("guards cost < 5% (precise, write)", f"largest {worst[1]}: {100 * (worst[0] - 1):.1f}%",
                          worst[0] - 1 < 0.05))
    caps, store = r.ns("caps", "precise", "write"), r.ns("all", "store-only", "write")
    if caps and store:
        out.append(target("the write job within 2.5x of a kernel that stores the same bytes",
                          f"caps {caps:.2f} ns, store {store:.2f} ns: {caps / store:.2f}x", caps / store <= 2.5))
    worst = worst_ratio((m, r.ns(m, "precise", "per-sample"), r.ns(m, "precise", "write")) for m in METHODS)
    if worst:
        out.append(target("per-sample view and alpha within 2x of the uniform write job",
                          f"largest {worst[1]}: {worst[0]:.2f}x", worst[0] <= 2))
    return out


def baseline_targets(r):
    out = []
    speedups = [(r.ns(m, "native", "write") / r.ns(m, "precise", "write"), m) for m in METHODS
                if r.ns(m, "native", "write") and r.ns(m, "precise", "write")]
    vectorized, plain = r.ns("caps", "native-vectorized", "furnace"), r.ns("caps", "native", "furnace")
    if speedups:
        lowest, who = min(speedups)
        by_hand = f"; caps furnace vectorized (omp simd): {plain / vectorized:.1f}x its plain loop" \
            if vectorized and plain else ""
        out.append(target("every method >= 12x the native C++ baseline (write)", f"lowest {who}: {lowest:.1f}x{by_hand}",
                          lowest >= 12))
    caps_world, iso_world = r.ns("caps", "precise", "world"), r.ns("caps-iso", "precise", "world")
    if caps_world and iso_world:
        out.append(target("caps-iso >= 1.1x caps with a basis, world space (blog: 1.15)",
                          f"{caps_world / iso_world:.2f}x", caps_world / iso_world >= 1.1))
    fused = r.ns("caps", "precise", "furnace")
    if vectorized and fused:
        out.append(target("fused caps estimator >= 90% of the vectorized native C++ (omp simd)",
                          f"{100 * vectorized / fused:.0f}% (vectorized C++ {vectorized:.2f} ns, fused {fused:.2f} ns)",
                          vectorized / fused >= 0.9))
    return out


def process_targets(r):
    out = []
    warm, cold = r.find("ggx", "process", "startup-warm"), r.find("ggx", "process", "startup-cold")
    if warm and cold:
        warm_ms, cold_ms = float(warm["ns_median"]) / 1e6, float(cold["ns_median"]) / 1e6
        out.append(target("process start to first result <= 100 ms, warm kernel cache", f"{warm_ms:.0f} ms",
                          warm_ms <= 100))
        out.append(target("cold build <= 1.5 s per variant", f"{cold_ms:.0f} ms", cold_ms <= 1500))
    write = r.ns("caps", "precise", "write")
    npy, bins = r.find("caps", "process", "sample-npy"), r.find("caps", "process", "histogram")
    if write and npy and bins:
        file_ns, bins_ns = float(npy["ns_median"]), float(bins["ns_median"])
        start_ns = float(warm["ns_median"]) / float(npy["samples_per_run"]) if warm else 0.0
        floor = start_ns + r.ns("caps", "process", "npy-file-floor")
        binning = r.ns("caps", "process", "histogram-binning")
        out.append(target("`ggx sample` into .npy within 3x of the write job per sample, whole process",
                          f"{file_ns:.2f} ns: {file_ns / write:.1f}x; its floor ({'start-up + ' if warm else ''}the "
                          f"file's bytes written from memory) {floor:.2f} ns: {floor / write:.1f}x", file_ns / write <= 3))
        out.append(target("`ggx histogram` within 3x of the write job per sample, whole process",
                          f"{bins_ns:.2f} ns: {bins_ns / write:.1f}x; its binning alone {binning:.2f} ns: "
                          f"{binning / write:.1f}x", bins_ns / write <= 3))
    enqueue, second = r.find("caps", "host", "enqueue"), r.find("caps", "host", "enqueue-second-sampler-first")
    if enqueue:
        us = [float(enqueue[k]) / 1e3 for k in ("ns_median", "ns_min", "ns_max")]
        also = f"; a second Sampler's first: {float(second['ns_median']) / 1e3:.0f} us" if second else ""
        out.append(target(f"host time of one enqueue of {enqueue['samples_per_run']} samples < 20 us (warm, median)",
                          f"{us[0]:.1f} us ({us[1]:.1f}–{us[2]:.1f}){also}", us[0] < 20))
    return out


def section(targets, csv_name, command):
    lines = [BEGIN, "## The project's speed targets", "", f"- Command: `{command}`", "",
             f"What ggxcl expects of itself on this device, checked by `bench/check_targets.py` against the bench's "
             f"CSV ({csv_name}) and ggx-limits' (bench/limits). The report above is what a user reads; these are the project's own goals. "
             f"Cost probes, the limits' arithmetic and earlier measurements: [COST-PROBES.md](COST-PROBES.md).", "",
             "| target | measured | met |", "|---|---|---|"]
    lines += [f"| {t['what']} | {t['measured']} | {'yes' if t['met'] else '**no**'} |" for t in targets]
    met = sum(t["met"] for t in targets)
    lines += ["", f"{met} of {len(targets)} met.", END]
    return "\n".join(lines) + "\n"


def write_into(document, text):
    """Replaces the section between the markers in `document`, or appends it; through a temporary file."""
    with open(document) as f:
        old = f.read()
    if BEGIN in old and END in old:
        new = old[:old.index(BEGIN)] + text.rstrip("\n") + old[old.index(END) + len(END):]
    else:
        new = old.rstrip("\n") + "\n\n" + text
    temporary = f"{document}.tmp-{os.getpid()}"
    with open(temporary, "w") as f:
        f.write(new)
    os.replace(temporary, document)


def main():
    parser = argparse.ArgumentParser(description="The project's speed targets from a `ggx bench --csv` file.")
    parser.add_argument("csv", help="the bench's CSV")
    parser.add_argument("--limits", help="the CSV of a ggx-limits run on the same device (the 2x target)")
    parser.add_argument("--into", help="write the section into this Markdown document (replacing the one there)")
    args = parser.parse_args()
    r = Rows(args.csv)
    targets = limit_targets(args.limits) + rate_targets(r) + mode_and_job_targets(r) + baseline_targets(r) + \
        process_targets(r)
    text = section(targets, os.path.basename(args.csv), " ".join(["python3", "bench/check_targets.py", *sys.argv[1:]]))
    sys.stdout.write(text)
    if args.into:
        write_into(args.into, text)


if __name__ == "__main__":
    main()
