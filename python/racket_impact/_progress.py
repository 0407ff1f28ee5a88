"""A call's progress as it runs, in a notebook or a terminal, and its notes as warnings.

The library tells how far a call is (every impact counts itself from inside the solver, so
the bar moves during a long impact too) with a rate a person reads and the time left; this
module draws it: tqdm's bar where tqdm is installed (``tqdm.auto``: a widget in a notebook),
else one line on standard error. A call shows its bar once it has run :data:`DELAY` seconds
(``progress=True``: at once; ``progress=False``: never)."""

from __future__ import annotations

import sys
from typing import Callable

#: Seconds a call runs before its progress is shown (``progress=None``), as on the command line.
DELAY = 1.0


class _Line:
    """The package's own bar: one line on standard error, redrawn in place."""

    WIDTH = 30

    def __init__(self, stream=None):
        self.stream = stream if stream is not None else sys.stderr
        self.drawn = 0

    def set(self, fraction: float, words: str) -> None:
        filled = int(round(self.WIDTH * fraction))
        text = f"{100 * fraction:3.0f}% |{'#' * filled}{'.' * (self.WIDTH - filled)}| {words}"
        pad = " " * max(0, self.drawn - len(text))
        self.stream.write("\r" + text + pad)
        self.stream.flush()
        self.drawn = len(text)

    def close(self) -> None:
        if self.drawn:
            self.stream.write("\n")
            self.stream.flush()


class _Tqdm:
    """tqdm's bar (a widget in a notebook), with the library's words after it."""

    def __init__(self, tqdm, total: int, unit: str):
        self.total = total
        self.bar = tqdm(total=total, unit=unit, bar_format="{percentage:3.0f}%|{bar}| {desc}", leave=True)

    def set(self, fraction: float, words: str) -> None:
        self.bar.n = fraction * self.total
        self.bar.set_description_str(words, refresh=False)
        self.bar.refresh()

    def close(self) -> None:
        self.bar.close()


def _tqdm():
    """tqdm's ``auto`` bar, where tqdm is installed."""
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None
    return tqdm


class Reporter:
    """What the library calls as a call runs: ``note(text)`` for a note (``warn``), and
    ``update(position, total, unit, words, elapsed_s)`` for the progress; ``close()`` at the
    end. ``show``: ``None`` (once the call has run :data:`DELAY` seconds), ``True`` or
    ``False``."""

    def __init__(self, show: bool | None, warn: Callable[[str], None]):
        if show is not None and not isinstance(show, bool):
            raise TypeError(f"progress takes True, False or None, not {show!r}")
        self.show = show
        self.warn = warn
        self.bar = None

    def note(self, text: str) -> None:
        self.warn(text)

    def update(self, position: float, total: int, unit: str, words: str, elapsed_s: float) -> None:
        if self.show is False or total == 0:
            return
        if self.bar is None:
            if self.show is None and elapsed_s < DELAY:
                return
            tqdm = _tqdm()
            self.bar = _Tqdm(tqdm, total, unit) if tqdm is not None else _Line()
        self.bar.set(min(1.0, position / total), words)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
            self.bar = None
