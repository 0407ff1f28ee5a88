"""A sweep from Python is the command line's sweep: its columns, its numbers, its order."""

import csv
import io

import numpy as np
import pytest

import racket_impact as ri

from conftest import cli

pd = pytest.importorskip("pandas")


def read_csv(text):
    """A CSV as the command line wrote it: each column as numbers (Python's exact reading of
    each field, an empty field NaN) where every field is one, else as text."""
    rows = list(csv.reader(io.StringIO(text)))
    columns = {}
    for k, name in enumerate(rows[0]):
        fields = [r[k] for r in rows[1:]]
        try:
            columns[name] = np.array([float(f) if f else np.nan for f in fields])
        except ValueError:
            columns[name] = np.array(fields, dtype=object)
    return columns


def same(frame, csv_text):
    """The DataFrame holds exactly the CSV's columns and values (a flag column as bool, a text
    column as text), every number the same double."""
    shown = read_csv(csv_text)
    assert list(frame.columns) == list(shown)
    for c, b in shown.items():
        a = frame[c].to_numpy()
        assert len(a) == len(b), c
        if frame[c].dtype == bool:
            assert (a == (b == 1)).all(), c
        elif b.dtype == object:
            assert [str(v) for v in a] == list(b), c
        else:
            a = a.astype(float)
            assert ((a == b) | (np.isnan(a) & np.isnan(b))).all(), c


CASES = [
    ({"x": "0.02:0.6:7", "ks": [2e4, 4e4]}, ["--x", "0.02:0.6:7", "--ks", "2e4,4e4"]),
    ({"x": np.array([0.02, 0.1, 0.3]), "ks": np.array([2e4, 4e4])}, ["--x", "0.02,0.1,0.3", "--ks", "2e4,4e4"]),
    ({"ks": "1e4:1e5:4:log", "load": ["node", "hat"]}, ["--ks", "1e4:1e5:4:log", "--load", "node,hat"]),
    ({"angle_deg": [10, 30], "tangential": ["elastic", "loss"], "mu": 0.4}, ["--angle-deg", "10,30", "--tangential", "elastic,loss", "--mu", "0.4"]),
    ({"segments": [20, 39], "solver": ["fd", "modal"]}, ["--segments", "20,39", "--solver", "fd,modal"]),
    ({"x": 0.1, "racket": "tweener"}, ["--racket", "tweener", "--x", "0.1"]),
]


@pytest.mark.parametrize("kwargs,args", CASES, ids=[str(i) for i in range(len(CASES))])
def test_dataframe_equals_the_command_lines_csv(kwargs, args):
    racket = [a for i, a in enumerate(args) if i > 0 and args[i - 1] == "--racket"]
    pairs = [a for i, a in enumerate(args) if a != "--racket" and a not in racket]
    shown = cli("sweep", *(["--racket", *racket] if racket else []), *pairs).stdout
    frame = ri.sweep(**kwargs)
    same(frame, shown)


def test_dtypes_follow_the_declaration():
    df = ri.sweep(segments=[20, 39], load=["node", "hat"], x=[0.1, 0.2])
    assert df["segments"].dtype == np.int64
    assert df["x_m"].dtype == np.float64 and df["e_a"].dtype == np.float64
    assert df["recontact"].dtype == bool
    assert list(df["load"]) == ["node", "node", "hat", "hat"] * 2
    assert set(df["solver"]) == {"modal"}
    # the first keyword varies slowest
    assert list(df["segments"]) == [20] * 4 + [39] * 4


def test_dataframe_round_trip():
    df = ri.sweep(x=np.linspace(0.05, 0.5, 5), angle_deg=[0, 20], spin_rpm=1000)
    # (pandas before 3 reads floats exactly only when asked to)
    exact = {} if int(pd.__version__.split(".")[0]) >= 3 else {"float_precision": "round_trip"}
    back = pd.read_csv(io.StringIO(df.to_csv(index=False)), **exact)
    pd.testing.assert_frame_equal(back, df, check_dtype=False)
    # and one row is the single impact
    one = ri.simulate(x=df["x_m"][3], angle_deg=df["angle_deg"][3], spin_rpm=1000, solver="modal")
    assert one.e_a == df["e_a"][3] and one.spin_out_rpm == df["spin_out_rpm"][3]


def test_without_pandas_a_dict_of_numpy_arrays(monkeypatch):
    frame = ri.sweep(x=[0.1, 0.2], ks=3e4)
    monkeypatch.setattr(ri._tables, "_pandas", lambda: None)  # (where the tables are made)
    d = ri.sweep(x=[0.1, 0.2], ks=3e4)
    assert isinstance(d, dict) and list(d) == list(frame.columns)
    assert all((d[c] == frame[c].to_numpy()).all() for c in d)
    assert isinstance(d["e_a"], np.ndarray) and d["e_a"].dtype == np.float64 and len(d["e_a"]) == 2
    assert d["solver"].tolist() == ["modal", "modal"]
    d["e_a"][0] = 1.0  # writable
    assert isinstance(ri.presets(), dict) and isinstance(ri.strings(), dict)


def test_many_values_no_python_per_impact():
    # 2000 impacts: the values go over as bytes, the results come back as whole columns
    x = np.linspace(0.02, 0.6, 1000)
    df = ri.sweep(x=x, ks=[2e4, 4e4])
    assert len(df) == 2000
    assert (df["x_m"].to_numpy()[::2] == x).all(), "every value exactly as given"
