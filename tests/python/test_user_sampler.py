"""ggxcl.UserSampler from Python: a copy of caps gives caps' bits and passes
the histogram's tests against its own pdf and the VNDF it claims; swapped
roughness axes fail both, a pdf off by 2 integrates to 2; a file that does
not compile raises BuildError naming its file and line; bad input raises
InvalidArgument naming the argument, and so does a GLSL or HLSL sampler
(Python runs on OpenCL), naming its file."""
import os

import numpy as np
import pytest

import ggxcl

SAMPLERS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "user_samplers")


def user(file, **kwargs):
    return ggxcl.UserSampler(os.path.join(SAMPLERS, file), **kwargs)


@pytest.fixture(scope="module")
def sampler():
    return ggxcl.Sampler()


def test_a_user_sampler_describes_itself():
    copy = user("caps_copy.h")
    assert copy.name == "caps_copy"
    assert copy.distribution == "vndf"
    assert not copy.samples_m
    assert len(copy.key) == 16
    assert user("heitz_normal_only.h", name="mine").name == "mine"
    assert user("heitz_normal_only.h").samples_m


def test_a_copy_of_caps_gives_caps_bits(sampler):
    fields = ("m", "o", "pdf_m", "pdf_o", "weight", "u")
    args = dict(alpha=(0.2, 0.5), theta=75, seed=3, first=10, fields=fields, sequence="sobol")
    mine = sampler.sample(user("caps_copy.h"), 3000, **args)
    caps = sampler.sample("caps", 3000, **args)
    for field in fields:
        assert np.array_equal(mine[field].view(np.uint32), caps[field].view(np.uint32)), field
    directions = caps["o"]
    assert np.array_equal(sampler.pdf(user("caps_copy.h"), directions, alpha=(0.2, 0.5), theta=75),
                          sampler.pdf("caps", directions, alpha=(0.2, 0.5), theta=75))
    assert sampler.furnace(user("caps_copy.h"), 5000, seed=2)["mean"] == sampler.furnace("caps", 5000, seed=2)["mean"]


def test_histogram_of_a_user_sampler_tests_its_pdf_and_its_claim(sampler):
    good = sampler.histogram(user("caps_copy.h"), 200000, alpha=(0.2, 0.6))
    assert good["p_value"] > 1e-3
    assert good["claimed"]["distribution"] == "vndf"
    assert good["claimed"]["p_value"] > 1e-3
    assert abs(good["pdf_integral"] - 1.0) < 1e-3
    swapped = sampler.histogram(user("swapped_axes.h"), 200000, alpha=(0.2, 0.6))
    assert swapped["p_value"] < 1e-9
    assert swapped["claimed"]["p_value"] < 1e-9
    doubled = sampler.histogram(user("pdf_doubled.h"), 20000, alpha=(0.2, 0.6))
    assert abs(doubled["pdf_integral"] - 2.0) < 1e-3


def test_a_file_that_does_not_compile_names_its_line(sampler):
    with pytest.raises(ggxcl.BuildError) as error:
        sampler.sample(user("syntax_error.h"), 10)
    assert "syntax_error.h:9:" in str(error.value).splitlines()[0]


def test_a_shader_sampler_is_refused_on_opencl_naming_its_file(sampler):
    path = os.path.join(SAMPLERS, "shaders", "caps_copy.glsl")
    with pytest.raises(ggxcl.InvalidArgument) as error:
        sampler.sample(ggxcl.UserSampler(path), 10)
    assert error.value.parameter == "sampler"
    assert path in str(error.value) and "GLSL" in str(error.value)


@pytest.mark.parametrize("make, parameter", [
    (lambda: ggxcl.UserSampler(os.path.join(SAMPLERS, "none.h")), "sampler"),
    (lambda: user("caps_copy.h", name="caps"), "sampler name"),
])
def test_bad_user_samplers_name_the_argument(make, parameter):
    with pytest.raises(ggxcl.InvalidArgument) as error:
        make()
    assert error.value.parameter == parameter


@pytest.mark.parametrize("kwargs, parameter", [
    (dict(method=42), "method"),
    (dict(eta=1.5), "eta"),
])
def test_bad_method_or_dielectric_names_the_argument(sampler, kwargs, parameter):
    args = dict(method=user("caps_copy.h"), n=5)
    args.update(kwargs)
    with pytest.raises(ggxcl.InvalidArgument) as error:
        sampler.sample(args.pop("method"), args.pop("n"), **args)
    assert error.value.parameter == parameter


def test_histogram_of_a_user_sampler_counts_discarded_samples_apart_and_bins_m(sampler):
    n = 200000
    kept = sampler.histogram(user("harness/bounded_discards.h"), n, alpha=0.5, theta=70)
    assert kept["discarded"] == kept["invalid"] > 0
    assert kept["p_value"] > 1e-3
    # A pdf of 0 where it discards integrates to what it keeps.
    assert abs(kept["pdf_integral"] - (1.0 - kept["discarded"] / n)) < 4e-3
    assert kept["pdf_integral_error"] < 1e-4
    m = sampler.histogram(user("caps_copy.h"), n, alpha=0.3, theta=45, of="m")
    assert m["p_value"] > 1e-3
    assert m["claimed"]["p_value"] > 1e-3
    assert abs(m["pdf_integral"] - 1.0) < 1e-3
    with pytest.raises(ggxcl.InvalidArgument) as error:
        sampler.histogram(user("caps_copy.h"), 1000, bins_z=31)
    assert error.value.parameter == "bins_z"
