"""spirv_counts.py - the size of each method's sample shader (tests/vulkan/shaders:
one sample and the pdf of its o, as stored by test_shaders) in SPIR-V after
spirv-opt -O, for GLSL and HLSL, conductor and dielectric: the instructions
inside functions (spirv-dis, labels and declarations left out) and the
arithmetic among them.  A Markdown table for docs/DEVICES.md; drivers
compile SPIR-V further, so this measures what a shader hands them.

usage: python3 tests/vulkan/spirv_counts.py   (from the repository root)"""

import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SHADERS = os.path.join(ROOT, "tests", "vulkan", "shaders")
KERNELS = os.path.join(ROOT, "kernels")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from method_table import methods  # noqa: E402
ARITHMETIC = ("OpF", "OpI", "OpS", "OpU", "OpExtInst", "OpDot", "OpVectorTimesScalar", "OpSelect",
              "OpBitwise", "OpShift", "OpNot", "OpLogical", "OpConvert", "OpBitcast")


def compile_shader(language, method_id, dielectric, work):
    source = os.path.join(SHADERS, "sample.comp" if language == "glsl" else "sample.hlsl")
    raw, optimized = os.path.join(work, "raw.spv"), os.path.join(work, "opt.spv")
    defines = [f"-DGGX_TEST_METHOD={method_id}", f"-DGGX_ONLY_METHOD={method_id}",
               f"-DGGX_TEST_DIELECTRIC={1 if dielectric else 0}"]
    front = ["-V"] if language == "glsl" else ["-V", "-D", "-e", "main", "-S", "comp", "--target-env", "vulkan1.1",
                                               "-DGGX_HLSL=1"]
    subprocess.run(["glslangValidator", "--quiet", *front, *defines, f"-I{KERNELS}", source, "-o", raw], check=True)
    subprocess.run(["spirv-opt", "-O", raw, "-o", optimized], check=True)
    return subprocess.run(["spirv-dis", "--raw-id", optimized], check=True, capture_output=True, text=True).stdout


def count(disassembly):
    inside, total, arithmetic = False, 0, 0
    for line in disassembly.splitlines():
        words = line.split()
        op = next((w for w in words if w.startswith("Op")), "")
        if op == "OpFunction":
            inside = True
        elif op == "OpFunctionEnd":
            inside = False
        elif inside and op not in ("", "OpLabel", "OpFunctionParameter", "OpVariable"):
            total += 1
            arithmetic += op.startswith(ARITHMETIC) and not op.startswith(("OpStore", "OpLoad"))
    return total, arithmetic


def main():
    print("| method | kind | GLSL instructions (arithmetic) | HLSL instructions (arithmetic) |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for method_id, (method, has_dielectric) in enumerate(methods()):
            for dielectric in (False, True) if has_dielectric else (False,):
                cells = []
                for language in ("glsl", "hlsl"):
                    total, arithmetic = count(compile_shader(language, method_id, dielectric, work))
                    cells.append(f"{total} ({arithmetic})")
                kind = "dielectric" if dielectric else "conductor"
                print(f"| {method} | {kind} | {cells[0]} | {cells[1]} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
