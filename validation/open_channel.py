#!/usr/bin/python3
"""F9: an open channel through the particle models' open boundaries (issue 43).

Runs cases/open_channel_2d.yaml (water 0.3 m deep entering a 3 m flume at 0.3 m/s through an
inlet's buffer, leaving by an outlet hydrostatic below the same depth, a free-slip bed) with wcsph
at 0.02 and 0.01 m and with mps at 0.02 m, to 20 s. Over the last 10 s: the mean volume flux in
and out (the flux probes at the buffers' inner faces) and how far they differ (bar 1 %); the
water's mean depth over the middle 2.4 m in each frame (every 0.5 s): in each column a spacing
wide, the highest fluid particle's height plus half a spacing, averaged over the columns, as the
physics tests measure it; its mean and its largest departure from 0.3 m (bar 2 %); and the three
gauges' mean readings (the water-height probe reads in quarter spacings). Writes
docs/validation.md's table f9-open-channel and docs/img/f9_open_channel.png; each run's
probes.csv and depths.csv are kept in validation/results/.

usage: /usr/bin/python3 validation/open_channel.py [--no-run] [--runs wcsph@0.02,...]
"""
import glob
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from frames import read_frame
from runs import (each_run, keep_results, model_runs_parser, read_columns, result_path,
                  result_statistics, run_model, runs_to_tabulate, save_figure, wall_time,
                  write_table)

CASE = "open_channel_2d"
DEPTH, END, FROM = 0.3, 20.0, 10.0
STRETCH = (0.3, 2.7)  # where the mean depth is measured [m]


def write_depths(out, spacing):
    """out/depths.csv: the mean depth over the stretch in each frame (the module's doc)."""
    rows = []
    for path in sorted(glob.glob(os.path.join(out, "frames", "frame_*.vtp"))):
        points, fields = read_frame(path, "kind")
        x, z = points[:, 0], points[:, 2]
        water = (fields["kind"] == 0) & (x >= STRETCH[0]) & (x < STRETCH[1])
        columns = int(round((STRETCH[1] - STRETCH[0]) / spacing))
        top = np.full(columns, -0.5 * spacing)
        column = np.minimum(((x[water] - STRETCH[0]) / spacing).astype(int), columns - 1)
        np.maximum.at(top, column, z[water])
        rows.append(np.mean(top + 0.5 * spacing))
    series = os.path.join(out, f"{CASE}.pvd")
    with open(series) as f:
        times = [float(line.split('timestep="')[1].split('"')[0]) for line in f
                 if "timestep=" in line]
    with open(os.path.join(out, "depths.csv"), "w") as f:
        f.write("time,depth\n")
        for t, d in zip(times, rows):
            f.write(f"{t:.6g},{d:.8g}\n")


def figures(out, name):
    probes = read_columns(result_path(out, name, "probes.csv"))
    t = probes["time [s]"]
    late = t > FROM
    flux_in = -probes["inflow [m^2/s]"][late].mean()
    flux_out = probes["outflow [m^2/s]"][late].mean()
    gauges = [probes[k][late].mean() for k in probes if k.startswith("depth_")]
    depths = read_columns(result_path(out, name, "depths.csv"))
    d = depths["depth"][depths["time"] > FROM]
    return {"in": flux_in, "out": flux_out, "imbalance": 100 * (flux_out / flux_in - 1),
            "depth": d.mean(), "depth_error": 100 * (d.mean() / DEPTH - 1),
            "worst": 100 * max(d / DEPTH - 1, key=abs), "gauges": np.mean(gauges),
            "series": (t, probes["inflow [m^2/s]"], probes["outflow [m^2/s]"], depths)}


def main():
    parser = model_runs_parser(CASE, __doc__, "wcsph@0.02,wcsph@0.01,mps@0.02")
    args = parser.parse_args()
    rows, results = [], []
    for item in runs_to_tabulate(args.runs, parser.get_default("runs")):
        model, spacing = next(each_run(item))
        name = f"f9_{model}_{spacing:g}"
        out = os.path.join(args.out, name)
        if not args.no_run and item in args.runs.split(","):
            run_model(CASE, out, model, spacing, END, args)
            write_depths(out, spacing)
            keep_results(out, name, ("probes.csv", "depths.csv"))
        f = figures(out, name)
        statistics = result_statistics(out, name)
        wall = wall_time(statistics)
        rows.append(f"| `{model}` | {spacing:g} | {f['in']:.5f} | {f['out']:.5f} | "
                    f"{f['imbalance']:+.2f} % | {f['depth']:.4f} ({f['depth_error']:+.2f} %) | "
                    f"{f['worst']:+.2f} % | {f['gauges']:.4f} | {wall} |")
        results.append((model, spacing, f))
    table = ("| model | spacing [m] | flux in [m^2/s] | flux out [m^2/s] | out from in (bar 1 %) | "
             "mean depth [m] (bar 2 %) | worst frame's depth (bar 2 %) | gauges' mean [m] | "
             "wall time |\n|---|---|---|---|---|---|---|---|---|\n" + "\n".join(rows) + "\n")
    write_table("validation.md", "f9-open-channel", table)

    fig, (ax_flux, ax_depth) = plt.subplots(2, 1, figsize=(7.5, 6), sharex=True)
    for model, spacing, f in results:
        t, flux_in, flux_out, depths = f["series"]
        # Half-second running means: a probe's reading is one step's.
        window = max(1, int(round(0.5 / (t[1] - t[0]))))
        mean = lambda v: np.convolve(v, np.ones(window) / window, mode="valid")
        tm = mean(t)
        line, = ax_flux.plot(tm, -mean(flux_in), lw=0.8, label=f"{model} {spacing:g} m: in")
        ax_flux.plot(tm, mean(flux_out), lw=0.8, ls="--", color=line.get_color(), label="out")
        ax_depth.plot(depths["time"], depths["depth"], "o-", ms=3, color=line.get_color(),
                      label=f"{model} {spacing:g} m")
    ax_flux.axhline(0.09, color="k", lw=0.6)
    ax_flux.set_ylabel("volume flux, 0.5 s means [m$^2$/s]")
    ax_flux.set_ylim(0.08, 0.10)
    ax_flux.legend(fontsize=7, ncol=2)
    ax_depth.axhspan(0.98 * DEPTH, 1.02 * DEPTH, color="0.9", label="target $\\pm$ 2 %")
    ax_depth.axhline(DEPTH, color="k", lw=0.6)
    ax_depth.axvline(FROM, color="0.5", lw=0.6, ls=":")
    ax_depth.set_ylabel(f"mean depth, x in [{STRETCH[0]}, {STRETCH[1]}] m [m]")
    ax_depth.set_xlabel("time [s]")
    ax_depth.legend(fontsize=7)
    save_figure(fig, "f9_open_channel.png")


if __name__ == "__main__":
    main()
