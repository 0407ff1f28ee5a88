"""The work runs with the GIL released: Python threads go on while a sweep runs, and two
sweeps at once give each its own exact result."""

import threading

import numpy as np

import racket_impact as ri


def test_python_runs_while_a_sweep_runs():
    entered, done = threading.Event(), threading.Event()
    ticks = []
    x, ks = np.linspace(0.02, 0.6, 400), np.linspace(2e4, 6e4, 20)

    def sweep():
        entered.set()
        ri.sweep(x=x, ks=ks)
        done.set()

    worker = threading.Thread(target=sweep)
    worker.start()
    entered.wait()
    # this thread counts only while it holds the GIL: were the sweep to hold it for its whole
    # call (8000 impacts), this loop would stand still until the sweep ended
    while not done.is_set():
        ticks.append(1)
    worker.join()
    assert len(ticks) > 1000, len(ticks)


def test_two_threads_sweep_at_once():
    x = np.linspace(0.02, 0.6, 300)
    expected = {ks: ri.sweep(x=x, ks=ks) for ks in (2e4, 5e4)}
    results = {}
    started = threading.Barrier(2)

    def run(ks):
        started.wait()
        results[ks] = ri.sweep(x=x, ks=ks)

    threads = [threading.Thread(target=run, args=(ks,)) for ks in expected]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for ks, frame in expected.items():
        assert results[ks].equals(frame), ks


def test_ctrl_c_stops_a_long_sweep():
    import _thread
    import time

    x = np.linspace(0.02, 0.6, 1000)
    # the processor time of 1e4 impacts, then of a 1e6-impact sweep interrupted (a simulated
    # Ctrl-C) 0.3 s in: the sweep stops after the chunk the signal arrives in, long before the
    # hundred times 1e4 impacts it would otherwise run
    ri.sweep(x=x[:100], ks=np.linspace(2e4, 6e4, 100))  # (warm: the modes are computed once)
    start = time.process_time()
    ri.sweep(x=x[:100], ks=np.linspace(2e4, 6e4, 100))
    small = time.process_time() - start
    timer = threading.Timer(0.3, _thread.interrupt_main)
    start = time.process_time()
    timer.start()
    try:
        ri.sweep(x=x, ks=np.linspace(2e4, 6e4, 1000))
        raise AssertionError("no KeyboardInterrupt")
    except KeyboardInterrupt:
        pass
    finally:
        timer.cancel()
    spent = time.process_time() - start
    assert spent < 0.5 * 100 * small, (spent, small)
