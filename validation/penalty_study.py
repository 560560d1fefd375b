#!/usr/bin/python3
"""B4 of VALIDATION.md: seed 002's study of the penalty stiffness Ks against the spacing ratio.
Runs `sluice sweep` over Ks = 5e3, 5e4, 1e5 N/m for the three cases (rain on concrete, ratio
0.20; water on concrete, 0.61; water on a granular bed, 4.902), writes the table of the share
held back and the boundary forces beside the paper's shares into docs/validation.md (table b4),
and draws docs/img/b4_penalty_study.png. Each case's sweep summary is kept in
validation/results/penalty_study/, which --no-run reads where the sweep's directory is gone.

usage: /usr/bin/python3 validation/penalty_study.py [--no-run]
"""
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from runs import ROOT, keep_results, open_text, result_path, save_figure, write_table

SLUICE = os.path.join(ROOT, "build", "release", "sluice")
STIFFNESSES = "5e3,5e4,1e5"
OUT = os.path.join(ROOT, "out", "validation", "penalty_study")
MODELS = [  # case, label, spacing ratio, the paper's shares held back (Ks: share)
    ("seed002_rain_concrete", "model 1: rain on concrete", "0.20", {5e3: 0.0, 5e4: 0.76}),
    ("seed002_water_concrete", "model 2: water on concrete", "0.61", {5e3: 0.0, 5e4: 0.9968}),
    ("seed002_water_granular", "model 3: water on a granular bed", "4.902",
     {5e3: 0.0, 5e4: 1.0, 1e5: 1.0}),
]


def sweep(case):
    out = os.path.join(OUT, case)
    if "--no-run" not in sys.argv:
        subprocess.run([SLUICE, "sweep", os.path.join(ROOT, "cases", case + ".yaml"), "--out",
                        out, "--jobs", "1", "--set", "output_interval=5",
                        "--set", "model.Ks=" + STIFFNESSES],
                       check=True, stdout=subprocess.DEVNULL)
    name = os.path.join("penalty_study", case)
    keep_results(out, name, ("summary.csv",))
    path = result_path(out, name, "summary.csv")
    if path is None:
        sys.exit(f"penalty_study.py: no sweep of {case} in {out} and none kept: run without "
                 "--no-run")
    with open_text(path) as f:
        return [r for r in csv.DictReader(f) if r["status"] == "done"]


def main():
    figure, (held, force) = plt.subplots(1, 2, figsize=(11, 4.2))
    lines = ["| model | spacing ratio | Ks [N/m] | held back (sluice) | held back (paper) "
             "| mean boundary force [N] | peak boundary force [N] | wall time [s] |",
             "|---|---|---|---|---|---|---|---|"]
    for (case, label, ratio, paper), colour in zip(MODELS, ["C0", "C1", "C2"]):
        rows = sweep(case)
        ks = [float(r["model.Ks"]) for r in rows]
        share = [float(r["held_back_fraction"]) for r in rows]
        mean = [float(r["mean_boundary_force"]) for r in rows]
        for r, k, s, m in zip(rows, ks, share, mean):
            reported = f"{100 * paper[k]:.2f} %" if k in paper else "–"
            stiffness = f"{k:.0e}".replace("e+0", "e")
            lines.append(f"| {label} | {ratio} | {stiffness} | {100 * s:.2f} % | {reported} | "
                         f"{m:.3g} | {float(r['peak_boundary_force']):.3g} | "
                         f"{float(r['wall_seconds']):.1f} |")
        held.plot(ks, [100 * s for s in share], "o-", color=colour, label=label + " (sluice)")
        held.plot(list(paper), [100 * s for s in paper.values()], "x--", color=colour,
                  label=label + " (paper)")
        force.plot(ks, mean, "o-", color=colour, label=label)
    write_table("validation.md", "b4", "\n".join(lines))
    held.set_xscale("log")
    held.set_xlabel("Ks [N/m]")
    held.set_ylabel("fluid particles held back [%]")
    held.set_ylim(-5, 105)
    held.legend(fontsize=7)
    force.set_xscale("log")
    force.set_yscale("log")
    force.set_xlabel("Ks [N/m]")
    force.set_ylabel("mean boundary force per particle in contact [N]")
    force.legend(fontsize=7)
    figure.suptitle("B4: seed 002's penalty boundary, share held back and force against Ks")
    save_figure(figure, "b4_penalty_study.png")


if __name__ == "__main__":
    main()
