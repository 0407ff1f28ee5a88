"""A modal sweep of 1e5 impacts from Python beside the same sweep on the command line, in one
run, alternating the two (A B A B ...) so that a drift in the machine's speed hits both.

    python python/benches/sweep_vs_cli.py [ROUNDS]

The command line writes its CSV to a file (``--out``); Python keeps the columns (a pandas
DataFrame where pandas is installed). Python is timed in this process (as a notebook calls
it: the package imported once), the command line as a whole process (its start-up is a few
milliseconds). Prints each round and the medians; not a test (no wall-clock limit in tests).
"""

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import racket_impact as ri

ROOT = Path(__file__).resolve().parents[2]
BIN = ROOT / "target" / "release" / "racket-impact"
SPEC = {"x": "0.02:0.6:1000", "ks": "2e4:6e4:100"}  # 1e5 impacts, the modal solver (sweep's default)


def main(rounds=5):
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "sweep.csv"
        args = [str(BIN), "sweep", "--out", str(out), "--x", SPEC["x"], "--ks", SPEC["ks"]]
        subprocess.run(args, check=True)  # warm-up of both (files, caches)
        frame = ri.sweep(**SPEC)
        assert len(frame) == 100_000
        cli, py = [], []
        for i in range(rounds):
            t = time.perf_counter()
            subprocess.run(args, check=True)
            cli.append(time.perf_counter() - t)
            t = time.perf_counter()
            frame = ri.sweep(**SPEC)
            py.append(time.perf_counter() - t)
            print(f"round {i + 1}: command line {cli[-1]:.3f} s, Python {py[-1]:.3f} s, ratio {py[-1] / cli[-1]:.3f}")
    ratios = [p / c for p, c in zip(py, cli)]
    print(
        f"median of {rounds}: command line {statistics.median(cli):.3f} s, Python {statistics.median(py):.3f} s, "
        f"Python / command line {statistics.median(ratios):.3f} (pair by pair)"
    )


if __name__ == "__main__":
    main(*map(int, sys.argv[1:]))
