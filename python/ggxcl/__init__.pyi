"""Type stubs of the ggxcl Python package (see __init__.py)."""
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str
methods: Tuple[str, ...]
# Per method name: paper, how, space ("tangent" or "world"), isotropic_only, normals ("vndf", "ndf", "own"),
# dielectric, views_below (bool each) and limits (why a trait is missing; "" when none is).
method_traits: Dict[str, Dict[str, Any]]

class InvalidArgument(ValueError):
    parameter: str

class DeviceError(RuntimeError): ...

class BuildError(DeviceError):
    log: str

class DeviceLost(DeviceError): ...

Alpha = Union[float, Tuple[float, float], npt.NDArray[np.floating[Any]]]

class UserSampler:
    """A sampler of your own in one file (docs/USER-SAMPLERS.md): pass it as `method`. A .glsl or .hlsl file is a
    shader for a Sampler(api='vulkan'), any other OpenCL C for an OpenCL Sampler; the other API raises
    InvalidArgument naming the file."""

    def __init__(self, path: str, name: Optional[str] = None) -> None:
        """Reads `path` and what it includes; `name` (default: the file's stem) names it in reports. A file
        without ggx_user_sample(_m), ggx_user_pdf or GGX_USER_DISTRIBUTION raises InvalidArgument naming the file;
        one that does not compile raises BuildError at its first use, naming its file and line."""
    @property
    def name(self) -> str: ...
    @property
    def path(self) -> str: ...
    @property
    def distribution(self) -> str:
        """The distribution it claims: 'vndf', 'ndf' or 'own'."""
    @property
    def samples_m(self) -> bool: ...
    @property
    def key(self) -> str: ...

Method = Union[str, UserSampler]
Vector = Union[Sequence[float], npt.NDArray[np.floating[Any]]]

def devices() -> List[Dict[str, Any]]:
    """Every device: api ('opencl' or 'vulkan'), index, selector (what Sampler's `device` takes with that api),
    name and label; OpenCL's also platform, type, compute_units and opencl_version. Vulkan devices where ggxcl
    was built with Vulkan and a driver is installed."""

class Sampler:
    """GGX samplers on one device of OpenCL or Vulkan (`device`: an index or part of a label; default GGXCL_DEVICE
    or GGXCL_VULKAN_DEVICE, else the first). Every call works on both APIs but enqueue (OpenCL's buffers); calls
    from several threads at once are safe and give the bits each gives alone."""

    def __init__(
        self,
        device: Optional[Any] = None,
        context: Optional[Any] = None,
        *,
        api: str = "opencl",
        shader_language: Optional[str] = None,
    ) -> None:
        """`device`: an index or part of a label (default GGXCL_DEVICE, or GGXCL_VULKAN_DEVICE with api='vulkan',
        else the first); with a pyopencl.Context `context` (OpenCL only), the sampler works on that context and
        `device` is a pyopencl.Device. `api`: 'opencl' or 'vulkan' (compute shaders from the same headers);
        `shader_language`: 'glsl' (the default) or 'hlsl', the Vulkan shaders' language. No driver for the API
        raises DeviceError saying what to install."""
    def enqueue(
        self,
        queue: Any,
        method: Method,
        n: Union[int, float],  # a whole number: 1000000, 1e6 or 2**20
        *,
        outputs: Mapping[str, Any],
        seed: int = 0,
        first: int = 0,
        stride: int = 0,
        alpha: Union[float, Tuple[float, float]] = 0.3,
        theta: float = 60.0,
        phi: float = 0.0,
        view: Optional[Sequence[float]] = None,
        normal: Optional[Sequence[float]] = None,
        precision: Optional[str] = None,
        sequence: str = "philox",
        inputs: Optional[Mapping[str, Any]] = None,
        views_above_horizon: bool = False,
        isotropic: bool = False,
        wait_for: Optional[Sequence[Any]] = None,
        eta: Optional[float] = None,
        transport: str = "radiance",
    ) -> Any:
        """Samples first .. first + n - 1 into pyopencl Buffers (outputs={'m': buffer, ...}: planar, plane c of a
        field at c * stride floats, stride 0 meaning n) on a pyopencl queue of this sampler's context, after the
        events of `wait_for`; per-sample inputs as Buffers too (inputs={'view', 'alpha', 'normal', 'uniforms'};
        with `eta`, uniforms and u have 3 planes). Returns a pyopencl.Event. A buffer too small raises
        InvalidArgument naming it; so does a Sampler on Vulkan (parameter 'api')."""
    @property
    def device_name(self) -> str: ...
    @property
    def api(self) -> str:
        """'opencl' or 'vulkan'."""
    @property
    def shader_language(self) -> Optional[str]:
        """'glsl' or 'hlsl' on Vulkan; None on OpenCL."""
    chunk_size: int
    def sample(
        self,
        method: Method,
        n: Union[int, float],  # a whole number: 1000000, 1e6 or 2**20
        *,
        alpha: Alpha = 0.3,
        theta: float = 60.0,
        phi: float = 0.0,
        view: Optional[Vector] = None,
        normal: Optional[Vector] = None,
        seed: int = 0,
        first: int = 0,
        fields: Sequence[str] = ("m", "o", "pdf_m", "pdf_o", "weight"),
        precision: Optional[str] = None,
        sequence: str = "philox",
        uniforms: Optional[npt.NDArray[np.floating[Any]]] = None,
        world_space: bool = False,
        out: Optional[Mapping[str, npt.NDArray[np.float32]]] = None,
        eta: Optional[float] = None,
        transport: str = "radiance",
    ) -> Dict[str, npt.NDArray[np.float32]]:
        """Samples first .. first + n - 1 of stream `seed` of `method`: a dict of float32 arrays, m and o (n, 3),
        pdf_m, pdf_o, weight (n,), u (n, 2). The view is (theta, phi) in degrees unless `view` is given (a vector,
        or (n, 3) per sample); alpha is a number, a pair (alpha_x, alpha_y) or an (n,) or (n, 2) array; `normal` is
        caps-iso's and world space's normal; `uniforms` (n, 2) replaces the sequence (philox or sobol); `out` maps
        fields to preallocated float32 arrays (a numpy.memmap too) that are filled instead. `eta` (index below the
        surface over index above) samples a rough dielectric: o reflected with probability F(i.m) or refracted,
        pdf_o its density over the whole sphere, weight in `transport` ("radiance" or "importance"); u and
        `uniforms` then have 3 columns (u3 chooses the lobe). Every method but bounded."""
    def pdf(
        self,
        method: Method,
        directions: npt.NDArray[np.floating[Any]],
        *,
        alpha: Alpha = 0.3,
        theta: float = 60.0,
        phi: float = 0.0,
        view: Optional[Vector] = None,
        normal: Optional[Vector] = None,
        precision: Optional[str] = None,
        world_space: bool = False,
        eta: Optional[float] = None,
    ) -> npt.NDArray[np.float32]:
        """The pdf (per steradian) of each direction (n, 3) for `method`'s sampler (with `eta`: its dielectric
        sampler, over the whole sphere)."""
    def eval(
        self,
        directions: npt.NDArray[np.floating[Any]],
        *,
        alpha: Alpha = 0.3,
        theta: float = 60.0,
        phi: float = 0.0,
        view: Optional[Vector] = None,
        normal: Optional[Vector] = None,
        precision: Optional[str] = None,
        world_space: bool = False,
        eta: Optional[float] = None,
        transport: str = "radiance",
    ) -> npt.NDArray[np.float32]:
        """The GGX BSDF value f(i, o) |cos theta_o| of each direction (n, 3): the BRDF with Fresnel 1, or with
        `eta` the rough dielectric's, both lobes with the exact Fresnel, in `transport`. With pdf(), what multiple
        importance sampling needs; for a sampled o, eval / pdf_o is its weight."""
    def furnace(
        self,
        method: Method,
        n: Union[int, float],  # a whole number: 1000000, 1e6 or 2**20
        *,
        alpha: Alpha = 0.3,
        theta: float = 60.0,
        phi: float = 0.0,
        view: Optional[Vector] = None,
        normal: Optional[Vector] = None,
        seed: int = 0,
        first: int = 0,
        precision: Optional[str] = None,
        sequence: str = "philox",
        eta: Optional[float] = None,
        transport: str = "radiance",
    ) -> Dict[str, float]:
        """The fused white-furnace estimator: {'mean': albedo estimate, 'variance': per sample, 'count'}; with
        `eta` also 'reflectance' and 'transmittance' (their sum is the mean)."""
    def histogram(
        self,
        method: Method,
        n: Union[int, float],  # a whole number: 1000000, 1e6 or 2**20
        *,
        alpha: Alpha = 0.3,
        theta: float = 60.0,
        phi: float = 0.0,
        normal: Optional[Vector] = None,
        seed: int = 0,
        first: int = 0,
        bins_z: int = 32,
        bins_phi: int = 64,
        of: str = "o",
        against: Optional[str] = None,
        precision: Optional[str] = None,
        sequence: str = "philox",
        eta: Optional[float] = None,
    ) -> Dict[str, Any]:
        """Counts of o (or m) in bins of equal solid angle over (cos theta, phi), binned on the device:
        {'counts': (bins_z, bins_phi) uint64, 'expected': float64 from `against`'s pdf (default: the method's),
        'chi_square', 'dof', 'p_value', 'non_finite', 'invalid'}. With `eta` (o only) both lobes over the whole
        sphere; 'invalid' counts the samples without density, tested as one more category. For a UserSampler
        (no `against`, an even `bins_z`): 'invalid' and 'discarded' count its discarded samples (o below the
        horizon with weight 0), tested as one more category; 'expected' is its own pdf (of m: 4 |i.m| pdf_o)
        integrated adaptively over each bin on the device where it keeps samples, with 'pdf_integral' over
        the sphere (1 for a density, or 1 minus the discarded fraction for a pdf of 0 where it discards),
        'pdf_integral_error' (also 'quadrature_error'), 'pdf_above_horizon', and 'claimed': the chi-square
        against the distribution it claims ({'distribution', 'chi_square', 'dof', 'p_value',
        'below_horizon'}) unless it claims its own."""
