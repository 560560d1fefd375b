#!/usr/bin/python3
"""B1 of VALIDATION.md: a 1 m x 1 m box of density 700 kg/m^3 in a 2D tank 3 m wide with water
2 m deep (cases/floating_box_2d.yaml), released at a draft of 0.60 m; Archimedes gives 0.70 m.
Plots the draft over time, from mass conservation and from the water gauges, and the sideways
drift. Writes docs/img/floating_box_2d.png.

The draft from mass conservation: the water's area A_w is the initial water minus the part of
the box under it, 3 * 2 - 0.6 * 1 = 5.4 m^2 (nominal: the fluid is particles at spacing
0.05 m). With water level h and draft d, 3 h = A_w + 1 * d and d = h - (z - 0.5), so
d = (A_w / 3 - z + 0.5) / (1 - 1/3).

usage: /usr/bin/python3 validation/floating_box_2d.py [--out DIR] [--no-run] [--sluice PATH]
"""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from probes_csv import read_probe
from runs import case_parser, read_body, require, run_case, save_figure

# cases/floating_box_2d.yaml
TANK_WIDTH, BOX_SIZE, X_CENTRE = 3.0, 1.0, 1.5
WATER_AREA = TANK_WIDTH * 2.0 - 0.6 * BOX_SIZE
ARCHIMEDES = 0.70 * BOX_SIZE  # relative density 0.7
AVERAGE_OVER = 3.0  # s, at the end of the run


def main():
    args = case_parser("floating_box_2d", __doc__.splitlines()[0]).parse_args()
    out = run_case("floating_box_2d", args)
    data = read_body(out, "box")
    probes = os.path.join(out, "probes.csv")
    require(probes)
    t, x, z = data["time"], data["x"], data["z"]
    bottom = z - BOX_SIZE / 2
    draft = (WATER_AREA / TANK_WIDTH - bottom) / (1 - BOX_SIZE / TANK_WIDTH)

    probe_t, left = read_probe(probes, "gauge_left")
    _, right = read_probe(probes, "gauge_right")
    gauge_draft = (np.array(left) + np.array(right)) / 2 - np.interp(probe_t, t, bottom)

    late = t >= t[-1] - AVERAGE_OVER
    mean = draft[late].mean()
    drift = np.abs(x - X_CENTRE).max()
    print(f"mean draft over the last {AVERAGE_OVER:g} s {mean:.4f} m against {ARCHIMEDES:.2f} m "
          f"({100 * (mean / ARCHIMEDES - 1):+.2f} %); range {draft[late].min():.4f} to "
          f"{draft[late].max():.4f} m")
    print(f"largest sideways drift |x - {X_CENTRE}| = {1e3 * drift:.2f} mm")

    fig, (top, low) = plt.subplots(2, 1, figsize=(6.4, 5.6), sharex=True,
                                   gridspec_kw={"height_ratios": [3, 1]})
    top.axhspan(0.97 * ARCHIMEDES, 1.03 * ARCHIMEDES, color="0.9", label="+-3 %")
    top.axhline(ARCHIMEDES, color="k", lw=0.8, label=f"Archimedes, {ARCHIMEDES:.2f} m")
    top.plot(probe_t, gauge_draft, "-", lw=0.7, color="tab:orange",
             label="from the gauges (quantised to dx/2)")
    top.plot(t, draft, "-", lw=2, color="tab:blue", label="from mass conservation")
    top.axvspan(t[-1] - AVERAGE_OVER, t[-1], color="tab:blue", alpha=0.05)
    top.text(t[-1] - AVERAGE_OVER + 0.05, 0.98,
             f"mean over the last {AVERAGE_OVER:g} s: {mean:.3f} m "
             f"({100 * (mean / ARCHIMEDES - 1):+.1f} %)", fontsize=8,
             va="top", transform=top.get_xaxis_transform())
    top.set_ylabel("draft [m]")
    top.legend(loc="lower right", fontsize=8)
    top.grid(alpha=0.3)
    low.plot(t, 1e3 * (x - X_CENTRE), "-", color="tab:green")
    low.set_ylabel(f"x - {X_CENTRE} [mm]")
    low.set_xlabel("time [s]")
    low.grid(alpha=0.3)
    fig.suptitle("B1 floating box (2D), density 700 kg/m^3")
    save_figure(fig, "floating_box_2d.png")


if __name__ == "__main__":
    main()
