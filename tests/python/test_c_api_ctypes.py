"""test_c_api_ctypes.py - ggxcl's C API (ggxcl/ggxcl.h) from Python's ctypes,
as any language with a C FFI reaches it: ggxcl_generate gives the bits the
Python module's sample() gives, and a bad alpha or an unknown sequence
comes back as GGXCL_INVALID_ARGUMENT with its message and parameter.  The library is the
one GGXCL_C_LIBRARY names (CTest: the build tree's libggxcl.so)."""
import ctypes
import os

import numpy as np
import pytest

import ggxcl

LIBRARY = os.environ.get("GGXCL_C_LIBRARY")
GGXCL_SUCCESS, GGXCL_INVALID_ARGUMENT = 0, -1
FIELD_O, FIELD_PDF_O = 1, 3


class Params(ctypes.Structure):  # ggxcl_params
    _fields_ = [("method", ctypes.c_int), ("alpha_x", ctypes.c_float), ("alpha_y", ctypes.c_float),
                ("view", ctypes.c_float * 3), ("normal", ctypes.c_float * 3), ("precision", ctypes.c_int),
                ("sequence", ctypes.c_int), ("world_space", ctypes.c_int), ("eta", ctypes.c_float),
                ("transport", ctypes.c_int), ("user_sampler", ctypes.c_void_p)]


class Range(ctypes.Structure):  # ggxcl_range
    _fields_ = [("seed", ctypes.c_uint64), ("first", ctypes.c_uint64), ("count", ctypes.c_uint64)]


FloatPointer = ctypes.POINTER(ctypes.c_float)


class HostOutputs(ctypes.Structure):  # ggxcl_host_outputs
    _fields_ = [(name, FloatPointer) for name in ("m", "o", "pdf_m", "pdf_o", "weight", "u")]


@pytest.fixture(scope="module")
def lib():
    if not LIBRARY:
        pytest.fail("GGXCL_C_LIBRARY is not set (CTest sets it to the build tree's libggxcl)")
    lib = ctypes.CDLL(LIBRARY)
    lib.ggxcl_version.restype = ctypes.c_char_p
    lib.ggxcl_last_error.restype = ctypes.c_char_p
    lib.ggxcl_last_error_parameter.restype = ctypes.c_char_p
    lib.ggxcl_method_name.restype = ctypes.c_char_p
    lib.ggxcl_sampler_create.argtypes = [ctypes.c_char_p, ctypes.POINTER(ctypes.c_void_p)]
    lib.ggxcl_sampler_release.argtypes = [ctypes.c_void_p]
    lib.ggxcl_generate.argtypes = [ctypes.c_void_p, ctypes.POINTER(Params), ctypes.POINTER(Range), ctypes.c_uint,
                                   ctypes.POINTER(HostOutputs)]
    return lib


@pytest.fixture(scope="module")
def c_sampler(lib):
    handle = ctypes.c_void_p()
    assert lib.ggxcl_sampler_create(b"", ctypes.byref(handle)) == GGXCL_SUCCESS, lib.ggxcl_last_error()
    yield handle
    lib.ggxcl_sampler_release(handle)


def params_of(lib, method, alpha, view):
    params = Params()
    lib.ggxcl_default_params(ctypes.byref(params))
    method_ids = {lib.ggxcl_method_name(i).decode(): i for i in range(len(ggxcl.methods))}
    params.method = method_ids[method]
    params.alpha_x, params.alpha_y = alpha
    params.view[:] = view
    return params


def test_version_is_the_modules(lib):
    assert lib.ggxcl_version().decode() == ggxcl.__version__


@pytest.mark.parametrize("method", ["caps", "bounded"])
def test_generate_through_ctypes_equals_sample(lib, c_sampler, method):
    n, alpha, view = 3000, (0.2, 0.5), (0.6, 0.0, 0.8)
    o = np.zeros(3 * n, dtype=np.float32)
    pdf_o = np.zeros(n, dtype=np.float32)
    outputs = HostOutputs(o=o.ctypes.data_as(FloatPointer), pdf_o=pdf_o.ctypes.data_as(FloatPointer))
    params = params_of(lib, method, alpha, view)
    mask = (1 << FIELD_O) | (1 << FIELD_PDF_O)
    status = lib.ggxcl_generate(c_sampler, ctypes.byref(params), ctypes.byref(Range(7, 123, n)), mask,
                                ctypes.byref(outputs))
    assert status == GGXCL_SUCCESS, lib.ggxcl_last_error()
    d = ggxcl.Sampler().sample(method, n, alpha=alpha, view=view, seed=7, first=123, fields=("o", "pdf_o"))
    assert np.array_equal(o.reshape(3, n).T.view(np.uint32), d["o"].view(np.uint32))
    assert np.array_equal(pdf_o.view(np.uint32), d["pdf_o"].view(np.uint32))


def test_bad_alpha_is_a_status_with_its_message(lib, c_sampler):
    params = params_of(lib, "caps", (-0.5, 0.3), (0.0, 0.0, 1.0))
    status = lib.ggxcl_generate(c_sampler, ctypes.byref(params), ctypes.byref(Range(1, 0, 10)), 0,
                                ctypes.byref(HostOutputs()))
    assert status == GGXCL_INVALID_ARGUMENT
    assert b"alpha" in lib.ggxcl_last_error_parameter() and b"-0.5" in lib.ggxcl_last_error()


def test_unknown_sequence_names_the_sequences(lib, c_sampler):
    params = params_of(lib, "caps", (0.3, 0.3), (0.0, 0.0, 1.0))
    params.sequence = 7
    status = lib.ggxcl_generate(c_sampler, ctypes.byref(params), ctypes.byref(Range(1, 0, 10)), 0,
                                ctypes.byref(HostOutputs()))
    assert status == GGXCL_INVALID_ARGUMENT
    assert lib.ggxcl_last_error_parameter() == b"params.sequence"
    assert b"philox, sobol" in lib.ggxcl_last_error()
