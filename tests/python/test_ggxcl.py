"""test_ggxcl.py - the ggxcl Python module against the C++ library and the
`ggx` tool: the same seed and range give the bits `ggx sample` writes and
the bits C++ `Sampler::generate` returns, for every method; pdf equals the pdf_o field; the histogram passes its
chi-square and rejects another method's pdf (negative control); the furnace
equals the mean of the weights; per-sample arrays and the caller's
uniforms; out= arrays; bad input raises errors naming the argument; a
signal raises KeyboardInterrupt in the middle of a long call; pyopencl
buffers written by Sampler.enqueue on a pyopencl queue equal sample(), its
events chain, and a buffer too small raises InvalidArgument.  Rough
dielectrics (eta=): three uniforms (and the caller's three), pdf equal to
pdf_o over the whole sphere, eval / pdf_o equal to the weight in both
transports, the furnace's reflectance and transmittance, the histogram over
both lobes (its negative controls are C++'s), pyopencl buffers, bad values.

Run by CTest (test_python) with PYTHONPATH at the build tree's python/,
GGX_BINARY the `ggx` tool and GGX_GENERATE_DUMP generate_dump (a C++
program writing generate's planar floats).
"""
import json
import os
import signal
import subprocess
import threading

import numpy as np
import pytest

import ggxcl

GGX = os.environ.get("GGX_BINARY", "ggx")
GENERATE_DUMP = os.environ.get("GGX_GENERATE_DUMP")
FIELDS = ("m", "o", "pdf_m", "pdf_o", "weight")


@pytest.fixture(scope="module")
def sampler():
    return ggxcl.Sampler()


def read_npy(path):
    return np.load(path)


@pytest.mark.parametrize("method", ggxcl.methods)
def test_sample_equals_ggx_sample_bit_for_bit(sampler, tmp_path, method):
    alpha = "0.25" if method == "caps-iso" else "0.2,0.5"
    out = tmp_path / "s.npy"
    subprocess.run([GGX, "sample", "--method", method, "--alpha", alpha, "--theta", "50", "--phi", "20", "-n", "5000",
                    "--seed", "7", "--first", "123", "--fields", "m,o,pdf_m,pdf_o,weight,u", "--out", str(out)],
                   check=True, stdout=subprocess.DEVNULL)
    rows = read_npy(out)
    a = tuple(float(x) for x in alpha.split(","))
    d = sampler.sample(method, 5000, alpha=a if len(a) == 2 else a[0], theta=50, phi=20, seed=7, first=123,
                       fields=FIELDS + ("u",))
    columns = np.concatenate([d["m"], d["o"], d["pdf_m"][:, None], d["pdf_o"][:, None], d["weight"][:, None],
                              d["u"]], axis=1)
    assert columns.dtype == np.float32 and columns.shape == rows.shape == (5000, 11)
    assert np.array_equal(columns.view(np.uint32), rows.view(np.uint32))
    side = json.loads((tmp_path / "s.json").read_text())
    assert side["method"] == method


@pytest.mark.parametrize("method", ggxcl.methods)
def test_sample_equals_cpp_generate_bit_for_bit(sampler, tmp_path, method):
    if GENERATE_DUMP is None:
        pytest.fail("GGX_GENERATE_DUMP is not set (CTest sets it to the generate_dump program)")
    n, alpha = 3001, (0.3, 0.3) if method == "caps-iso" else (0.15, 0.6)
    raw = tmp_path / "generate.f32"
    subprocess.run([GENERATE_DUMP, method, str(alpha[0]), str(alpha[1]), "70", "35", "11", "4096", str(n), str(raw)],
                   check=True)
    planes = np.fromfile(raw, dtype=np.float32)
    d = sampler.sample(method, n, alpha=alpha, theta=70, phi=35, seed=11, first=4096, fields=FIELDS + ("u",))
    at = 0
    for field, columns in (("m", 3), ("o", 3), ("pdf_m", 1), ("pdf_o", 1), ("weight", 1), ("u", 2)):
        expected = planes[at:at + columns * n].reshape(columns, n).T
        at += columns * n
        got = d[field].reshape(n, columns)
        assert np.array_equal(got.view(np.uint32), expected.view(np.uint32)), field
    assert at == planes.size


def test_sobol_and_the_callers_uniforms(sampler):
    d = sampler.sample("heitz", 4096, alpha=0.4, sequence="sobol", seed=3, fields=("o", "u"))
    again = sampler.sample("heitz", 4096, alpha=0.4, uniforms=d["u"].astype(np.float64), fields=("o", "u"))
    assert np.array_equal(d["o"], again["o"]) and np.array_equal(d["u"], again["u"])
    philox = sampler.sample("heitz", 4096, alpha=0.4, seed=3, fields=("o",))
    assert not np.array_equal(d["o"], philox["o"])  # control
    # The first 2^12 Sobol points are a net: every cell of 2^-6 x 2^-6 holds one.
    cells = (d["u"][:, 0] * 64).astype(int) * 64 + (d["u"][:, 1] * 64).astype(int)
    assert len(np.unique(cells)) == 4096


def test_pdf_equals_the_pdf_o_field(sampler):
    d = sampler.sample("bounded", 3000, alpha=(0.3, 0.6), theta=40, seed=2, fields=("o", "pdf_o"))
    p = sampler.pdf("bounded", d["o"], alpha=(0.3, 0.6), theta=40)
    assert p.shape == (3000,) and p.dtype == np.float32
    assert np.allclose(p, d["pdf_o"], rtol=1e-4, atol=0)


def test_eval_over_pdf_is_the_weight(sampler):
    for method in ("ndf", "heitz", "caps", "bounded"):
        d = sampler.sample(method, 3000, alpha=(0.3, 0.6), theta=40, seed=3, fields=("o", "pdf_o", "weight"))
        f = sampler.eval(d["o"], alpha=(0.3, 0.6), theta=40)
        assert f.shape == (3000,) and f.dtype == np.float32
        used = d["weight"] > 0
        assert used.sum() > 2000
        assert np.allclose(f[used] / d["pdf_o"][used], d["weight"][used], rtol=1e-3, atol=0)
    below = np.array([[0.0, 0.6, -0.8]], dtype=np.float32)
    assert sampler.eval(below, alpha=0.3)[0] == 0.0
    with pytest.raises(ggxcl.InvalidArgument, match="normal"):
        sampler.eval(below, normal=(0, 0, 1))


def test_histogram_passes_its_chi_square_and_rejects_another_pdf(sampler):
    h = sampler.histogram("caps", 10 ** 6, alpha=0.3, theta=60, seed=5, bins_z=16, bins_phi=32)
    assert h["counts"].shape == (16, 32) and h["counts"].dtype == np.uint64
    assert int(h["counts"].sum()) == 10 ** 6 and h["non_finite"] == 0
    assert h["p_value"] > 1e-3
    assert abs(h["expected"].sum() - 10 ** 6) < 1.0
    wrong = sampler.histogram("ndf", 10 ** 6, alpha=0.3, theta=60, seed=5, bins_z=16, bins_phi=32, against="caps")
    assert wrong["p_value"] < 1e-6


def test_furnace_equals_the_mean_weight(sampler):
    f = sampler.furnace("caps", 2 ** 16, alpha=0.5, theta=70, seed=9)
    w = sampler.sample("caps", 2 ** 16, alpha=0.5, theta=70, seed=9, fields=("weight",))["weight"]
    assert f["count"] == 2 ** 16
    assert f["mean"] == pytest.approx(float(np.mean(w, dtype=np.float64)), rel=1e-5)
    assert f["variance"] == pytest.approx(float(np.var(w, dtype=np.float64, ddof=1)), rel=1e-3)


def test_per_sample_arrays_and_out(sampler):
    n = 2000
    rng = np.random.default_rng(1)
    alpha = rng.uniform(0.05, 1.0, size=n).astype(np.float32)
    theta = rng.uniform(0, np.pi / 2 * 0.95, size=n)
    view = np.stack([np.sin(theta), np.zeros(n), np.cos(theta)], axis=1)
    d = sampler.sample("caps", n, alpha=alpha, view=view, seed=4, fields=("m", "pdf_m"))
    for j in (0, 777, n - 1):  # sample j equals a uniform request for its own parameters
        one = sampler.sample("caps", 1, alpha=float(alpha[j]), view=view[j].tolist(), seed=4, first=j,
                             fields=("m", "pdf_m"))
        assert np.array_equal(one["m"][0], d["m"][j]) and one["pdf_m"][0] == d["pdf_m"][j]
    out = {"o": np.zeros((n, 3), np.float32), "weight": np.zeros(n, np.float32)}
    got = sampler.sample("ndf", n, seed=8, fields=("o", "weight"), out=out)
    assert got["o"] is out["o"] and np.all(np.linalg.norm(out["o"], axis=1) > 0.999)


def test_out_fills_a_memmap_in_chunks(sampler, tmp_path):
    n = 3 * (1 << 16) + 5
    memmap = np.lib.format.open_memmap(tmp_path / "o.npy", mode="w+", dtype=np.float32, shape=(n, 3))
    sampler.chunk_size = 1 << 16
    try:
        sampler.sample("caps", n, seed=6, fields=("o",), out={"o": memmap})
    finally:
        sampler.chunk_size = 1 << 20
    memmap.flush()
    whole = sampler.sample("caps", n, seed=6, fields=("o",))["o"]
    assert np.array_equal(np.load(tmp_path / "o.npy"), whole)


def test_dielectric_samples_pdf_and_eval(sampler):
    kw = dict(alpha=(0.3, 0.5), theta=50, eta=1.5)
    d = sampler.sample("caps", 4000, seed=2, fields=("o", "pdf_o", "weight", "u"), **kw)
    assert d["u"].shape == (4000, 3)
    plain = sampler.sample("caps", 4000, seed=2, fields=("u",), alpha=(0.3, 0.5), theta=50)["u"]
    assert np.array_equal(d["u"][:, :2], plain)  # u1, u2 as a conductor's; u3 chooses the lobe
    transmitted = d["o"][:, 2] < 0
    assert 0.8 < transmitted.mean() < 0.99
    valid = d["pdf_o"] > 0
    p = sampler.pdf("caps", d["o"], alpha=(0.3, 0.5), theta=50, eta=1.5)
    assert np.allclose(p[valid], d["pdf_o"][valid], rtol=2e-3, atol=0)
    for transport in ("radiance", "importance"):
        t = sampler.sample("heitz", 3000, seed=4, fields=("o", "pdf_o", "weight"), transport=transport, **kw)
        f = sampler.eval(t["o"], alpha=(0.3, 0.5), theta=50, eta=1.5, transport=transport)
        used = t["weight"] > 0
        assert np.allclose(f[used] / t["pdf_o"][used], t["weight"][used], rtol=2e-3, atol=0)
    again = sampler.sample("caps", 4000, fields=("o",), uniforms=d["u"], **kw)
    assert np.array_equal(again["o"], d["o"])  # the caller's three uniforms give the same samples


def test_dielectric_furnace_and_histogram(sampler):
    f = sampler.furnace("caps", 2 ** 16, alpha=0.5, theta=70, seed=9, eta=1.33, transport="importance")
    w = sampler.sample("caps", 2 ** 16, alpha=0.5, theta=70, seed=9, fields=("o", "weight"), eta=1.33,
                       transport="importance")
    reflected = w["o"][:, 2] > 0
    assert f["reflectance"] == pytest.approx(float(np.sum(w["weight"][reflected], dtype=np.float64)) / 2 ** 16,
                                             rel=1e-5)
    assert f["reflectance"] + f["transmittance"] == pytest.approx(f["mean"], rel=1e-12)
    assert 0.5 < f["mean"] < 1.0
    assert "reflectance" not in sampler.furnace("caps", 1024)
    h = sampler.histogram("ndf", 4 * 10 ** 5, alpha=0.4, theta=130, seed=5, bins_z=16, bins_phi=32, eta=1.5)
    assert int(h["counts"].sum()) + h["invalid"] == 4 * 10 ** 5
    assert h["counts"][:8].sum() > 0 and h["counts"][8:].sum() > 0  # both hemispheres
    assert h["p_value"] > 1e-3
    with pytest.raises(ggxcl.InvalidArgument) as error:
        sampler.histogram("caps", 1000, eta=1.5, of="m")
    assert error.value.parameter == "direction"


@pytest.mark.parametrize("kwargs, parameter", [
    (dict(method="walter"), "method"),
    (dict(alpha=float("nan")), "alpha_x"),
    (dict(alpha=np.zeros((5, 3), np.float32)), "alpha"),
    (dict(alpha=np.ones(5, np.int32)), "alpha"),
    (dict(view=np.ones((5, 3), np.float32)[:, ::2].copy()), "view"),
    (dict(view=np.ones((10, 3), np.float32)[::2]), "view"),
    (dict(fields=("m", "x")), "field"),
    (dict(fields=("m", "m")), "fields"),
    (dict(uniforms=np.full((5, 2), 1.0)), "uniforms[0]"),
    (dict(sequence="halton"), "sequence"),
    (dict(precision="turbo"), "precision"),
    (dict(seed=2 ** 32), "seed"),
    (dict(out={"m": np.zeros((5, 3), np.float64)}), "out[m]"),
    (dict(eta=1.0), "eta"),
    (dict(eta=-2.0), "eta"),
    (dict(method="bounded", eta=1.5), "eta"),
    (dict(eta=1.5, transport="photons"), "transport"),
    (dict(eta=1.5, uniforms=np.full((5, 2), 0.5)), "uniforms"),
    (dict(eta=1.5, uniforms=np.full((5, 3), 0.5) + np.array([0, 0, 0.6])), "lobe_uniforms[0]"),
])
def test_bad_input_names_the_argument(sampler, kwargs, parameter):
    args = dict(method="caps", n=5, fields=("m",))
    args.update(kwargs)
    with pytest.raises(ggxcl.InvalidArgument) as error:
        sampler.sample(args.pop("method"), args.pop("n"), **args)
    assert error.value.parameter == parameter
    assert isinstance(error.value, ValueError)


@pytest.mark.parametrize("kwargs, message", [
    (dict(alpha=1e-35), "invalid alpha_x '1e-35': allowed is a number from 1e-30 to 1e30"),
    (dict(alpha=1e31), "invalid alpha_x '1e+31': allowed is a number from 1e-30 to 1e30"),
    (dict(theta=200), "invalid theta '200': allowed is degrees from 0 to 180"),
    (dict(method="caps-iso", alpha=(0.1, 0.2)),
     "allowed is one value (alpha_x == alpha_y) for caps-iso: " + ggxcl.method_traits["caps-iso"]["limits"]),
    (dict(method="bounded", eta=1.5), "allowed is 0 for bounded: " + ggxcl.method_traits["bounded"]["limits"]),
])
def test_the_library_rules_in_its_words(sampler, kwargs, message):
    """The library's rule and message, as C++, the C API and the CLI give them."""
    args = dict(method="caps", n=5, fields=("m",))
    args.update(kwargs)
    with pytest.raises(ggxcl.InvalidArgument) as error:
        sampler.sample(args.pop("method"), args.pop("n"), **args)
    assert message in str(error.value)


def test_n_is_a_whole_number_as_an_int_a_float_or_a_numpy_integer(sampler):
    a = sampler.sample("caps", 1e3, fields=("pdf_o",), seed=3)["pdf_o"]
    b = sampler.sample("caps", np.int64(1000), fields=("pdf_o",), seed=3)["pdf_o"]
    assert a.shape == (1000,) and np.array_equal(a, b)
    for bad in (1.5, -1, True, "10", float("nan")):
        with pytest.raises(ggxcl.InvalidArgument) as error:
            sampler.sample("caps", bad)
        assert error.value.parameter == "n"
        assert "a whole number of samples: 1000000, 1e6 or 2**20" in str(error.value)


def test_method_traits_name_every_method():
    assert set(ggxcl.method_traits) == set(ggxcl.methods)
    assert ggxcl.method_traits["caps-iso"]["space"] == "world" and ggxcl.method_traits["caps-iso"]["isotropic_only"]
    assert not ggxcl.method_traits["bounded"]["dielectric"] and ggxcl.method_traits["bounded"]["normals"] == "own"
    assert not ggxcl.method_traits["heitz2017"]["views_below"]
    assert ggxcl.method_traits["ndf"]["normals"] == "ndf"


def test_device_errors_are_runtime_errors():
    with pytest.raises(ggxcl.DeviceError) as error:
        ggxcl.Sampler("no-such-device")
    assert isinstance(error.value, RuntimeError)
    assert len(ggxcl.devices()) >= 1 and "label" in ggxcl.devices()[0]


def test_a_signal_interrupts_a_long_call(sampler):
    # 2^30 weights (4 GiB, allocated lazily) take seconds; SIGINT after 0.3 s stops the call between chunks.
    # Then more calls: the interrupted call must have left no copy in flight into memory it freed.
    sampler.chunk_size = 1 << 16
    main = threading.main_thread().ident
    timer = threading.Timer(0.3, lambda: signal.pthread_kill(main, signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            sampler.sample("caps", 1 << 30, fields=("weight",))
    finally:
        timer.cancel()
        sampler.chunk_size = 1 << 20
    for seed in range(20):
        assert sampler.sample("caps", 100_000, seed=seed)["m"].shape == (100_000, 3)


def pyopencl_device_of(sampler):
    """The pyopencl device that `sampler` runs on (same platform and name)."""
    platforms = {d["platform"] for d in ggxcl.devices() if d["api"] == "opencl" and d["name"] == sampler.device_name}
    cl = pytest.importorskip("pyopencl")
    for platform in cl.get_platforms():
        if platform.name in platforms:
            for device in platform.get_devices():
                if device.name == sampler.device_name:
                    return cl, device
    pytest.fail("pyopencl does not see " + sampler.device_name)


def test_pyopencl_buffers_equal_sample_and_chain_by_events(sampler):
    cl, device = pyopencl_device_of(sampler)
    context = cl.Context([device])
    queue = cl.CommandQueue(context)
    on_context = ggxcl.Sampler(device=device, context=context)
    n, stride = 3000, 3072
    m = cl.Buffer(context, cl.mem_flags.READ_WRITE, 3 * stride * 4)
    pdf_o = cl.Buffer(context, cl.mem_flags.READ_WRITE, stride * 4)
    first = on_context.enqueue(queue, "caps", n, outputs={"m": m, "pdf_o": pdf_o}, seed=3, stride=stride, theta=45)
    assert isinstance(first, cl.Event)
    second = on_context.enqueue(queue, "bounded", n, outputs={"pdf_o": pdf_o}, seed=3, stride=stride, theta=45,
                                wait_for=[first])
    second.wait()
    host_m, host_pdf = np.empty(3 * stride, np.float32), np.empty(stride, np.float32)
    cl.enqueue_copy(queue, host_m, m)
    cl.enqueue_copy(queue, host_pdf, pdf_o)
    expected = sampler.sample("caps", n, seed=3, theta=45, fields=("m",))["m"]
    assert np.array_equal(host_m.reshape(3, stride)[:, :n].T, expected)
    bounded = sampler.sample("bounded", n, seed=3, theta=45, fields=("pdf_o",))["pdf_o"]
    assert np.array_equal(host_pdf[:n], bounded)  # the second launch, after the first
    small = cl.Buffer(context, cl.mem_flags.READ_WRITE, 3 * stride * 4 - 4)
    with pytest.raises(ggxcl.InvalidArgument) as error:
        on_context.enqueue(queue, "caps", n, outputs={"m": small}, stride=stride)
    assert error.value.parameter == "outputs.m"
    with pytest.raises(ggxcl.InvalidArgument) as error:
        on_context.enqueue(queue, "caps", n, outputs={"m": "not a buffer"})
    assert error.value.parameter == "outputs[m]"
    u = cl.Buffer(context, cl.mem_flags.READ_WRITE, 3 * stride * 4)
    on_context.enqueue(queue, "caps", n, outputs={"u": u}, seed=3, stride=stride, eta=1.5).wait()
    host_u = np.empty(3 * stride, np.float32)
    cl.enqueue_copy(queue, host_u, u)
    assert np.array_equal(host_u.reshape(3, stride)[:, :n].T, sampler.sample("caps", n, seed=3, eta=1.5,
                                                                              fields=("u",))["u"])
    with pytest.raises(ggxcl.InvalidArgument) as error:  # a conductor's two planes are too few
        on_context.enqueue(queue, "caps", n, outputs={"u": small}, stride=stride, eta=1.5)
    assert error.value.parameter == "outputs.u"
