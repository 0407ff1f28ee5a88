"""The docstrings and signatures of the package's functions, made from the library's one
declaration of the parameters, the commands' options and the result fields (a parameter added
there is documented here), each function's from its template below."""

from __future__ import annotations

import inspect
import textwrap
from typing import Any, Callable

from . import _args

#: The command each function runs (its options are the library's declaration of them), set by
#: :func:`install`. The declaration's tables are read from :mod:`racket_impact._args` when used.
COMMAND_OF: dict[Callable, str] = {}


def param_doc(p: dict[str, Any]) -> str:
    """One parameter in a numpydoc ``Parameters`` list: name, type and unit, its help, allowed
    and usual ranges, default (and how it is chosen), which impacts use it, and its declared
    uncertainty; its help heading in brackets."""
    kind = {"number": "float", "count": "int", "choice": "str"}[p["kind"]]
    unit = f", {p['unit']}" if p["unit"] else ""
    lines = [f"{p['name']} : {kind}{unit} [{p['heading']}]", f"    {p['help']}."]
    if p["kind"] == "choice":
        for c in p["choices"]:
            lines.append(f"    ``{c['name']}``" + (f": {c['help']}" if c["help"] else ""))
    else:
        lines.append(f"    Allowed: {p['range_text'].replace(p['key'], p['name'])}.")
    if p["usual"]:
        lo, hi = p["usual"]
        lines.append(f"    Usual: {_num(lo)} .. {_num(hi)}{(' ' + p['unit']) if p['unit'] else ''} (outside: a warning).")
    default = p["default"]
    if default is not None:
        unit_default = f" {p['unit']}" if p["unit"] and p["kind"] != "choice" and _is_number(default) else ""
        how = f" ({p['default_words'].replace('--racket', 'racket=')})" if p["default_words"] else ""
        lines.append(f"    Default: {default}{unit_default}{how}.")
    if p["used_when"] != "always":
        lines.append(f"    Used only {p['used_when']}.")
    if p["uncertainty"]:
        u = p["uncertainty"]
        lines.append(f"    Declared uncertainty: {u['dist']} (nominal {_num(u['nominal'])}).")
    return "\n".join(lines)


def _num(v: float) -> str:
    """A bound as the help writes it: ``1e12``, ``0.01``, ``5000``."""
    return f"{v:g}".replace("e+0", "e").replace("e+", "e").replace("e-0", "e-")


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True



_RACKET_DOC = """racket : str, os.PathLike or Racket, optional
    A preset name (see presets()) or a racket file (TOML, player units); its values replace
    the paper's racket, strings and ball, and the impact moves to the centre of its head.
config : str or os.PathLike, optional
    A TOML file with any parameter key (as the command line's --config); keywords win.
progress : bool, optional
    Show the call's progress (tqdm's bar where tqdm is installed, else a line on standard
    error): by default once the call has run a second; False: never. Ctrl-C stops any call
    within a second (KeyboardInterrupt), with nothing kept."""

_COMMON_NOTE = """The defaults are the paper's racket hit at the centre of its strings with the
paper's ball (the command line's): with ``racket=``, the racket's own values. Precedence: the
defaults < the racket < the config file < the keywords."""

_DOCS = {
    "simulate": f"""One impact: the ball's rebound (e_A), contact time, twist and where the energy went.

Returns an :class:`Impact` with every field of ``racket-impact simulate --format json`` as an
attribute (and ``to_dict()``), bit for bit the command line's numbers. A bad value raises
``ValueError`` with the command line's message; a doubt about the run is a warning
(:class:`RacketImpactWarning`).

{_COMMON_NOTE}

Example: ``simulate(x=0.10, r=0.05, ks=3e4).e_a``

Parameters
----------
{_RACKET_DOC}
@OPTIONS@
@PARAMETERS@

Returns
-------
Impact
    The result, every field an attribute (SI units unless the name says otherwise); a field
    of an oblique or spinning ball only is absent at normal incidence:

@FIELDS@
""",
    "sweep": f"""Every impact of the cartesian product of the values given, in parallel, as ``sweep``.

Each keyword is a parameter and its values: an array or list (``x=np.linspace(0.02, 0.6,
50)``, ``load=["node", "hat"]``), one value, or a spec string as the command line's
(``"0.02:0.6:50"``, ``"1e3:1e5:5:log"``); the first keyword varies slowest. Returns a pandas
DataFrame where pandas is installed, else a dict of numpy arrays, with ``sweep``'s CSV
columns: the swept parameters, the recorded ones, every result field, and the solver. The
numbers are the command line's, at full precision. The work runs on every core with the GIL
released; nothing is done in Python per impact. Sweeps use the modal solver unless
``solver`` is given or a hand grip or stiffening strings need fd.

{_COMMON_NOTE}

Parameters
----------
{_RACKET_DOC}
@OPTIONS@
@PARAMETERS@
""",
    "map": f"""A quantity over the string face, one impact per point of an nx x nr grid (``map``).

Returns a :class:`FaceMap`: the grid ``x`` and ``r``, ``values[i, j]`` at ``(x[i], r[j])``,
the ``table`` of every quantity at every point, ``metadata`` and ``diagnostics``. No file is
written. The grid sets the impact point and the map its solver, so ``x``, ``r``, ``solver`` and
``dt`` are not keywords here.

Parameters
----------
{_RACKET_DOC}
@OPTIONS@
@PARAMETERS@
""",
    "speed": f"""Outgoing ball speed for a swing and an incoming ball, compared across tensions or rackets.

The command line's ``speed``: v_out = e_A v_in + (1 + e_A) v_racket, with e_A computed at the
relative speed and the racket's swing speed at the impact point; a tilted swing path or an
incoming spin makes the impact oblique. Returns a DataFrame where pandas is installed (else a
dict of numpy arrays) with ``speed``'s CSV columns, one row per variant, the first the reference.

Parameters
----------
{_RACKET_DOC}
@OPTIONS@
@PARAMETERS@
""",
    "modes": f"""The free racket's flexible modes: frequencies and the nodes of the fundamental (``modes``).

Returns a :class:`Modes`. Only the racket's length, mass, stiffness and segments matter: the
other parameters are not keywords here.

Parameters
----------
{_RACKET_DOC}
@OPTIONS@
@PARAMETERS@
""",
    "calibrate": f"""Fit parameters with a declared range to measured rows (``calibrate``).

``measurements``: a CSV in the schema of data/measured (the shipped measurements if not given);
``fit``: the parameters to fit (each with a declared range, or ``range=["KEY=LO:HI"]``). The rows
with role = calibration are fitted, those with role = validation predicted and judged. Returns
the command line's ``calibrate --format json`` document as a dict: each fitted parameter with
its 95 % interval, the correlation, every row's model value and its held-out prediction, and the
in-sample, held-out and validation errors. The fit runs on the library's threads with the GIL
released; Ctrl-C stops it.

Example: ``calibrate(fit=["kt"], hold_out="string")``

Parameters
----------
measurements : str or os.PathLike, optional
    The measurements CSV.
{_RACKET_DOC}
@OPTIONS@
@PARAMETERS@
""",
    "card": f"""What string tension does to one racket: power, sweet spot, control, comfort and spin against the tension (``card``).

For a racket (``racket=``, or the paper's), a string (``string=``, data/strings) and a range of
tensions, every panel computed as the command that computes it alone: the ball speeds as
``speed``, the sweet spot from ``map``, the twist, vibration and contact time as ``simulate``,
the spin as ``speed``'s stroke. Returns a :class:`Card` (its table, header block, the paper
beside the model on the paper's racket, the PNG); with ``out`` its two files are written too,
the CSV at ``out`` and the PNG beside it. Refused above ten minutes of estimated work unless
``long=True``. The card sets the impact points, speeds, incidence and ``ks`` itself, so
those are not keywords here.

Parameters
----------
out : str or os.PathLike, optional
    Write the card's CSV here and its PNG beside it (same stem), atomically.
{_RACKET_DOC}
@OPTIONS@
@PARAMETERS@
""",
    "uncertainty": f"""An impact's result fields under uncertain inputs: quantiles and Sobol' indices.

``vary``: the uncertain inputs, each ``"KEY=DIST"`` (DIST ``uniform:LO:HI``,
``normal:MEAN:SD`` or ``loguniform:LO:HI``) or ``"KEY"`` alone for the distribution declared
with the parameter; or a dict ``{{KEY: DIST or None}}``. The impact runs ``samples`` (d + 2)
times over a Saltelli design (scrambled Sobol' sequence, deterministic for ``seed``) on every
core with the GIL released, with the modal solver unless ``solver`` is given or a hand grip or
stiffening strings need fd. Returns an :class:`Uncertainty` (DataFrames of the quantiles and
indices), equal to ``uncertainty --format json``.

With ``claims=True`` (and no ``vary``): every paper claim under the declared uncertainty of the
paper's inputs, as ``uncertainty --claims`` (its CSV's table).

Parameters
----------
vary : list of str or dict
    The uncertain inputs.
{_RACKET_DOC}
@OPTIONS@
@PARAMETERS@
""",
}


def own_parameters(function) -> list[inspect.Parameter]:
    """The function's own parameters, as written (kept before a signature made here replaces
    what ``inspect`` sees)."""
    if "_own_parameters" not in function.__dict__:
        function._own_parameters = [
            q for q in inspect.signature(function).parameters.values() if q.kind is not inspect.Parameter.VAR_KEYWORD
        ]
    return function._own_parameters


def command_options(function) -> list[dict[str, Any]]:
    """The options of the function's command that are keywords of their own (not the
    function's own parameters: ``uncertainty``'s ``vary`` comes first, positional)."""
    own = {q.name for q in own_parameters(function)}
    return [o for o in _args._COMMANDS.get(COMMAND_OF.get(function, ""), []) if o["keyword"] not in own]


def option_default(o: dict[str, Any]) -> Any:
    """An option's default as a Python value (a switch's is False)."""
    if o["kind"] == "switch":
        return False
    if o["default"] is None:
        return None
    return {"count": int, "number": float}.get(o["kind"], str)(o["default"])


def option_doc(o: dict[str, Any]) -> str:
    """One option in a numpydoc ``Parameters`` list: its type, help, range and default."""
    kind = {"switch": "bool", "count": "int", "number": "float", "text": "str", "choice": "str"}[o["kind"]]
    if o["many"]:
        kind = f"{kind} or sequence of {kind}"
    lines = [f"{o['keyword']} : {kind}"]
    lines += textwrap.wrap(_args._python_words(o["help"]) + ".", 92, initial_indent="    ", subsequent_indent="    ")
    if o["kind"] == "count":
        lines.append(f"    Allowed: {o['lo']} <= {o['keyword']} <= {o['hi']}.")
    if o["kind"] == "choice":
        lines.append(f"    One of: {', '.join(o['choices'])}.")
    default = option_default(o)
    if default is not None:
        lines.append(f"    Default: {default!r}.")
    return "\n".join(lines)


def signature(function, names: list[str]) -> inspect.Signature:
    """The function's own parameters, its command's options with their defaults, then every
    impact parameter as a keyword (default None: the default named in the docstring)."""
    options = [
        inspect.Parameter(
            o["keyword"],
            inspect.Parameter.KEYWORD_ONLY,
            default=inspect.Parameter.empty if o["required"] else option_default(o),
        )
        for o in command_options(function)
    ]
    extra = [inspect.Parameter(n, inspect.Parameter.KEYWORD_ONLY, default=None) for n in names]
    return inspect.Signature(own_parameters(function) + options + extra)


def taken(function) -> list[dict[str, Any]]:
    """The parameters ``function`` takes as keywords: those its command takes."""
    not_taken = _args._NOT_TAKEN.get(COMMAND_OF.get(function, ""), {})
    return [p for p in _args._PARAMS if p["key"] not in not_taken]


def fields_doc() -> str:
    """Every result field of one impact as the returned :class:`Impact` has it: name, type and
    unit, and what it is (the library's field table)."""
    lines = []
    for f in _args._FIELDS:
        kind = {"number": "float", "flag": "bool"}[f["kind"]]
        unit = f", {f['unit']}" if f["unit"] else ""
        where = " (oblique or spinning ball only)" if f["oblique"] else ""
        lines.append(f"    {f['key']} : {kind}{unit}{where}")
        lines += textwrap.wrap(" ".join(f["doc"].split()), 88, initial_indent="        ", subsequent_indent="        ")
    lines.append("    params : dict, f1_hz : float, diagnostics : list, series : DataFrame or None")
    lines.append("        The parameters it ran with, the free racket's first bending frequency, the")
    lines.append("        diagnostics (also given as warnings), the time series (``series=True``).")
    return "\n".join(lines)


def docstring(function) -> str:
    """The function's docstring with every parameter it takes."""
    options = "\n".join(option_doc(o) for o in command_options(function))
    text = _DOCS[COMMAND_OF[function]].replace("@OPTIONS@\n", options + "\n" if options else "")
    text = text.replace("@FIELDS@", fields_doc())
    return text.replace("@PARAMETERS@", "\n".join(param_doc(p) for p in taken(function)))


def install(command_of: dict[Callable, str]) -> None:
    """Give each function of ``command_of`` (function: the command it runs) its docstring and
    signature from the declaration's tables."""
    COMMAND_OF.update(command_of)
    for f in command_of:
        f.__doc__ = docstring(f)
        f.__signature__ = signature(f, [p["name"] for p in taken(f)])
