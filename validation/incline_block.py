#!/usr/bin/python3
"""C3 of VALIDATION.md: a 0.1 m cube sliding on a 30 degree incline with mu = 0.3
(cases/incline_block.yaml, the incline made by tilting gravity). Compares the distance slid
with g (sin theta - mu cos theta) t^2 / 2 and writes docs/img/incline_block.png.

usage: /usr/bin/python3 validation/incline_block.py [--out DIR] [--no-run] [--sluice PATH]
"""
import argparse
import math
import os
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASE = os.path.join("cases", "incline_block.yaml")


def read_case():
    """g, incline angle and mu from the case file: 'gravity: [gx, 0, gz]' (9.81 m/s^2 at 30
    degrees from the floor's normal) and the block's 'friction: 0.3'."""
    with open(os.path.join(ROOT, CASE)) as f:
        text = f.read()
    gx, _, gz = (float(v) for v in re.search(r"^gravity:\s*\[([^\]]*)\]", text, re.M)
                 .group(1).split(","))
    mu = float(re.search(r"friction:\s*([0-9.eE+-]+)", text).group(1))
    return math.hypot(gx, gz), math.atan2(gx, -gz), mu


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join("out", "incline_block"), help="run directory")
    parser.add_argument("--no-run", action="store_true", help="use the existing output in --out")
    parser.add_argument("--sluice", default=os.path.join("build", "release", "sluice"))
    args = parser.parse_args()
    out = os.path.join(ROOT, args.out)
    if not args.no_run:
        subprocess.run([os.path.join(ROOT, args.sluice), "run", CASE, "--out", out], cwd=ROOT,
                       check=True, stdout=subprocess.DEVNULL)
    path = os.path.join(out, "bodies", "block.csv")
    if not os.path.exists(path):
        sys.exit(f"incline_block.py: {path} is missing")
    data = np.genfromtxt(path, delimiter=",", names=True)
    t = data["time"]
    s = data["x"] - data["x"][0]

    g, theta, mu = read_case()
    a = g * (math.sin(theta) - mu * math.cos(theta))
    expected = a * t ** 2 / 2
    error = s[-1] / expected[-1] - 1
    print(f"g = {g:.4f} m/s^2 at {math.degrees(theta):.2f} degrees, mu = {mu}: a = {a:.4f} m/s^2; "
          f"at t = {t[-1]:g} s distance {s[-1]:.5f} m against {expected[-1]:.5f} m "
          f"({100 * error:+.2f} %)")

    plt.figure(figsize=(6.4, 4.4))
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
    plt.tight_layout()
    png = os.path.join(ROOT, "docs", "img", "incline_block.png")
    plt.savefig(png, dpi=120)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
