#!/usr/bin/python3
"""C3 of VALIDATION.md: a 0.1 m cube sliding on a 30 degree incline with mu = 0.3
(cases/incline_block.yaml, the incline made by tilting gravity). Compares the distance slid
with g (sin theta - mu cos theta) t^2 / 2 and writes docs/img/incline_block.png.

usage: /usr/bin/python3 validation/incline_block.py [--out DIR] [--no-run] [--sluice PATH]
"""
import math
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from runs import ROOT, case_parser, read_body, run_case, save_figure

CASE = "incline_block"


def read_case():
    """g, incline angle and mu from the case file: 'gravity: [gx, 0, gz]' (9.81 m/s^2 at 30
    degrees from the floor's normal) and the block's 'friction: 0.3'."""
    with open(os.path.join(ROOT, "cases", f"{CASE}.yaml")) as f:
        text = f.read()
    gx, _, gz = (float(v) for v in re.search(r"^gravity:\s*\[([^\]]*)\]", text, re.M)
                 .group(1).split(","))
    mu = float(re.search(r"friction:\s*([0-9.eE+-]+)", text).group(1))
    return math.hypot(gx, gz), math.atan2(gx, -gz), mu


def main():
    args = case_parser(CASE, __doc__.splitlines()[0]).parse_args()
    data = read_body(run_case(CASE, args), "block")
    t = data["time"]
    s = data["x"] - data["x"][0]

    g, theta, mu = read_case()
    a = g * (math.sin(theta) - mu * math.cos(theta))
    expected = a * t ** 2 / 2
    error = s[-1] / expected[-1] - 1
    print(f"g = {g:.4f} m/s^2 at {math.degrees(theta):.2f} degrees, mu = {mu}: a = {a:.4f} m/s^2; "
          f"at t = {t[-1]:g} s distance {s[-1]:.5f} m against {expected[-1]:.5f} m "
          f"({100 * error:+.2f} %)")

    fig = plt.figure(figsize=(6.4, 4.4))
    plt.plot(t, s, "-", lw=2.5, color="tab:blue", label="sluice, x(t) - x(0) of the block")
    plt.plot(t, expected, "k--", lw=1.2,
             label=f"g (sin {math.degrees(theta):.0f} - mu cos {math.degrees(theta):.0f}) t^2 / 2")
    plt.xlabel("time [s]")
    plt.ylabel("distance slid down the incline [m]")
    plt.title(f"C3 block on a {math.degrees(theta):.0f} degree incline, mu = {mu:g}")
    plt.text(0.03, 0.80, f"at t = {t[-1]:g} s: {s[-1]:.4f} m against {expected[-1]:.4f} m "
             f"({100 * error:+.2f} %)", transform=plt.gca().transAxes, fontsize=8)
    plt.legend(loc="upper left", fontsize=8)
    plt.grid(alpha=0.3)
    save_figure(fig, "incline_block.png")


if __name__ == "__main__":
    main()
