#!/usr/bin/python3
"""Why MPS's F2 front depends on the form of the artificial compressibility (docs/validation.md,
F2): runs the 2D dam break (cases/dam_break_2d_mps.yaml, to 0.75 s) and the still tank of F1
(cases/hydrostatic_2d_mps.yaml, to 2 s) over alpha, each in the `rate` form (the default, which
keeps the pressure the water holds) and in Ikeda et al.'s form (which forgets it every step).
Writes the table mps-compressibility into docs/validation.md (the front's RMS difference from
the experiment over [0, 0.70] s at 0.025 m and, for the rows the text discusses, 0.0125 m; the
tank's bottom pressure and level, means over 1.9-2 s) and docs/img/f2_mps_compressibility.png
(the front at 0.4 s, the tank's level and bottom pressure, against alpha).

usage: /usr/bin/python3 validation/mps_compressibility.py [--no-run]
"""
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from dam_break_2d import interpolate, read_reference, rms_error
from probes_csv import read_probe
from runs import ROOT, save_figure, write_table

SLUICE = os.path.join(ROOT, "build", "release", "sluice")
OUT = os.path.join(ROOT, "out", "validation", "mps_compressibility")
WATER = 4.5e-10  # 1/Pa, water's own compressibility: the model's default
ALPHAS = (WATER, 1e-9, 1e-8, 1e-7, 2e-7, 2.55e-7, 3e-7, 1e-6)
# The rows of the table: (form, alpha, also at half the spacing), and what each alpha is.
ROWS = (("rate", WATER, True), ("rate", 2.55e-7, True), ("ikeda", 2.55e-7, True),
        ("ikeda", 2e-7, False), ("ikeda", 3e-7, False), ("ikeda", 1e-6, False))
NAMES = {WATER: "(water)", 2.55e-7: "(c = 10 sqrt(2 g H), as `wcsph`)"}
RHO_G_H = 1000 * 9.81 * 1.0  # the still tank's bottom pressure [Pa]


def run(case, form, alpha, spacing, end):
    out = os.path.join(OUT, f"{case}_{form}_{alpha:g}_{spacing:g}")
    if "--no-run" not in sys.argv:
        # A run whose water leaks through the floor stops (exit 3) and keeps what it wrote.
        subprocess.run([SLUICE, "run", os.path.join(ROOT, "cases", case + ".yaml"), "--out", out,
                        "--end", f"{end:g}", "--set", f"spacing={spacing}", "--set",
                        "output_interval=1", "--set", f"model.compressibility={alpha}",
                        "--set", f"model.compressibility_form={form}"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return out


def front(form, alpha, spacing):
    """(times, fronts) of the dam break, and the time it reached."""
    times, fronts = read_probe(os.path.join(run("dam_break_2d_mps", form, alpha, spacing, 0.75),
                                            "probes.csv"), "front")
    return times, fronts, times[-1]


def still_tank(form, alpha):
    """The tank's bottom pressure and level, means over 1.9-2 s, and at 2 s."""
    out = os.path.join(run("hydrostatic_2d_mps", form, alpha, 0.025, 2.0), "probes.csv")
    figures = {}
    for name in ("bottom", "level"):
        times, values = read_probe(out, name)
        late = [v for t, v in zip(times, values) if t >= 1.9 - 1e-9]
        figures[name] = sum(late) / len(late) if times[-1] >= 2.0 - 1e-9 else math.nan
        figures[name + " at 2 s"] = values[-1] if times[-1] >= 2.0 - 1e-9 else math.nan
    return figures


def front_rms(form, alpha, spacing, reference):
    times, fronts, reached = front(form, alpha, spacing)
    if reached < 0.70:
        return f"stops at {reached:.2f} s"
    return f"{rms_error(times, fronts, reference)[0]:.3f}"


def main():
    reference = read_reference()
    lines = ["| form, alpha [1/Pa] | F2 front RMS, dx 0.025 / 0.0125 m [m] | F1 (still tank 1 m "
             "deep, 0.025 m), 1.9-2 s: bottom against rho g H, level [m] |", "|---|---|---|"]
    for form, alpha, finer in ROWS:
        rms = front_rms(form, alpha, 0.025, reference)
        if finer:
            rms += " / " + front_rms(form, alpha, 0.0125, reference)
        tank = still_tank(form, alpha)
        bottom = "–" if math.isnan(tank["bottom"]) else \
            f"{100 * (tank['bottom'] / RHO_G_H - 1):+.1f} %, {tank['level']:.3f}"
        default = ", the default" if (form, alpha) == ("rate", WATER) else ""
        name = f"{alpha:g} {NAMES.get(alpha, '')}".strip()
        lines.append(f"| `{form}`{default}, {name} | {rms} | {bottom} |")
    write_table("validation.md", "mps-compressibility", "\n".join(lines))

    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    for form, style in (("rate", "o-"), ("ikeda", "s--")):
        label = "rate (default)" if form == "rate" else "Ikeda et al.'s form"
        at_04, levels, bottoms, alphas = [], [], [], []
        for alpha in ALPHAS:
            times, fronts, reached = front(form, alpha, 0.025)
            tank = still_tank(form, alpha)
            if reached < 0.4 or math.isnan(tank["level at 2 s"]):
                continue
            alphas.append(alpha)
            at_04.append(interpolate(times, fronts, 0.4))
            levels.append(tank["level at 2 s"])
            bottoms.append(100 * (tank["bottom at 2 s"] / RHO_G_H - 1))
        axes[0].plot(alphas, at_04, style, label=label)
        axes[1].plot(alphas, levels, style, label=label)
        axes[2].plot(alphas, bottoms, style, label=label)
    axes[0].axhline(interpolate(*zip(*reference), 0.4), color="k", lw=0.8,
                    label="experiment at 0.4 s")
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
    save_figure(fig, "f2_mps_compressibility.png")


if __name__ == "__main__":
    main()
