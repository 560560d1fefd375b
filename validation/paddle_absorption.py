#!/usr/bin/python3
"""F8, active absorption: a piston before a closed end, with and without absorbing.

Runs cases/paddle_absorption_2d.yaml (the F8 piston at kh = 1, steepness 0.02, water 0.5 m
deep, a wall two wavelengths from the paddle's face and no damping zone) to 30 s with
`active_absorption` on and off, for each of --runs MODEL@PADDLE (the grid's and wcsph's piston,
the grid's flap hinged at the bed, first order; 0.02 m). Over windows of three periods sliding
along the records, the incident and reflected waves at the gauges a wavelength from the paddle and a quarter beyond
(Goda & Suzuki 1976): with absorption the incident wave should stay Biésel's while the wall
returns it whole; without, the paddle sends the returning waves out again. Writes
docs/validation.md's table f8-absorption and docs/img/f8_absorption.png; each run's probes.csv is
kept in validation/results/.

usage: /usr/bin/python3 validation/paddle_absorption.py [--no-run] [--threads N]
                                                     [--runs mac@piston,...]
"""
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from runs import (case_parser, keep_results, read_columns, result_path, result_statistics,
                  run_model, runs_to_tabulate, save_figure, wall_time, write_table)
from wave_flume import goda_suzuki, harmonic

CASE = "paddle_absorption_2d"
DEPTH, HEIGHT, PERIOD, END = 0.5, 0.0628, 1.6254, 30.0
GAUGES = (3.342, 4.127)
K = 2.0  # kh = 1


def windows(out, name):
    """(window's mid time, incident height, reflection coefficient) over sliding windows of
    three periods, a period apart."""
    probes = read_columns(result_path(out, name, "probes.csv"))
    t = probes["time [s]"]
    omega = 2 * math.pi / PERIOD
    rows = []
    start = 0.0
    while start + 3 * PERIOD <= t[-1] + 1e-9:
        inside = (t >= start) & (t <= start + 3 * PERIOD)
        z1 = harmonic(t[inside], probes["one_wavelength [m]"][inside] - DEPTH, omega)
        z2 = harmonic(t[inside], probes["quarter_beyond [m]"][inside] - DEPTH, omega)
        incident, reflected = goda_suzuki(z1, GAUGES[0], z2, GAUGES[1], K)
        rows.append((start + 1.5 * PERIOD, 2 * incident, reflected / incident))
        start += PERIOD
    return np.array(rows)


RUNS = "mac@piston,wcsph@piston,mac@flap"


def main():
    parser = case_parser(CASE, __doc__.split("\n")[0])
    parser.set_defaults(out=os.path.join("out", "validation", CASE))
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--resume", action="store_true")
    parser.add_argument("--runs", default=RUNS,
                        help="MODEL@PADDLE,... to run")
    args = parser.parse_args()
    results = []
    for item in runs_to_tabulate(args.runs, RUNS):
        model, paddle = item.split("@")
        for absorbing in (True, False):
            name = "f8_absorption_" + ("on" if absorbing else "off")
            name += "" if model == "mac" else f"_{model}"
            name += "" if paddle == "piston" else f"_{paddle}"
            out = os.path.join(args.out, name)
            sets = [f"bodies.0.prescribed.active_absorption={str(absorbing).lower()}"]
            if paddle != "piston":
                sets += [f"bodies.0.prescribed.paddle={paddle}", "bodies.0.prescribed.order=1"]
            if not args.no_run and item in args.runs.split(","):
                run_model(CASE, out, model, 0.02, END, args, sets)
                keep_results(out, name)
            results.append((f"{model}, {paddle}", absorbing, windows(out, name),
                            result_statistics(out, name) or {}))

    def within_14_to_22(w):  # the windows that lie within 14-22 s
        return w[(w[:, 0] > 14 + 1.5 * PERIOD) & (w[:, 0] < 22 - 1.5 * PERIOD)]

    def span(mids):  # the seconds a set of windows covers
        return f"{mids.min() - 1.5 * PERIOD:.1f}-{mids.max() + 1.5 * PERIOD:.1f} s"

    w = results[0][2]
    early_span, last_span = span(within_14_to_22(w)[:, 0]), span(w[-1:, 0])
    lines = [f"| model, paddle | active absorption | incident H, {early_span} [m] | from Biésel's "
             f"0.0628 | incident H, last 3 periods ({last_span}) [m] | from Biésel's | the wall's "
             "reflection, last 3 periods | steps | wall time |", "|---" * 9 + "|"]
    for model, absorbing, w, s in results:
        mean_early = within_14_to_22(w)[:, 1].mean()
        wall = wall_time(s)
        lines.append(f"| {model} | {'yes' if absorbing else 'no'} | {mean_early:.4f} | "
                     f"{100 * (mean_early / HEIGHT - 1):+.1f} % | {w[-1, 1]:.4f} | "
                     f"{100 * (w[-1, 1] / HEIGHT - 1):+.1f} % | {w[-1, 2]:.2f} | "
                     f"{s.get('steps', '')} | {wall} |")
    write_table("validation.md", "f8-absorption", "\n".join(lines))

    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for model, absorbing, w, _ in results:
        label = f"{model}: " + ("active absorption" if absorbing else "no absorption")
        marker = {"mac, piston": "o", "wcsph, piston": "s"}.get(model, "^")
        style = marker + ("-" if absorbing else "--")
        axes[0].plot(w[:, 0], w[:, 1] / HEIGHT, style, ms=3, label=label)
        axes[1].plot(w[:, 0], w[:, 2], style, ms=3, label=label)
    axes[0].axhspan(0.95, 1.05, color="tab:green", alpha=0.3, label="±5 % of Biésel")
    axes[0].set(xlabel="t [s] (windows of 3 periods)", ylabel="incident H / Biésel's",
                title="the wave leaving the paddle")
    axes[1].set(xlabel="t [s] (windows of 3 periods)", ylabel="reflected / incident",
                title="what comes back from the wall")
    for ax in axes:
        ax.legend(fontsize=8)
    save_figure(fig, "f8_absorption.png")


if __name__ == "__main__":
    main()
