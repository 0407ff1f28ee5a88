#!/bin/sh
# The Python that `make python-test` (and `make test`) runs the Python tests with: prints its
# path on standard output.
#
#   sh python/tools.sh PYTHON VENV
#
# PYTHON is the Python asked for (`python3` unless `make PYTHON=...`). If it has the tools the
# tests need (maturin, pytest, numpy, pandas), it is the one. Otherwise the tools are installed
# from the package registry into the virtual environment VENV (`target/venv`, made once and
# reused; its log beside it, VENV.log), and VENV's Python is the one.
#
# Without Python 3.9+, nothing is printed and one line on standard error says that the Python
# tests need it (exit 0: the Rust tests ran; under CI, where every test must run, exit 1). When
# the environment cannot be made (no `venv` module, no registry), one line on standard error
# says so and where the log is (exit 1).
set -u
python=${1:-python3}
venv=${2:-target/venv}
# the tools, and the versions the package and its tests are built and run with
names="maturin, pytest, numpy, pandas"
specs="maturin>=1.5,<2 pytest>=7 numpy>=1.20 pandas>=1.3"

has_tools() {
    "$1" -c "import maturin, pytest, numpy, pandas" >/dev/null 2>&1
}

if ! command -v "$python" >/dev/null 2>&1 \
    || ! "$python" -c "import sys; sys.exit(sys.version_info < (3, 9))" >/dev/null 2>&1; then
    if [ -n "${CI:-}" ]; then
        echo "error: the Python tests need Python 3.9+ ($python: not found or older)" >&2
        exit 1
    fi
    echo "Python tests not run: they need Python 3.9+ ($python: not found or older)" >&2
    exit 0
fi
if has_tools "$python"; then
    command -v "$python"
    exit 0
fi
venv_python="$venv/bin/python"
if ! has_tools "$venv_python"; then
    log="$venv.log"
    mkdir -p "$(dirname "$venv")"
    echo "Python tests: installing $names from the package registry into $venv (once; log: $log)" >&2
    if ! { [ -x "$venv_python" ] || "$python" -m venv "$venv"; } >"$log" 2>&1; then
        echo "error: cannot make a virtual environment with $python -m venv (on Debian or Ubuntu: apt install python3-venv); log: $log" >&2
        exit 1
    fi
    # (a short timeout and few retries: without a registry this fails in seconds, not minutes)
    # shellcheck disable=SC2086
    if ! "$venv_python" -m pip install --disable-pip-version-check --retries 1 --timeout 20 $specs >>"$log" 2>&1 \
        || ! has_tools "$venv_python"; then
        echo "error: cannot install $names into $venv from the package registry (no network, or no registry?); log: $log" >&2
        exit 1
    fi
fi
echo "$venv_python"
