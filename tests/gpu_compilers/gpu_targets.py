"""gpu_targets.py - the GPU compilers Debian ships, as targets of one OpenCL C
program: AMD machine code and NVIDIA PTX from clang-15 with libclc, SPIR-V
from llvm-spirv-15 checked by spirv-val; and what their output says about
each kernel (resources, and instructions by class)."""

import dataclasses
import os
import re
import subprocess

CLANG = os.environ.get("GGX_CLANG15", "clang-15")
LLVM_SPIRV = os.environ.get("GGX_LLVM_SPIRV", "llvm-spirv-15")
SPIRV_VAL = os.environ.get("GGX_SPIRV_VAL", "spirv-val")
LIBCLC = os.environ.get("GGX_LIBCLC_DIR", "/usr/lib/clc")
OPENCL_C = ["-x", "cl", "-cl-std=CL1.2", "-O3", "-Werror"]


@dataclasses.dataclass
class Target:
    name: str        # as the tables print it
    isa: str         # "amdgcn", "nvptx" or "spirv"
    flags: list      # clang's target flags

    @property
    def slug(self):
        """The name as a file name: "RDNA2-gfx1030"."""
        return re.sub(r"[^A-Za-z0-9.]+", "-", self.name)


def amd(name, cpu):
    return Target(name, "amdgcn", ["-target", "amdgcn-unknown-amdhsa", f"-mcpu={cpu}", "-nogpulib",
                                   "-include", "clc/clc.h", "-Xclang", "-mlink-bitcode-file",
                                   "-Xclang", f"{LIBCLC}/amdgcn--amdhsa.bc",
                                   "-Rpass-analysis=kernel-resource-usage"])


TARGETS = [
    amd("RDNA2 gfx1030", "gfx1030"),
    amd("RDNA3 gfx1100", "gfx1100"),
    amd("CDNA2 gfx90a", "gfx90a"),
    amd("GCN5 gfx906", "gfx906"),
    Target("NVPTX sm_80", "nvptx", ["-target", "nvptx64-unknown-nvidiacl", "-march=sm_80", "-nogpulib",
                                    "-include", "clc/clc.h", "-Xclang", "-mlink-bitcode-file",
                                    "-Xclang", f"{LIBCLC}/nvptx64--nvidiacl.bc"]),
    # The module as the front end writes it, before LLVM's passes, as SPIR-V is shipped (the driver
    # optimizes for its device; llvm-spirv-15 cannot translate the freeze instructions that LLVM's
    # optimizations make).
    Target("SPIR-V 1.0", "spirv", ["-target", "spir64-unknown-unknown", "-Xclang", "-finclude-default-header",
                                   "-Xclang", "-disable-llvm-passes"]),
]


@dataclasses.dataclass
class Compiled:
    ok: bool
    log: str
    code: str = ""   # the assembly (AMD, PTX) or the front end's LLVM IR (SPIR-V)


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    return done.returncode == 0, done.stdout + done.stderr


def compile_program(target, source, options, out_base):
    """Builds `source` with `options` (a string of -D and -cl-* flags) for `target`."""
    command = [CLANG, *OPENCL_C, *target.flags, *options.split(), source]
    if target.isa != "spirv":
        ok, log = run(command + ["-S", "-o", out_base + ".s"])
        code = open(out_base + ".s").read() if ok else ""
        return Compiled(ok, log, code)
    # The front end's LLVM IR as text (kept in `code`: what the contraction check reads), then
    # assembled to bitcode for the SPIR-V translator.
    ok, log = run(command + ["-emit-llvm", "-S", "-o", out_base + ".ll"])
    code = open(out_base + ".ll").read() if ok else ""
    if ok:
        ok, more = run([CLANG, *target.flags[:2], "-c", "-emit-llvm", out_base + ".ll", "-o", out_base + ".bc"])
        log += more
    if ok:
        ok, more = run([LLVM_SPIRV, "--spirv-max-version=1.0", out_base + ".bc", "-o", out_base + ".spv"])
        log += more
    if ok:
        ok, more = run([SPIRV_VAL, "--target-env", "opencl1.2", out_base + ".spv"])
        log += more
    return Compiled(ok, log, code)


def contractions(ir):
    """The front end's contractions in LLVM IR text: fused multiply-adds it made of a * b + c
    (llvm.fmuladd) and instructions it allowed to fuse later (the `contract` flag)."""
    fused = len(re.findall(r"call [^\n]*@llvm\.fmuladd\.", ir))
    flagged = len(re.findall(r"= (?:fadd|fsub|fmul)[^\n]*\bcontract\b", ir))
    return fused + flagged


# --- what the code says --------------------------------------------------

def amd_kernel_info(code):
    """{kernel: {"sgprs", "vgprs", "scratch", "occupancy", "bytes"}} from the assembly's comments."""
    info = {}
    for name, body in amd_functions(code).items():
        fields = dict(re.findall(r"^; (\w+)(?: =|:) (\d+)", body[1], re.M))
        info[name] = {"sgprs": int(fields["NumSgprs"]), "vgprs": int(fields["NumVgprs"]),
                      "scratch": int(fields["ScratchSize"]), "occupancy": int(fields["Occupancy"]),
                      "bytes": int(fields["codeLenInByte"])}
    return info


def amd_functions(code):
    """{kernel: (instructions text, kernel info comments)} of each kernel in AMD assembly: the
    instructions from the kernel's label to s_endpgm, the info block the assembler writes after it."""
    out, name, body, info = {}, None, [], None
    for line in code.splitlines():
        label = re.match(r"^([A-Za-z_]\w*):", line)
        if label:
            name, body, info = label.group(1), [], None
        elif name and info is None:
            body.append(line)
            if line.strip() == "s_endpgm":
                info = []
        elif name and info is not None:
            if line.startswith("; Kernel info:") or (info and line.startswith(";")):
                info.append(line)
            elif info:
                out[name] = ("\n".join(body), "\n".join(info))
                name = None
    return out


def amd_spills(log):
    """{kernel: registers spilled} from clang's resource remarks."""
    spills, kernel = {}, None
    for line in log.splitlines():
        if (name := re.search(r"remark: Function Name: (\w+)", line)):
            kernel = name.group(1)
            spills[kernel] = 0
        elif (count := re.search(r"[SV]GPRs Spill: (\d+)", line)) and kernel:
            spills[kernel] += int(count.group(1))
    return spills


def ptx_functions(code):
    """{kernel: body} of each .entry in PTX."""
    out = {}
    for match in re.finditer(r"^(?:\.visible\s+)?\.entry (\w+)\(.*?^\)\s*\{(.*?)^\}", code, re.M | re.S):
        out[match.group(1)] = match.group(2)
    return out


def ptx_uses_local_memory(code):
    return "__local_depot" in code or re.search(r"\.local\b", code) is not None


def ptx_registers(body):
    """Virtual registers declared by class: {"f32": n, ...}."""
    return {kind: int(n) for kind, n in re.findall(r"\.reg\s+\.(\w+)\s+\S+<(\d+)>;", body)}


AMD_TRANSCENDENTAL = re.compile(r"^v_(sqrt|rsq|rcp|sin|cos|exp|log)_")
AMD_MEMORY = re.compile(r"^(global|buffer|flat|scratch|ds|s_load|s_buffer_load|s_store)_?")
AMD_CONTROL = re.compile(r"^s_(branch|cbranch|endpgm|setpc|getpc|swappc|waitcnt|nop|\w*saveexec|sleep|clause|delay_alu"
                         r"|inst_prefetch|setprio)")
PTX_TRANSCENDENTAL = re.compile(r"^(sqrt|rsqrt|rcp|sin|cos|ex2|lg2|div)\.")
PTX_MEMORY = re.compile(r"^(ld|st|atom|red|prefetch)\.")
PTX_CONTROL = re.compile(r"^(bra|ret|exit|call|bar)\b")


def instruction_classes(isa, body):
    """Counts of the instructions of one kernel body by class."""
    counts = {"arithmetic": 0, "transcendental": 0, "memory": 0, "control": 0}
    for line in body.splitlines():
        text = line.split(";")[0].split("//")[0].strip()
        if not text or text.endswith(":") or text.startswith((".", "{", "}", "@@")):
            continue
        mnemonic = text.split()[0]
        if isa == "nvptx" and mnemonic.startswith("@"):  # predicated: the instruction follows
            mnemonic = text.split()[1]
        memory, transcendental, control = ((AMD_MEMORY, AMD_TRANSCENDENTAL, AMD_CONTROL) if isa == "amdgcn"
                                           else (PTX_MEMORY, PTX_TRANSCENDENTAL, PTX_CONTROL))
        if transcendental.match(mnemonic):
            counts["transcendental"] += 1
        elif memory.match(mnemonic):
            counts["memory"] += 1
        elif control.match(mnemonic):
            counts["control"] += 1
        else:
            counts["arithmetic"] += 1
    return counts
