#!/usr/bin/python3
"""F7: flow past a cylinder in a channel, Schäfer & Turek (1996), with the grid model (mac).

Runs cases/cylinder_channel_2d.yaml (benchmark 2D-1, Re = 20, steady) at cells of 0.01, 0.005
and 0.0025 m to 4 s, and benchmark 2D-2 (Re = 100: the inflow's mean speed 1 m/s, vortex
shedding) at 0.01 and 0.005 m to 8 s. 2D-1: the means over the last 0.5 s of C_D, C_L
(2 F / (rho U^2 D), U = 0.2 m/s, D = 0.1 m) and of the pressure drop across the cylinder; 2D-2:
the largest C_D and C_L over the last 3 s and the Strouhal number D f / U of the lift's
oscillation. Writes docs/validation.md's tables f7-2d1 and f7-2d2 and docs/img/f7_cylinder.png
(each coefficient against the cells across the cylinder, beside Schäfer & Turek's ranges).
Each run's loads.csv and probes.csv are kept in validation/results/.

usage: /usr/bin/python3 validation/cylinder_channel.py [--no-run] [--runs 2d1@0.01,...]
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from runs import (keep_results, model_runs_parser, read_columns, result_path,
                  result_statistics, run_model, save_figure, write_table)

CASE = "cylinder_channel_2d"
DIAMETER = 0.1
# Schäfer & Turek's ranges.
RANGES_2D1 = {"C_D": (5.57, 5.59), "C_L": (0.0104, 0.0110), "dp": (0.1172, 0.1176)}
RANGES_2D2 = {"C_D,max": (3.22, 3.24), "C_L,max": (0.99, 1.01), "St": (0.295, 0.305)}
BENCHMARKS = {
    # mean inflow speed [m/s], end [s], the span the figures come from [s], extra settings
    "2d1": (0.2, 4.0, 0.5, []),
    "2d2": (1.0, 8.0, 3.0, ["boundaries.0.mean_speed=1", "probe_interval=0.005"]),
}


def figures(benchmark, out, name):
    """The benchmark's figures from one run's loads.csv and probes.csv."""
    speed, end, span, _ = BENCHMARKS[benchmark]
    scale = 2 / (1.0 * speed ** 2 * DIAMETER)
    loads = read_columns(result_path(out, name, "loads.csv"))
    late = loads["time"] > end - span
    drag, lift = scale * loads["cylinder_drag"][late], scale * loads["cylinder_lift"][late]
    if benchmark == "2d1":
        probes = read_columns(result_path(out, name, "probes.csv"))
        late_p = probes["time [s]"] > end - span
        drop = probes["front [Pa]"][late_p] - probes["back [Pa]"][late_p]
        return {"C_D": drag.mean(), "C_L": lift.mean(), "dp": drop.mean()}
    # The lift's period from its upward crossings of its mean, interpolated between rows.
    t = loads["time"][late]
    centred = lift - lift.mean()
    up = [t[k] - centred[k] * (t[k + 1] - t[k]) / (centred[k + 1] - centred[k])
          for k in range(len(t) - 1) if centred[k] < 0 <= centred[k + 1]]
    period = (up[-1] - up[0]) / (len(up) - 1) if len(up) > 1 else float("nan")
    return {"C_D,max": drag.max(), "C_L,max": lift.max(), "St": DIAMETER / (period * speed)}


def main():
    parser = model_runs_parser(CASE, __doc__.split("\n")[0],
                               "2d1@0.01,2d1@0.005,2d1@0.0025,2d2@0.01,2d2@0.005")
    args = parser.parse_args()
    results = {"2d1": [], "2d2": []}
    for item in args.runs.split(","):
        benchmark, spacing = item.split("@")
        spacing = float(spacing)
        _, end, _, extra = BENCHMARKS[benchmark]
        name = f"f7_{benchmark}_{spacing:g}"
        out = os.path.join(args.out, name)
        if not args.no_run:
            run_model(CASE, out, "mac+solver=boomeramg", spacing, end, args, extra)
            keep_results(out, name, ("loads.csv", "probes.csv"))
        statistics = result_statistics(out, name) or {}
        results[benchmark].append((spacing, figures(benchmark, out, name), statistics))

    def table(benchmark, ranges, formats):
        header = "| cells across the cylinder | " + " | ".join(ranges) + " | steps | wall time |"
        lines = [header, "|---" * (len(ranges) + 3) + "|",
                 "| Schäfer & Turek | " + " | ".join(f"{lo:g}-{hi:g}" for lo, hi in
                                                     ranges.values()) + " | | |"]
        for spacing, f, s in results[benchmark]:
            wall = f"{s['wall']:.0f} s ({s['threads']} threads)" if s else ""
            lines.append(f"| {DIAMETER / spacing:.0f} | " +
                         " | ".join(fmt.format(f[key]) for key, fmt in zip(ranges, formats)) +
                         f" | {s.get('steps', '')} | {wall} |")
        write_table("validation.md", f"f7-{benchmark}", "\n".join(lines))

    table("2d1", RANGES_2D1, ("{:.3f}", "{:.4f}", "{:.4f}"))
    table("2d2", RANGES_2D2, ("{:.3f}", "{:.3f}", "{:.3f}"))

    panels = [("2d1", key, lo, hi) for key, (lo, hi) in RANGES_2D1.items()] + \
        [("2d2", key, lo, hi) for key, (lo, hi) in RANGES_2D2.items()]
    fig, axes = plt.subplots(2, 3, figsize=(11, 6))
    for ax, (benchmark, key, lo, hi) in zip(axes.flat, panels):
        across = [DIAMETER / spacing for spacing, _, _ in results[benchmark]]
        values = [f[key] for _, f, _ in results[benchmark]]
        ax.axhspan(lo, hi, color="tab:green", alpha=0.3, label="Schäfer & Turek")
        ax.plot(across, values, "o-", color="tab:blue", label="mac")
        ax.set_xscale("log", base=2)
        ax.set_xticks(across, [f"{a:.0f}" for a in across])
        ax.minorticks_off()
        ax.set_title(f"{benchmark.upper()}: {key}")
        ax.set_xlabel("cells across the cylinder")
        ax.legend(fontsize=8)
    save_figure(fig, "f7_cylinder.png")


if __name__ == "__main__":
    main()
