"""A long call shows its progress as it goes, with a rate a person reads: tqdm's bar where tqdm is
installed, else the package's own line on standard error; a short call shows nothing (issue 48:
the bar stood at "0/8 impacts" for a whole hand-held sweep, and rates read "44,808.221/s")."""

import re

import numpy as np

import racket_impact as ri
from racket_impact import _progress


def test_the_own_line_shows_the_part_done_and_the_librarys_words(capsys, monkeypatch):
    monkeypatch.setattr(_progress, "_tqdm", lambda: None)
    told = []
    r = _progress.Reporter(True, told.append)
    r.update(2.5, 8, "impacts", "2.5 of 8 impacts, 1.2 impacts/s, about 4 s left", 2.0)
    r.update(4.0, 8, "impacts", "4 of 8 impacts, 1.3 impacts/s, about 3 s left", 3.0)
    r.note("this run is estimated at about 7 s")
    r.close()
    err = capsys.readouterr().err
    assert " 31% |#########" in err and "2.5 of 8 impacts, 1.2 impacts/s" in err
    assert err.rstrip(" \n").endswith("about 3 s left") and " 50% |###############" in err
    assert told == ["this run is estimated at about 7 s"]


def test_a_short_call_shows_nothing_and_progress_false_never(capsys, monkeypatch):
    monkeypatch.setattr(_progress, "_tqdm", lambda: None)
    quiet = _progress.Reporter(None, print)
    quiet.update(1.0, 8, "impacts", "1 of 8 impacts", 0.5)  # (before the second has passed)
    never = _progress.Reporter(False, print)
    never.update(1.0, 8, "impacts", "1 of 8 impacts", 50.0)
    quiet.close()
    never.close()
    assert capsys.readouterr().err == ""


def test_a_call_draws_the_bar_as_it_goes_with_a_readable_rate(capfd, monkeypatch):
    monkeypatch.setattr(_progress, "_tqdm", lambda: None)
    ri.sweep(x=np.linspace(0.05, 0.25, 400), ks=[2e4, 3e4], progress=True)
    err = capfd.readouterr().err
    assert "of 800 impacts" in err and "100% |" in err
    rates = re.findall(r"impacts, ([^,]*/s|[^,]* s per impact)", err)
    assert rates, err
    for rate in rates:
        # a count or a few significant digits, never a thousands separator or three decimals
        assert re.fullmatch(r"\d+ impacts/s|\d(\.\d)? impacts/s|\d+(\.\d)? s per impact", rate), rate
