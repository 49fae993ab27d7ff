"""make_bundle.py - a relocatable folder that checks ggxcl on a machine without
packages (a GPU node with its driver, CMake and nothing else): `ggx`, libggxcl,
the device test suites and what they read, the shared libraries such a
machine lacks (the OpenCL ICD loader, cmark-gfm; not libc or libstdc++),
$ORIGIN run paths, a CTest file whose paths are relative to itself, and
run.sh (scripts/bundle/run.sh).  (In a CTest file CMAKE_CURRENT_LIST_DIR is
not set: the file finds its folder as the one ctest reads it in.)

The layout mirrors the build and source trees: BUILD/x goes to build/x and
SOURCE/x to src/x, so that every path a test names keeps its place relative
to the others.  Paths compiled into the tests are given again through the
environment variables of the same names (tests/helpers/test_paths.hpp),
pointing into the bundle.

usage: python3 make_bundle.py --build BUILD --source SOURCE --out DIR"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys

# Libraries every Linux machine with a C++ runtime has: not carried (run.sh checks their versions).
SYSTEM_LIBRARIES = re.compile(r"^(linux-vdso|ld-linux|libc\.so|libm\.so|libstdc\+\+\.so|libgcc_s\.so|"
                              r"libpthread\.so|libdl\.so|librt\.so)")
# Suites left out: test_python needs the build machine's Python with pybind11 and NumPy.
LEFT_OUT = {"test_python"}
# The fast subset of run.sh --quick: suites that each take seconds on a GPU and together touch
# every layer (device math, every sampler's samples against the reference, the runtime's bits,
# user kernels on the installed headers, the C API, the tool).
QUICK = {"test_uniforms", "test_device_math", "test_fresnel_eval", "test_per_sample", "test_runtime",
         "test_contract", "test_specialization", "test_user_kernels", "test_user_sampler",
         "test_histogram_bins", "test_c_api"}
# Paths the tests have compiled in (tests/CMakeLists.txt), as they lie in the trees.
COMPILED_PATHS = {
    "GGX_BINARY": ("build", "apps/ggx"),
    "GGX_LIMITS_BINARY": ("build", "bench/limits/ggx-limits"),
    "GGX_USER_SAMPLERS_DIR": ("source", "tests/user_samplers"),
    "GGX_KERNEL_DIR": ("source", "kernels"),
    "GGX_EXAMPLES_DIR": ("source", "examples"),
    "GGX_CUDA_DIR": ("source", "tests/cuda"),
    "GGX_CHECK_TARGETS": ("source", "bench/check_targets.py"),
}
# Also carried: the native baseline beside ggx, and what run.sh builds with nvcc.
EXTRA = [("build", "apps/ggx-native"), ("source", "examples/cuda"), ("source", "kernels")]
BUNDLE_VAR = "${GGX_BUNDLE}"


class Trees:
    """The build and source trees and where their files go in the bundle."""

    def __init__(self, build, source, out):
        self.roots = {"build": os.path.realpath(build), "source": os.path.realpath(source)}
        self.places = {"build": "build", "source": "src"}
        self.out = out

    def relative(self, path):
        """(tree, path inside it) of an absolute path inside one of the trees, else None.
        The build tree is tried first: it may lie inside the source tree."""
        real = os.path.realpath(path) if os.path.exists(path) else os.path.normpath(path)
        for tree in ("build", "source"):
            root = self.roots[tree]
            if real == root or real.startswith(root + os.sep):
                return tree, os.path.relpath(real, root)
        return None

    def bundle_path(self, tree, inside):
        return os.path.join(self.places[tree], inside)

    def rewrite(self, text):
        """`text` with each path into the trees replaced by its place under ${GGX_BUNDLE}."""
        for tree in ("build", "source"):
            root = self.roots[tree]
            text = re.sub(re.escape(root) + r"(?=/|$|;|\s)", BUNDLE_VAR + "/" + self.places[tree], text)
        return text


def copy_item(trees, tree, inside):
    """Copies a file or folder of a tree into the bundle at its mirrored place."""
    source = os.path.join(trees.roots[tree], inside)
    target = os.path.join(trees.out, trees.bundle_path(tree, inside))
    os.makedirs(os.path.dirname(target), exist_ok=True)
    if os.path.isdir(source):
        shutil.copytree(source, target, dirs_exist_ok=True)
    else:
        shutil.copy2(source, target)


def device_suites(build):
    """The device and cross-implementation suites as `ctest --show-only=json-v1` describes them."""
    listing = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1", "-L", "device|cross"],
                             check=True, capture_output=True, text=True).stdout
    return [t for t in json.loads(listing)["tests"] if t["name"] not in LEFT_OUT]


def carry_test_files(trees, test):
    """Copies every existing file a suite's command names (its executable, scripts, data folders as
    arguments); folders named as working directories are made empty."""
    for word in test["command"]:
        where = trees.relative(word)
        if where and os.path.exists(word):
            copy_item(trees, *where)
    for prop in test.get("properties", []):
        if prop["name"] == "WORKING_DIRECTORY" and trees.relative(prop["value"]):
            os.makedirs(os.path.join(trees.out, trees.bundle_path(*trees.relative(prop["value"]))), exist_ok=True)


def cmake_quoted(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def property_value(trees, value):
    if isinstance(value, list):
        return cmake_quoted(trees.rewrite(";".join(str(v) for v in value)))
    return cmake_quoted(trees.rewrite(str(value)))


def ctest_file(trees, tests):
    """The bundle's CTestTestfile.cmake: each suite with its paths under the bundle's folder, the
    compiled-in paths given again through the environment, and the label quick on the fast subset."""
    environment = [f"{name}={BUNDLE_VAR}/{trees.bundle_path(tree, inside)}"
                   for name, (tree, inside) in COMPILED_PATHS.items()]
    lines = ["# CTestTestfile.cmake - ggxcl's device suites in this bundle (scripts/bundle/make_bundle.py);",
             "# every path relative to this file: run `ctest --test-dir THIS_FOLDER`.",
             "# ctest reads this file in its own folder (CMAKE_CURRENT_LIST_DIR is not set here): that folder",
             "# is the bundle.",
             "execute_process(COMMAND pwd OUTPUT_VARIABLE GGX_BUNDLE OUTPUT_STRIP_TRAILING_WHITESPACE)", ""]
    for test in tests:
        name = test["name"]
        command = list(test["command"])
        if not trees.relative(command[0]):  # an interpreter (/usr/bin/sh): by name, from the node's PATH
            command[0] = os.path.basename(command[0])
        lines.append(f"add_test({name} " + " ".join(property_value(trees, w) for w in command) + ")")
        props = {p["name"]: p["value"] for p in test.get("properties", [])}
        env = [e for e in props.pop("ENVIRONMENT", []) if e.split("=", 1)[0] not in COMPILED_PATHS] + environment
        labels = list(props.pop("LABELS", [])) + (["quick"] if name in QUICK else [])
        props.pop("WORKING_DIRECTORY", None)
        fields = [f"LABELS {property_value(trees, labels)}", f"ENVIRONMENT {property_value(trees, env)}",
                  f"WORKING_DIRECTORY {cmake_quoted(BUNDLE_VAR + '/build/tests')}"]
        fields += [f"{key} {property_value(trees, value)}" for key, value in sorted(props.items())]
        lines.append(f"set_tests_properties({name} PROPERTIES " + " ".join(fields) + ")")
    return "\n".join(lines) + "\n"


def is_elf(path):
    with open(path, "rb") as f:
        return f.read(4) == b"\x7fELF"


def elf_files(out):
    for folder, _, files in os.walk(out):
        for name in files:
            path = os.path.join(folder, name)
            if not os.path.islink(path) and is_elf(path):
                yield path


def needed_libraries(path):
    """{soname: resolved path} of what `path` loads that a bare machine may lack (ldd, here)."""
    found = {}
    for line in subprocess.run(["ldd", path], capture_output=True, text=True).stdout.splitlines():
        match = re.match(r"\s*(\S+) => (\S+)", line)
        if match and not SYSTEM_LIBRARIES.match(match.group(1)) and match.group(2) != "not":
            found[match.group(1)] = match.group(2)
    return found


def carry_libraries(out):
    """Copies every library the bundle's programs load, system ones aside, into lib/ under its soname."""
    lib = os.path.join(out, "lib")
    os.makedirs(lib, exist_ok=True)
    wanted = {}
    for path in list(elf_files(out)):
        wanted.update(needed_libraries(path))
    for soname, path in sorted(wanted.items()):
        shutil.copy2(os.path.realpath(path), os.path.join(lib, soname))
    return sorted(wanted)


def relocate(out):
    """Strips each ELF file and points its run path at the bundle's lib/ ($ORIGIN-relative)."""
    lib = os.path.join(out, "lib")
    for path in elf_files(out):
        subprocess.run(["strip", "--strip-unneeded", path], check=True)
        rpath = "$ORIGIN/" + os.path.relpath(lib, os.path.dirname(path))
        subprocess.run(["patchelf", "--set-rpath", rpath.rstrip("/.") or "$ORIGIN", path], check=True)


def symbol_versions(out):
    """The newest GLIBC_ and GLIBCXX_ symbol versions any ELF file of the bundle asks for."""
    newest = {"GLIBC": (0,), "GLIBCXX": (0,)}
    for path in elf_files(out):
        data = open(path, "rb").read()
        for family, version in re.findall(rb"\b(GLIBC|GLIBCXX)_(\d+(?:\.\d+)+)\b", data):
            key, numbers = family.decode(), tuple(int(n) for n in version.decode().split("."))
            newest[key] = max(newest[key], numbers)
    return {k: ".".join(map(str, v)) for k, v in newest.items()}


def write_text(path, text, mode=0o644):
    temporary = path + ".tmp"
    with open(temporary, "w") as f:
        f.write(text)
    os.chmod(temporary, mode)
    os.replace(temporary, path)


def make_bundle(build, source, out):
    trees = Trees(build, source, out)
    tests = device_suites(build)
    if not tests:
        sys.exit(f"make_bundle: no device suites in {build} (configure with -DGGXCL_BUILD_TESTS=ON)")
    for test in tests:
        carry_test_files(trees, test)
    for tree, inside in list(COMPILED_PATHS.values()) + EXTRA:
        copy_item(trees, tree, inside)
    libraries = carry_libraries(out)
    relocate(out)
    write_text(os.path.join(out, "CTestTestfile.cmake"), ctest_file(trees, tests))
    versions = symbol_versions(out)
    write_text(os.path.join(out, "requirements.txt"), f"GLIBC {versions['GLIBC']}\nGLIBCXX {versions['GLIBCXX']}\n")
    for script in ("run.sh", "nvidia_icd.sh"):
        shutil.copy2(os.path.join(source, "scripts", "bundle", script), os.path.join(out, script))
    commit = subprocess.run(["git", "-C", source, "describe", "--always", "--dirty"], capture_output=True,
                            text=True).stdout.strip() or "unknown"
    write_text(os.path.join(out, "ABOUT.txt"),
               f"ggxcl device check, built from {commit}\n{len(tests)} suites, {len(libraries)} carried libraries: "
               f"{', '.join(libraries)}\nneeds GLIBC {versions['GLIBC']} and GLIBCXX {versions['GLIBCXX']}\n"
               "run: ./run.sh [--quick]  (OUT=folder for the logs; GGXCL_DEVICE=name to pick a device)\n")
    return tests, libraries, versions


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    out = os.path.abspath(args.out)
    if os.path.exists(out) and os.listdir(out):
        sys.exit(f"make_bundle: --out {out} exists and is not empty: allowed is a new or empty folder")
    for tool in ("patchelf", "strip", "ldd", "ctest"):
        if not shutil.which(tool):
            sys.exit(f"make_bundle: {tool} not found (Debian: apt-get install patchelf binutils cmake)")
    tests, libraries, versions = make_bundle(args.build, args.source, out)
    size = sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(out) for f in fs)
    print(f"bundle {out}: {len(tests)} suites, libraries {', '.join(libraries)}; needs GLIBC {versions['GLIBC']}, "
          f"GLIBCXX {versions['GLIBCXX']}; {size / 2**20:.1f} MiB")


if __name__ == "__main__":
    main()
