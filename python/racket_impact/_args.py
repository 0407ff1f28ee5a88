"""The package's arguments as the library takes them: the declaration's tables (the parameters,
the result fields, each command's options and the parameters it does not take, read once from
the library), a keyword's declaration, a value as its flag would be given it (a value of the
wrong type a ``TypeError`` naming the keyword), and a library text in Python's words."""

from __future__ import annotations

import difflib
import json
import numbers
import os
import re
from typing import Any

import numpy as np

from . import _native

#: The package's :class:`racket_impact.Racket` (set by the package once defined): a racket
#: given where a file is taken stands for its source.
Racket: type = type(None)

#: The declaration of every impact parameter (key, name, help, unit, range, default, ...), as the
#: library declares it.
_PARAMS: list[dict[str, Any]] = json.loads(_native.parameters())
#: The result fields of one impact (key, unit, doc, ...), as the library declares them.
_FIELDS: list[dict[str, Any]] = json.loads(_native.result_fields())
#: Every command's own options (not the parameters: ``nx``, ``samples``, ``long``, ...), as the
#: library declares them: name (the flag), keyword, kind (switch, count, number, text, choice),
#: range, choices, whether a list, default (as the flag takes it) and help.
_DECLARED: dict[str, dict[str, Any]] = json.loads(_native.commands())
_COMMANDS: dict[str, list[dict[str, Any]]] = {name: d["options"] for name, d in _DECLARED.items()}
#: The parameters each command does not take, with why (a map's grid sets the impact point, the
#: swing sets a speed's ball speed, a free racket's modes need neither ball nor strings).
_NOT_TAKEN: dict[str, dict[str, str]] = {name: d["not_taken"] for name, d in _DECLARED.items()}


def _by_name() -> dict[str, dict[str, Any]]:
    """Every spelling of a parameter: its Python name, its key and its CSV column."""
    names: dict[str, dict[str, Any]] = {}
    for p in _PARAMS:
        for n in (p["name"], p["key"], p["column"]):
            names.setdefault(n, p)
    return names


def _param(name: str, function: str) -> dict[str, Any]:
    """The declaration a keyword names, else ``TypeError`` with the nearest names."""
    p = _by_name().get(name)
    if p is None:
        near = difflib.get_close_matches(name, [q["name"] for q in _PARAMS], n=3)
        hint = f"; did you mean {' or '.join(repr(n) for n in near)}?" if near else ""
        raise TypeError(f"{function}() got an unexpected keyword argument {name!r}{hint}")
    return p


def _text(p: dict[str, Any], value: Any) -> str:
    """A value as the command line's flag would be given it: a name as it is, a whole number in
    digits, a real number in its shortest exact form (``repr``). A value of another type is a
    ``TypeError``, as in any numpy-style API: ``ks="4e4"`` is not a number, ``segments=39.0``
    not a whole one."""
    if p["kind"] == "choice":
        if isinstance(value, str):
            return value
        names = ", ".join(c["name"] for c in p["choices"])
        raise TypeError(f"{p['name']} takes one of the names {names}, not {value!r}")
    if p["kind"] == "count":
        if isinstance(value, numbers.Integral) and not isinstance(value, (bool, np.bool_)):
            return str(int(value))
        raise TypeError(f"{p['name']} takes a whole number, not {value!r}")
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise TypeError(f"{p['name']} takes a number, not {value!r}")
    if isinstance(value, numbers.Integral):
        return str(int(value))
    return repr(float(value))


def _takes(o: dict[str, Any]) -> str:
    """What a command's option takes, in words."""
    return {
        "switch": "True or False",
        "count": f"a whole number ({o['lo']}..={o['hi']})",
        "number": "a number",
        "text": "a text",
        "choice": "one of the names " + ", ".join(o["choices"]),
    }[o["kind"]]


def _option_text(o: dict[str, Any], function: str, value: Any) -> str:
    """A command option's value as its flag takes it; a value of another type is a
    ``TypeError`` naming the keyword (its range is the library's to check: a ``ValueError``
    with the command line's message)."""
    kind = o["kind"]
    if kind == "switch" and isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if kind == "count" and isinstance(value, numbers.Integral) and not isinstance(value, (bool, np.bool_)):
        return str(int(value))
    if kind == "number" and isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_)):
        return repr(float(value))
    if kind == "text" and isinstance(value, Racket):
        return value.source
    if kind == "text" and isinstance(value, (str, os.PathLike)):
        return os.fspath(value)
    if kind == "choice" and isinstance(value, str):
        return value
    raise TypeError(f"{function}() argument {o['keyword']} takes {_takes(o)}, not {value!r}")


def _options(command: str, function: str, given: dict[str, Any]) -> list[tuple[str, list[str]]]:
    """The command's options among ``given`` as ``(keyword, [texts])``: a list option takes a
    sequence or one value; ``None`` is "not given" for an option without a default, and a
    ``TypeError`` for one with a default (``nx=None``)."""
    out = []
    for o in _COMMANDS[command]:
        if o["keyword"] not in given:
            if o["required"]:
                raise TypeError(f"{function}() missing required keyword argument: {o['keyword']!r}")
            continue
        value = given[o["keyword"]]
        if value is None:
            if o["default"] is None and o["kind"] != "switch":
                continue
            raise TypeError(f"{function}() argument {o['keyword']} takes {_takes(o)}, not None")
        if o["many"] and not isinstance(value, (str, os.PathLike, Racket)) and np.ndim(value) > 0:
            values = list(value)
        else:
            values = [value]
        out.append((o["keyword"], [_option_text(o, function, v) for v in values]))
    return out


def _split(command: str, kwargs: dict[str, Any]) -> tuple[dict[str, Any], dict[str, Any]]:
    """The keywords as (the command's options, the impact parameters)."""
    own = {o["keyword"] for o in _COMMANDS[command]}
    return {k: v for k, v in kwargs.items() if k in own}, {k: v for k, v in kwargs.items() if k not in own}


def _command_pairs(command: str, function: str, params: dict[str, Any]) -> list[tuple[str, str]]:
    """The parameters as ``_pairs``, a parameter the command does not take a ``TypeError`` that
    says why (a map's grid sets the impact point)."""
    for name in params:
        why = _NOT_TAKEN[command].get(_param(name, function)["key"])
        if why:
            raise TypeError(f"{function}() got an unexpected keyword argument {name!r}: {_python_words(why)}")
    return _pairs(params, function)


def _pairs(params: dict[str, Any], function: str) -> list[tuple[str, str]]:
    return [(_param(name, function)["key"], _text(_param(name, function), v)) for name, v in params.items()]


def _path(config: Any) -> str | None:
    if config is None:
        return None
    if isinstance(config, (str, os.PathLike)):
        return os.fspath(config)
    raise TypeError(f"config is a TOML file's path, not {config!r}")


def _python_words(text: str) -> str:
    """A text of the library in Python's words: a flag ``--angle-deg`` is the keyword
    ``angle_deg``, a switch ``--long`` is ``long=True``."""
    switches = {o["name"] for options in _COMMANDS.values() for o in options if o["kind"] == "switch"}
    return re.sub(
        r"--([a-z][a-z0-9-]*)", lambda m: m[1].replace("-", "_") + ("=True" if m[1] in switches else ""), text
    )
