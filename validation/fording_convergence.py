#!/usr/bin/python3
"""B5 of VALIDATION.md, the fording vehicle (cases/fording.yaml): every model at 0.04 and 0.02 m
(the grid at cells of that size), its drag and lift, the wave at the gauges, its steps and wall
time; one table per spacing, and one of how far each figure moved between the two. Writes the
tables b5-0.04, b5-0.02 and b5-change into docs/validation.md and
docs/img/b5_fording_convergence.png (drag and lift, 0.05 s running means).

Drag and lift are the water's force on the chassis and the four wheels together; a mean is over
every row from 0.5 to 2 s (the carriage's ramp ends at 0.3 s), a peak the largest 0.05 s running
mean over the same span; a wave is the largest rise of a gauge above its start. A run lives in
OUT_MODEL_SPACING (OUT: --out) and goes on from its newest checkpoint with --resume.

usage: /usr/bin/python3 validation/fording_convergence.py [--no-run | --resume] [--out DIR]
           [--runs wcsph@0.04,mps@0.02,...] [--threads N]
"""
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from probes_csv import read_probe
from runs import (ROOT, base_model, build_cell, each_run, keep_results, model_runs_parser,
                  result_path, result_statistics, run_model, save_figure, wall_per_simulated,
                  write_table)

MODELS = ("wcsph", "mps", "penalty-sph", "constraint", "mac", "granular", "mac-prescribed")
# `mac-prescribed` runs the grid with every part carried at the carriage's motion (the wheels do
# not turn), without joints: beside `mac`, whose rolling wheels squeeze the water between them and
# the bed (docs/validation.md, B5).
CARRIED = "{type: constant_velocity, ramp_time: 0.3}"
VARIANTS = {"mac-prescribed": ("mac", ["joints=[]"] + [
    item for b in range(1, 6) for item in (f"bodies.{b}.motion=prescribed",
                                           f"bodies.{b}.velocity=[1.5, 0, 0]",
                                           f"bodies.{b}.prescribed={CARRIED}")])}
SPACINGS = (0.04, 0.02)
RUNS = ",".join(f"{m}@{s:g}" for s in SPACINGS for m in MODELS)
# At the finer spacing a mean drag further than 25 % from the median of these models' asks why
# (issue 39), as does a figure that moves more than 10 % between the spacings (VALIDATION.md's B5).
MEDIAN_OF = ("wcsph", "mps", "penalty-sph", "constraint")
END = 2.0
MEAN_FROM = 0.5
PEAK_WINDOW = 0.05  # s, as sluice compare's peaks
GAUGES = ("gauge_2m", "gauge_3m", "gauge_4m")
COLOURS = {"wcsph": "tab:blue", "mps": "tab:red", "penalty-sph": "tab:orange",
           "constraint": "tab:purple", "granular": "tab:green", "mac": "tab:brown",
           "mac-prescribed": "tab:pink"}
STYLES = {0.04: "-", 0.02: "--", 0.01: ":"}


def run_dir(args, model, spacing):
    return os.path.join(ROOT, f"{args.out}_{model}_{spacing:g}")


def running_mean(t, v, window=PEAK_WINDOW):
    """The mean of v over window seconds centred on each time."""
    cumulative = np.concatenate(([0.0], np.cumsum(v)))
    first = np.searchsorted(t, t - window / 2, side="left")
    last = np.searchsorted(t, t + window / 2, side="right")
    return (cumulative[last] - cumulative[first]) / (last - first)


def figures(out, name):
    """The run's figures (from OUT, or what keep_results kept of run NAME), or None where it
    wrote no loads."""
    path = result_path(out, name, "loads.csv")
    if path is None:
        return None
    loads = np.genfromtxt(path, delimiter=",", names=True)
    t = loads["time"]
    later, window = t > 0, (t >= MEAN_FROM) & (t <= END)
    result = {"reached": float(t[-1]), "time": t[later]}
    for load in ("drag", "lift"):
        v = loads[f"all_bodies_{load}"]
        result[f"{load}_series"] = running_mean(t[later], v[later])
        result[f"mean_{load}"] = v[window].mean() if t[-1] >= END else math.nan
        # Over the same span: before it the vehicle settles and the ramp ends, a transient
        # that is not the fording's.
        result[f"peak_{load}"] = result[f"{load}_series"][window[later]].max() \
            if t[-1] >= MEAN_FROM else math.nan
    for gauge in GAUGES:
        times, heights = read_probe(result_path(out, name, "probes.csv"), gauge)
        result[gauge] = max(heights) - heights[0]
    statistics = result_statistics(out, name) or {}
    result["steps"] = statistics.get("steps", math.nan)
    result["wall"] = wall_per_simulated(statistics, result["reached"], threads=True)
    result["source"] = statistics.get("source_revision")
    result["build"] = build_cell(statistics)
    return result


def cell(value, digits, scale=1.0):
    return "–" if value is None or math.isnan(value) else f"{value * scale:.{digits}f}"


def spacing_table(results, spacing):
    lines = ["| model | reached [s] | mean drag [N] | peak drag [N] | mean lift [N] | peak lift "
             "[N] | wave at 2 / 3 / 4 m [mm] | steps | wall s per simulated s (threads) | build |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for (model, s), f in sorted(results.items(),
                                key=lambda item: MODELS.index(base_model(item[0][0]))):
        if s != spacing:
            continue
        if f is None:
            lines.append(f"| {model} | not run yet | | | | | | | | |")
            continue
        waves = " / ".join(cell(f[g], 0, 1e3) for g in GAUGES)
        lines.append(f"| {model} | {f['reached']:.2f} | {cell(f['mean_drag'], 0)} | "
                     f"{cell(f['peak_drag'], 0)} | {cell(f['mean_lift'], 0)} | "
                     f"{cell(f['peak_lift'], 0)} | {waves} | {cell(f['steps'], 0)} | "
                     f"{f['wall']} | {f['build']} |")
    return "\n".join(lines)


CHANGED = ("mean_drag", "peak_drag", "mean_lift", "peak_lift") + GAUGES


def change_table(results, coarse, fine):
    """Each figure's change from the coarse to the fine run, and at the fine spacing each mean
    drag against the median of MEDIAN_OF's; beyond VALIDATION.md's 10 % and issue 39's 25 % in bold."""
    drags = [results[(m, fine)]["mean_drag"] for m in MEDIAN_OF
             if results.get((m, fine)) and not math.isnan(results[(m, fine)]["mean_drag"])]
    median = float(np.median(drags)) if len(drags) == len(MEDIAN_OF) else math.nan
    lines = [f"| model | mean drag | peak drag | mean lift | peak lift | wave at 2 / 3 / 4 m | "
             f"mean drag at {fine:g} m against the median ({cell(median, 0)} N) | "
             "the two runs' builds |",
             "|---|---|---|---|---|---|---|---|"]

    def percent(value, bar):
        if value is None or math.isnan(value):
            return "–"
        text = f"{100 * value:+.0f} %"
        return f"**{text}**" if abs(value) > bar else text

    for model in MODELS:
        a, b = results.get((model, coarse)), results.get((model, fine))
        if a is None or b is None or min(a["reached"], b["reached"]) < END:
            continue
        moved = {k: (b[k] - a[k]) / abs(a[k]) if a[k] else math.nan for k in CHANGED}
        waves = " / ".join(percent(moved[g], 0.10) for g in GAUGES)
        off = (b["mean_drag"] - median) / median if median else math.nan
        lines.append(f"| {model} | {percent(moved['mean_drag'], 0.10)} | "
                     f"{percent(moved['peak_drag'], 0.10)} | {percent(moved['mean_lift'], 0.10)} | "
                     f"{percent(moved['peak_lift'], 0.10)} | {waves} | {percent(off, 0.25)} | "
                     f"{builds(a, b)} |")
    return "\n".join(lines)


def builds(coarse, fine):
    """Whether a change compares one build with itself: "the same", or both builds, since a
    change between builds is not the spacing's alone."""
    if coarse["source"] and coarse["source"] == fine["source"]:
        return "the same"
    return f"{coarse['build']} / {fine['build']}"


def plot(results):
    fig, axes = plt.subplots(2, 1, figsize=(7.5, 6.5), sharex=True)
    for (model, spacing), f in results.items():
        if f is None:
            continue
        for ax, load in zip(axes, ("drag", "lift")):
            ax.plot(f["time"], f[f"{load}_series"], STYLES.get(spacing, "-"),
                    color=COLOURS[base_model(model)], lw=1.0, label=f"{model}, {spacing:g} m")
    axes[0].set_ylabel("drag [N]")
    axes[1].set_ylabel("lift [N]")
    axes[1].set_xlabel("time [s]")
    axes[0].set_title("B5 fording: the water's force on the vehicle (0.05 s running means)")
    for ax in axes:
        ax.axvline(MEAN_FROM, color="0.7", lw=0.8)
        ax.grid(alpha=0.3)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", fontsize=7, ncol=4)
    save_figure(fig, "b5_fording_convergence.png", rect=(0, 0.02 + 0.02 * math.ceil(
        len(labels) / 4), 1, 1))


def main():
    parser = model_runs_parser("fording", __doc__.splitlines()[0], RUNS)
    args = parser.parse_args()
    results = {}
    for model, spacing in each_run(args.runs):
        out = run_dir(args, model, spacing)
        kept = f"fording/{model}_{spacing:g}"
        if not args.no_run:
            name, extra = VARIANTS.get(model, (model, []))
            run_model("fording", out, name, spacing, END, args, extra)
        keep_results(out, kept, ("loads.csv", "probes.csv"))
        results[(model, spacing)] = figures(out, kept)
    # The tables hold every model at every spacing: the runs not asked for this time come from
    # their run directories or kept results, so that a run of one model does not shrink a table
    # to one row. A run not started yet is a row that says so; one under way, a row with the time
    # it reached and no means (they are over 0.5-2 s).
    for model, spacing in each_run(RUNS):
        if (model, spacing) not in results:
            results[(model, spacing)] = figures(run_dir(args, model, spacing),
                                                f"fording/{model}_{spacing:g}")
    for (model, spacing), f in results.items():
        if f is None or f["reached"] < END:
            print(f"{model}@{spacing:g}: " + ("not run" if f is None else
                                              f"reached {f['reached']:.2f} s of {END:g}"))
    for spacing in SPACINGS:
        write_table("validation.md", f"b5-{spacing:g}", spacing_table(results, spacing))
    write_table("validation.md", "b5-change", change_table(results, SPACINGS[0], SPACINGS[1]))
    plot(results)

if __name__ == "__main__":
    main()
