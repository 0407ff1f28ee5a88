"""Paper Fig 5(a) from Python: the impact along the racket on soft strings.

R. Cross (2000), Fig 5(a): e_A (the ball's rebound speed over its incident speed, the racket at
rest), the ball's energy loss f(ball), the frame's vibration energy f(vib) and the contact time
tau, for an impact at every node of the paper's 39-segment beam on its long axis (r = 0), with
strings of k_s = 2e4 N/m and the paper's numerics (force on the nearest node, explicit time
stepping). The paper reads e_A = 0.44 and tau ~ 6.0 ms at the centre of the strings, a dead spot
(e_A ~ 0) near the tip, and f(vib) ~ 0 at the fundamental's node, 16 cm from the tip.

    python examples/fig5a_position_soft.py [figure.png]

prints the curve as a table, and with matplotlib installed draws it (to the PNG named, else to
fig5a_position_soft.png). The numbers are those of `racket-impact figures --only
fig5a_position_soft` (the tests check them), here from one call: a sweep over 40 positions.
"""

import sys

import numpy as np

import racket_impact as ri


def figure5a():
    """The sweep of Fig 5(a): a table with x_m, e_a, f_ball, f_vib, tau_s, ... per position."""
    length = float(next(p["default"] for p in ri.parameters() if p["name"] == "length"))  # the paper's 0.71 m
    segments = 39
    x = length * np.arange(segments + 1) / segments  # every node of the beam
    return ri.sweep(x=x, ks=2e4, r=0.0, load="node", segments=segments, solver="fd")


def main(png="fig5a_position_soft.png"):
    table = figure5a()
    x, e_a, f_vib, tau = (np.asarray(table[c]) for c in ("x_m", "e_a", "f_vib", "tau_s"))
    centre = int(np.argmin(np.abs(x - 0.158)))  # the paper's centre of the strings
    print(f"{'x (cm)':>7} {'e_A':>8} {'f(ball)':>8} {'f(vib)':>8} {'tau (ms)':>8}")
    for i in range(len(x)):
        print(f"{100 * x[i]:7.1f} {e_a[i]:8.4f} {table['f_ball'][i]:8.4f} {f_vib[i]:8.4f} {1e3 * tau[i]:8.3f}")
    print(f"at the centre (x = {100 * x[centre]:.1f} cm): e_A = {e_a[centre]:.3f} (paper 0.44), tau = {1e3 * tau[centre]:.2f} ms (paper ~6.0)")
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return table
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(100 * x, e_a, label="e_A")
    ax.plot(100 * x, table["f_ball"], label="f(ball)")
    ax.plot(100 * x, f_vib, label="f(vib)")
    ax.set_xlabel("impact distance from the tip, x (cm)")
    ax.set_ylabel("e_A, energy fractions")
    ax2 = ax.twinx()
    ax2.plot(100 * x, 1e3 * tau, "k--", label="tau")
    ax2.set_ylabel("contact time tau (ms)")
    ax.set_title("Fig 5(a): impact position, ks 2e4 N/m, r 0 (from Python)")
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    print(f"wrote {png}")
    return table


if __name__ == "__main__":
    main(*sys.argv[1:])
