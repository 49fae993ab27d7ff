"""setup.py - `pip install .`: the ggxcl Python package, built by CMake through
scikit-build (classic: Debian's python3-skbuild, so it builds offline with
`--no-build-isolation --no-index`).  The wheel holds the package, its
compiled module and libggxcl beside it; the OpenCL loader, an OpenCL driver
(PoCL) and pyopencl stay system packages.  The version is CMakeLists.txt's."""
import re
import sys
from pathlib import Path

from skbuild import setup

version = re.search(r"project\(ggxcl VERSION ([0-9.]+)", Path(__file__).with_name("CMakeLists.txt").read_text()).group(1)

setup(
    name="ggxcl",
    version=version,
    description="GGX microfacet importance samplers on OpenCL devices",
    packages=["ggxcl"],
    package_dir={"ggxcl": "python/ggxcl"},
    package_data={"ggxcl": ["__init__.pyi", "py.typed"]},
    python_requires=">=3.9",
    install_requires=["numpy"],
    cmake_args=[
        "-DGGXCL_PYTHON_WHEEL=ON",
        "-DGGXCL_BUILD_TESTS=OFF",
        "-DGGXCL_BUILD_APPS=OFF",
        "-DGGXCL_BUILD_PYTHON=ON",
        "-DCMAKE_BUILD_TYPE=Release",
        f"-DPython_EXECUTABLE={sys.executable}",
    ],
)
