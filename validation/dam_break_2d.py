#!/usr/bin/python3
"""F2 of VALIDATION.md: runs cases/dam_break_2d.yaml to 0.75 s with every model at its CI spacing
and at half of it, and measures the surge front against Koshizuka & Oka (1996) twice over t in
[0, 0.70] s: (a) the RMS difference as it is, and (b) the RMS with the experiment's clock shifted
by the one delay d in [0, 0.08] s that fits best (least squares over d in 1 ms steps), since no
model lifts the experiment's gate. Writes the F2 table into docs/validation.md and the fronts to
docs/img/f2_dam_break_front.png. Each run's probes and statistics are kept in
validation/results/dam_break_2d/, which --no-run reads where the run's directory is gone.

usage: /usr/bin/python3 validation/dam_break_2d.py [--no-run] [--runs wcsph@0.025,mps@0.0125,...]
"""
import argparse
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from probes_csv import read_probe
from runs import (ROOT, each_run, keep_results, result_path, result_statistics, runs_to_tabulate,
                  save_figure, write_table)

SLUICE = os.path.join(ROOT, "build", "release", "sluice")
REFERENCE = os.path.join(ROOT, "validation", "data", "dam_break_front_koshizuka_oka_1996.tsv")
# Each model at the spacing its CI checks use, and at half of it.
RUNS = ("wcsph@0.025,wcsph@0.0125,mps@0.025,mps@0.0125,penalty-sph@0.025,penalty-sph@0.0125,"
        "constraint@0.05,constraint@0.025,granular@0.05,granular@0.025,mac@0.05,mac@0.025")
COLOURS = {"wcsph": "tab:blue", "mps": "tab:red", "penalty-sph": "tab:orange",
           "constraint": "tab:purple", "granular": "tab:green", "mac": "tab:brown"}
LONGEST_DELAY = 0.08  # s


def read_reference():
    rows = []
    with open(REFERENCE) as f:
        for line in f:
            parts = line.split()
            try:
                rows.append((float(parts[0]), float(parts[1])))
            except (ValueError, IndexError):
                continue
    return rows


def out_dir(model, spacing):
    return os.path.join(ROOT, "out", "validation", f"dam_break_2d_{model}_{spacing:g}")


def kept_name(model, spacing):
    """The run's name in validation/results (keep_results)."""
    return f"dam_break_2d/{model}_{spacing:g}"


def probes_path(model, spacing):
    """The run's probes.csv, or its kept copy, or None."""
    return result_path(out_dir(model, spacing), kept_name(model, spacing), "probes.csv")


def run(model, spacing):
    out = out_dir(model, spacing)
    subprocess.run([SLUICE, "run", os.path.join(ROOT, "cases", "dam_break_2d.yaml"), "--out", out,
                    "--end", "0.75", "--set", f"spacing={spacing}", "--set",
                    f"model.name={model}", "--stats", os.path.join(out, "stats.json")],
                   check=True, stdout=subprocess.DEVNULL)


def interpolate(times, values, t):
    for k in range(1, len(times)):
        if times[k] >= t:
            w = (t - times[k - 1]) / (times[k] - times[k - 1])
            return values[k - 1] + w * (values[k] - values[k - 1])
    return values[-1]


def rms_error(times, fronts, reference, delay=0.0):
    """RMS of the front against the experiment's at its times up to 0.70 s, the experiment's
    clock started `delay` later; and the number of points."""
    errors = [interpolate(times, fronts, max(t - delay, 0.0)) - x for t, x in reference
              if t <= 0.70]
    return math.sqrt(sum(e * e for e in errors) / len(errors)), len(errors)


def best_delay(times, fronts, reference):
    """(RMS, d) at the delay d in [0, 0.08] s, in 1 ms steps, that fits best."""
    steps = round(LONGEST_DELAY / 0.001)
    return min((rms_error(times, fronts, reference, 0.001 * k)[0], 0.001 * k)
               for k in range(steps + 1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-run", action="store_true",
                        help="use the runs in out/validation or their kept results")
    parser.add_argument("--runs", default=RUNS, help="MODEL@SPACING,...")
    args = parser.parse_args()
    reference = read_reference()
    fig = plt.figure(figsize=(7.5, 5))
    plt.plot([t for t, _ in reference], [x for _, x in reference], "ko",
             label="experiment (Koshizuka & Oka 1996)")
    lines = ["| model | spacing [m] | (a) RMS as measured [m] | (b) RMS, experiment delayed "
             "[m] | fitted delay [s] | wall s per simulated s |", "|---|---|---|---|---|---|"]
    coarse = {}
    for item in runs_to_tabulate(args.runs, RUNS):
        [(model, spacing)] = each_run(item)
        out = out_dir(model, spacing)
        if not args.no_run and item in args.runs.split(","):
            run(model, spacing)
            keep_results(out, kept_name(model, spacing))
        path = probes_path(model, spacing)
        if path is None:
            sys.exit(f"dam_break_2d.py: no run of {model} at {spacing:g} m: run it (without "
                     "--no-run)")
        times, fronts = read_probe(path, "front")
        rms, _ = rms_error(times, fronts, reference)
        shifted, delay = best_delay(times, fronts, reference)
        wall = result_statistics(out, kept_name(model, spacing))["wall_per_simulated_second"]
        lines.append(f"| `{model}` | {spacing:g} | {rms:.3f} | {shifted:.3f} | {delay:.3f} | "
                     f"{wall:.0f} |")
        finer = model in coarse
        coarse.setdefault(model, spacing)
        plt.plot(times, fronts, "--" if finer else "-", color=COLOURS.get(model), lw=0.9,
                 label=f"{model}, {spacing:g} m")
    write_table("validation.md", "f2", "\n".join(lines))
    plt.axvline(0.70, color="0.7", lw=0.8)
    plt.xlim(0, 0.75)
    plt.xlabel("time [s]")
    plt.ylabel("surge front x [m]")
    plt.title("F2: 2D dam break, column 1 m x 2 m, every model at two spacings")
    plt.legend(loc="upper left", fontsize=7, ncol=2)
    plt.grid(alpha=0.3)
    save_figure(fig, "f2_dam_break_front.png")


if __name__ == "__main__":
    main()
