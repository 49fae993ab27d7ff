"""ggxcl - GGX microfacet importance samplers on OpenCL devices.

    import ggxcl
    s = ggxcl.Sampler()                     # GGXCL_DEVICE, else the first device
    d = s.sample("caps", 1 << 20, alpha=0.3, theta=60, seed=1)
    d["o"].shape, d["pdf_o"].shape          # (1048576, 3) float32, (1048576,) float32

Methods: ndf, heitz, heitz2017, caps, caps-iso, bounded (ggxcl.method_traits
holds what each is: its space, isotropic only, the distribution of its normals,
dielectric, views below the horizon, and why a trait is missing), or a sampler of your
own in one file: ggxcl.UserSampler("my.h") in place of the name
(docs/USER-SAMPLERS.md).  Fields: m and o
(n, 3), pdf_m, pdf_o, weight (n,), u (n, 2): the uniforms a sample used.
Sample k depends on (seed, k) alone: the same seed and range give the bits
that `ggx sample` writes and the C++ Sampler::generate returns.  Per-sample
parameters come as arrays: alpha (n,) or (n, 2), view and normal (n, 3),
uniforms (n, 2) in [0, 1) (the caller's own, in place of `sequence`).

In a pyopencl pipeline: Sampler(device=pyopencl_device, context=pyopencl_context)
and sampler.enqueue(queue, method, n, outputs={"m": buffer, ...}) write into
pyopencl Buffers on a pyopencl queue and return a pyopencl.Event.

Errors: InvalidArgument (a ValueError; .parameter names the argument),
DeviceError (a RuntimeError), BuildError (.log) and DeviceLost.  The device
works without the GIL; Ctrl-C stops a long call between chunks with
KeyboardInterrupt.
"""
from ._ggxcl import (  # noqa: F401
    BuildError,
    DeviceError,
    DeviceLost,
    InvalidArgument,
    Sampler,
    UserSampler,
    __version__,
    devices,
    method_traits,
    methods,
)

__all__ = ["Sampler", "UserSampler", "devices", "methods", "method_traits", "InvalidArgument", "DeviceError", "BuildError", "DeviceLost",
           "__version__"]
