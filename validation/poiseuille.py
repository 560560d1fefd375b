#!/usr/bin/python3
"""F10: plane Poiseuille flow across a periodic axis (issue 43; Morris, Fox & Zhu 1997).

Runs cases/poiseuille_2d.yaml (water between no-slip plates 0.1 m apart, driven from rest
along a periodic x by a body force of 0.8 m/s^2, nu = 0.01 m^2/s) to 1.5 s with wcsph at 0.005
and 0.0025 m, and so mps, penalty-sph and mac (cells of those sizes). At 0.1, 0.3 and 1.5 s it compares the
fluid particles' speed along x with the series solution
  u(z, t) = F z (d - z) / (2 nu) - sum_n 4 F d^2 / (nu pi^3 (2n+1)^3) sin((2n+1) pi z / d)
            exp(-(2n+1)^2 pi^2 nu t / d^2):
the RMS difference over the particles' (mac: cells') rows as a share of the steady centre speed (0.1 m/s; the
physics tests' bars: wcsph 4 %, mac 1 %), the mean speed from the series' mean, and the mean
speed within 0.02 m of a periodic side from that between them. Writes docs/validation.md's
table f10-poiseuille and docs/img/f10_poiseuille.png; each run's profiles.csv (the particles'
mean speed in each row, at each time) is kept in validation/results/.

usage: /usr/bin/python3 validation/poiseuille.py [--no-run] [--runs wcsph@0.005,...]
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from frames import read_frame, read_grid
from runs import (each_run, keep_results, model_runs_parser, read_columns, result_path,
                  result_statistics, run_model, runs_to_tabulate, save_figure, wall_time,
                  write_table)

CASE = "poiseuille_2d"
FORCE, NU, GAP = 0.8, 0.01, 0.1
CENTRE = FORCE * GAP ** 2 / (8 * NU)
TIMES = (0.1, 0.3, 1.5)  # frames 1, 3 and 15 (output_interval 0.1 s)
END = 1.5


def series(z, t):
    u = FORCE * z * (GAP - z) / (2 * NU)
    for n in range(100):
        k = 2 * n + 1
        u = u - (4 * FORCE * GAP ** 2 / (NU * np.pi ** 3 * k ** 3) * np.sin(k * np.pi * z / GAP)
                 * np.exp(-k * k * np.pi ** 2 * NU * t / GAP ** 2))
    return u


def write_profiles(out, model, spacing):
    """out/profiles.csv: time, the row's height and the mean speed of its particles (mac: of
    its cells, the face velocities averaged to their centres)."""
    with open(os.path.join(out, "profiles.csv"), "w") as f:
        f.write("time,z,speed,near_sides\n")
        for t in TIMES:
            frame = int(round(t / 0.1))
            if model == "mac":
                points, fields = read_grid(os.path.join(out, "frames", f"grid_{frame:06d}.vti"),
                                           "velocity")
                x, z, u = points[:, 0], points[:, 2], fields["velocity"][:, 0]
            else:
                points, fields = read_frame(
                    os.path.join(out, "frames", f"frame_{frame:06d}.vtp"), "velocity", "kind")
                water = fields["kind"] == 0
                x, z, u = points[water, 0], points[water, 2], fields["velocity"][water, 0]
            rows = np.round(z / spacing - 0.5).astype(int)
            for r in np.unique(rows):
                here = rows == r
                near = here & ((x < 0.02) | (x > GAP - 0.02))
                f.write(f"{t:g},{z[here].mean():.8g},{u[here].mean():.8g},"
                        f"{u[near].mean():.8g}\n")


def figures(out, name):
    p = read_columns(result_path(out, name, "profiles.csv"))
    f = {"rms": [], "profiles": []}
    for t in TIMES:
        at = p["time"] == t
        z, u, near = p["z"][at], p["speed"][at], p["near_sides"][at]
        exact = series(z, t)
        # Every row holds as many particles (a lattice that slides along x): rows weigh alike.
        f["rms"].append(100 * np.sqrt(np.mean((u - exact) ** 2)) / CENTRE)
        f["profiles"].append((t, z, u))
        f["mean"] = 100 * (u.mean() / exact.mean() - 1)
        f["ends"] = 100 * (near.mean() / u.mean() - 1)
    return f


def main():
    parser = model_runs_parser(CASE, __doc__,
                               "wcsph@0.005,wcsph@0.0025,mps@0.005,mps@0.0025,penalty-sph@0.005,"
                               "penalty-sph@0.0025,mac@0.005,mac@0.0025")
    args = parser.parse_args()
    rows, results = [], []
    for item in runs_to_tabulate(args.runs, parser.get_default("runs")):
        model, spacing = next(each_run(item))
        name = f"f10_{model}_{spacing:g}"
        out = os.path.join(args.out, name)
        if not args.no_run and item in args.runs.split(","):
            run_model(CASE, out, model, spacing, END, args)
            write_profiles(out, model, spacing)
            keep_results(out, name, ("profiles.csv",))
        f = figures(out, name)
        statistics = result_statistics(out, name)
        wall = wall_time(statistics)
        rows.append(f"| `{model}` | {spacing:g} | " + " | ".join(f"{r:.2f} %" for r in f["rms"]) +
                    f" | {f['mean']:+.2f} % | {f['ends']:+.3f} % | {wall} |")
        results.append((model, spacing, f))
    table = ("| model | spacing [m] | RMS from the series at 0.1 s | at 0.3 s | at 1.5 s "
             "(bars: wcsph 4 %, mac 1 %) | mean speed at 1.5 s from the series' | mean speed near the "
             "sides from the whole | wall time |\n|---|---|---|---|---|---|---|---|\n" +
             "\n".join(rows) + "\n")
    write_table("validation.md", "f10-poiseuille", table)

    fig, axes = plt.subplots(1, len(TIMES), figsize=(9, 4.2), sharey=True)
    zz = np.linspace(0, GAP, 201)
    markers = "os^v<>"
    for j, (t, ax) in enumerate(zip(TIMES, axes)):
        ax.plot(series(zz, t), zz, color="k", lw=0.9, label="series" if j == 0 else None)
        for k, (model, spacing, f) in enumerate(results):
            _, z, u = f["profiles"][j]
            ax.plot(u, z, markers[k % len(markers)], ms=3, mfc="none", color=f"C{k}",
                    label=f"{model} {spacing:g} m" if j == 0 else None)
        ax.set_title(f"t = {t:g} s", fontsize=9)
        ax.set_xlabel("speed along x [m/s]")
    axes[0].set_ylabel("height above the lower plate [m]")
    fig.legend(fontsize=7, loc="lower center", ncol=4)
    save_figure(fig, "f10_poiseuille.png", rect=(0, 0.1, 1, 1))


if __name__ == "__main__":
    main()
