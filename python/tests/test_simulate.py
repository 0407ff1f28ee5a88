"""One impact from Python is the command line's, bit for bit."""

import json
import math

import pytest

import racket_impact as ri
from racket_impact import _native

from conftest import cli, flags

CASES = [
    {},
    {"x": 0.10, "r": 0.05, "ks": 3e4},
    {"x": 0.1, "r": 0.05, "load": "node", "segments": 39},
    {"solver": "modal", "x": 0.2, "r": -0.03},
    {"angle_deg": 30, "spin_rpm": 2000, "azimuth_deg": 90},
    {"angle_deg": 40, "tangential": "physical", "string": "alu-power-16"},
    {"angle_deg": 0.5},
    {"grip": "hand", "x": 0.12},
    {"strings": "stiffening"},
    {"frame": "rigid", "x": 0.05},
    {"racket": "tweener"},
    {"racket": "players", "angle_deg": 20, "spin_rpm": -1500},
    {"mu": 0.3},
    {"ks": 40},
    {"ks": 4e4, "v1": 25},
]


def walk(a, b, path="$"):
    """Equal documents with every number the same double (its hex form)."""
    assert type(a) is type(b), (path, a, b)
    if isinstance(a, dict):
        assert list(a) == list(b), path
        for k in a:
            walk(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            walk(x, y, f"{path}[{i}]")
    elif isinstance(a, float):
        assert a.hex() == b.hex(), (path, a, b)
    else:
        assert a == b, (path, a, b)


@pytest.mark.parametrize("case", CASES, ids=lambda c: ",".join(f"{k}={v}" for k, v in c.items()) or "defaults")
def test_result_equals_the_command_lines_json_bit_for_bit(case, recwarn):
    shown = cli("simulate", "--format", "json", *flags(case)).stdout
    impact = ri.simulate(**case)
    walk(impact.to_dict(), json.loads(shown))
    # the very text the command prints
    params = {k: v for k, v in case.items() if k not in ("racket",)}
    pairs = [(ri._param(n, "t")["key"], ri._text(ri._param(n, "t"), v)) for n, v in params.items()]
    doc, series = _native.call("simulate", case.get("racket"), None, pairs, [], None)
    assert doc == shown and series is None


def test_fields_are_attributes_with_units_in_their_names():
    r = ri.simulate(x=0.1, r=0.05, load="node")
    d = r.to_dict()
    for f in ri._FIELDS:
        if f["oblique"]:
            assert not hasattr(r, f["key"]), "oblique fields are left out at normal incidence, as in the JSON"
            continue
        assert getattr(r, f["key"]) == d[f["key"]]
        assert f["key"] in dir(r)
    assert r.params["impact"]["x"] == 0.1 and r.params["numerics"]["load"] == "node"
    assert isinstance(r.f1_hz, float) and r.diagnostics == []
    assert "e_a" in repr(r)
    # paper Fig 4: tau 4.78 ms, e_A 0.166
    assert abs(r.tau_s - 4.78e-3) < 0.05e-3 and abs(r.e_a - 0.166) < 0.003
    with pytest.raises(AttributeError):
        r.nope
    with pytest.raises(AttributeError):
        r.e_a = 1.0
    d["e_a"] = 2.0
    assert r.e_a != 2.0, "to_dict() is a copy"


def test_undefined_field_is_none_as_null_in_the_json():
    r = ri.simulate(angle_deg=0.5)
    assert r.e_t is None and r.to_dict()["e_t"] is None
    assert math.isfinite(r.spin_out_rpm)


def test_a_config_file_and_a_racket_file(tmp_path):
    config = tmp_path / "c.toml"
    config.write_text('ks = 3.5e4\nload = "node"\n')
    racket = tmp_path / "mine.toml"
    racket.write_text(
        'name = "mine"\nlength_in = 27\nmass_g = 320\nbalance_cm = 32.5\nswingweight_kg_cm2 = 325\n'
        "twistweight_kg_cm2 = 14\nfrequency_hz = 140\ntension_lb = 55\n"
    )
    for kwargs in ({"config": config}, {"config": str(config), "x": 0.12}, {"racket": racket}):
        shown = json.loads(cli("simulate", "--format", "json", *flags(kwargs)).stdout)
        walk(ri.simulate(**kwargs).to_dict(), shown)
    fitted = ri.Racket.from_toml(racket)
    assert fitted.name == "mine" and fitted.source == str(racket)
    walk(ri.simulate(racket=fitted).to_dict(), ri.simulate(racket=str(racket)).to_dict())
    # keywords win over the config file, as flags do
    with pytest.warns(ri.NotUsedWarning, match=r"not used here: ks \(set on the command line\)"):
        assert ri.simulate(config=config, ks=2e4).params["strings"]["ks"] == 2e4


def test_every_spelling_of_a_parameter_is_the_same_parameter():
    a = ri.simulate(angle_deg=20, ks=3e4)
    b = ri.simulate(**{"angle-deg": 20, "ks_n_per_m": 3e4})
    assert a == b
    # numpy scalars are numbers
    np = pytest.importorskip("numpy")
    assert ri.simulate(angle_deg=np.float64(20), ks=np.int64(30000)) == a
