"""The keywords, the help and the type stub come from the parameters' declaration."""

import inspect
import pydoc
from pathlib import Path

import pytest

import racket_impact as ri
from racket_impact import _stub

from conftest import ROOT, cli

#: simulate's flags that are not impact parameters
OWN_FLAGS = {"config", "racket", "format", "series", "series-dt", "series-end", "quiet", "help"}


def test_the_stub_is_the_one_the_declaration_gives():
    committed = (ROOT / "python" / "racket_impact" / "__init__.pyi").read_text()
    assert committed == _stub.stub(), "python/racket_impact/__init__.pyi is stale: run `make python-stub`"
    installed = Path(ri.__file__).with_name("__init__.pyi")
    assert installed.read_text() == committed, "the package installs the stub"
    compile(committed, "__init__.pyi", "exec")


def entries(doc):
    """A numpydoc Parameters list: name -> (its header line, its lines below)."""
    out, name = {}, None
    for line in inspect.cleandoc(doc).split("Parameters\n----------\n", 1)[1].splitlines():
        if line and not line.startswith(" "):
            name = line.split(" : ")[0]
            out[name] = (line, [])
        elif name:
            out[name][1].append(line.strip())
    return out


def test_every_parameter_is_a_keyword_with_its_unit_range_and_default_in_the_help():
    text = pydoc.render_doc(ri.simulate, renderer=pydoc.plaintext)
    assert "Default: 40000 N/m (the paper's; with racket=, the racket file's)." in text
    assert "ks : float, N/m [Strings]" in text and "Used only for an oblique or spinning ball." in text
    signature = inspect.signature(ri.simulate)
    documented = entries(ri.simulate.__doc__)
    for p in ri.parameters():
        assert signature.parameters[p["name"]].kind is inspect.Parameter.KEYWORD_ONLY
        header, lines = documented[p["name"]]
        body = " ".join(lines)
        kind = dict(number="float", count="int", choice="str")[p["kind"]]
        assert header == f"{p['name']} : {kind}" + (f", {p['unit']}" if p["unit"] else "") + f" [{p['heading']}]"
        assert p["help"] in body, p["name"]
        if p["kind"] != "choice":
            # (the library's words for the range: "1 <= ks <= 1e12 N/m", "|r| <= half-width")
            assert f"Allowed: {p['range_text'].replace(p['key'], p['name'])}." in body, p["name"]
        assert p["default"] is not None and f"Default: {p['default']}" in body, p["name"]
        assert (f"Used only {p['used_when']}." in body) == (p["used_when"] != "always"), p["name"]
        for c in p["choices"]:
            assert f"``{c['name']}``" in body
    # the keywords are the command line's parameter flags (a flag's line is indented by 6; the
    # help is wrapped, and a description's line, indented by 10, may open with a flag's name)
    shown = {
        line.split()[0][2:]
        for line in cli("simulate", "--help").stdout.splitlines()
        if line.startswith("      --") and not line.startswith("       ")
    }
    assert {p["key"] for p in ri.parameters()} == shown - OWN_FLAGS


def test_a_new_declaration_row_reaches_every_python_name(monkeypatch):
    # a made-up parameter as the library would hand its row over: nothing else is written for
    # it, yet it is a keyword (accepted, spelled three ways), in the help and in the stub
    row = dict(
        next(p for p in ri._PARAMS if p["name"] == "ks"),
        name="made_up",
        key="made-up",
        column="made_up_n_per_m",
        help="A made-up stiffness, N/m (1 ..= 1e12)",
    )
    # (the tables live in racket_impact._args, where every name reads them)
    monkeypatch.setattr(ri._args, "_PARAMS", ri._PARAMS + [row])
    for spelling in ("made_up", "made-up", "made_up_n_per_m"):
        assert ri._param(spelling, "simulate")["key"] == "made-up"
    assert ri._pairs({"made_up": 3e4}, "simulate") == [("made-up", "30000.0")]
    assert "made_up : float, N/m [Strings]" in ri._docstring(ri.simulate)
    assert "    made_up: float | None = None," in _stub.stub()


def test_a_new_option_row_reaches_the_keyword_its_type_check_the_help_and_the_stub(monkeypatch):
    # a made-up option of sweep as the library would hand its row over (`command::sweep::OPTIONS`):
    # nothing else is written for it, yet it is a keyword with its default, checked for its type,
    # passed to the library as its flag's text, in the help and in the stub
    row = dict(name="max-twist-deg", keyword="max_twist_deg", kind="number", lo=None, hi=None, choices=[],
               many=False, default="5", required=False, help="A made-up limit on the twist, degrees")
    monkeypatch.setitem(ri._COMMANDS, "sweep", ri._COMMANDS["sweep"] + [row])
    options, axes = ri._split("sweep", {"max_twist_deg": 2.5, "x": [0.1]})
    assert axes == {"x": [0.1]}
    assert ri._options("sweep", "sweep", options) == [("max_twist_deg", ["2.5"])]
    with pytest.raises(TypeError, match=r"sweep\(\) argument max_twist_deg takes a number, not '2.5'"):
        ri._options("sweep", "sweep", {"max_twist_deg": "2.5"})
    assert ri._signature(ri.sweep, []).parameters["max_twist_deg"].default == 5.0
    assert "max_twist_deg : float\n    A made-up limit on the twist, degrees.\n    Default: 5.0." in ri._docstring(ri.sweep)
    assert "    max_twist_deg: float = 5.0," in _stub.stub()


def test_the_help_of_simulate_lists_every_returned_field():
    # (issue 48: help(racket_impact.simulate) did not list the returned fields)
    text = pydoc.render_doc(ri.simulate, renderer=pydoc.plaintext)
    returns = text.split("Returns\n", 1)[1]
    for f in ri._FIELDS:
        unit = f", {f['unit']}" if f["unit"] else ""
        assert f"{f['key']} : {dict(number='float', flag='bool')[f['kind']]}{unit}" in returns, f["key"]
    assert "series : DataFrame or None" in returns
