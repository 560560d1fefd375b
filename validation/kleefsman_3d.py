#!/usr/bin/python3
"""F3 of VALIDATION.md: the Kleefsman et al. (2005) 3D dam break with an obstacle
(cases/kleefsman_3d.yaml), run with each model and spacing to 6 s, against the experiment and
beside seed 000's MPS at the same particle distance. Writes the F3 tables into docs/validation.md
(with f3-mass, the water's mass of each run that kept its energy.csv),
docs/img/f3_kleefsman_gauges.png (the four gauges) and docs/img/f3_kleefsman_pressure.png (P1-P4,
5 ms running means). The figures' definitions are in kleefsman_figures.py.

A run is MODEL@SPACING (MODEL+KEY=VALUE@SPACING sets model.KEY too) and lives in
OUT_MODEL_SPACING (OUT: --out). A run that stopped before
6 s is measured over the span it reached (seed 000 over the same span) and says so; a long run
goes on with --resume (sluice run --resume, from its newest checkpoint).

usage: /usr/bin/python3 validation/kleefsman_3d.py [--no-run | --resume] [--out DIR]
           [--runs wcsph@0.03,mps@0.03,...] [--threads N]
       /usr/bin/python3 validation/kleefsman_3d.py --variants [--no-run]
           (wcsph's settings compared to 0.7 s, past the first impact: the table f3-variants)
"""
import math
import os

import matplotlib

matplotlib.use("Agg")
import kleefsman_figures as f3
import matplotlib.pyplot as plt
import numpy as np
from runs import (ROOT, base_model, each_run, keep_results, model_runs_parser, open_text,
                  result_path, result_statistics, run_model, save_figure, wall_per_simulated,
                  write_table)

# Every model at 0.03 m; mac's cells must tile the 3.22 m x 1 m tank, so its coarse run is at
# 0.02 m, the nearest that does; and without its volume correction, which it had not before
# 2026-12-06 (the level set then lost a fifth of the water). wcsph and mps also at 0.015 m.
RUNS = ("wcsph@0.03,mps@0.03,penalty-sph@0.03,constraint@0.03,granular@0.03,mac@0.02,"
        "mac+volume_correction=false@0.02,wcsph@0.015,mps@0.015")
COLOURS = {"wcsph": "tab:blue", "mps": "tab:red", "penalty-sph": "tab:orange",
           "constraint": "tab:purple", "granular": "tab:green", "mac": "tab:brown"}
STYLES = {0.03: "-", 0.02: "-", 0.015: "--", 0.01: ":", 0.0075: ":"}
END = 6.0
# wcsph at 0.03 m to 0.7 s, each setting named whatever the case or the engine defaults to:
# walls no-slip or free-slip, negative pressure kept or clamped; without artificial viscosity;
# with twice the sound speed.
VARIANTS = ",".join(f"wcsph+{v}@0.03" for v in (
    "wall_slip=no_slip+negative_pressure=keep", "wall_slip=no_slip+negative_pressure=clamp",
    "wall_slip=free_slip+negative_pressure=keep", "wall_slip=free_slip+negative_pressure=clamp",
    "wall_slip=no_slip+negative_pressure=clamp+artificial_viscosity=0",
    "wall_slip=no_slip+negative_pressure=clamp+speed_factor=20"))
VARIANTS_END = 0.7
# The complementarity model and the grid write their probes every 10 ms: probes every 1 ms (the
# case's) would cut their steps (of up to 10-17 ms; 1.7-1.9 ms on average over their 6 s runs)
# and lengthen runs of hours. Table f3-readings sets every run's pressures on that footing.
PROBE_INTERVAL = {"constraint": 0.01, "mac": 0.01}
CI_END = 1.0  # s, the CI checks' run


def run_dir(args, model, spacing):
    return os.path.join(ROOT, f"{args.out}_{model}_{spacing:g}")


def kept_name(model, spacing, variants=False):
    """The name keep_results keeps the run under (validation/results/NAME)."""
    return f"kleefsman_3d{'_variants' if variants else ''}/{model}_{spacing:g}"


def cell(value, digits, scale=1.0):
    return "–" if value is None or math.isnan(value) else f"{value * scale:.{digits}f}"


def row(name, figures, reached, extra=""):
    wet = " / ".join(cell(figures.get(f"wet_{g}"), 3) for g in reversed(f3.DOWNSTREAM))
    gauges = " / ".join(cell(figures.get(f"rms_{g}"), 3) for g in reversed(f3.GAUGES[:3]))
    pressures = " / ".join(cell(figures[f"rms_{s}"], 0) for s in f3.SENSORS[:4])
    returns = f"{cell(figures.get('bore'), 2)} / {cell(figures.get('p1_second_rise'), 2)}"
    return (f"| {name} | {reached} | {wet} | {gauges} | {cell(figures.get('rms_g2638'), 3)} | "
            f"{cell(figures['p1_rise'], 3)} | {cell(figures['p1_peak'], 1, 1e-3)} | "
            f"{cell(figures['p1_impulse'], 0)} | {pressures} | {returns} | {extra} |")


def table(results, experiment, end):
    lines = [
        "| run | to [s] | first wet at x = 1.488 / 0.992 / 0.496 m [s] | height RMS there [m] | "
        "reservoir (2.638 m) height RMS [m] | P1 rise [s] | P1 peak [kPa] | P1 impulse "
        "0.35-0.6 s [Pa s] | P1 / P2 / P3 / P4 RMS [Pa] | the bore's return: reservoir gauge "
        "above 0.18 m / P1 above 2 kPa again [s] | wall s per simulated s |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
        row("experiment (Kleefsman et al. 2005)", f3.figures(experiment, experiment, (0, end)),
            f"{end:g}")]
    for name, series, span, wall in with_seed_rows(results):
        if series is None:
            lines.append(f"| {name} | not run | | | | | | | | | |")
        elif wall is None:  # seed 000's
            lines.append(row(name, f3.figures(series, experiment, span), f"{span[1]:g}"))
        else:
            lines.append(row(name, f3.figures(series, experiment, span), f"{span[1]:.2f}", wall))
    return "\n".join(lines)


def with_seed_rows(results):
    """(name, series, span, wall cell) for each run of results, before the first run of each
    spacing and span seed 000's MPS at that l0 over that span (its wall cell None) where the
    seed has a run at it."""
    seeds_shown = set()
    for (model, spacing), (series, span, wall) in results.items():
        seed = f3.seed000(spacing)
        if seed is not None and (spacing, span) not in seeds_shown:
            seeds_shown.add((spacing, span))
            yield f"seed 000's MPS, l0 = {spacing:g} m", seed, span, None
        yield f"sluice `{model}`, {spacing:g} m", series, span, wall


READING = 0.01  # s, the probe interval of the models that write coarser probes


def readings_table(results, experiment):
    """Every run's P1-P4 RMS as table f3 gives them and as the probes of PROBE_INTERVAL's
    models read them (one reading every READING, no 5 ms mean), so that those models' figures
    are set beside the others' on one footing; seed 000 beside."""
    ms = f"{1000 * READING:g} ms"
    lines = [f"| run | probes written every | P1 / P2 / P3 / P4 RMS, 5 ms means of the probes "
             f"(table f3) [Pa] | the same from one reading every {ms} [Pa] | P1 peak from one "
             f"reading every {ms} [kPa] |", "|---|---|---|---|---|"]

    def line(name, series, span):
        written = float(np.median(np.diff(series["time"])))
        as_written = f3.figures(series, experiment, span)
        read = f3.figures(f3.read_every(series, READING), experiment, span)
        pressures = [" / ".join(cell(f[f"rms_{s}"], 0) for s in f3.SENSORS[:4])
                     for f in (as_written, read)]
        return (f"| {name} | {1000 * written:.1f} ms | {pressures[0]} | {pressures[1]} | "
                f"{cell(read['p1_peak'], 1, 1e-3)} |")

    lines += [line(name + (f", to {span[1]:g} s" if wall is None else ""), series, span)
              for name, series, span, wall in with_seed_rows(results) if series is not None]
    return "\n".join(lines)


MASS_TIMES = (1.0, 2.0, 4.0)


def mass_table(results, args):
    """The water's mass over each run that kept its energy.csv: a particle model's is its
    particles' and cannot change; the grid's is its level set's volume, which can."""
    times = " / ".join(f"{t:g}" for t in MASS_TIMES)
    lines = [f"| run | water's mass at the start [kg] | at {times} s [kg] | at the end [kg] | "
             "end / start - 1 |", "|---|---|---|---|---|"]
    for model, spacing in results:
        path = result_path(run_dir(args, model, spacing), kept_name(model, spacing), "energy.csv")
        if path is None:
            continue
        with open_text(path) as f:
            energy = np.genfromtxt(f, delimiter=",", names=True)
        t, mass = energy["time"], energy["fluid_mass"]
        at = " / ".join(cell(mass[np.searchsorted(t, s)] if s <= t[-1] else math.nan, 1)
                        for s in MASS_TIMES)
        lines.append(f"| sluice `{model}`, {spacing:g} m (to {t[-1]:.2f} s) | {mass[0]:.1f} | "
                     f"{at} | {mass[-1]:.1f} | {100 * (mass[-1] / mass[0] - 1):+.1f} % |")
    return "\n".join(lines)


def bars_table(results, experiment):
    """VALIDATION.md's bars at 0.03 m over the first second, as tests/physics/test_kleefsman.cpp
    measures them, from each 0.03 m run's first second: met or not."""
    span = (0.0, CI_END)
    seed = f3.figures(f3.seed000(0.03), experiment, span)
    measured = f3.figures(experiment, experiment, span)

    def mark(ok):
        return "met" if ok else "**not met**"

    seeds = " / ".join(f"{seed['rms_' + s]:.0f}" for s in f3.SENSORS[:4])
    lines = ["| run | first wet at x = 1.488 / 0.992 / 0.496 m, late by [s] (bar 0.05) | P1 rise, "
             "late by [s] (bar 0.05) | reservoir RMS [m] (bar 0.03) | P1 / P2 / P3 / P4 RMS [Pa] "
             f"(seed 000: {seeds}) |", "|---|---|---|---|---|"]
    for (model, spacing), (series, span_reached, _) in results.items():
        if series is None or spacing != 0.03 or span_reached[1] < CI_END:
            continue
        f = f3.figures(series, experiment, span)
        late = {g: f["wet_" + g] - measured["wet_" + g] for g in f3.DOWNSTREAM}
        wet = " / ".join(f"not wet by {CI_END:g} s (**not met**)" if math.isnan(late[g]) else
                         f"{late[g]:+.3f} ({mark(abs(late[g]) < 0.05)})"
                         for g in reversed(f3.DOWNSTREAM))
        rise = f["p1_rise"] - measured["p1_rise"]
        pressures = " / ".join(f"{f['rms_' + s]:.0f} ({mark(f['rms_' + s] <= seed['rms_' + s])})"
                               for s in f3.SENSORS[:4])
        lines.append(f"| sluice `{model}` | {wet} | {rise:+.3f} ({mark(abs(rise) < 0.05)}) | "
                     f"{f['rms_g2638']:.3f} ({mark(f['rms_g2638'] < 0.03)}) | {pressures} |")
    return "\n".join(lines)


VARIANT_COLOURS = ["tab:cyan", "tab:olive", "tab:pink", "tab:gray"]


def plot(results, experiment, names, title, filename, scale, unit, seed_spacing, zoom=None):
    """One row per probe: the whole run, and beside it the span `zoom` (the first impact);
    pressures beside seed 000's MPS at l0 = seed_spacing."""
    columns = 2 if zoom else 1
    fig, axes = plt.subplots(len(names), columns, figsize=(5 * columns + 2, 2.1 * len(names) + 1),
                             sharex="col", squeeze=False)
    variants = iter(VARIANT_COLOURS)
    colours = {key: COLOURS.get(key[0]) if "+" not in key[0] else next(variants, "black")
               for key in results}
    for row, name in zip(axes, names):
        for ax, span in zip(row, [(0, END), zoom][:columns]):
            ax.plot(experiment["time"], f3.smoothed(experiment, name) * scale, color="black",
                    lw=0.9, label="experiment (Kleefsman et al. 2005)")
            for key, (series, _, _) in results.items():
                if series is not None:
                    ax.plot(series["time"], f3.smoothed(series, name) * scale,
                            STYLES.get(key[1], "-"), color=colours[key], lw=0.7,
                            label=f"sluice {key[0]}, {key[1]:g} m")
            if name in f3.SENSORS:
                seed = f3.seed000(seed_spacing)
                ax.plot(seed["time"], f3.smoothed(seed, name) * scale, color="0.6", lw=0.7,
                        label=f"seed 000's MPS, l0 = {seed_spacing:g} m")
                ax.set_ylim(-2, 25)  # the runs' first peaks reach 23 kPa
            ax.set_xlim(*span)
            ax.grid(alpha=0.3)
        row[0].set_ylabel(f"{name} [{unit}]")
    axes[0][0].set_title(title)
    if zoom:
        axes[0][1].set_title(f"the first impact, {zoom[0]:g}-{zoom[1]:g} s")
    for ax in axes[-1]:
        ax.set_xlabel("time [s]")
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", fontsize=7, ncol=2)
    save_figure(fig, filename, rect=(0, 0.02 + 0.011 * len(labels), 1, 1))


# The runs' two groups, each with its own table and plots: the coarse runs (every model, with
# the CI checks' bars) and the finer runs beside seed 000 at 0.015 m. A group's table and plots
# are written when every one of its runs has results (a run directory, or what keep_results
# kept of it in validation/results/); else they are left as they are.
GROUPS = (
    {"fine": False, "table": "f3", "seed": 0.03, "gauges": "f3_kleefsman_gauges.png",
     "pressure": "f3_kleefsman_pressure.png"},
    {"fine": True, "table": "f3-fine", "seed": 0.015, "gauges": "f3_kleefsman_fine_gauges.png",
     "pressure": "f3_kleefsman_fine_pressure.png"},
)


def main():
    parser = model_runs_parser("kleefsman_3d", __doc__.splitlines()[0], RUNS)
    parser.add_argument("--variants", action="store_true",
                        help="wcsph's settings to 0.7 s (table f3-variants, no plots)")
    args = parser.parse_args()
    end, runs = (VARIANTS_END, VARIANTS) if args.variants else (END, args.runs)
    if args.variants:
        args.out += "_variants"
    experiment = f3.experiment()

    def result(model, spacing, run):
        """The run's probes, span and wall time per simulated second, from its directory or
        what keep_results kept (running it first where `run`)."""
        out = run_dir(args, model, spacing)
        name = kept_name(model, spacing, args.variants)
        if run:
            interval = PROBE_INTERVAL.get(base_model(model))
            # A checkpoint every 0.1 s, not the case's 0.5 s: a run of hours stopped at a
            # session's end loses less (a resumed run may change the interval).
            extra = ("checkpoint_interval=0.1",)
            if interval:
                extra += (f"probe_interval={interval}",)
            run_model("kleefsman_3d", out, model, spacing, end, args, extra)
        keep_results(out, name, ("probes.csv", "energy.csv"))
        path = result_path(out, name, "probes.csv")
        series = f3.read_probes(path) if path else None
        span = (0.0, min(end, float(series["time"][-1]))) if series is not None else (0.0, end)
        statistics = result_statistics(out, name)
        return series, span, wall_per_simulated(statistics, span[1])

    results = {key: result(*key, not args.no_run) for key in each_run(runs)}
    if not args.variants:
        # The groups' tables hold every run of RUNS: those not asked for this time come from
        # their directories or kept results, so that a run of one model cannot shrink a table.
        for key in each_run(RUNS):
            if key not in results:
                results[key] = result(*key, False)
        # In RUNS's order whatever was asked for, the runs not of RUNS after them.
        order = list(each_run(RUNS))
        results = dict(sorted(results.items(),
                              key=lambda item: order.index(item[0]) if item[0] in order
                              else len(order)))

    if args.variants:
        write_table("validation.md", "f3-variants", table(results, experiment, end))
        return
    for group in GROUPS:
        mine = {key: value for key, value in results.items() if (key[1] < 0.02) == group["fine"]}
        missing = [f"{m}@{s:g}" for (m, s), value in mine.items() if value[0] is None]
        if not mine or missing:
            print(f"table {group['table']} and its plots left as they are"
                  + (f": no results for {', '.join(missing)}" if missing else ""))
            continue
        write_table("validation.md", group["table"], table(mine, experiment, end))
        if not group["fine"]:
            write_table("validation.md", "f3-bars", bars_table(mine, experiment))
            write_table("validation.md", "f3-mass", mass_table(mine, args))
            write_table("validation.md", "f3-readings", readings_table(mine, experiment))
        plot(mine, experiment, f3.GAUGES, "F3: water height at the gauges (x in mm)",
             group["gauges"], 1.0, "m", group["seed"])
        plot(mine, experiment, f3.SENSORS[:4],
             "F3: pressure on the obstacle's face, 5 ms running means", group["pressure"],
             1e-3, "kPa", group["seed"], zoom=(0.3, 1.0))


if __name__ == "__main__":
    main()
