"""compile_programs.py - every program ggxcl builds, through every GPU compiler
Debian ships (gpu_targets.py): the covering set of list_programs (every option
value, every pair of values) for AMD RDNA2, RDNA3, CDNA2 and GCN5, NVPTX and
SPIR-V.  Fails on a failed compile or validation, on any scratch use or spill
on the AMD targets, on a local-memory depot in PTX, and on any contraction
(llvm.fmuladd, `contract`) in the front end's LLVM IR of a precise program
(ggx_platform.h turns FP_CONTRACT off); first checks that the spill check
fails a kernel made to spill (spill_control.cl) and that the contraction
check finds the one of contraction_control.cl.

usage: python3 compile_programs.py LIST_PROGRAMS [--jobs N]"""

import argparse
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile

import gpu_targets as gpu

HERE = os.path.dirname(os.path.abspath(__file__))


def spill_problems(target, compiled):
    """Why a compiled program breaks the no-spill rule on `target` (empty when it does not)."""
    problems = []
    if target.isa == "amdgcn":
        for kernel, info in gpu.amd_kernel_info(compiled.code).items():
            if info["scratch"] > 0:
                problems.append(f"{kernel}: {info['scratch']} bytes of scratch per lane")
        for kernel, spilled in gpu.amd_spills(compiled.log).items():
            if spilled > 0:
                problems.append(f"{kernel}: {spilled} registers spilled")
    elif target.isa == "nvptx":
        for kernel, body in gpu.ptx_functions(compiled.code).items():
            if gpu.ptx_uses_local_memory(body):
                problems.append(f"{kernel}: a local-memory depot (.local) in the PTX")
        if not problems and gpu.ptx_uses_local_memory(compiled.code):
            problems.append("a local-memory depot (.local) in the PTX, outside the kernels")
    return problems


def check(program, target, sources, work):
    """One program on one target: a list of failure messages."""
    base = os.path.join(work, f"{program['name']}-{target.slug}")
    compiled = gpu.compile_program(target, os.path.join(sources, program["file"]), program["options"], base)
    where = f"{program['name']} ({program['file']} {program['options']}) on {target.name}"
    if not compiled.ok:
        return [f"{where}: compile failed:\n{compiled.log}"]
    if target.isa == "amdgcn" and not gpu.amd_kernel_info(compiled.code):
        return [f"{where}: no kernel found in the assembly"]
    if target.isa == "nvptx" and not gpu.ptx_functions(compiled.code):
        return [f"{where}: no .entry in the PTX"]
    problems = spill_problems(target, compiled)
    if target.isa == "spirv" and program.get("precision") == "precise" and gpu.contractions(compiled.code):
        problems.append(f"{gpu.contractions(compiled.code)} contractions (llvm.fmuladd or `contract`) in the "
                        "LLVM IR of a precise program")
    return [f"{where}: {p}" for p in problems]


def negative_control(work):
    """The spill check must fail every kernel of spill_control.cl on every AMD and PTX target
    (register_spill, for AMD only, must fail on its spilled registers)."""
    failures = []
    control = {"name": "spill-control", "file": "spill_control.cl", "options": ""}
    for target in gpu.TARGETS:
        if target.isa == "spirv":
            continue
        problems = " ".join(check(control, target, HERE, work))
        expected = ["private_array"] + (["register_spill: "] if target.isa == "amdgcn" else [])
        for kernel in expected:
            if kernel not in problems:
                failures.append(f"negative control: the spill check passed {kernel.strip(': ')} of "
                                f"spill_control.cl on {target.name}: {problems}")
        if target.isa == "amdgcn" and "registers spilled" not in problems:
            failures.append(f"negative control: no spilled registers reported on {target.name}: {problems}")
    spirv = next(t for t in gpu.TARGETS if t.isa == "spirv")
    contraction = {"name": "contraction-control", "file": "contraction_control.cl", "options": "",
                   "precision": "precise"}
    if "contractions" not in " ".join(check(contraction, spirv, HERE, work)):
        failures.append("negative control: the contraction check passed contraction_control.cl's a * b + c")
    return failures


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("list_programs")
    parser.add_argument("--jobs", type=int, default=os.cpu_count())
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="ggx-gpu-") as work:
        sources = os.path.join(work, "sources")
        listing = subprocess.run([args.list_programs, sources, "covering"], check=True, capture_output=True,
                                 text=True).stdout
        programs = [json.loads(line) for line in listing.splitlines()]
        failures = negative_control(work)
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            runs = [pool.submit(check, p, t, sources, work) for p in programs for t in gpu.TARGETS]
            for run in runs:
                failures += run.result()
    kinds = sorted({p["kind"] for p in programs})
    print(f"{len(programs)} programs ({', '.join(kinds)}) x {len(gpu.TARGETS)} targets "
          f"({', '.join(t.name for t in gpu.TARGETS)}): {len(runs)} builds, {len(failures)} failures")
    for failure in failures:
        print("FAIL", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
