"""Maps, uncertainty studies, rackets, strings and the paper's experiments from Python: the
command line's numbers."""

import csv
import io
import json

import numpy as np
import pytest

import racket_impact as ri

from conftest import ROOT, cli, flags

pd = pytest.importorskip("pandas")


def test_face_map_is_the_maps(tmp_cwd):
    m = ri.face_map(racket="tweener", quantity="e_a", nx=9, nr=5, angle_deg=0, ks=3e4)
    cli("map", "--racket", "tweener", "--quantity", "e_a", "--nx", "9", "--nr", "5", "--ks", "3e4", "--out", "m.csv", "--quiet")
    assert m.metadata == json.loads((tmp_cwd / "m.json").read_text())
    shown = pd.read_csv(tmp_cwd / "m.csv")
    assert list(m.table.columns) == list(shown.columns) and len(m.table) == len(shown)
    # (the CSV is written to 6 significant digits)
    for c in shown.columns:
        if shown[c].dtype.kind == "f":
            assert np.allclose(m.table[c], shown[c], rtol=5e-6, atol=0), c
    # the grid: values[i, j] at (x[i], r[j]) is the table's row there, NaN off the face
    assert m.values.shape == (9, 5) and len(m.x) == 9 and len(m.r) == 5
    for _, row in m.table.iterrows():
        i, j = list(m.x).index(row["x_m"]), list(m.r).index(row["r_m"])
        assert m.values[i, j] == row["e_a"]
    assert np.isnan(m.values).sum() == 45 - len(m.table)


def test_difference_map():
    m = ri.face_map(quantity="power", nx=7, nr=5, compare_tension_lb=[50, 60])
    assert "power_pct_b_minus_a" in m.table.columns
    assert np.nanmax(np.abs(m.values)) > 0


def test_uncertainty_is_the_studys_json():
    kwargs = dict(vary=["ks=uniform:2e4:6e4", "mb"], samples=32, seed=3, x=0.06)
    with pytest.warns(ri.UnusualValueWarning, match="samples = 32"):
        u = ri.uncertainty(**kwargs)
    shown = json.loads(cli("uncertainty", "--vary", "ks=uniform:2e4:6e4", "--vary", "mb", "--samples", "32", "--seed", "3", "--x", "0.06", "--format", "json", "--quiet").stdout)
    assert u.to_dict() == shown
    assert list(u.first_order.columns) == ["ks", "mb"] and "e_a" in u.summary.index
    assert u.summary.loc["e_a", "q05"] == shown["outputs"]["e_a"]["q05"]
    assert u.total_order.loc["tau_s", "ks"] == shown["outputs"]["tau_s"]["total_order"]["ks"]
    row = u.intervals[(u.intervals.output == "e_a") & (u.intervals.input == "mb") & (u.intervals.order == "first")]
    assert list(row[["lo", "hi"]].iloc[0]) == shown["outputs"]["e_a"]["first_order_ci"]["mb"]
    # python names for the inputs, and a dict of them
    with pytest.warns(ri.UnusualValueWarning):
        same = ri.uncertainty(vary={"ks": "uniform:2e4:6e4", "mb": None}, samples=32, seed=3, x=0.06)
    assert same.to_dict() == shown


def test_presets_racket_and_strings():
    presets = ri.presets()
    shown = pd.read_csv(io.StringIO(cli("racket", "--list", "--format", "csv").stdout))
    assert list(presets["name"]) == list(shown["name"])
    assert np.allclose(presets["f1_hz"], shown["f1_hz"], rtol=5e-6)
    r = ri.Racket.preset("tweener")
    fit = json.loads(cli("racket", "tweener", "--format", "json").stdout)
    assert r.model["racket"] == fit["racket"] and r.model["ball"] == fit["ball"] and r.diagnostics == fit["diagnostics"]
    assert list(r.fit["quantity"]) == [row["quantity"] for row in fit["fit"]]
    assert "tweener" in repr(r)
    table = ri.strings()
    with open(ROOT / "data" / "strings" / "strings.csv") as f:
        rows = list(csv.DictReader(f))
    assert list(table.columns) == list(rows[0])
    assert list(table["id"]) == [r["id"] for r in rows]
    assert list(table["string_ball_cof"]) == [float(r["string_ball_cof"]) for r in rows]
    # a string named by its id runs
    assert ri.simulate(angle_deg=20, string=rows[1]["id"]).params["oblique"]["mu"] == float(rows[1]["string_ball_cof"])


def test_every_experiment_is_listed_and_one_runs_as_its_figure():
    ids = [e.id for e in ri.experiments()]
    listed = cli("figures", "--list").stdout.split()
    assert all(i in listed for i in ids) and "fig5a_position_soft" in ids
    table = ri.run_experiment("fig5a_position_soft")
    with open(ROOT / "figures" / "fig5a_position_soft.csv") as f:
        shown = list(csv.DictReader(f))
    assert list(table.columns) == list(shown[0]) and len(table) == len(shown)
    # (the figure's CSV holds 6 significant digits)
    for c in table.columns:
        assert np.allclose(table[c], [float(r[c]) for r in shown], rtol=5e-6, atol=1e-300), c
    other = ri.run_experiment("fig5a_position_soft", racket="tweener")
    assert not other["e_a"].equals(table["e_a"])
