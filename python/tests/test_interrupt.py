"""Ctrl-C stops any long call within a second: KeyboardInterrupt, no result, no file written
(issue 47: a hand-held face map ran 607 s ignoring it; uncertainty and a hand-held sweep 40 s;
a modal map interrupted at 3 s finished its work, then threw the result away)."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import racket_impact as ri

#: A racket of 1e6 kg held in the hand: each impact is stepped on for two periods of its 0.07 Hz
#: fundamental after it, about 2 s of work.
HELD = {"grip": "hand", "mass": 1e6}

#: The long calls, each far longer than the half second before its interrupt.
LONG_CALLS = {
    "simulate, one long impact": lambda: ri.simulate(**HELD),
    "sweep": lambda: ri.sweep(x=np.linspace(0.1, 0.2, 8), long=True, **HELD),
    "face_map, held": lambda: ri.face_map(nx=61, nr=21, long=True, **HELD),
    "face_map, modal": lambda: ri.face_map(nx=401, nr=401),
    "uncertainty": lambda: ri.uncertainty("ks", samples=64, long=True, **HELD),
    "run_experiment": lambda: ri.run_experiment("robustness"),
    "card, held": lambda: ri.card(tensions_lb=[50, 60], long=True, out="c.csv", **HELD),
}


@pytest.mark.parametrize("name", list(LONG_CALLS))
def test_ctrl_c_stops_a_long_call_within_a_second_and_leaves_nothing(name, tmp_cwd, recwarn):
    interrupt = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    interrupt.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            LONG_CALLS[name]()
        stopped = time.monotonic() - start
    finally:
        interrupt.cancel()
    assert stopped - 0.5 < 1.0, f"{name}: stopped {stopped - 0.5:.2f} s after the interrupt"
    assert list(tmp_cwd.iterdir()) == [], "no file written"
    # the package is fit for the next call
    assert ri.simulate(x=0.1).e_a > 0
