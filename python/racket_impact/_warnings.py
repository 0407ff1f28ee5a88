"""The package's warnings: a doubt about a valid run (a value outside its usual range, a result
beyond the model's range, a property given but not used, a long run) as a warning of its kind,
pointing at the line that called into the package, never a print. The classes are the
package's (``racket_impact.UnusualValueWarning``)."""

from __future__ import annotations

import os
import sys
import warnings

#: The package's folder: the frames in it are the package's own.
_HERE = os.path.dirname(__file__)


class RacketImpactWarning(UserWarning):
    """A doubt about a valid run, as the command line prints it after ``warning:``.

    ``kind`` says what kind of doubt (``unusual``, ``beyond_model``, ``missing_data``,
    ``not_used``), ``field`` the parameter key or result field it is about."""

    kind: str = ""
    field: str = ""

    def __init__(self, sentence: str, kind: str = "", field: str = ""):
        super().__init__(sentence)
        self.kind = kind
        self.field = field


class UnusualValueWarning(RacketImpactWarning):
    """A valid value outside the range usual for it (a typo or a unit slip?), computed anyway."""


class BeyondModelWarning(RacketImpactWarning):
    """A result beyond the range the model is meant for, computed anyway."""


class MissingDataWarning(RacketImpactWarning):
    """A value the data does not give, taken from elsewhere."""


class NotUsedWarning(RacketImpactWarning):
    """A property or key given that this run does not use."""


class LongRunWarning(RacketImpactWarning):
    """A call estimated to take more than a minute (told before it starts), or one that has
    taken more than three times its estimate (told as it goes)."""


_WARNINGS = {
    "unusual": UnusualValueWarning,
    "beyond_model": BeyondModelWarning,
    "missing_data": MissingDataWarning,
    "not_used": NotUsedWarning,
    "long_run": LongRunWarning,
}


def _caller_level() -> int:
    """The ``stacklevel`` of the line that called into this package."""
    level, frame = 1, sys._getframe(1)
    while frame is not None and os.path.dirname(frame.f_code.co_filename) == _HERE:
        frame, level = frame.f_back, level + 1
    return level


def _warn(diagnostics: list[dict[str, str]]) -> None:
    """Each diagnostic as a warning, pointing at the line that called into this package."""
    level = _caller_level()
    for d in diagnostics:
        cls = _WARNINGS.get(d["kind"], RacketImpactWarning)
        warnings.warn(cls(d["sentence"], d["kind"], d["field"]), stacklevel=level)


for _cls in _WARNINGS.values():
    _cls.__module__ = "racket_impact"
RacketImpactWarning.__module__ = "racket_impact"
del _cls
