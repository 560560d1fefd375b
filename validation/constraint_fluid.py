#!/usr/bin/python3
"""F2 of VALIDATION.md with the constraint fluid: runs cases/dam_break_2d.yaml to 0.75 s with the
wcsph, mps and constraint models at spacing 0.025 m and the granular one at 0.05 m, and plots the
surge front of all four against Koshizuka & Oka (1996) into docs/img/f2_constraint_front.png,
printing each model's RMS difference over t in [0, 0.70] s (as validation/dam_break_2d.py), its
wall time and its steps (from sluice's --stats). From the constraint run's frames (one every
0.01 s) it plots the fluid's density error against time into
docs/img/f2_constraint_density_error.png: the largest compression max(rho / rho0 - 1) and the
mean of |rho / rho0 - 1| over the compressed particles (rho > rho0), with the 1 % bar, and prints
the largest compression over all frames.

usage: /usr/bin/python3 validation/constraint_fluid.py [--no-run]
       (--no-run: plot the existing output in out/validation/constraint_f2_*)
"""
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from dam_break_2d import read_reference, rms_error
from frames import frame_series, read_frame
from probes_csv import read_probe
from runs import ROOT, require, save_figure

SLUICE = os.path.join(ROOT, "build", "release", "sluice")
CASE = os.path.join(ROOT, "cases", "dam_break_2d.yaml")
END = 0.75             # simulated time [s]
REST_DENSITY = 1000.0  # the case's fluid density [kg/m^3]
FRAME_INTERVAL = 0.01  # the constraint run's output interval [s]
MODELS = (("wcsph", 0.025, "tab:blue"), ("mps", 0.025, "tab:red"),
          ("constraint", 0.025, "tab:purple"), ("granular", 0.05, "tab:green"))


def out_dir(model, spacing):
    return os.path.join(ROOT, "out", "validation", f"constraint_f2_{model}_{spacing}")


def run(model, spacing, no_run):
    """Runs the case with the model at the spacing (unless no_run); returns the output
    directory and the run's statistics."""
    out = out_dir(model, spacing)
    stats = os.path.join(out, "stats.json")
    if not no_run:
        sets = [f"model.name={model}", f"spacing={spacing}"]
        if model == "constraint":
            sets.append(f"output_interval={FRAME_INTERVAL}")
        command = [SLUICE, "run", CASE, "--out", out, "--end", str(END), "--stats", stats]
        command += [item for s in sets for item in ("--set", s)]
        subprocess.run(command, cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    require(stats)
    with open(stats) as f:
        return out, json.load(f)


def fluid_density_ratio(path):
    """rho / rho0 - 1 of the fluid particles (kind 0) of one .vtp frame."""
    _, fields = read_frame(path, "kind", "density")
    return fields["density"][fields["kind"] == 0] / REST_DENSITY - 1.0


def density_errors(out):
    """Per frame: time, the largest compression and the mean |rho / rho0 - 1| over the
    compressed particles (0 where none is compressed)."""
    rows = []
    for t, path in frame_series(out):
        error = fluid_density_ratio(path)
        compressed = error[error > 0]
        mean = float(np.abs(compressed).mean()) if len(compressed) else 0.0
        rows.append((t, float(error.max()), mean))
    return np.array(rows)


def plot_fronts(results, reference):
    fig = plt.figure(figsize=(6.4, 4.4))
    plt.plot([t for t, _ in reference], [x for _, x in reference], "ko",
             label="experiment (Koshizuka & Oka 1996)")
    for model, spacing, colour, times, fronts, rms in results:
        plt.plot(times, fronts, "-", color=colour,
                 label=f"sluice {model}, dx = {spacing} m (RMS {rms:.2f} m)")
    plt.axvline(0.70, color="0.7", lw=0.8)
    plt.xlabel("time [s]")
    plt.ylabel("surge front x [m]")
    plt.title("F2: 2D dam break, surge front of the four fluid models")
    plt.legend(loc="upper left", fontsize=8)
    plt.grid(alpha=0.3)
    save_figure(fig, "f2_constraint_front.png")


def plot_density_errors(errors, spacing):
    fig = plt.figure(figsize=(6.4, 4.4))
    plt.plot(errors[:, 0], 100 * errors[:, 1], "-", color="tab:purple",
             label="largest compression max(rho/rho0 - 1)")
    plt.plot(errors[:, 0], 100 * errors[:, 2], "-", color="tab:orange",
             label="mean |rho/rho0 - 1| of the compressed particles")
    plt.axhline(1.0, color="k", ls="--", lw=1, label="1 % bar")
    plt.xlabel("time [s]")
    plt.ylabel("density error [%]")
    plt.title(f"F2: constraint fluid's density error, dx = {spacing} m")
    plt.legend(loc="center right", fontsize=8)
    plt.grid(alpha=0.3)
    save_figure(fig, "f2_constraint_density_error.png")


def main():
    no_run = "--no-run" in sys.argv
    reference = read_reference()
    results = []
    constraint_out = None
    for model, spacing, colour in MODELS:
        out, stats = run(model, spacing, no_run)
        times, fronts = read_probe(os.path.join(out, "probes.csv"), "front")
        rms, count = rms_error(times, fronts, reference)
        print(f"{model:10s} dx = {spacing:<6g} m: front RMS {rms:.3f} m over {count} points; "
              f"wall {stats['wall_seconds']:.1f} s, {stats['steps']} steps")
        results.append((model, spacing, colour, times, fronts, rms))
        if model == "constraint":
            constraint_out, constraint_spacing = out, spacing
    plot_fronts(results, reference)
    errors = density_errors(constraint_out)
    worst = int(np.argmax(errors[:, 1]))
    print(f"constraint density error over {len(errors)} frames: largest compression "
          f"{100 * errors[worst, 1]:.3f} % (t = {errors[worst, 0]:.2f} s); largest mean over the "
          f"compressed particles {100 * errors[:, 2].max():.3f} %")
    plot_density_errors(errors, constraint_spacing)


if __name__ == "__main__":
    main()
