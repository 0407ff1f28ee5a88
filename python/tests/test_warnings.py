"""A doubt about a valid run is a Python warning with its kind and field, never a print."""

import warnings

import pytest

import racket_impact as ri

from conftest import cli, flags


def caught(function, **kwargs):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        result = function(**kwargs)
    return result, [x.message for x in w]


@pytest.mark.parametrize(
    "kwargs,cls,kind,field",
    [
        ({"ks": 40}, ri.UnusualValueWarning, "unusual", "ks"),
        ({"mu": 0.3}, ri.NotUsedWarning, "not_used", "mu"),
        ({"r": 0.12, "v1": 60, "ix": 3e-4}, ri.BeyondModelWarning, "beyond_model", "theta_end_deg"),
        ({"v1": 70, "k1": 5000}, ri.BeyondModelWarning, "beyond_model", "y0_m"),
        ({"angle_deg": 20, "string": "tonic-gut-16", "tangential": "bed"}, ri.MissingDataWarning, "missing_data", "string"),
    ],
)
def test_each_kind_of_diagnostic_is_its_warning(kwargs, cls, kind, field, capfd):
    result, messages = caught(ri.simulate, **kwargs)
    mine = [m for m in messages if isinstance(m, cls) and m.field == field]
    assert mine, [(type(m).__name__, m.field, str(m)) for m in messages]
    assert mine[0].kind == kind and isinstance(mine[0], ri.RacketImpactWarning) and isinstance(mine[0], UserWarning)
    # the same sentences as the command line's warnings, and as the result's diagnostics
    stderr = cli("simulate", *flags(kwargs)).stderr
    assert [f"warning: {m}" for m in messages] == [l for l in stderr.splitlines() if l.startswith("warning: ")]
    assert [d["sentence"] for d in result.diagnostics] == [str(m) for m in messages]
    out, err = capfd.readouterr()
    assert out == "" and err == "", "a warning is never a print"


def test_warnings_point_at_the_callers_line():
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        ri.simulate(ks=40)
    assert w[0].filename == __file__


def test_warnings_can_be_errors_or_silenced():
    with warnings.catch_warnings():
        warnings.simplefilter("error", ri.UnusualValueWarning)
        with pytest.raises(ri.UnusualValueWarning, match="ks = 40 N/m is outside the usual"):
            ri.simulate(ks=40)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.filterwarnings("ignore", category=ri.RacketImpactWarning)
        ri.simulate(ks=40)


def test_studies_warn_too():
    _, messages = caught(ri.sweep, ks=[40, 4e4])
    assert [(m.kind, m.field) for m in messages] == [("unusual", "ks")]
    _, messages = caught(ri.uncertainty, vary=["ks"], samples=8)
    assert ("unusual", "samples") in [(m.kind, m.field) for m in messages]
    _, messages = caught(ri.face_map, nx=5, nr=5, mass=5.0)
    assert ("unusual", "mass") in [(m.kind, m.field) for m in messages]
