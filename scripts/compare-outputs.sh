#!/usr/bin/env bash
# compare-outputs.sh - a before/after check for refactors: do two builds of
# ggxcl give the same bits?  Builds BASE_COMMIT in a git worktree beside the
# repository (/tmp/ggxcl-base-<short sha>, reused when present; Release, the
# library and `ggx` only), then runs the same requests on it and on
# NEW_BUILD_DIR (default: the repository's build/, which the caller has built;
# it is never rebuilt here) and compares the outputs exactly:
#   - scripts/compare/dump_outputs.cpp, compiled against each side's public
#     headers and library: samples, pdf, eval, histograms and furnace sums of
#     every method on OpenCL and on Vulkan (GLSL, HLSL), as exact text;
#   - the `ggx` CLI with identical arguments: sample (OpenCL and Vulkan,
#     .npy byte for byte), histogram (counts; JSON without time/version
#     keys), stress (CSV), converge (CSV).
# Prints `same  WHAT` or `DIFFERS WHAT` (with the first differences) per
# comparison and a summary; exit status 0 when everything is the same, 1
# when something differs, 2 for bad usage or a build that is missing.
#
#   bash scripts/compare-outputs.sh BASE_COMMIT [NEW_BUILD_DIR]
set -euo pipefail

usage() {
    echo "usage: $0 BASE_COMMIT [NEW_BUILD_DIR]" >&2
    echo "  BASE_COMMIT    the commit to compare against (built in /tmp/ggxcl-base-<short sha>)" >&2
    echo "  NEW_BUILD_DIR  a built CMake build folder of the new side (default: <repo>/build)" >&2
    exit 2
}
fail() { echo "compare-outputs: $*" >&2; exit 2; }

[[ $# -ge 1 && $# -le 2 && $1 != -* ]] || usage
script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(git -C "$script_dir" rev-parse --show-toplevel)
base_sha=$(git -C "$repo" rev-parse --verify --quiet "$1^{commit}") || fail "not a commit: $1"
short=$(git -C "$repo" rev-parse --short "$base_sha")
base_tree=/tmp/ggxcl-base-$short
new_build=${2:-$repo/build}
[[ -d $new_build ]] || fail "no build folder $new_build"
new_build=$(cd "$new_build" && pwd)
driver_src=$script_dir/compare/dump_outputs.cpp
export LC_ALL=C

# The new side: built by the caller, and not older than its sources.
check_new_build() {
    local build=$1 src lib=$1/lib/libggxcl.so ggx=$1/apps/ggx newer
    src=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt" 2>/dev/null || true)
    [[ -n $src && -f $lib && -x $ggx && -f $build/lib/include/ggxcl/cl/ggx_contract.h ]] ||
        fail "$build lacks the library or apps/ggx: build them first (cmake -S $repo -B $build -DCMAKE_BUILD_TYPE=Release && make -C $build ggxcl ggx)"
    newer=$( { find "$src/lib" "$src/kernels" -type f -newer "$lib"
               find "$src/apps" "$src/bridge" "$src/reference" "$src/lib" "$src/kernels" -type f -newer "$ggx"; } 2>/dev/null |
            sort -u | sed "s|^$src/||" | awk 'NR <= 5' | tr '\n' ' ' || true)
    [[ -z $newer ]] || fail "$build is older than its sources ($newer): rebuild it first (make -C $build ggxcl ggx)"
    new_src=$src
}

build_base() {
    if [[ ! -e $base_tree/.git ]]; then
        git -C "$repo" worktree add --detach "$base_tree" "$base_sha" >"$work/base-build.log" 2>&1 ||
            { cat "$work/base-build.log" >&2; fail "git worktree add $base_tree failed"; }
    fi
    [[ $(git -C "$base_tree" rev-parse HEAD) == "$base_sha" ]] ||
        fail "$base_tree holds $(git -C "$base_tree" rev-parse --short HEAD), not $short: remove it (git worktree remove $base_tree)"
    if ! { cmake -S "$base_tree" -B "$base_tree/build" -DCMAKE_BUILD_TYPE=Release -DGGXCL_BUILD_TESTS=OFF \
               -DGGXCL_BUILD_PYTHON=OFF && make -C "$base_tree/build" -j2 ggxcl ggx; } >>"$work/base-build.log" 2>&1; then
        tail -20 "$work/base-build.log" >&2
        fail "the build of $short failed (log: $work/base-build.log)"
    fi
}

compile_driver() {  # SOURCE_TREE BUILD_DIR OUTPUT
    "${CXX:-c++}" -std=c++17 -O1 -I"$1/lib/include" -I"$2/lib/include" "$driver_src" -o "$3" \
        -L"$2/lib" -lggxcl -lOpenCL -pthread -Wl,-rpath,"$2/lib" >"$3.log" 2>&1
}

# The CLI jobs, one a line: a name, then the arguments (none has spaces).  Both sides run them alike.
cli_jobs() {
    local m alpha
    for m in ndf heitz heitz2017 caps caps-iso bounded; do
        alpha="--alpha 0.2,0.5"; [[ $m == caps-iso ]] && alpha="--alpha 0.3 --normal 0,0.6,0.8"
        local common="--method $m $alpha --theta 60 --phi 30 --seed 3 -n 4096 --fields m,o,pdf_m,pdf_o,weight,u"
        echo "sample-$m sample $common --out sample-$m.npy"
        echo "sample-$m-vulkan sample $common --api vulkan --out sample-$m-vulkan.npy"
    done
    echo "sample-heitz-vulkan-hlsl sample --method heitz --alpha 0.2,0.5 --theta 60 --seed 3 -n 4096 --api vulkan --shader-language hlsl --out sample-heitz-vulkan-hlsl.npy"
    echo "sample-caps-eta-sobol sample --method caps --eta 1.5 --sequence sobol --theta 40 -n 4096 --fields o,pdf_o,weight,u --out sample-caps-eta-sobol.npy"
    echo "sample-caps-opposite sample --method caps --theta 180 -n 64 --out sample-caps-opposite.npy"
    echo "histogram-caps histogram --method caps --alpha 0.3 --theta 60 -n 2^18 --seed 5 --no-png --out histogram-caps"
    echo "histogram-heitz-eta histogram --method heitz --eta 1.5 --theta 130 -n 2^18 --seed 5 --no-png --out histogram-heitz-eta"
    echo "stress stress --methods caps,bounded --no-png --out stress"
    echo "converge converge --methods all --alphas 0.05,0.3 --thetas 0,60 --max-n 2^10 --randomizations 8 --no-speed --csv converge.csv"
}

run_side() {  # GGX DRIVER OUTDIR: the driver's dump, then every CLI job in OUTDIR/cli
    local ggx=$1 driver=$2 out=$3 name args
    mkdir -p "$out/cli"
    "$driver" </dev/null >"$out/dump.txt" 2>"$out/dump.err" && echo 0 >"$out/dump.rc" || echo $? >"$out/dump.rc"
    while read -r name args; do
        # shellcheck disable=SC2086  # the arguments are split on purpose
        (cd "$out/cli" && "$ggx" $args </dev/null >"$name.log" 2>&1) && echo 0 >"$out/cli/$name.rc" || echo $? >"$out/cli/$name.rc"
    done < <(cli_jobs)
}

same=0 differs=0
report_same() { echo "same  $1"; same=$((same + 1)); }
report_differs() { echo "DIFFERS $1"; differs=$((differs + 1)); }
indent() { cut -c1-220 | sed 's/^/    /'; }

# JSON without the keys that change from run to run (time, seconds, version, date, command).
json_normalized() {
    python3 - "$1" <<'EOF'
import json, sys
drop = ("time", "seconds", "version", "date", "command")
def clean(x):
    if isinstance(x, dict):
        return {k: clean(v) for k, v in x.items() if not any(d in k.lower() for d in drop)}
    return [clean(v) for v in x] if isinstance(x, list) else x
print(json.dumps(clean(json.load(open(sys.argv[1]))), indent=1, sort_keys=True))
EOF
}

# How two .npy files of the same shape differ: elements, largest difference, the first one.
npy_differences() {
    python3 - "$1" "$2" <<'EOF'
import ast, struct, sys
def load(path):
    data = open(path, "rb").read()
    major = data[6]
    size = struct.unpack("<H" if major == 1 else "<I", data[8:10] if major == 1 else data[8:12])[0]
    start = (10 if major == 1 else 12) + size
    header = ast.literal_eval(data[10 if major == 1 else 12:start].decode("latin1"))
    code = {"<f4": "f", "<f8": "d"}[header["descr"]]
    values = struct.unpack("<%d%s" % ((len(data) - start) // struct.calcsize(code), code), data[start:])
    return header["shape"], values
(sa, a), (sb, b) = load(sys.argv[1]), load(sys.argv[2])
if sa != sb:
    sys.exit(print("shape %s against %s" % (sa, sb)))
bad = [k for k in range(len(a)) if a[k] != b[k] and not (a[k] != a[k] and b[k] != b[k])]
if not bad:
    sys.exit(print("the same values; the headers or the bits of NaNs differ"))
cols = sa[1] if len(sa) > 1 else 1
worst = max(abs(a[k] - b[k]) for k in bad)
k = bad[0]
print("%d of %d values differ, largest by %.9g; first at row %d column %d: %.9g against %.9g"
      % (len(bad), len(a), worst, k // cols, k % cols, a[k], b[k]))
EOF
}

# How two text files differ: how many lines, and the first three of each side.
text_differences() {
    diff "$1" "$2" >"$work/diff.txt" || true
    echo "$(grep -c '^>' "$work/diff.txt") of $(wc -l <"$2") lines differ; the first (< base, > new):"
    grep '^<' "$work/diff.txt" | awk 'NR <= 3'
    grep '^>' "$work/diff.txt" | awk 'NR <= 3'
}

compare_file() {  # WHAT BASE_FILE NEW_FILE
    local what=$1 a=$2 b=$3
    if [[ ! -f $a || ! -f $b ]]; then
        report_differs "$what (only on the $([[ -f $a ]] && echo base || echo new) side)"
    elif [[ $a == *.json ]]; then
        if diff <(json_normalized "$a") <(json_normalized "$b") >"$work/diff.txt"; then report_same "$what"
        else report_differs "$what"; head -12 "$work/diff.txt" | indent; fi
    elif cmp -s "$a" "$b"; then
        report_same "$what"
    else
        report_differs "$what"
        if [[ $a == *.npy ]]; then npy_differences "$a" "$b" 2>&1 | indent || true
        else text_differences "$a" "$b" | indent; fi
    fi
}

# The driver's dump, one comparison per API: which groups differ, and the first differing lines.
compare_dump() {
    local api a=$work/base/dump.txt b=$work/new/dump.txt
    for side in base new; do
        [[ $(cat "$work/$side/dump.rc") == 0 ]] ||
            { report_differs "API dump: the $side driver failed (exit $(cat "$work/$side/dump.rc"))"; tail -3 "$work/$side/dump.err" | indent; }
    done
    head -1 "$a" >"$work/a.txt"; head -1 "$b" >"$work/b.txt"
    compare_file "API dump: header" "$work/a.txt" "$work/b.txt"
    for api in opencl vulkan-glsl vulkan-hlsl; do
        grep -E "^${api}[ :]" "$a" >"$work/a.txt" || true
        grep -E "^${api}[ :]" "$b" >"$work/b.txt" || true
        if cmp -s "$work/a.txt" "$work/b.txt"; then
            report_same "API dump: $api ($(wc -l <"$work/a.txt") lines; $(grep -m1 -E "^$api:" "$work/a.txt" | cut -d' ' -f2-))"
            continue
        fi
        diff "$work/a.txt" "$work/b.txt" >"$work/diff.txt" || true
        report_differs "API dump: $api ($(grep -c '^>' "$work/diff.txt") of $(wc -l <"$work/b.txt") lines differ), in (configuration: what):"
        grep '^[<>]' "$work/diff.txt" | cut -c3- | sed -E 's/ (\[[0-9]+\]|count|counts|bins|throws:).*//' |
            awk -F' [|] ' '!(($1 " | " $2) in ops) { order[n++] = $1 " | " $2; ops[$1 " | " $2] = $3; next }
                           index(", " ops[$1 " | " $2] ", ", ", " $3 ", ") == 0 { ops[$1 " | " $2] = ops[$1 " | " $2] ", " $3 }
                           END { for (i = 0; i < n && i < 12; ++i) print order[i] ": " ops[order[i]]
                                 if (n > 12) print "... and " n - 12 " more configurations" }' | indent
        echo "    first differing lines (< base, > new):"
        grep '^[<>]' "$work/diff.txt" | awk 'NR <= 4' | indent
    done
}

compare_cli() {
    local name args rc_a rc_b file
    while read -r name args; do
        rc_a=$(cat "$work/base/cli/$name.rc") rc_b=$(cat "$work/new/cli/$name.rc")
        if [[ $rc_a != 0 || $rc_b != 0 ]]; then
            if [[ $rc_a == "$rc_b" ]] && cmp -s "$work/base/cli/$name.log" "$work/new/cli/$name.log"; then
                report_same "ggx $name (fails alike on both sides, exit $rc_a)"
            else
                report_differs "ggx $name: exit $rc_a (base) against $rc_b (new)"
                for side in base new; do tail -2 "$work/$side/cli/$name.log" | sed "s/^/$side: /" | indent; done
            fi
            continue
        fi
        for file in $( (cd "$work/base/cli" && ls -- "$name".*; cd "$work/new/cli" && ls -- "$name".*) 2>/dev/null |
                       grep -v -E '\.(log|rc)$' | sort -u || true); do
            compare_file "ggx $name: $file" "$work/base/cli/$file" "$work/new/cli/$file"
        done
    done < <(cli_jobs)
}

check_new_build "$new_build"
work=$(mktemp -d "${TMPDIR:-/tmp}/ggxcl-compare.XXXXXX")
echo "# base: $short ($base_tree/build); new: $new_build (sources $new_src); outputs in $work"
start=$SECONDS
build_base
echo "# base built in $((SECONDS - start)) s"
start=$SECONDS
compile_driver "$base_tree" "$base_tree/build" "$work/dump-base" & base_compile=$!
compile_driver "$new_src" "$new_build" "$work/dump-new" || { cat "$work/dump-new.log" >&2; fail "the driver does not compile against $new_build"; }
wait "$base_compile" || { cat "$work/dump-base.log" >&2; fail "the driver does not compile against $short"; }
# The two sides run side by side (the work is mostly single-threaded kernel and shader builds).
run_side "$base_tree/build/apps/ggx" "$work/dump-base" "$work/base" & base_run=$!
run_side "$new_build/apps/ggx" "$work/dump-new" "$work/new"
wait "$base_run"
echo "# drivers compiled and both sides run in $((SECONDS - start)) s"
compare_dump
compare_cli
echo "summary: $same same, $differs differ ($short against $new_build)"
if ((differs == 0)); then
    rm -rf "$work"
    exit 0
fi
echo "(outputs kept in $work)"
exit 1
