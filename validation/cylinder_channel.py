#!/usr/bin/python3
"""F7: flow past a cylinder in a channel, Schäfer & Turek (1996), with the grid model (mac) and
weakly compressible SPH (wcsph, with its transport velocity).

Runs benchmark 2D-1 (Re = 20, steady) and 2D-2 (Re = 100: the inflow's mean speed 1 m/s, vortex
shedding) at several sizes: `mac` from cases/cylinder_channel_2d.yaml (2D-1 to 4 s at cells of
0.01, 0.005 and 0.0025 m; 2D-2 to 8 s at 0.01 and 0.005 m), `wcsph` from
cases/cylinder_channel_wcsph_2d.yaml (its inflow ramped up over 4 s, 2 s for 2D-2; 2D-1 to 7 s at
spacings of 0.01 and 0.005 m, and 0.0025 m when --runs asks for it; 2D-2 to 8 s at 0.01 and
0.005 m; c0 = 15 m/s and the background pressure rho0 c0^2). 2D-1: the means over the last span
(0.5 s for mac, 1 s for wcsph) of C_D, C_L (2 F / (rho U^2 D), U = 0.2 m/s, D = 0.1 m) and of the pressure drop across the
cylinder; 2D-2: over the last 3 s, the Strouhal number D f / U of the lift's oscillation and the
largest C_D and C_L of a fit of four harmonics of it (the SPH forces are noisy). Writes
docs/validation.md's tables f7-2d1 and f7-2d2 and docs/img/f7_cylinder.png (each coefficient
against the cells or particles across the cylinder, beside Schäfer & Turek's ranges). Each run's
loads.csv and probes.csv are kept in validation/results/.

usage: /usr/bin/python3 validation/cylinder_channel.py [--no-run] [--runs mac:2d1@0.01,...]
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from runs import (keep_results, model_runs_parser, read_columns, result_path,
                  result_statistics, run_model, runs_to_tabulate, save_figure, wall_time,
                  write_table)

DIAMETER = 0.1
# Schäfer & Turek's ranges.
RANGES_2D1 = {"C_D": (5.57, 5.59), "C_L": (0.0104, 0.0110), "dp": (0.1172, 0.1176)}
RANGES_2D2 = {"C_D,max": (3.22, 3.24), "C_L,max": (0.99, 1.01), "St": (0.295, 0.305)}
# Each model's case and its settings, and for each benchmark: the mean inflow speed [m/s], the
# end [s], the span the figures come from [s] and the extra settings.
MODELS = {
    "mac": ("cylinder_channel_2d", "mac+solver=boomeramg", {
        "2d1": (0.2, 4.0, 0.5, []),
        "2d2": (1.0, 8.0, 3.0, ["boundaries.0.mean_speed=1", "probe_interval=0.005"]),
    }),
    "wcsph": ("cylinder_channel_wcsph_2d", "wcsph", {
        "2d1": (0.2, 7.0, 1.0, []),
        "2d2": (1.0, 8.0, 3.0, ["boundaries.0.mean_speed=1", "boundaries.0.ramp_time=2",
                                "probe_interval=0.005", "model.sound_speed=15",
                                "model.background_pressure=225"]),
    }),
}
COLOURS = {"mac": "tab:blue", "wcsph": "tab:orange"}


def figures(model, benchmark, out, name):
    """The benchmark's figures from one run's loads.csv and probes.csv."""
    speed, end, span, _ = MODELS[model][2][benchmark]
    scale = 2 / (1.0 * speed ** 2 * DIAMETER)
    loads = read_columns(result_path(out, name, "loads.csv"))
    late = loads["time"] > end - span
    drag, lift = scale * loads["cylinder_drag"][late], scale * loads["cylinder_lift"][late]
    if benchmark == "2d1":
        probes = read_columns(result_path(out, name, "probes.csv"))
        late_p = probes["time [s]"] > end - span
        drop = probes["front [Pa]"][late_p] - probes["back [Pa]"][late_p]
        return {"C_D": drag.mean(), "C_L": lift.mean(), "dp": drop.mean()}
    # The lift's frequency: the peak of its spectrum (a Hann window, zero-padded sixteenfold), for
    # an SPH lift is noisy (the raw signal crosses its mean many times a period); the largest
    # values are those of a fit of the first four harmonics of that frequency, which follows a
    # smooth signal and passes through a noisy one.
    t = loads["time"][late]
    padded = 16 * len(t)
    spectrum = np.abs(np.fft.rfft((lift - lift.mean()) * np.hanning(len(t)), padded))
    frequency = np.fft.rfftfreq(padded, t[1] - t[0])[np.argmax(spectrum)]
    period = 1 / frequency
    omega = 2 * np.pi / period
    basis = np.column_stack([np.ones_like(t)] + [f(n * omega * t) for n in range(1, 5)
                                                 for f in (np.cos, np.sin)])

    def fitted_max(signal):
        return (basis @ np.linalg.lstsq(basis, signal, rcond=None)[0]).max()

    return {"C_D,max": fitted_max(drag), "C_L,max": fitted_max(lift),
            "St": DIAMETER / (period * speed)}


RUNS = ("mac:2d1@0.01,mac:2d1@0.005,mac:2d1@0.0025,mac:2d2@0.01,mac:2d2@0.005,"
        "wcsph:2d1@0.01,wcsph:2d1@0.005,wcsph:2d2@0.01,wcsph:2d2@0.005")


def main():
    parser = model_runs_parser("cylinder_channel_2d", __doc__.split("\n")[0], RUNS)
    parser.set_defaults(out=os.path.join("out", "validation", "cylinder_channel"))
    args = parser.parse_args()
    results = {"2d1": [], "2d2": []}
    for item in runs_to_tabulate(args.runs, RUNS):
        model, rest = item.split(":")
        benchmark, spacing = rest.split("@")
        spacing = float(spacing)
        case, settings, benchmarks = MODELS[model]
        _, end, _, extra = benchmarks[benchmark]
        name = f"f7_{model}_{benchmark}_{spacing:g}"
        out = os.path.join(args.out, name)
        if not args.no_run and item in args.runs.split(","):
            run_model(case, out, settings, spacing, end, args, extra)
            keep_results(out, name, ("loads.csv", "probes.csv"))
        statistics = result_statistics(out, name) or {}
        results[benchmark].append((model, spacing, figures(model, benchmark, out, name),
                                   statistics))

    def table(benchmark, ranges, formats):
        header = ("| model | cells or particles across the cylinder | " + " | ".join(ranges) +
                  " | steps | wall time |")
        lines = [header, "|---" * (len(ranges) + 4) + "|",
                 "| Schäfer & Turek | | " + " | ".join(f"{lo:g}-{hi:g}" for lo, hi in
                                                       ranges.values()) + " | | |"]
        for model, spacing, f, s in results[benchmark]:
            wall = wall_time(s)
            lines.append(f"| `{model}` | {DIAMETER / spacing:.0f} | " +
                         " | ".join(fmt.format(f[key]) for key, fmt in zip(ranges, formats)) +
                         f" | {s.get('steps', '')} | {wall} |")
        write_table("validation.md", f"f7-{benchmark}", "\n".join(lines))

    table("2d1", RANGES_2D1, ("{:.3f}", "{:.4f}", "{:.4f}"))
    table("2d2", RANGES_2D2, ("{:.3f}", "{:.3f}", "{:.3f}"))

    panels = [("2d1", key, lo, hi) for key, (lo, hi) in RANGES_2D1.items()] + \
        [("2d2", key, lo, hi) for key, (lo, hi) in RANGES_2D2.items()]
    fig, axes = plt.subplots(2, 3, figsize=(11, 6))
    for ax, (benchmark, key, lo, hi) in zip(axes.flat, panels):
        ax.axhspan(lo, hi, color="tab:green", alpha=0.3, label="Schäfer & Turek")
        ticks = set()
        for model in MODELS:
            rows = [(DIAMETER / spacing, f[key]) for m, spacing, f, _ in results[benchmark]
                    if m == model]
            if rows:
                across, values = zip(*rows)
                ax.plot(across, values, "o-", color=COLOURS[model], label=model)
                ticks.update(across)
        ax.set_xscale("log", base=2)
        ax.set_xticks(sorted(ticks), [f"{a:.0f}" for a in sorted(ticks)])
        ax.minorticks_off()
        ax.set_title(f"{benchmark.upper()}: {key}")
        ax.set_xlabel("cells or particles across the cylinder")
        ax.legend(fontsize=8)
    save_figure(fig, "f7_cylinder.png")


if __name__ == "__main__":
    main()
