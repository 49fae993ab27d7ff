"""test_check_targets.py - bench/check_targets.py on CSVs made for the purpose:
a target met and not met turns on the numbers (caps / heitz at 1.4 and 1.2),
targets without their rows are left out, --into replaces its own section
(run twice, one section) and keeps the rest, and a file that is not a bench
CSV is refused with a message naming what is missing; a run on two APIs is
checked on its first device's rows; the 2x-of-the-limit target reads
ggx-limits' CSV (--limits)."""
import os
import subprocess
import sys

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "bench", "check_targets.py")
HEADER = "method,precision,job,ns_median,ns_min,ns_max,sequence,eta,samples_per_run\n"
LIMITS_HEADER = "method,precision,job,ns_median,ns_low,ns_high,compute_limit_ns,percent_of_limit\n"


def write_csv(path, rows):
    with open(path, "w") as f:
        f.write(HEADER + "".join(",".join(map(str, row)) + "\n" for row in rows))


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *map(str, args)], capture_output=True, text=True)


def rows(caps_ns, heitz_ns):
    return [("caps", "precise", "write", caps_ns, caps_ns, caps_ns, "philox", 0, 1024),
            ("heitz", "precise", "write", heitz_ns, heitz_ns, heitz_ns, "philox", 0, 1024)]


def write_limits(path, caps_percent, heitz_percent):
    with open(path, "w") as f:
        f.write(LIMITS_HEADER + f"caps,precise,write,5,5,5,3.0,{caps_percent}\n"
                f"heitz,precise,write,7,7,7,3.0,{heitz_percent}\nall,store-only,write,1,1,1,,\n")


def target_line(output, start):
    return next(line for line in output.splitlines() if line.startswith("| " + start))


def test_a_target_turns_on_the_numbers(tmp_path):
    met, missed = tmp_path / "met.csv", tmp_path / "missed.csv"
    write_csv(met, rows(5.0, 7.0))      # heitz / caps = 1.4
    write_csv(missed, rows(5.0, 6.0))   # 1.2: the negative control
    out_met, out_missed = run(met), run(missed)
    assert out_met.returncode == 0 and out_missed.returncode == 0
    assert target_line(out_met.stdout, "caps / heitz speed >= 1.35, write").endswith("| 1.40 | yes |")
    assert target_line(out_missed.stdout, "caps / heitz speed >= 1.35, write").endswith("| 1.20 | **no** |")
    assert "furnace" not in out_met.stdout         # no furnace rows: no furnace target
    assert "native C++" not in out_met.stdout      # no native rows: no baseline target
    assert "of its limit" not in out_met.stdout    # no --limits: no limit target
    assert "2 of 2 met." in out_met.stdout      # every method within 2x of caps, too


def test_the_limit_target_reads_the_limits_csv(tmp_path):
    bench, limits = tmp_path / "b.csv", tmp_path / "limits.csv"
    write_csv(bench, rows(5.0, 7.0))
    write_limits(limits, 60, 40)
    out = run(bench, "--limits", limits)
    assert out.returncode == 0
    assert "slowest heitz write: 40% of its limit | **no** |" in out.stdout
    write_limits(limits, 60, 50)   # both at 50% or more: met
    assert "slowest heitz write: 50% of its limit | yes |" in run(bench, "--limits", limits).stdout
    result = run(bench, "--limits", bench)   # the bench's CSV given as the limits'
    assert result.returncode == 1 and "is not the CSV of `ggx-limits --csv`" in result.stderr


def test_into_replaces_its_own_section(tmp_path):
    csv_path, document = tmp_path / "b.csv", tmp_path / "BENCHMARKS.md"
    write_csv(csv_path, rows(5.0, 7.0))
    document.write_text("# Benchmarks\n\nthe user's report\n")
    assert run(csv_path, "--into", document).returncode == 0
    write_csv(csv_path, rows(5.0, 6.0))
    assert run(csv_path, "--into", document).returncode == 0
    text = document.read_text()
    assert text.startswith("# Benchmarks\n\nthe user's report\n")
    assert text.count("## The project's speed targets") == 1
    assert "| 1.20 | **no** |" in text and "| 1.40 |" not in text


def test_a_file_that_is_not_a_bench_csv_is_refused(tmp_path):
    other = tmp_path / "other.csv"
    other.write_text("alpha,theta\n0.3,60\n")
    result = run(other)
    assert result.returncode == 1
    assert "is not the CSV of `ggx bench --csv`" in result.stderr and "ns_median" in result.stderr


def test_a_run_on_two_apis_is_checked_on_its_first_device(tmp_path):
    two = tmp_path / "two.csv"
    with open(two, "w") as f:  # OpenCL's rows meet caps / heitz, Vulkan's (slower caps) would not
        f.write(HEADER.rstrip("\n") + ",api\n")
        for row in rows(5.0, 7.0):
            f.write(",".join(map(str, row)) + ",opencl\n")
        for row in rows(6.5, 7.0):
            f.write(",".join(map(str, row)) + ",vulkan (glsl)\n")
    out = run(two)
    assert out.returncode == 0
    assert target_line(out.stdout, "caps / heitz speed >= 1.35, write").endswith("| 1.40 | yes |")
    flipped = tmp_path / "flipped.csv"  # the control: Vulkan first, its numbers checked
    lines = two.read_text().splitlines()
    flipped.write_text("\n".join([lines[0]] + lines[3:] + lines[1:3]) + "\n")
    assert target_line(run(flipped).stdout, "caps / heitz speed >= 1.35, write").endswith("| 1.08 | **no** |")
