#!/usr/bin/python3
"""A1: the stability of a vehicle parked broadside to a current (issue 43's application).

Runs cases/broadside_vehicle.yaml (the parked vehicle turned across a 1.6 m channel, wheels
braked, tyre-bed friction 0.5, weight 708 N; wcsph at 0.04 m) with `sluice sweep` over the water's
depth (0.12, 0.16, 0.20, 0.24 m: the block's top and both boundaries' depth, one axis) and the
current's speed (0.4, 0.8, 1.2 m/s: the inlet's and the block's, one axis), twice: free, and held
(every body fixed, no joints). Each free run to 2.5 s says what the vehicle did: it floats where
its chassis rose more than 0.02 m, slides where it moved more than 0.05 m downstream (a run that
the current carries the vehicle out of the domain stops there: it slid), and holds otherwise. Each held run gives the water's mean drag D and lift L (buoyancy included) on the
vehicle over 1.5-2.5 s, and the force balance predicts from them: floating where L > W,
sliding where D > mu (W - L), mu = 0.5. Writes docs/validation.md's table a1-stability and
docs/img/a1_stability_chart.png (the chart of what the free runs did, with the lines where the
held runs' force balance changes sign; and the balance itself against the speed).

usage: /usr/bin/python3 validation/stability_chart.py [--no-run] [--out out/validation/stability]
"""
import argparse
import csv
import os
import re
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from runs import ROOT, read_columns, save_figure, write_table

CASE = os.path.join("cases", "broadside_vehicle.yaml")
DEPTHS = (0.12, 0.16, 0.2, 0.24)
SPEEDS = (0.4, 0.8, 1.2)
DEPTH_KEY = "fluid.blocks.0.max.2+boundaries.0.depth+boundaries.1.depth"
SPEED_KEY = "boundaries.0.mean_speed+fluid.blocks.0.velocity.0"
HELD = ["joints=[]"] + [f"bodies.{b}.motion=fixed" for b in range(5)]
MU = 0.5
G = 9.81
# The case's bodies: a 0.48 x 1.04 x 0.24 m chassis of density 300, four wheels of radius 0.2 m,
# 0.12 m wide, of density 600.
WEIGHT = G * (0.48 * 1.04 * 0.24 * 300 + 4 * np.pi * 0.2 ** 2 * 0.12 * 600)
START_X, START_Z = 1.0, 0.28  # the chassis's centre
BODIES = ("chassis", "wheel_fl", "wheel_fr", "wheel_rl", "wheel_rr")
FLOAT_RISE, SLIDE_RUN = 0.02, 0.05  # [m]
AVERAGE_FROM = 1.5  # [s]


def sweep(out, extra):
    sets = ["--set", f"{DEPTH_KEY}={','.join(f'{d:g}' for d in DEPTHS)}",
            "--set", f"{SPEED_KEY}={','.join(f'{v:g}' for v in SPEEDS)}"]
    for item in extra:
        sets += ["--set", item]
    subprocess.run([os.path.join(ROOT, "build", "release", "sluice"), "sweep", CASE,
                    "--out", out] + sets, cwd=ROOT, stdout=subprocess.DEVNULL)


def runs_of(out):
    """{(depth, speed): run directory} from the sweep's summary.csv."""
    with open(os.path.join(out, "summary.csv")) as f:
        rows = list(csv.DictReader(f))
    return {(float(r[DEPTH_KEY]), float(r[SPEED_KEY])):
            (os.path.join(out, f"run_{int(r['run']):03d}"), r["status"]) for r in rows}


def free_outcome(run):
    """(what the vehicle did, how far downstream it moved, how high it rose, what the bed
    carried at the end, and where the run stopped early, the time it was carried out of the
    domain, else None)."""
    chassis = read_columns(os.path.join(run, "bodies", "chassis.csv"))
    run_x = chassis["x"][-1] - START_X
    rise = chassis["z"].max() - START_Z
    # What the bed carries: the bodies' vertical contact force over the run's last 0.5 s.
    late = chassis["time"] >= chassis["time"][-1] - 0.5
    bed = sum(read_columns(os.path.join(run, "bodies", f"{b}.csv"))["contact_fz"][late].mean()
              for b in BODIES)
    what = "floats" if rise > FLOAT_RISE else "slides" if run_x > SLIDE_RUN else "holds"
    with open(run + ".log") as f:
        out = re.search(r"diverged at step \d+, t = ([0-9.]+) s: body .* it left the domain",
                        f.read())
    return what, run_x, rise, bed, float(out.group(1)) if out else None


def held_forces(run):
    loads = read_columns(os.path.join(run, "loads.csv"))
    late = loads["time"] >= AVERAGE_FROM
    return loads["all_bodies_drag"][late].mean(), loads["all_bodies_lift"][late].mean()


def predicted(drag, lift):
    if lift > WEIGHT:
        return "floats"
    return "slides" if drag > MU * (WEIGHT - lift) else "holds"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--out", default=os.path.join("out", "validation", "stability"))
    parser.add_argument("--no-run", action="store_true")
    args = parser.parse_args()
    out = os.path.join(ROOT, args.out)
    free_out, held_out = os.path.join(out, "free"), os.path.join(out, "held")
    if not args.no_run:
        sweep(free_out, [])
        sweep(held_out, HELD)
    free, held = runs_of(free_out), runs_of(held_out)

    rows, grid = [], {}
    for d in DEPTHS:
        for v in SPEEDS:
            (free_run, free_status), (held_run, held_status) = free[(d, v)], held[(d, v)]
            # A free run stops where the current carries the vehicle out of the domain.
            what, run_x, rise, bed, out_at = free_outcome(free_run)
            if held_status != "done" or (free_status != "done" and out_at is None):
                rows.append(f"| {d:g} | {v:g} | {held_status} | | | | {free_status} | | | | |")
                continue
            drag, lift = held_forces(held_run)
            guess = predicted(drag, lift)
            grid[(d, v)] = (drag, lift, what, guess)
            did = what + (f" (out of the domain at {out_at:.1f} s)" if out_at else "")
            rows.append(f"| {d:g} | {v:g} | {drag:.0f} | {lift:.0f} | {MU * (WEIGHT - lift):.0f} | "
                        f"{guess} | {did} | {run_x:+.3f} | {rise:+.3f} | {bed:.0f} | "
                        f"{'yes' if what == guess else '**no**'} |")
    agree = sum(1 for g in grid.values() if g[2] == g[3])
    stable = sum(1 for g in grid.values() if (g[2] == "holds") == (g[3] == "holds"))
    table = ("| depth [m] | speed [m/s] | held drag D [N] | held lift L [N] | mu (W - L) [N] "
             "| force balance says | free run did | moved downstream [m] | rose [m] | bed "
             "carries at the end [N] | agree |\n|---|---|---|---|---|---|---|---|---|---|---|\n" +
             "\n".join(rows) +
             f"\n\nW = {WEIGHT:.0f} N, mu = {MU}: {agree} of {len(grid)} runs do what the balance "
             f"says; {stable} of {len(grid)} hold where it says they hold and move where it says "
             f"they move.\n")
    write_table("validation.md", "a1-stability", table)

    fig, (chart, balance) = plt.subplots(1, 2, figsize=(10, 4.3))
    markers = {"holds": ("o", "C2"), "slides": (">", "C1"), "floats": ("^", "C0")}
    for (d, v), (drag, lift, what, guess) in grid.items():
        marker, color = markers[what]
        chart.plot(v, d, marker, color=color, ms=9, mfc=color if what == guess else "none")
    for what, (marker, color) in markers.items():
        chart.plot([], [], marker, color=color, label=f"free run {what}")
    # Where the held runs' balance changes sign, interpolated over the grid.
    if len(grid) == len(DEPTHS) * len(SPEEDS):
        V, D = np.meshgrid(SPEEDS, DEPTHS)
        slide = np.array([[grid[(d, v)][0] - MU * (WEIGHT - grid[(d, v)][1]) for v in SPEEDS]
                          for d in DEPTHS])
        lift = np.array([[grid[(d, v)][1] - WEIGHT for v in SPEEDS] for d in DEPTHS])
        chart.contour(V, D, slide, levels=[0], colors="C1", linestyles="--")
        chart.contour(V, D, lift, levels=[0], colors="C0", linestyles=":")
        chart.plot([], [], "--", color="C1", label="held: D = mu (W - L)")
        chart.plot([], [], ":", color="C0", label="held: L = W")
    chart.set_xlim(min(SPEEDS) - 0.45, max(SPEEDS) + 0.1)  # room for the legend on the left
    chart.set_ylim(min(DEPTHS) - 0.02, max(DEPTHS) + 0.02)
    chart.set_xlabel("current's speed [m/s]")
    chart.set_ylabel("water depth [m]")
    chart.set_title("filled: as the held vehicle's force balance says", fontsize=8)
    chart.legend(fontsize=7, loc="upper left")
    for k, d in enumerate(DEPTHS):
        vs = [v for v in SPEEDS if (d, v) in grid]
        balance.plot(vs, [grid[(d, v)][0] for v in vs], "o-", color=f"C{k}",
                     label=f"D, depth {d:g} m")
        balance.plot(vs, [MU * (WEIGHT - grid[(d, v)][1]) for v in vs], "s--", color=f"C{k}",
                     mfc="none", label=f"mu (W - L), {d:g} m")
    balance.axhline(0, color="k", lw=0.6)
    balance.set_xlabel("current's speed [m/s]")
    balance.set_ylabel("force [N] (held vehicle, 1.5-2.5 s)")
    balance.legend(fontsize=6, ncol=2)
    save_figure(fig, "a1_stability_chart.png")


if __name__ == "__main__":
    main()
