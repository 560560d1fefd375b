#!/usr/bin/python3
"""A parameter study from Python: a floating box's draft against its density.

Runs cases/floating_box_2d.yaml (a 1 m box in a 3 m tank of water 2 m deep) once for each
density, the box starting at its Archimedes draft plus 5 cm, and reads the box's height and the
two gauges' water level every 0.05 s; the draft is the level less the box's underside, averaged
over the run's second half. Plots the drafts against Archimedes' (density / 1000 m) into
FIGURE (default OUT/floating_box_draft.png) and prints a table.

usage: /usr/bin/python3 examples/python/floating_box_draft.py [--quick] [--out DIR] [--figure PNG]
  --quick: 0.1 m particles, 1.5 s, three densities (3 s on 2 cores; what CI runs); without it
           0.05 m, 4 s, five densities (45 s; docs/python.md's figure:
           --figure docs/img/python_floating_box_draft.png)
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import sluice

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CASE = os.path.join(ROOT, "cases", "floating_box_2d.yaml")
SIZE = 1.0  # the box's height [m]


def measured_draft(density, spacing, end, out):
    """The box's mean draft [m] over the second half of a run at `density` [kg/m^3]."""
    archimedes = density / 1000 * SIZE
    centre = 2.0 - archimedes + SIZE / 2 + 0.05
    case = sluice.Case.from_yaml(CASE, set={"spacing": spacing, "end_time": end,
                                            "bodies.0.density": density,
                                            "bodies.0.position": [1.5, centre]})
    sim = sluice.Simulation(case, out=out)
    drafts = []

    def record(s):
        if s.time > end / 2:
            level = np.mean(list(s.probes().values()))  # the two gauges [m]
            underside = s.bodies()["box"]["position"][2] - SIZE / 2
            drafts.append(level - underside)

    sim.run(every=0.05, callback=record)
    return float(np.mean(drafts))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "examples"))
    parser.add_argument("--figure", help="the plot's path (default OUT/floating_box_draft.png)")
    args = parser.parse_args()
    spacing, end = (0.1, 1.5) if args.quick else (0.05, 4.0)
    densities = [300, 600, 900] if args.quick else [300, 450, 600, 750, 900]
    drafts = []
    print("| density [kg/m^3] | draft [m] | Archimedes [m] | from it |")
    print("|---|---|---|---|")
    for density in densities:
        draft = measured_draft(density, spacing, end,
                               os.path.join(args.out, f"floating_box_{density}"))
        drafts.append(draft)
        archimedes = density / 1000 * SIZE
        print(f"| {density} | {draft:.3f} | {archimedes:.3f} | "
              f"{100 * (draft / archimedes - 1):+.1f} % |", flush=True)
    fig, ax = plt.subplots(figsize=(6, 4))
    line = np.linspace(0, 1000, 2)
    ax.plot(line, line / 1000 * SIZE, "k-", label="Archimedes: density / 1000 x height")
    ax.plot(densities, drafts, "o", label=f"sluice (wcsph, {spacing:g} m particles)")
    ax.set_xlabel("box density [kg/m³]")
    ax.set_ylabel("draft [m]")
    ax.set_title("A 1 m box floating in 2 m of water (2D)")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    path = args.figure or os.path.join(args.out, "floating_box_draft.png")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
