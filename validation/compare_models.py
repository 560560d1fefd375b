#!/usr/bin/python3
"""Every fluid model on one case, side by side (issue 14): runs `sluice compare` on
  - B5, cases/fording.yaml: the vehicle's drag and lift, the gauges beside its path;
  - F2, cases/dam_break_2d.yaml to 0.75 s: the surge front's RMS difference from Koshizuka &
    Oka (1996) over t in [0, 0.70] s;
  - B1, cases/floating_box_2d.yaml: the box's mean draft over the last 4 s against
    Archimedes' 0.70 m (from the water's area, as validation/floating_box_2d.py);
and prints one Markdown table per case for docs/validation.md. Writes
docs/img/b5_fording_forces.png (drag and lift, 0.05 s running means) and
docs/img/f2_all_models_front.png.

usage: /usr/bin/python3 validation/compare_models.py [--no-run] [--only fording,f2,b1]
"""
import argparse
import csv
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from dam_break_2d import read_reference, rms_error
from probes_csv import read_probe
from runs import ROOT, save_figure

SLUICE = os.path.join(ROOT, "build", "release", "sluice")
CASES = {"fording": ("fording", []), "f2": ("dam_break_2d", ["--end", "0.75"]),
         "b1": ("floating_box_2d", [])}


def out_dir(key):
    return os.path.join(ROOT, "out", "validation", f"compare_{key}")


def read_table(key):
    with open(os.path.join(out_dir(key), "compare.csv")) as f:
        return list(csv.DictReader(f))


def number(row, column, digits):
    value = row.get(column, "")
    return f"{float(value):.{digits}f}" if value else "–"


def fording_table(rows):
    print("| model | fluid | mean drag [N] | peak drag [N] | mean lift [N] | peak lift [N] | "
          "wave at 2 / 3 / 4 m [mm] | steps | wall s per simulated s |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        waves = " / ".join(number({"v": str(1e3 * float(r[f"gauge_{x}m rise [m]"]))}, "v", 0)
                           if r.get(f"gauge_{x}m rise [m]") else "–" for x in (2, 3, 4))
        print(f"| {r['model']} | {r['fluid'] or r['status']} | {number(r, 'mean drag [N]', 0)} | "
              f"{number(r, 'peak drag [N]', 0)} | {number(r, 'mean lift [N]', 0)} | "
              f"{number(r, 'peak lift [N]', 0)} | {waves} | {number(r, 'steps', 0)} | "
              f"{number(r, 'wall per simulated s', 0)} |")


def running_mean(t, v, window=0.05):
    return np.array([v[np.abs(t - s) <= window / 2].mean() for s in t])


def fording_plot(rows):
    fig, axes = plt.subplots(2, 1, figsize=(7.5, 6.0), sharex=True)
    for r in rows:
        path = os.path.join(out_dir("fording"), r["model"], "loads.csv")
        if r["status"] != "done" or not os.path.exists(path):
            continue
        d = np.genfromtxt(path, delimiter=",", names=True)
        t = d["time"]
        for ax, column in zip(axes, ("all_bodies_drag", "all_bodies_lift")):
            ax.plot(t[1:], running_mean(t[1:], d[column][1:]), label=r["model"], linewidth=1.2)
    axes[0].set_ylabel("drag [N]")
    axes[1].set_ylabel("lift [N]")
    axes[1].set_xlabel("time [s]")
    axes[0].set_title("B5 fording: the fluid's force on the vehicle (0.05 s running means)")
    axes[0].legend(fontsize=8, ncol=3)
    for ax in axes:
        ax.grid(alpha=0.3)
    save_figure(fig, "b5_fording_forces.png")


def f2_table_and_plot(rows):
    reference = read_reference()
    fig, ax = plt.subplots(figsize=(6.5, 4.3))
    ax.plot(*zip(*reference), "ko", label="experiment (Koshizuka & Oka 1996)")
    print("| model | settings | fluid | front RMS [m] | steps | wall s per simulated s |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        rms = "–"
        if r["status"] == "done":
            times, fronts = read_probe(os.path.join(out_dir("f2"), r["model"], "probes.csv"),
                                       "front")
            rms = f"{rms_error(times, fronts, reference)[0]:.3f}"
            ax.plot(times, fronts, label=f"{r['model']} (RMS {rms} m)", linewidth=1.2)
        print(f"| {r['model']} | {r['settings']} | {r['fluid'] or r['status']} | {rms} | "
              f"{number(r, 'steps', 0)} | {number(r, 'wall per simulated s', 1)} |")
    ax.axvline(0.70, color="0.7", linewidth=0.8)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("surge front x [m]")
    ax.set_title("F2: every model's surge front (sluice compare)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    save_figure(fig, "f2_all_models_front.png")


def b1_table(rows):
    print("| model | fluid | mean draft [m] | error against Archimedes | steps | "
          "wall s per simulated s |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        draft, error = "–", "–"
        run = os.path.join(out_dir("b1"), r["model"])
        if r["status"] == "done":
            box = np.genfromtxt(os.path.join(run, "bodies", "box.csv"), delimiter=",", names=True)
            energy = np.genfromtxt(os.path.join(run, "energy.csv"), delimiter=",", names=True)
            area = energy["fluid_mass"][0] / 1000.0
            last = box["time"] > box["time"][-1] - 4.0
            d = ((area / 3 - box["z"][last] + 0.5) / (1 - 1 / 3)).mean()
            draft, error = f"{d:.4f}", f"{100 * (d - 0.7) / 0.7:+.2f} %"
        print(f"| {r['model']} | {r['fluid'] or r['status']} | {draft} | {error} | "
              f"{number(r, 'steps', 0)} | {number(r, 'wall per simulated s', 1)} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-run", action="store_true", help="use the existing output")
    parser.add_argument("--only", default="fording,f2,b1", help="which comparisons")
    args = parser.parse_args()
    for key in args.only.split(","):
        case, extra = CASES[key]
        if not args.no_run:
            subprocess.run([SLUICE, "compare", os.path.join(ROOT, "cases", f"{case}.yaml"),
                            "--out", out_dir(key)] + extra, check=False)
        rows = read_table(key)
        print(f"\n{key}:\n")
        if key == "fording":
            fording_table(rows)
            fording_plot(rows)
        elif key == "f2":
            f2_table_and_plot(rows)
        else:
            b1_table(rows)


if __name__ == "__main__":
    main()
