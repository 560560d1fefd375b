#!/usr/bin/python3
"""F3 of VALIDATION.md: the Kleefsman et al. (2005) 3D dam break with an obstacle
(cases/kleefsman_3d.yaml), run with each model and spacing to 6 s, against the experiment and
beside seed 000's MPS at the same particle distance. Writes the F3 table into docs/validation.md,
docs/img/f3_kleefsman_gauges.png (the four gauges) and docs/img/f3_kleefsman_pressure.png (P1-P4,
5 ms running means). The figures' definitions are in kleefsman_figures.py.

A run is MODEL@SPACING and lives in OUT_MODEL_SPACING (OUT: --out). A run that stopped before
6 s is measured over the span it reached (seed 000 over the same span) and says so; a long run
goes on with --resume (sluice run --resume, from its newest checkpoint).

usage: /usr/bin/python3 validation/kleefsman_3d.py [--no-run | --resume] [--out DIR]
           [--runs wcsph@0.03,mps@0.03,...] [--threads N]
"""
import json
import math
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import kleefsman_figures as f3
import matplotlib.pyplot as plt
from runs import ROOT, case_parser, save_figure, write_table

# Every model at 0.03 m; mac's cells must tile the 3.22 m x 1 m tank, so its coarse run is at
# 0.02 m, the nearest that does. wcsph and mps also at 0.015 m.
RUNS = ("wcsph@0.03,mps@0.03,penalty-sph@0.03,constraint@0.03,granular@0.03,mac@0.02,"
        "wcsph@0.015,mps@0.015")
COLOURS = {"wcsph": "tab:blue", "mps": "tab:red", "penalty-sph": "tab:orange",
           "constraint": "tab:purple", "granular": "tab:green", "mac": "tab:brown"}
STYLES = {0.03: "-", 0.02: "-", 0.015: "--", 0.01: ":", 0.0075: ":"}
END = 6.0


def run_dir(args, model, spacing):
    return os.path.join(ROOT, f"{args.out}_{model}_{spacing:g}")


def run(args, model, spacing):
    out = run_dir(args, model, spacing)
    command = [os.path.join(ROOT, args.sluice), "run", os.path.join(ROOT, "cases",
                                                                      "kleefsman_3d.yaml")]
    if args.resume and os.path.isdir(os.path.join(out, "checkpoints")):
        command += ["--resume", out]
    else:
        command += ["--out", out, "--set", f"model.name={model}", "--set", f"spacing={spacing}"]
    command += ["--stats", os.path.join(out, "stats.json")]
    if args.threads:
        command += ["--threads", str(args.threads)]
    # A run that diverges (exit 3) keeps what it wrote; the table says how far it got.
    subprocess.run(command, cwd=ROOT, stdout=subprocess.DEVNULL)


def wall_per_simulated_second(out):
    """From the run's --stats (a resumed run's covers its last leg), or None."""
    path = os.path.join(out, "stats.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f).get("wall_seconds_per_simulated_second")


def cell(value, digits, scale=1.0):
    return "–" if value is None or math.isnan(value) else f"{value * scale:.{digits}f}"


def row(name, figures, reached, extra=""):
    wet = " / ".join(cell(figures.get(f"wet_{g}"), 3) for g in reversed(f3.DOWNSTREAM))
    gauges = " / ".join(cell(figures.get(f"rms_{g}"), 3) for g in reversed(f3.GAUGES[:3]))
    pressures = " / ".join(cell(figures[f"rms_{s}"], 0) for s in f3.SENSORS[:4])
    return (f"| {name} | {reached} | {wet} | {gauges} | {cell(figures.get('rms_g2638'), 3)} | "
            f"{cell(figures['p1_rise'], 3)} | {cell(figures['p1_peak'], 1, 1e-3)} | "
            f"{cell(figures['p1_impulse'], 0)} | {pressures} | {extra} |")


def table(results, experiment):
    lines = [
        "| run | to [s] | first wet at x = 1.488 / 0.992 / 0.496 m [s] | height RMS there [m] | "
        "reservoir (2.638 m) height RMS [m] | P1 rise [s] | P1 peak [kPa] | P1 impulse "
        "0.35-0.6 s [Pa s] | P1 / P2 / P3 / P4 RMS [Pa] | wall s per simulated s |",
        "|---|---|---|---|---|---|---|---|---|---|",
        row("experiment (Kleefsman et al. 2005)", f3.figures(experiment, experiment, (0, END)),
            f"{END:g}")]
    seeds_shown = set()
    for (model, spacing), (series, span, wall) in results.items():
        seed = f3.seed000(spacing)
        if seed is not None and (spacing, span) not in seeds_shown:
            seeds_shown.add((spacing, span))
            lines.append(row(f"seed 000's MPS, l0 = {spacing:g} m",
                             f3.figures(seed, experiment, span), f"{span[1]:g}"))
        if series is None:
            lines.append(f"| sluice `{model}`, {spacing:g} m | not run | | | | | | | | |")
            continue
        lines.append(row(f"sluice `{model}`, {spacing:g} m", f3.figures(series, experiment, span),
                         f"{span[1]:.2f}", cell(wall, 0)))
    return "\n".join(lines)


def plot(results, experiment, names, title, filename, scale, unit):
    fig, axes = plt.subplots(len(names), 1, figsize=(8, 2.1 * len(names)), sharex=True)
    for ax, name in zip(axes, names):
        ax.plot(experiment["time"], f3.smoothed(experiment, name) * scale, color="black", lw=0.9,
                label="experiment (Kleefsman et al. 2005)")
        for (model, spacing), (series, _, _) in results.items():
            if series is None:
                continue
            ax.plot(series["time"], f3.smoothed(series, name) * scale, STYLES.get(spacing, "-"),
                    color=COLOURS.get(model), lw=0.7, label=f"sluice {model}, {spacing:g} m")
        if name in f3.SENSORS:
            seed = f3.seed000(0.03)
            ax.plot(seed["time"], f3.smoothed(seed, name) * scale, color="0.6", lw=0.7,
                    label="seed 000's MPS, l0 = 0.03 m")
            ax.set_ylim(-2, 20)
        ax.set_ylabel(f"{name} [{unit}]")
        ax.set_xlim(0, END)
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper right", fontsize=7, ncol=2)
    axes[0].set_title(title)
    axes[-1].set_xlabel("time [s]")
    save_figure(fig, filename)


def main():
    parser = case_parser("kleefsman_3d", __doc__.splitlines()[0])
    parser.set_defaults(out=os.path.join("out", "validation", "kleefsman_3d"))
    parser.add_argument("--runs", default=RUNS, help="MODEL@SPACING,...")
    parser.add_argument("--resume", action="store_true", help="go on from each run's checkpoint")
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()
    experiment = f3.experiment()
    results = {}
    for item in args.runs.split(","):
        model, spacing = item.split("@")
        spacing = float(spacing)
        if not args.no_run:
            run(args, model, spacing)
        out = run_dir(args, model, spacing)
        path = os.path.join(out, "probes.csv")
        series = f3.read_probes(path) if os.path.exists(path) else None
        span = (0.0, min(END, float(series["time"][-1]))) if series is not None else (0.0, END)
        results[(model, spacing)] = (series, span, wall_per_simulated_second(out))

    write_table("validation.md", "f3", table(results, experiment))
    plot(results, experiment, f3.GAUGES, "F3: water height at the gauges (x in mm)",
         "f3_kleefsman_gauges.png", 1.0, "m")
    plot(results, experiment, f3.SENSORS[:4],
         "F3: pressure on the obstacle's face, 5 ms running means", "f3_kleefsman_pressure.png",
         1e-3, "kPa")


if __name__ == "__main__":
    main()
