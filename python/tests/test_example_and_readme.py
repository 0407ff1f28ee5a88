"""The example under examples/ reproduces its paper figure, and the README's Python example
prints what the README shows."""

import os
import re
import runpy
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import racket_impact as ri

from conftest import ROOT

EXAMPLE = ROOT / "python" / "examples" / "fig5a_position_soft.py"


def python(*args, cwd):
    """A new Python process that imports the package under test (wherever it is installed)."""
    path = [str(Path(ri.__file__).resolve().parents[1]), os.environ.get("PYTHONPATH", "")]
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in path if p)}
    return subprocess.run([sys.executable, *args], capture_output=True, text=True, cwd=cwd, env=env)


def test_the_example_reproduces_fig5a_exactly(tmp_cwd):
    pytest.importorskip("pandas")
    done = python(str(EXAMPLE), cwd=tmp_cwd)
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""
    assert "at the centre (x = 16.4 cm): e_A = 0.4" in done.stdout
    example = runpy.run_path(str(EXAMPLE))["figure5a"]()
    figure = ri.run_experiment("fig5a_position_soft")
    for c in figure.columns:
        assert (np.asarray(example[c]) == np.asarray(figure[c])).all(), c


def readme_example():
    """The README's Python block and the output block under it."""
    text = (ROOT / "README.md").read_text()
    m = re.search(r"```python\n(.*?)```\n+```text\n(.*?)```", text, re.S)
    assert m, "README.md has a ```python block followed by its ```text output"
    return m.group(1), m.group(2)


def test_the_readme_python_example_prints_the_readmes_numbers(tmp_cwd):
    code, shown = readme_example()
    done = python("-c", code, cwd=tmp_cwd)
    assert done.returncode == 0, done.stderr
    assert done.stdout == shown


def test_the_readme_shows_the_install_beside_the_set_up_commands():
    text = (ROOT / "README.md").read_text()
    setup = text.split("## Set up on a fresh machine", 1)[1].split("\n## ", 1)[0]
    assert "pip install ./python" in setup


def test_the_readme_install_line_brings_what_its_example_needs():
    """README's install line is `pip install ./python`, and its example iterates a DataFrame
    (`itertuples`): pandas is a dependency of the package, not an extra to know about."""
    text = (ROOT / "python" / "pyproject.toml").read_text()
    m = re.search(r"^dependencies = \[(.*?)\]", text, re.M | re.S)
    assert m, "pyproject.toml declares its dependencies on one list"
    names = {re.split(r"[<>=!~ ;\[]", d.strip().strip('"'))[0] for d in m.group(1).split(",") if d.strip()}
    assert {"numpy", "pandas"} <= names, names
    code, _ = readme_example()
    assert "itertuples" in code  # (what needs pandas: if the example changes, so may this test)
