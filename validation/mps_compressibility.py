#!/usr/bin/python3
"""Why MPS's F2 front depends on the form of the artificial compressibility (docs/validation.md,
F2): two `sluice sweep`s over alpha, each in the `rate` form (the default, which keeps the
pressure the water holds) and in Ikeda et al.'s form (which forgets it every step), one of the
2D dam break (front at 0.4 s, against the experiment's then) and one of the still tank of F1
(water level and bottom pressure at 2 s). Writes docs/img/f2_mps_compressibility.png.

usage: /usr/bin/python3 validation/mps_compressibility.py [--no-run]
"""
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from runs import ROOT, save_figure

SLUICE = os.path.join(ROOT, "build", "release", "sluice")
ALPHAS = "1e-9,1e-8,1e-7,2e-7,2.55e-7,3e-7"
OUT = os.path.join(ROOT, "out", "validation", "mps_compressibility")


def sweep(case, name, end):
    out = os.path.join(OUT, name)
    if "--no-run" not in sys.argv:
        subprocess.run([SLUICE, "sweep", os.path.join(ROOT, "cases", case), "--out", out,
                        "--end", str(end), "--set", "output_interval=1",
                        "--set", "model.compressibility=" + ALPHAS,
                        "--set", "model.compressibility_form=rate,ikeda"],
                       check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.csv")) as f:
        return list(csv.DictReader(f))


def series(rows, form, column):
    points = [(float(r["model.compressibility"]), float(r[column])) for r in rows
              if r["model.compressibility_form"] == form and r["status"] == "done"]
    return [p[0] for p in sorted(points)], [p[1] for p in sorted(points)]


def experiment_front(t):
    path = os.path.join(ROOT, "validation", "data", "dam_break_front_koshizuka_oka_1996.tsv")
    rows = []
    with open(path) as f:
        for line in f:
            try:
                rows.append(tuple(float(v) for v in line.split()[:2]))
            except ValueError:
                continue
    for (t0, x0), (t1, x1) in zip(rows, rows[1:]):
        if t0 <= t <= t1:
            return x0 + (t - t0) / (t1 - t0) * (x1 - x0)
    raise ValueError(t)


def main():
    dam = sweep("dam_break_2d_mps.yaml", "dam_break", 0.4)
    tank = sweep("hydrostatic_2d_mps.yaml", "still_tank", 2.0)
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    for form, style in (("rate", "o-"), ("ikeda", "s--")):
        label = "rate (default)" if form == "rate" else "Ikeda et al.'s form"
        axes[0].plot(*series(dam, form, "front [m]"), style, label=label)
        axes[1].plot(*series(tank, form, "level [m]"), style, label=label)
        alphas, bottom = series(tank, form, "bottom [Pa]")
        axes[2].plot(alphas, [100 * (p / 9810.0 - 1) for p in bottom], style, label=label)
    axes[0].axhline(experiment_front(0.4), color="k", lw=0.8, label="experiment at 0.4 s")
    axes[1].axhline(1.0, color="k", lw=0.8, label="water depth 1 m")
    axes[2].axhline(0.0, color="k", lw=0.8)
    titles = ("F2: surge front at 0.4 s [m]", "F1: water level at 2 s [m]",
              "F1: bottom pressure at 2 s, % from rho g H")
    for ax, title in zip(axes, titles):
        ax.set_xscale("log")
        ax.set_xlabel("alpha [1/Pa]")
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, "f2_mps_compressibility.png")
    for form in ("rate", "ikeda"):
        a, x = series(dam, form, "front [m]")
        _, level = series(tank, form, "level [m]")
        print(form, "alpha:", a, "front at 0.4 s:", x, "level at 2 s:", level)


if __name__ == "__main__":
    main()
