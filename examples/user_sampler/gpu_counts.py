"""gpu_counts.py - a user sampler's bulk write kernel (m + pdf_m, precise
mode, uniform parameters, philox) against a built-in method's, compiled for
the GPU targets of tests/gpu_compilers (clang-15 with libclc): the kernel's
instructions by class, its vector registers and scratch (AMD), local memory
(PTX); a Markdown table on stdout.

usage: python3 examples/user_sampler/gpu_counts.py USER_SAMPLER.h METHOD_ID
  (METHOD_ID: the built-in method's id, GGX_METHOD_* of kernels/ggx_contract.h: caps is 3)"""
import os
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "gpu_compilers"))
import gpu_targets as gpu  # noqa: E402

FLAGS = ("-DGGX_WRITE_MASK=5 -DGGX_SEQUENCE=0 -DGGX_PER_SAMPLE_VIEW=0 -DGGX_PER_SAMPLE_ALPHA=0 "
         "-DGGX_PER_SAMPLE_NORMAL=0 -DGGX_PER_SAMPLE_UNIFORMS=0 -DGGX_ISOTROPIC=1 -DGGX_BELOW_HORIZON=0 "
         "-DGGX_WORLD_SPACE=0 -DGGX_GUARDS=1 -DGGX_NORMAL_IS_Z=1 -DGGX_DIELECTRIC=0 -DGGX_IMPORTANCE=0 -DGGX_EVAL=0 "
         "-I" + os.path.join(ROOT, "kernels"))


def counts(target, source_text, options, work, tag):
    path = os.path.join(work, tag + ".cl")
    with open(path, "w") as f:
        f.write(source_text)
    compiled = gpu.compile_program(target, path, options, os.path.join(work, tag + "-" + target.slug))
    if not compiled.ok:
        errors = [line for line in compiled.log.splitlines() if "error" in line]
        return "compile failed: " + (errors[0] if errors else "see the log").replace("|", "/")
    if target.isa == "amdgcn":
        body = gpu.amd_functions(compiled.code).get("ggx_sample_bulk", ("", ""))[0]
        info = gpu.amd_kernel_info(compiled.code).get("ggx_sample_bulk", {})
        extra = f", {info.get('vgprs', '?')} VGPRs, scratch {info.get('scratch', '?')}"
    else:
        body = gpu.ptx_functions(compiled.code).get("ggx_sample_bulk", "")
        extra = ", local memory" if gpu.ptx_uses_local_memory(body) else ""
    c = gpu.instruction_classes(target.isa, body)
    return f"{sum(c.values())} ({c['arithmetic']} arithmetic, {c['transcendental']} transcendental{extra})"


def main():
    user, method = os.path.abspath(sys.argv[1]), sys.argv[2]
    with tempfile.TemporaryDirectory() as work:
        print("| target | built-in method " + method + " | " + os.path.basename(user) + " |\n|---|---|---|")
        for target in gpu.TARGETS:
            if target.isa == "spirv":
                continue
            builtin = counts(target, '#include "ggx_bulk.cl"\n', FLAGS + " -DGGX_METHOD=" + method, work, "builtin")
            mine = counts(target, '#include "ggx_bulk.cl"\n#include "' + user + '"\n',
                          FLAGS + " -DGGX_METHOD=64 -DGGX_USER_SAMPLER=1 -DGGX_USER_SAMPLES_M=0", work, "user")
            print(f"| {target.name} | {builtin} | {mine} |")


if __name__ == "__main__":
    main()
