#!/usr/bin/python3
"""A solid sphere on a plane wall sloping at 30 degrees (cases/slope_roll.yaml), run with
mu = 0.5 (it rolls: a = 5/7 g sin theta, omega R = v) and mu = 0.1 (it slips: a = g (sin theta
- mu cos theta), omega' = 5/2 mu g cos theta / R). Writes docs/img/slope_roll.png.

usage: /usr/bin/python3 validation/slope_roll.py [--out DIR] [--no-run] [--sluice PATH]
"""
import math

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from runs import case_parser, read_body, run_case, save_figure

CASE = "slope_roll"
THETA = math.radians(30)
G = 9.81
RADIUS = 0.05
DOWN_SLOPE = np.array([math.cos(THETA), 0.0, -math.sin(THETA)])


def along_slope(data, prefix):
    """The components of the columns prefix+x, y, z along the slope, downward."""
    return sum(DOWN_SLOPE[i] * data[prefix + axis] for i, axis in enumerate("xyz"))


def main():
    args = case_parser(CASE, __doc__.splitlines()[0]).parse_args()
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    for mu, colour in ((0.5, "tab:blue"), (0.1, "tab:red")):
        out = run_case(CASE, args, [f"bodies.0.material.friction={mu}"], f"_mu{mu:g}")
        data = read_body(out, "ball")
        t = data["time"]
        s = along_slope(data, "") - along_slope(data, "")[0]
        v = along_slope(data, "v")
        spin = data["wy"]
        rolls = mu >= 2 / 7 * math.tan(THETA)
        a = 5 / 7 * G * math.sin(THETA) if rolls else G * (math.sin(THETA) - mu * math.cos(THETA))
        alpha = a / RADIUS if rolls else 2.5 * mu * G * math.cos(THETA) / RADIUS
        how = "rolls" if rolls else "slips"
        print(f"mu = {mu} ({how}): distance {s[-1]:.5f} m against {a * t[-1] ** 2 / 2:.5f} m, "
              f"v {v[-1]:.4f} m/s against {a * t[-1]:.4f}, omega R {spin[-1] * RADIUS:.4f} m/s "
              f"against {alpha * t[-1] * RADIUS:.4f}")
        left.plot(t, s, "-", lw=2.5, color=colour, label=f"sluice, mu = {mu:g} ({how})")
        left.plot(t, a * t ** 2 / 2, "k--", lw=1.0)
        right.plot(t, v, "-", lw=2.5, color=colour, label=f"v, mu = {mu:g}")
        right.plot(t, spin * RADIUS, ":", lw=2.5, color=colour, label=f"omega R, mu = {mu:g}")
        right.plot(t, a * t, "k--", lw=1.0)
        right.plot(t, alpha * t * RADIUS, "k--", lw=1.0)
    left.plot([], [], "k--", lw=1.0, label="analytic")
    left.set_xlabel("time [s]")
    left.set_ylabel("distance down the slope [m]")
    left.set_title("ball on a 30 degree plane wall")
    left.legend(loc="upper left", fontsize=8)
    right.set_xlabel("time [s]")
    right.set_ylabel("speed down the slope, and omega R [m/s]")
    right.set_title("rolling: omega R = v; slipping: omega R < v")
    right.legend(loc="upper left", fontsize=8)
    for ax in (left, right):
        ax.grid(alpha=0.3)
    save_figure(fig, "slope_roll.png")


if __name__ == "__main__":
    main()
