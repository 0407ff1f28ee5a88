"""racket-impact from Python: a tennis ball on a flexible racket, R. Cross (2000) replicated.

The model runs in Rust (the same library as the ``racket-impact`` command line); this package
is its Python surface::

    import racket_impact as ri
    r = ri.simulate(x=0.10, r=0.05, ks=3e4)       # one impact, as `simulate --format json`
    r.e_a, r.tau_s, r.to_dict()
    df = ri.sweep(x=np.linspace(0.02, 0.6, 50), ks=[2e4, 4e4])   # `sweep`'s CSV columns

Every impact parameter is a keyword named as its command-line flag with underscores
(``--angle-deg`` is ``angle_deg``; its CSV column, ``angle_deg``, and its key, ``"angle-deg"``
through ``**{...}``, are accepted too): see ``help(racket_impact.simulate)`` for each one's unit,
range and default. The names, units, ranges, defaults and checks are read from the library's
one declaration of the parameters, so a parameter added there is a keyword here.

A bad value raises ``ValueError`` with the command line's one-line message; an unknown keyword
``TypeError``. A doubt about a valid run (a value outside its usual range, a result beyond the
model's range, a property given but not exercised) is a warning: a :class:`RacketImpactWarning`
subclass with the diagnostic's ``kind`` and ``field``, never a print.
"""

from __future__ import annotations

import copy
import json
import numbers
import os
import warnings
from typing import Any, NamedTuple

import numpy as np

from . import _args, _docs, _native, _progress
from ._tables import _array, _frame, _pandas, _table
from ._warnings import (
    BeyondModelWarning,
    LongRunWarning,
    MissingDataWarning,
    NotUsedWarning,
    RacketImpactWarning,
    UnusualValueWarning,
    _caller_level,
    _warn,
)
from ._args import (
    _COMMANDS,
    _DECLARED,
    _FIELDS,
    _NOT_TAKEN,
    _PARAMS,
    _by_name,
    _command_pairs,
    _option_text,
    _options,
    _pairs,
    _param,
    _path,
    _python_words,
    _split,
    _takes,
    _text,
)

__version__ = _native.__version__

__all__ = [
    "simulate",
    "sweep",
    "face_map",
    "card",
    "uncertainty",
    "speed",
    "modes",
    "calibrate",
    "presets",
    "strings",
    "experiments",
    "run_experiment",
    "parameters",
    "Impact",
    "FaceMap",
    "Card",
    "Uncertainty",
    "Racket",
    "Modes",
    "Experiment",
    "RacketImpactWarning",
    "UnusualValueWarning",
    "BeyondModelWarning",
    "MissingDataWarning",
    "NotUsedWarning",
    "LongRunWarning",
]

def parameters() -> list[dict[str, Any]]:
    """Every impact parameter as the library declares it: ``name`` (the keyword), ``key`` (the
    flag), ``help``, ``unit``, ``column`` (in a sweep's table), ``kind`` (number, count or
    choice, with its ``choices``), ``range`` (allowed), ``usual`` (beyond it: a warning),
    ``default`` (as the flag spells it) and the declared ``uncertainty``."""
    return copy.deepcopy(_PARAMS)


# --- arguments ------------------------------------------------------------------------------


def _call(command: str, racket, config, pairs, options, progress) -> Any:
    """Run the library's ``command`` with the parameters ``pairs`` (for a sweep its axes) and
    its ``options``, its progress drawn and its notes warned of as it runs
    (:mod:`racket_impact._progress`); Ctrl-C stops it within a second with KeyboardInterrupt."""
    def note(text: str) -> None:
        warnings.warn(LongRunWarning(text, "long_run", ""), stacklevel=_caller_level())

    reporter = _progress.Reporter(progress, note)
    try:
        return _native.call(command, _source(racket), _path(config), pairs, options, reporter)
    finally:
        reporter.close()


def _source(racket: Any) -> str | None:
    """A racket argument as the command line's ``--racket``: a preset name or a file path."""
    if racket is None:
        return None
    if isinstance(racket, Racket):
        return racket.source
    if isinstance(racket, (str, os.PathLike)):
        return os.fspath(racket)
    raise TypeError(f"racket is a preset name, a racket file's path or a Racket, not {racket!r}")


# --- one impact -----------------------------------------------------------------------------


class Impact:
    """One impact's result: every field of ``simulate --format json`` as an attribute (units in
    the names: ``tau_s``, ``theta_end_deg``), with ``params`` (the parameters it ran with),
    ``f1_hz`` (the free racket's first bending frequency) and ``diagnostics``.

    ``to_dict()`` gives the whole document, equal to the command line's JSON. A field of an
    oblique or spinning ball that is undefined (``e_t`` at too little incoming slip) is ``None``,
    as ``null`` in the JSON."""

    __slots__ = ("_doc", "_series")

    def __init__(self, document: dict[str, Any], series=None):
        object.__setattr__(self, "_doc", document)
        object.__setattr__(self, "_series", series)

    @property
    def series(self):
        """The impact's time series (``simulate(series=True)``; ``simulate --series``'s CSV
        columns), a DataFrame where pandas is installed, else a dict of numpy arrays; ``None``
        unless asked for."""
        return self._series

    def __getattr__(self, name: str) -> Any:
        try:
            return self._doc[name]
        except KeyError:
            raise AttributeError(f"an Impact has no field {name!r}") from None

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("an Impact is a result: read-only")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._doc))

    def __getitem__(self, name: str) -> Any:
        return self._doc[name]

    def keys(self):
        return self._doc.keys()

    def to_dict(self) -> dict[str, Any]:
        """The result as the JSON document of ``simulate --format json`` (a copy)."""
        return copy.deepcopy(self._doc)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Impact) and other._doc == self._doc

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        shown = ["e_a", "tau_s", "theta_end_deg", "f_vib", "spin_out_rpm"]
        parts = [f"{k}={self._doc[k]:.6g}" for k in shown if isinstance(self._doc.get(k), float)]
        return f"Impact({', '.join(parts)}, ...)"


def simulate(*, racket=None, config=None, progress=None, **kwargs) -> Impact:
    # (the docstring is made from the parameters' and the options' declarations below)
    options, params = _split("simulate", kwargs)
    pairs = _pairs(params, "simulate")
    doc, series = _call("simulate", racket, config, pairs, _options("simulate", "simulate", options), progress)
    doc = json.loads(doc)
    _warn(doc["diagnostics"])
    return Impact(doc, None if series is None else _table(series[1]))


# --- many impacts ---------------------------------------------------------------------------


def _axis(p: dict[str, Any], values: Any) -> Any:
    """A swept parameter's values as the native sweep takes them: a spec string as the command
    line's (``"0.02:0.6:50"``, ``"2e4,4e4"``), little-endian f64 bytes for real numbers (an
    array or a list), else a list of texts."""
    if isinstance(values, str):
        return values
    if isinstance(values, (numbers.Number, bool)) or np.ndim(values) == 0:
        return [_text(p, values.item() if isinstance(values, np.generic) else values)]
    if np.ndim(values) != 1:
        raise TypeError(f"{p['name']} takes one value, a list of values or a spec string, not a {np.ndim(values)}-d array")
    items = list(np.asarray(values, dtype=object)) if isinstance(values, np.ndarray) else list(values)
    if p["kind"] == "number" and items and all(
        isinstance(v, numbers.Real) and not isinstance(v, bool) for v in items
    ):
        return np.asarray(items, dtype="<f8").tobytes()
    return [_text(p, v.item() if isinstance(v, np.generic) else v) for v in items]


def sweep(*, racket=None, config=None, progress=None, **kwargs):
    # (the docstring is made from the parameters' and the options' declarations below)
    options, axes = _split("sweep", kwargs)
    if not axes:
        raise TypeError("sweep() needs at least one parameter to vary, e.g. sweep(x=np.linspace(0.02, 0.6, 50))")
    pairs = [(_param(name, "sweep")["key"], _axis(_param(name, "sweep"), v)) for name, v in axes.items()]
    columns, diagnostics = _call("sweep", racket, config, pairs, _options("sweep", "sweep", options), progress)
    _warn(json.loads(diagnostics))
    return _table(columns)


class FaceMap:
    """A quantity over the string face (``map``): ``x`` (m from the tip) and ``r`` (m from the
    long axis) are the grid, ``values[i, j]`` the quantity at ``(x[i], r[j])`` (NaN off the
    face; for a comparison, B - A), ``table`` every quantity at every point (``map``'s CSV),
    ``metadata`` ``map``'s JSON (parameters, mode-1 node, maximum) and ``diagnostics``."""

    def __init__(self, quantity: str, metadata: dict[str, Any], table, x, r, values, diagnostics):
        self.quantity = quantity
        self.metadata = metadata
        self.table = table
        self.x = x
        self.r = r
        self.values = values
        self.diagnostics = diagnostics

    def __repr__(self) -> str:
        return f"FaceMap({self.quantity!r}, {len(self.x)} x {len(self.r)} grid, {np.isfinite(self.values).sum()} points)"


def face_map(*, racket=None, config=None, progress=None, **kwargs) -> FaceMap:
    # (the docstring is made from the parameters' and the options' declarations below)
    options, params = _split("map", kwargs)
    pairs = _command_pairs("map", "face_map", params)
    texts = _options("map", "face_map", options)
    metadata, (_, columns), (xs, rs, z), diagnostics = _call("map", racket, config, pairs, texts, progress)
    diagnostics = json.loads(diagnostics)
    _warn(diagnostics)
    x, r = np.frombuffer(xs, "<f8"), np.frombuffer(rs, "<f8")
    values = np.frombuffer(z, "<f8").reshape(len(x), len(r))
    quantity = dict(texts).get("quantity", ["power"])[0]
    return FaceMap(quantity, json.loads(metadata), _table(columns), x, r, values, diagnostics)


class Card:
    """What string tension does to one racket (``card``).

    ``table``: one row per racket and tension with every panel's numbers (the card's CSV
    columns, at full precision); ``header``: the CSV's header block (the racket, tensions and
    numerics, each panel's assumptions, what the spin law was validated on and what not, and on
    the paper's racket the paper beside the model); ``paper``: the paper's conclusions beside the
    model's as a table (the paper's racket only, else None); ``png``: the picture's bytes (a
    notebook shows the card itself); ``diagnostics``."""

    def __init__(self, table, header: list[str], paper, png: bytes, diagnostics: list[dict[str, str]]):
        self.table = table
        self.header = header
        self.paper = paper
        self.png = png
        self.diagnostics = diagnostics

    def _repr_png_(self) -> bytes:
        return self.png

    def __repr__(self) -> str:
        return f"Card({self.header[0] if self.header else ''!r}, {len(self.table)} rows)"


def card(*, racket=None, config=None, progress=None, out=None, **kwargs) -> Card:
    # (the docstring is made from the parameters' and the options' declarations below)
    options, params = _split("card", kwargs)
    tensions = options.get("tensions_lb")
    if tensions is not None and not isinstance(tensions, str):
        if np.ndim(tensions) != 1 or not all(isinstance(t, numbers.Real) and not isinstance(t, bool) for t in tensions):
            raise TypeError(f"card() argument tensions_lb takes a text (lo:hi:count) or a sequence of numbers, not {tensions!r}")
        options["tensions_lb"] = ",".join(repr(float(t)) for t in tensions)
    if out is not None:
        out = os.fspath(out)
        _native.card_files(out, None, None)
    pairs = _command_pairs("card", "card", params)
    (_, columns), header, paper, csv, png, diagnostics = _call(
        "card", racket, config, pairs, _options("card", "card", options), progress
    )
    if out is not None:
        _native.card_files(out, csv, bytes(png))
    diagnostics = json.loads(diagnostics)
    _warn(diagnostics)
    return Card(_table(columns), list(header), None if paper is None else _table(paper[1]), bytes(png), diagnostics)


class Uncertainty:
    """An impact's result fields under uncertain inputs (``uncertainty --vary``).

    ``summary``: one row per result field (unit, mean, sd, q05, q50, q95); ``first_order`` and
    ``total_order``: the Sobol' indices, one row per result field and a column per input;
    ``intervals``: every index with its bootstrap interval (output, input, order, value, lo, hi).
    DataFrames where pandas is installed, else dicts of numpy arrays. ``to_dict()`` is the JSON
    document of ``uncertainty --format json``."""

    def __init__(self, document: dict[str, Any]):
        self._doc = document
        outputs = document["outputs"]
        inputs = [i["key"] for i in document["inputs"]]
        names = list(outputs)
        f = lambda v: np.nan if v is None else float(v)  # noqa: E731  (an index of a constant output is null)
        summary = [("output", "str", names), ("unit", "str", [outputs[n]["unit"] for n in names])]
        for stat in ("mean", "sd", "q05", "q50", "q95"):
            summary.append((stat, "f", [f(outputs[n][stat]) for n in names]))
        self.summary = _frame(summary, "output")
        for order in ("first_order", "total_order"):
            cols = [("output", "str", names)] + [(i, "f", [f(outputs[n][order][i]) for n in names]) for i in inputs]
            setattr(self, order, _frame(cols, "output"))
        rows = [
            (n, i, order.split("_")[0], f(outputs[n][order][i]), f(outputs[n][order + "_ci"][i][0]), f(outputs[n][order + "_ci"][i][1]))
            for n in names
            for i in inputs
            for order in ("first_order", "total_order")
        ]
        cols = list(zip(*rows)) if rows else [[]] * 6
        self.intervals = _frame(
            [
                ("output", "str", list(cols[0])),
                ("input", "str", list(cols[1])),
                ("order", "str", list(cols[2])),
                ("value", "f", list(cols[3])),
                ("lo", "f", list(cols[4])),
                ("hi", "f", list(cols[5])),
            ]
        )
        self.inputs = inputs
        self.samples = document["samples"]
        self.seed = document["seed"]
        self.runs = document["runs"]
        self.diagnostics = document["diagnostics"]

    def to_dict(self) -> dict[str, Any]:
        """The study as the JSON document of ``uncertainty --format json`` (a copy)."""
        return copy.deepcopy(self._doc)

    def __repr__(self) -> str:
        return f"Uncertainty(inputs={self.inputs}, samples={self.samples}, runs={self.runs})"


def uncertainty(vary=None, *, racket=None, config=None, progress=None, **kwargs):
    # (the docstring is made from the parameters' and the options' declarations below)
    options, params = _split("uncertainty", kwargs)
    if vary is not None:
        if isinstance(vary, (str, dict)):
            vary = [vary] if isinstance(vary, str) else [k if d is None else f"{k}={d}" for k, d in vary.items()]
        texts = []
        for v in vary:
            name, sep, dist = str(v).partition("=")
            p = _by_name().get(name.strip())
            texts.append(f"{p['key'] if p else name}{sep}{dist}")
        options["vary"] = texts
    pairs = _pairs(params, "uncertainty")
    doc, claims, diagnostics = _call(
        "uncertainty", racket, config, pairs, _options("uncertainty", "uncertainty", options), progress
    )
    if claims is not None:
        _warn(json.loads(diagnostics))
        return _table(claims[1])
    doc = json.loads(doc)
    _warn(doc["diagnostics"])
    return Uncertainty(doc)


def speed(*, racket=None, config=None, progress=None, **kwargs):
    # (the docstring is made from the parameters' and the options' declarations below)
    options, params = _split("speed", kwargs)
    pairs = _command_pairs("speed", "speed", params)
    table, _, diagnostics = _call("speed", racket, config, pairs, _options("speed", "speed", options), progress)
    _warn(json.loads(diagnostics))
    return _table(table[1])


class Modes(NamedTuple):
    """The free racket's modes (``modes``): the first flexible modes' frequencies (Hz), the
    nodes of the fundamental (m from the tip), the beam's segments and the diagnostics."""

    frequencies_hz: np.ndarray
    mode1_nodes_m: np.ndarray
    segments: int
    diagnostics: list


def modes(*, racket=None, config=None, progress=None, **kwargs) -> Modes:
    # (the docstring is made from the parameters' and the options' declarations below)
    options, params = _split("modes", kwargs)
    pairs = _command_pairs("modes", "modes", params)
    doc = json.loads(_call("modes", racket, config, pairs, _options("modes", "modes", options), progress))
    _warn(doc["diagnostics"])
    return Modes(np.array(doc["frequencies_hz"]), np.array(doc["mode1_nodes_m"]), doc["segments"], doc["diagnostics"])


def calibrate(measurements=None, *, racket=None, config=None, progress=None, **kwargs) -> dict:
    # (the docstring is made from the parameters' and the options' declarations below)
    options, params = _split("calibrate", kwargs)
    if measurements is not None:
        options["measurements"] = measurements
    pairs = _pairs(params, "calibrate")
    doc, diagnostics = _call(
        "calibrate", racket, config, pairs, _options("calibrate", "calibrate", options), progress
    )
    _warn(json.loads(diagnostics))
    return json.loads(doc)


# --- rackets, strings, experiments ----------------------------------------------------------

#: The beam segments a racket is fitted for unless told (the paper's N).
_SEGMENTS = 39


def presets(segments: int = _SEGMENTS):
    """The built-in racket presets fitted to the model (``racket --list``): name, length,
    mass, balance, swingweight, twistweight, first frequency, string-bed stiffness, profile.
    Give a name as ``racket=`` to any function."""
    _, columns = _native.presets(int(segments))
    return _table(columns)


class Racket:
    """A racket file (TOML in player units, README "Your own racket") or preset, fitted to the
    model's beam (``racket`` command). Give it as ``racket=`` to any function.

    ``name``; ``source`` (the preset name or file path); ``fit``: the spec sheet beside the
    model (``racket --format csv``); ``model``: the fitted racket, strings and ball (SI units,
    as ``racket --format json``); ``diagnostics``."""

    def __init__(self, source: str | os.PathLike, segments: int = _SEGMENTS):
        self.source = os.fspath(source)
        name, model, (_, columns) = _native.racket(self.source, int(segments))
        self.name = name
        self.model = json.loads(model)
        self.diagnostics = self.model.pop("diagnostics")
        self.fit = _table(columns)
        _warn(self.diagnostics)

    @classmethod
    def from_toml(cls, path: str | os.PathLike, segments: int = _SEGMENTS) -> "Racket":
        """A racket file (TOML, player units), fitted for ``segments`` beam segments."""
        return cls(path, segments)

    @classmethod
    def preset(cls, name: str, segments: int = _SEGMENTS) -> "Racket":
        """A built-in preset (see :func:`presets`), fitted for ``segments`` beam segments."""
        return cls(name, segments)

    def __repr__(self) -> str:
        r = self.model["racket"]
        return f"Racket({self.name!r}, length={r['length']:.4g} m, mass={r['mass']:.4g} kg)"


_args.Racket = Racket


def strings():
    """The strings ``string=`` can name (data/strings): material, gauge and the friction
    coefficients the tangential contact uses, with the database row they come from."""
    rows = json.loads(_native.strings())
    names = list(rows[0]) if rows else []
    cols = []
    for n in names:
        values = [row[n] for row in rows]
        numeric = all(v is None or isinstance(v, (int, float)) for v in values)
        cols.append((n, "f" if numeric else "str", [np.nan if v is None else v for v in values]))
    return _frame(cols)


class Experiment(NamedTuple):
    """One of the paper's results this package replicates (``figures --list``)."""

    id: str
    title: str
    paper_ref: str


def experiments() -> list[Experiment]:
    """Every experiment (the paper's figures and results, and ours beyond them), in the paper's
    order; :func:`run_experiment` gives one's table."""
    return [Experiment(**e) for e in json.loads(_native.experiments())]


def run_experiment(id: str, *, racket=None):
    """The table of the experiment ``id`` (see :func:`experiments`): the CSV ``figures`` writes
    for it, with numbers at full precision. ``racket``: run it on this racket instead of the
    paper's (as ``figures --racket``)."""
    _, columns = _native.run_experiment(str(id), _source(racket))
    return _table(columns)


# --- docstrings and signatures made from the declaration (``_docs``) ------------------------

#: The command each function runs: its options are the library's declaration of them.
_COMMAND_OF = {
    simulate: "simulate",
    sweep: "sweep",
    face_map: "map",
    uncertainty: "uncertainty",
    speed: "speed",
    modes: "modes",
    calibrate: "calibrate",
    card: "card",
}


_docs.install(_COMMAND_OF)
# (the names the type stub and the tests read)
_docstring = _docs.docstring
_signature = _docs.signature
_taken = _docs.taken
_command_options = _docs.command_options
_option_default = _docs.option_default
