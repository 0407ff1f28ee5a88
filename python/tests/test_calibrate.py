"""``calibrate`` from Python: the command line's fit, document for document, with its refusals
in Python's words (issue 47: one command layer under both front ends)."""

import json
from pathlib import Path

import pytest

import racket_impact as ri

from conftest import ROOT, cli, cli_error
from test_errors import python_words

SHIPPED = ROOT / "data" / "measured" / "measurements.csv"


def test_calibrate_is_the_command_lines_fit():
    expected = json.loads(cli("calibrate", "--fit", "kt", "--hold-out", "none", "--format", "json").stdout)
    assert ri.calibrate(fit=["kt"], hold_out="none") == expected


def test_a_measurements_file_and_the_options_reach_the_fit(tmp_path):
    csv = tmp_path / "mine.csv"
    csv.write_text(SHIPPED.read_text())
    args = ["calibrate", str(csv), "--fit", "kt", "--hold-out", "row", "--rows", "M001-M008", "--format", "json"]
    expected = json.loads(cli(*args).stdout)
    got = ri.calibrate(csv, fit="kt", hold_out="row", rows=["M001-M008"])
    assert got == expected
    # (of the rows asked for, the calibration ones are fitted, the others judged)
    assert [r["id"] for r in got["fitted"]] == ["M001", "M002", "M003", "M004"]


def test_refusals_are_the_command_lines_in_python_words():
    message = cli_error("calibrate", "--fit", "nope")
    with pytest.raises(ValueError) as e:
        ri.calibrate(fit=["nope"])
    assert str(e.value) == python_words(message)
    with pytest.raises(ValueError, match="weights"):
        ri.calibrate(fit=["kt"], weights="both")
    with pytest.raises(TypeError, match=r"calibrate\(\) missing required keyword argument: 'fit'"):
        ri.calibrate()
