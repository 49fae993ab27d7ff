"""isa_report.py - what the GPU compilers make of `ggx bench`'s jobs: per method
and job, registers, occupancy, scratch, code size and instructions per sample
by class on each AMD target and in PTX, and the speed ratios these counts
predict beside the papers' GPU measurements.  Static predictions from the
code, not measurements.  Writes Markdown to stdout (docs/DEVICES.md keeps it).

usage: python3 isa_report.py LIST_PROGRAMS"""

import concurrent.futures
import json
import os
import re
import subprocess
import sys
import tempfile

import gpu_targets as gpu

# The kernel a job's time is spent in.
JOB_KERNEL = {"write": "ggx_sample_bulk", "furnace": "ggx_furnace_bulk", "world": "ggx_sample_bulk",
              "pdf": "ggx_pdf_bulk"}
CLASSES = ["arithmetic", "transcendental", "memory", "control"]


def samples_per_item(sources):
    """The furnace's samples per work-item (GGX_FURNACE_PER_ITEM of the contract)."""
    contract = open(os.path.join(sources, "ggx_contract.h")).read()
    return int(re.search(r"#define GGX_FURNACE_PER_ITEM (\d+)", contract).group(1))


def measure(program, target, sources, work, per_item):
    base = os.path.join(work, f"{program['name'].replace(':', '-')}-{target.slug}")
    compiled = gpu.compile_program(target, os.path.join(sources, program["file"]), program["options"], base)
    if not compiled.ok:
        raise RuntimeError(f"{program['name']} on {target.name}: {compiled.log}")
    rows = {}
    for job in (["pdf"] if program["name"].endswith(":write") else []) + [program["name"].split(":")[1]]:
        kernel = JOB_KERNEL[job]
        per_sample = per_item if job == "furnace" else 1
        if target.isa == "amdgcn":
            body = gpu.amd_functions(compiled.code)[kernel][0]
            row = dict(gpu.amd_kernel_info(compiled.code)[kernel])
        else:
            body = gpu.ptx_functions(compiled.code)[kernel]
            row = {"registers": gpu.ptx_registers(body), "local": gpu.ptx_uses_local_memory(body)}
        counts = gpu.instruction_classes(target.isa, body)
        row.update({c: counts[c] / per_sample for c in CLASSES})
        row["total"] = sum(counts.values()) / per_sample
        rows[(program["method"], job)] = row
    return target.name, rows


def number(x):
    return f"{x:.0f}" if x == int(x) else f"{x:.1f}"


def amd_table(rows):
    out = ["| method | job | VGPRs | SGPRs | waves/SIMD | scratch | code bytes | arith. | transc. | memory | control | "
           "per sample |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for (method, job), r in rows.items():
        out.append(f"| {method} | {job} | {r['vgprs']} | {r['sgprs']} | {r['occupancy']} | {r['scratch']} | "
                   f"{r['bytes']} | " + " | ".join(number(r[c]) for c in CLASSES) + f" | {number(r['total'])} |")
    return out


def ptx_table(rows):
    out = ["| method | job | virtual registers (f32 / b32 / b64 / pred) | .local | arith. | transc. | memory | "
           "control | per sample |", "|---|---|---|---|---|---|---|---|---|"]
    for (method, job), r in rows.items():
        regs = " / ".join(str(r["registers"].get(k, 0)) for k in ("f32", "b32", "b64", "pred"))
        out.append(f"| {method} | {job} | {regs} | {'yes' if r['local'] else 'none'} | " +
                   " | ".join(number(r[c]) for c in CLASSES) + f" | {number(r['total'])} |")
    return out


def ratio_table(results):
    """Instructions per sample of the slower method over the faster one, per target."""
    out = ["| target | caps over heitz, write | caps over heitz, furnace | caps-iso over caps with a basis, world |",
           "|---|---|---|---|"]
    for name, rows in results.items():
        def r(slow, fast, job):
            return rows[(slow, job)]["total"] / rows[(fast, job)]["total"]
        out.append(f"| {name} | {r('heitz', 'caps', 'write'):.2f} | {r('heitz', 'caps', 'furnace'):.2f} | "
                   f"{r('caps', 'caps-iso', 'world'):.2f} |")
    out.append("| papers (measured on GPUs) | 1.39 and 1.53 (caps over Heitz 2018, two GPUs) | | "
               "1.15 (caps-iso over caps with a basis) |")
    return out


def main():
    with tempfile.TemporaryDirectory(prefix="ggx-isa-") as work:
        sources = os.path.join(work, "sources")
        listing = subprocess.run([sys.argv[1], sources, "jobs"], check=True, capture_output=True, text=True).stdout
        programs = [json.loads(line) for line in listing.splitlines()]
        per_item = samples_per_item(sources)
        targets = [t for t in gpu.TARGETS if t.isa != "spirv"]
        with concurrent.futures.ThreadPoolExecutor(os.cpu_count()) as pool:
            runs = [pool.submit(measure, p, t, sources, work, per_item) for t in targets for p in programs]
            results = {}
            for run in runs:
                name, rows = run.result()
                results.setdefault(name, {}).update(rows)
    for target in targets:
        print(f"\n#### {target.name}\n")
        print("\n".join(amd_table(results[target.name]) if target.isa == "amdgcn" else ptx_table(results[target.name])))
    print("\n#### Predicted speed ratios (instructions per sample, slower over faster)\n")
    print("\n".join(ratio_table(results)))


if __name__ == "__main__":
    main()
