#!/usr/bin/env bash
# pip_install.sh - the test_python_pip CTest test: `pip install .` as a Python
# user runs it, offline on Debian 12 (a venv with the system's packages,
# --no-build-isolation --no-index: scikit-build, NumPy and pyopencl come from
# Debian), then the Python suite against the installed package (no
# PYTHONPATH): the wheel must carry the module and libggxcl.  The build is
# scikit-build's own, beside the source (_skbuild/, ignored by git).
# Usage: pip_install.sh PYTHON SOURCE_DIR WORK_DIR  (the suite's GGX_* variables set by CTest)
set -euo pipefail
python=$1 source_dir=$2 work=$3
rm -rf "$work"
"$python" -m venv --system-site-packages "$work/venv"
"$work/venv/bin/pip" install --no-build-isolation --no-index --quiet "$source_dir"
cd "$work"  # not the source tree: `import ggxcl` must find the installed package
installed=$("$work/venv/bin/python" -c "import ggxcl; print(ggxcl.__file__)")
case $installed in
  "$work"/venv/*) echo "ggxcl imported from the installed package: $installed" ;;
  *) echo "ggxcl imported from $installed, not from the venv"; exit 1 ;;
esac
"$work/venv/bin/python" -m pytest -q -p no:cacheprovider --ignore="$source_dir/tests/python/vulkan" \
  "$source_dir/tests/python"  # the Vulkan suite runs once, as test_python_vulkan
rm -rf "$work"
