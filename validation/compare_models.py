#!/usr/bin/python3
"""Every fluid model on one case, side by side (issue 14): runs `sluice compare` on
  - F2, cases/dam_break_2d.yaml to 0.75 s: the surge front's RMS difference from Koshizuka &
    Oka (1996) over t in [0, 0.70] s;
  - B1, cases/floating_box_2d.yaml: the box's mean draft over the last 4 s against
    Archimedes' 0.70 m (from the water's area, as validation/floating_box_2d.py);
and writes one table per case into docs/validation.md (compare-f2, compare-b1), and
docs/img/f2_all_models_front.png; what the figures come from is kept in
validation/results/compare_f2/ and compare_b1/. (B5, the fording vehicle, is
validation/fording_convergence.py's: every model at two spacings.)

usage: /usr/bin/python3 validation/compare_models.py [--no-run] [--only f2,b1]
"""
import argparse
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from dam_break_2d import read_reference, rms_error
from probes_csv import read_probe
from runs import ROOT, keep_results, open_text, result_path, save_figure, write_table

SLUICE = os.path.join(ROOT, "build", "release", "sluice")
CASES = {"f2": ("dam_break_2d", ["--end", "0.75"]), "b1": ("floating_box_2d", [])}


def out_dir(key):
    return os.path.join(ROOT, "out", "validation", f"compare_{key}")


# What each comparison keeps in validation/results/compare_KEY/ (keep_results): its table and,
# of each model's run, the files its figures come from; --no-run reads them where the runs are gone.
KEPT = {"f2": ("probes.csv",), "b1": ("bodies/box.csv", "energy.csv")}


def kept_file(key, model, filename):
    """A model's file of comparison KEY from its run, or its kept copy; OSError where neither."""
    path = result_path(os.path.join(out_dir(key), model), f"compare_{key}/{model}", filename)
    if path is None:
        raise OSError(f"no {filename} of {model}'s {key} run: run compare_models.py")
    return path


def keep(key):
    """Keeps the comparison's table and, of each model's run that finished, its KEPT files."""
    keep_results(out_dir(key), f"compare_{key}", ("compare.csv",))
    for row in read_table(key):
        if row["status"] == "done":
            keep_results(os.path.join(out_dir(key), row["model"]), f"compare_{key}/{row['model']}",
                         KEPT[key])


def read_table(key):
    path = result_path(out_dir(key), f"compare_{key}", "compare.csv")
    if path is None:
        sys.exit(f"compare_models.py: no table of {key} in {out_dir(key)}: run it (without "
                 "--no-run)")
    with open_text(path) as f:
        return list(csv.DictReader(f))


def number(row, column, digits):
    value = row.get(column, "")
    return f"{float(value):.{digits}f}" if value else "–"


def f2_table_and_plot(rows):
    reference = read_reference()
    fig, ax = plt.subplots(figsize=(6.5, 4.3))
    ax.plot(*zip(*reference), "ko", label="experiment (Koshizuka & Oka 1996)")
    lines = ["| model | settings | fluid | front RMS [m] | steps | wall s per simulated s |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        rms = "–"
        if r["status"] == "done":
            times, fronts = read_probe(kept_file("f2", r["model"], "probes.csv"), "front")
            rms = f"{rms_error(times, fronts, reference)[0]:.3f}"
            ax.plot(times, fronts, label=f"{r['model']} (RMS {rms} m)", linewidth=1.2)
        lines.append(f"| {r['model']} | {r['settings']} | {r['fluid'] or r['status']} | {rms} | "
                     f"{number(r, 'steps', 0)} | {number(r, 'wall per simulated s', 1)} |")
    write_table("validation.md", "compare-f2", "\n".join(lines))
    ax.axvline(0.70, color="0.7", linewidth=0.8)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("surge front x [m]")
    ax.set_title("F2: every model's surge front (sluice compare)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    save_figure(fig, "f2_all_models_front.png")


def b1_draft(model):
    """The box's mean draft over the last 4 s of MODEL's B1 run [m], from the water's area."""
    box = np.genfromtxt(kept_file("b1", model, "bodies/box.csv"), delimiter=",", names=True)
    energy = np.genfromtxt(kept_file("b1", model, "energy.csv"), delimiter=",", names=True)
    area = energy["fluid_mass"][0] / 1000.0
    last = box["time"] > box["time"][-1] - 4.0
    return float(((area / 3 - box["z"][last] + 0.5) / (1 - 1 / 3)).mean())


def b1_table(rows):
    lines = ["| model | fluid | mean draft [m] | error against Archimedes | steps | "
             "wall s per simulated s |", "|---|---|---|---|---|---|"]
    for r in rows:
        draft, error = "–", "–"
        if r["status"] == "done":
            d = b1_draft(r["model"])
            draft, error = f"{d:.4f}", f"{100 * (d - 0.7) / 0.7:+.2f} %"
        lines.append(f"| {r['model']} | {r['fluid'] or r['status']} | {draft} | {error} | "
                     f"{number(r, 'steps', 0)} | {number(r, 'wall per simulated s', 1)} |")
    write_table("validation.md", "compare-b1", "\n".join(lines))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-run", action="store_true", help="use the existing output")
    parser.add_argument("--only", default="f2,b1", help="which comparisons")
    args = parser.parse_args()
    for key in args.only.split(","):
        case, extra = CASES[key]
        if not args.no_run:
            subprocess.run([SLUICE, "compare", os.path.join(ROOT, "cases", f"{case}.yaml"),
                            "--out", out_dir(key)] + extra, check=False)
            keep(key)
        rows = read_table(key)
        if key == "f2":
            f2_table_and_plot(rows)
        else:
            b1_table(rows)


if __name__ == "__main__":
    main()
