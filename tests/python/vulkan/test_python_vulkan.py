"""test_python_vulkan.py - ggxcl.Sampler(api="vulkan") (a VulkanSampler behind
the same Python class; lavapipe in CI, under the validation layer):
- every method's samples, conductor and dielectric, in GLSL and HLSL, agree
  with the OpenCL Sampler's on the same request within the bounds of
  test_vulkan_sampler (angle of o 99% <= 1e-5 rad, max <= 2e-3; pdf_o
  relative 99% <= 1e-4), and equal C++ VulkanSampler::generate's bits;
- pdf, eval, furnace and histogram work and agree with OpenCL's (the
  histogram passes its chi-square; control: against another method's pdf it
  fails);
- a GLSL user sampler runs on it and gives caps' bits; an OpenCL C file is
  refused there, a GLSL file on OpenCL;
- calls from several Python threads at once give the bits of one thread;
- ggxcl.devices() lists the Vulkan device; enqueue (pyopencl's buffers), a
  pyopencl context, a shader language on OpenCL and an unknown API raise
  InvalidArgument naming the argument;
- on a machine with the OpenCL loader and no OpenCL platform (an empty
  OCL_ICD_VENDORS), `import ggxcl`, devices() and every Vulkan call work,
  and an OpenCL Sampler raises DeviceError saying what to install; with no
  Vulkan driver (VK_ICD_FILENAMES naming nothing) devices() lists OpenCL's
  and Sampler(api="vulkan") raises DeviceError saying what to install.

Run by CTest (test_python_vulkan) as test_ggxcl.py is, with
GGXCL_VULKAN_VALIDATION=1; skipped where ggxcl has no Vulkan device.
"""
import os
import pathlib
import subprocess
import sys
import threading

import numpy as np
import pytest

import ggxcl

GENERATE_DUMP = os.environ.get("GGX_GENERATE_DUMP")
SHADERS = pathlib.Path(__file__).resolve().parents[2] / "user_samplers" / "shaders"
FIELDS = ("m", "o", "pdf_m", "pdf_o", "weight", "u")


def open_vulkan(language):
    try:
        return ggxcl.Sampler(api="vulkan", shader_language=language)
    except ggxcl.DeviceError as e:
        pytest.skip(f"no Vulkan device: {e}")


@pytest.fixture(scope="module", params=["glsl", "hlsl"])
def vulkan(request):
    return open_vulkan(request.param)


@pytest.fixture(scope="module")
def opencl():
    return ggxcl.Sampler()


def angles(a, b):
    """Angles between rows of unit vectors, atan2 form (accurate near 0)."""
    cross = np.linalg.norm(np.cross(a.astype(np.float64), b.astype(np.float64)), axis=1)
    return np.arctan2(cross, np.sum(a.astype(np.float64) * b, axis=1))


def check_agreement(v, c):
    assert np.array_equal(v["u"], c["u"])  # the same uniforms, bit for bit
    assert np.all(np.isfinite(v["o"])) and np.all(np.isfinite(v["pdf_o"]))
    theta = angles(v["o"], c["o"])
    assert np.quantile(theta, 0.99) <= 1e-5 and theta.max() <= 2e-3
    kept = c["pdf_o"] > 0
    relative = np.abs(v["pdf_o"][kept] / c["pdf_o"][kept] - 1)
    assert np.quantile(relative, 0.99) <= 1e-4


@pytest.mark.parametrize("method", ggxcl.methods)
def test_samples_agree_with_opencl(vulkan, opencl, method):
    alpha = 0.35 if method == "caps-iso" else (0.35, 0.7)
    ask = dict(alpha=alpha, theta=55, phi=20, seed=9, first=100, fields=FIELDS)
    check_agreement(vulkan.sample(method, 20000, **ask), opencl.sample(method, 20000, **ask))
    if ggxcl.method_traits[method]["dielectric"]:
        check_agreement(vulkan.sample(method, 20000, eta=1.5, **ask), opencl.sample(method, 20000, eta=1.5, **ask))


@pytest.mark.parametrize("method", ["caps", "bounded"])
def test_samples_equal_cpp_vulkan_sampler_bit_for_bit(vulkan, tmp_path, method):
    if GENERATE_DUMP is None:
        pytest.fail("GGX_GENERATE_DUMP is not set (CTest sets it to the generate_dump program)")
    n, alpha = 3001, (0.15, 0.6)
    raw = tmp_path / "generate.f32"
    subprocess.run([GENERATE_DUMP, method, str(alpha[0]), str(alpha[1]), "70", "35", "11", "4096", str(n), str(raw),
                    "vulkan", vulkan.shader_language], check=True)
    planes = np.fromfile(raw, dtype=np.float32)
    d = vulkan.sample(method, n, alpha=alpha, theta=70, phi=35, seed=11, first=4096, fields=FIELDS)
    at = 0
    for field, columns in (("m", 3), ("o", 3), ("pdf_m", 1), ("pdf_o", 1), ("weight", 1), ("u", 2)):
        expected = planes[at:at + columns * n].reshape(columns, n).T
        at += columns * n
        assert np.array_equal(d[field].reshape(n, columns).view(np.uint32), expected.view(np.uint32)), field
    assert at == planes.size
    other = vulkan.sample(method, n, alpha=alpha, theta=70, phi=35, seed=12, first=4096, fields=("o",))  # control
    assert not np.array_equal(other["o"], d["o"])


def test_sobol_uniforms_per_sample_inputs_and_out_arrays(vulkan, opencl):
    n = 5000
    sobol = vulkan.sample("caps", n, alpha=(0.3, 0.6), sequence="sobol", seed=3, fields=FIELDS)
    check_agreement(sobol, opencl.sample("caps", n, alpha=(0.3, 0.6), sequence="sobol", seed=3, fields=FIELDS))
    again = vulkan.sample("caps", n, alpha=(0.3, 0.6), uniforms=sobol["u"].astype(np.float64), fields=FIELDS)
    assert np.array_equal(again["o"], sobol["o"]) and np.array_equal(again["u"], sobol["u"])  # the caller's uniforms
    rng = np.random.default_rng(7)
    views = rng.normal(size=(n, 3))
    views[:, 2] = np.abs(views[:, 2]) + 0.1
    alphas = rng.uniform(0.05, 1.0, size=(n, 2)).astype(np.float32)
    ask = dict(view=views, alpha=alphas, seed=4, fields=FIELDS)
    check_agreement(vulkan.sample("heitz", n, **ask), opencl.sample("heitz", n, **ask))
    out = {"o": np.empty((n, 3), np.float32), "pdf_o": np.empty(n, np.float32)}
    filled = vulkan.sample("heitz", n, out=out, fields=("o", "pdf_o"), view=views, alpha=alphas, seed=4)
    assert filled["o"] is out["o"] or np.shares_memory(filled["o"], out["o"])
    assert np.array_equal(out["o"], vulkan.sample("heitz", n, **ask)["o"])


def test_pdf_eval_furnace_and_histogram(vulkan, opencl):
    d = vulkan.sample("heitz", 4000, alpha=(0.3, 0.6), theta=40, seed=2, fields=("o", "pdf_o", "weight"))
    assert np.allclose(vulkan.pdf("heitz", d["o"], alpha=(0.3, 0.6), theta=40), d["pdf_o"], rtol=1e-4, atol=0)
    assert np.allclose(vulkan.pdf("heitz", d["o"], alpha=(0.3, 0.6), theta=40),
                       opencl.pdf("heitz", d["o"], alpha=(0.3, 0.6), theta=40), rtol=1e-4, atol=1e-6)
    value = vulkan.eval(d["o"], alpha=(0.3, 0.6), theta=40)
    assert np.allclose(value / d["pdf_o"], d["weight"], rtol=1e-4, atol=1e-6)
    f, g = vulkan.furnace("caps", 2e5, eta=1.5, seed=4), opencl.furnace("caps", 2e5, eta=1.5, seed=4)
    assert abs(f["mean"] - g["mean"]) <= 2e-5 * g["mean"]
    assert abs(f["reflectance"] - g["reflectance"]) <= 2e-5 * g["reflectance"]
    assert vulkan.histogram("bounded", 4e5, alpha=(0.3, 0.5), seed=5)["p_value"] > 1e-3
    assert vulkan.histogram("ndf", 4e5, alpha=(0.3, 0.5), seed=5, against="caps")["p_value"] < 1e-6  # control


def test_a_glsl_user_sampler_runs_on_vulkan_alone(vulkan, opencl):
    copy = ggxcl.UserSampler(str(SHADERS / "caps_copy.glsl"))
    mine = vulkan.sample(copy, 3000, alpha=(0.2, 0.5), seed=3, fields=("o", "pdf_o"))
    caps = vulkan.sample("caps", 3000, alpha=(0.2, 0.5), seed=3, fields=("o", "pdf_o"))
    assert np.array_equal(mine["o"], caps["o"]) and np.array_equal(mine["pdf_o"], caps["pdf_o"])
    with pytest.raises(ggxcl.InvalidArgument, match="caps_copy.glsl"):
        opencl.sample(copy, 10)
    opencl_c = ggxcl.UserSampler(str(SHADERS.parent / "caps_copy.h"))
    with pytest.raises(ggxcl.InvalidArgument, match="caps_copy.h"):
        vulkan.sample(opencl_c, 10)


def test_threads_share_one_vulkan_sampler(vulkan):
    def draw(k):
        return vulkan.sample("heitz2017", 20000, alpha=0.1 + 0.1 * k, seed=k, fields=("o", "pdf_o"))

    alone = [draw(k) for k in range(4)]
    results = [None] * 4

    def run(k):
        results[k] = draw(k)

    threads = [threading.Thread(target=run, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for k in range(4):
        assert np.array_equal(results[k]["o"], alone[k]["o"]) and np.array_equal(results[k]["pdf_o"], alone[k]["pdf_o"])
    assert not np.array_equal(alone[0]["o"], alone[1]["o"])  # control: the tasks differ


def test_devices_properties_and_errors(vulkan):
    listed = [d for d in ggxcl.devices() if d["api"] == "vulkan"]
    assert listed and vulkan.device_name in [d["label"] for d in listed]
    assert vulkan.api == "vulkan" and vulkan.shader_language in ("glsl", "hlsl")
    assert ggxcl.Sampler().api == "opencl" and ggxcl.Sampler().shader_language is None
    with pytest.raises(ggxcl.InvalidArgument) as e:
        vulkan.enqueue(None, "caps", 10, outputs={})
    assert e.value.parameter == "api"
    for bad, parameter in ((dict(api="metal"), "api"), (dict(shader_language="hlsl"), "shader_language"),
                           (dict(api="vulkan", shader_language="wgsl"), "shader language"),
                           (dict(api="vulkan", context=object()), "context")):
        with pytest.raises(ggxcl.InvalidArgument) as e:
            ggxcl.Sampler(**bad)
        assert e.value.parameter == parameter, bad


NO_OPENCL = """
import ggxcl, numpy as np
assert [d["api"] for d in ggxcl.devices()] == ["vulkan"] * len(ggxcl.devices()) and ggxcl.devices()
v = ggxcl.Sampler(api="vulkan")
d = v.sample("caps", 1000, seed=1, fields=("o", "pdf_o"))
assert np.allclose(v.pdf("caps", d["o"]), d["pdf_o"], rtol=1e-4)
assert v.eval(d["o"]).shape == (1000,)
assert 0.5 < v.furnace("caps", 1e4)["mean"] <= 1
assert v.histogram("caps", 1e5)["p_value"] > 1e-3
try:
    ggxcl.Sampler()
    raise SystemExit("an OpenCL Sampler without a platform")
except ggxcl.DeviceError as e:
    assert "install" in str(e), e
print("ok")
"""


def test_without_an_opencl_platform(vulkan, tmp_path):
    env = dict(os.environ, OCL_ICD_VENDORS=str(tmp_path))  # an empty folder: the loader finds no platform
    run = subprocess.run([sys.executable, "-c", NO_OPENCL], env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "ok"


NO_VULKAN = """
import ggxcl
assert [d["api"] for d in ggxcl.devices()] == ["opencl"] * len(ggxcl.devices()) and ggxcl.devices()
try:
    ggxcl.Sampler(api="vulkan")
    raise SystemExit("a Vulkan Sampler without a driver")
except ggxcl.DeviceError as e:
    assert "mesa-vulkan-drivers" in str(e), e
print("ok")
"""


def test_without_a_vulkan_driver(vulkan, tmp_path):
    env = dict(os.environ, VK_ICD_FILENAMES=str(tmp_path / "none.json"))
    run = subprocess.run([sys.executable, "-c", NO_VULKAN], env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "ok"
