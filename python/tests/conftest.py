"""What the tests share: the command line they compare the package with, and a case's flags.

The command line is the release binary of this checkout (``make build``), or the one
``RACKET_IMPACT_BIN`` names."""

import os
import subprocess
from pathlib import Path

import pytest

import racket_impact as ri

ROOT = Path(__file__).resolve().parents[2]
BIN = ROOT / os.environ.get("RACKET_IMPACT_BIN", "target/release/racket-impact")


def cli(*args, cwd=None, check=True):
    """Run the command line; with ``check``, exit 0 is required."""
    if not BIN.exists():
        pytest.fail(f"the command line {BIN} is missing: run `make build` (or set RACKET_IMPACT_BIN)")
    done = subprocess.run([str(BIN), *map(str, args)], capture_output=True, text=True, cwd=cwd)
    if check and done.returncode != 0:
        raise AssertionError(f"racket-impact {' '.join(map(str, args))}: exit {done.returncode}: {done.stderr}")
    return done


def flags(case):
    """A case's keywords as the command line's flags, each value as the package sends it."""
    out = []
    for name, value in case.items():
        if name in ("racket", "config"):
            out += [f"--{name}", str(value)]
            continue
        p = ri._param(name, "test")
        out += [f"--{p['key']}", ri._text(p, value)]
    return out


def cli_error(*args):
    """The command line's one-line error (after ``error: ``) and its exit code."""
    done = cli(*args, check=False)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2, (done.returncode, done.stderr)
    assert lines and lines[-1].startswith("error: "), done.stderr
    return lines[-1][len("error: ") :]


@pytest.fixture
def tmp_cwd(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    return tmp_path
