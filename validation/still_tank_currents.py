#!/usr/bin/python3
"""F1's still tank with wcsph, watched over its 2 s: the fluid's kinetic energy for the default
model and for variants (a longer smoothing length, more artificial viscosity, half the spacing,
a quarter of the time step), the velocities of the default run when its currents are strongest,
and the kinetic energy of a 3D tank (written out by this script) at h = 1.5 and 2 dx. Writes
docs/img/f1_still_tank_currents.png and prints each run's kinetic energy.

usage: /usr/bin/python3 validation/still_tank_currents.py [--no-run]
"""
import os
import subprocess
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from frames import read_frame
from runs import ROOT, case_parser, require, run_case, save_figure

VARIANTS = [
    ("default (h = 1.5 dx, alpha = 0.02, dx = 0.025 m)", []),
    ("time step / 4 (cfl 0.05)", ["model.cfl=0.05"]),
    ("h = 2 dx", ["model.h_over_dx=2"]),
    ("alpha = 0.05", ["model.artificial_viscosity=0.05"]),
    ("alpha = 0.1", ["model.artificial_viscosity=0.1"]),
    ("dx = 0.0125 m", ["spacing=0.0125"]),
]


# A 3D tank 0.5 x 0.25 m with water 0.5 m deep, at F1's spacing (4,000 fluid particles).
TANK_3D = """name: still_tank_3d
dimension: 3
spacing: 0.025
domain: {min: [0, 0, 0], max: [0.5, 0.25, 0.6]}
end_time: 3.0
output_interval: 0.5
fluid:
  blocks:
    - {name: water, min: [0, 0, 0], max: [0.5, 0.25, 0.5]}
walls:
  - {type: tank, min: [0, 0, 0], max: [0.5, 0.25, 0.6], open: [z+]}
model:
  name: wcsph
"""


def run_tank_3d(args, h_over_dx):
    out = os.path.join(ROOT, args.out + f"_3d_h{h_over_dx}")
    if not args.no_run:
        os.makedirs(out, exist_ok=True)
        case = os.path.join(out, "still_tank_3d.yaml")
        with open(case, "w") as f:
            f.write(TANK_3D)
        subprocess.run([os.path.join(ROOT, args.sluice), "run", case, "--out", out, "--set",
                        f"model.h_over_dx={h_over_dx}"], cwd=ROOT, check=True,
                       stdout=subprocess.DEVNULL)
    return out


def kinetic_energy(out):
    path = os.path.join(out, "energy.csv")
    require(path)
    data = np.genfromtxt(path, delimiter=",", names=True)
    return data["time"], data["fluid_kinetic"]


def plot_energy(axes, out, label, times):
    """Draws the run's kinetic energy on axes and prints it at `times`."""
    t, ke = kinetic_energy(out)
    axes.semilogy(t, np.maximum(ke, 1e-8), label=label)
    print(f"{label}: fluid kinetic energy at " + ", ".join(f"{s:g}" for s in times) + " s: " +
          ", ".join(f"{np.interp(s, t, ke):.2e} J" for s in times))


def label_energy_axes(axes, mass, title):
    axes.set_xlabel("t (s)")
    axes.set_ylabel(f"fluid kinetic energy (J), {mass} kg of water")
    axes.set_title(title)
    axes.legend(fontsize=7)
    axes.grid(True, which="both", alpha=0.3)


def frame_at(out, time):
    """The fluid's positions (x, z) and velocities of the frame nearest `time`."""
    series = ET.parse(os.path.join(out, "hydrostatic_2d.pvd")).getroot().iter("DataSet")
    nearest = min(series, key=lambda d: abs(float(d.get("timestep")) - time))
    x, fields = read_frame(os.path.join(out, nearest.get("file")), "velocity", "kind")
    v = fields["velocity"]
    fluid = fields["kind"] == 0
    return float(nearest.get("timestep")), x[fluid][:, [0, 2]], v[fluid][:, [0, 2]]


def main():
    args = case_parser("still_tank_currents", __doc__).parse_args()
    fig, (energy, field, energy_3d) = plt.subplots(1, 3, figsize=(16, 4.4))
    first = None
    for k, (label, overrides) in enumerate(VARIANTS):
        out = run_case("hydrostatic_2d", args, overrides, suffix=f"_{k}")
        first = first or out
        plot_energy(energy, out, label, (0.5, 1.0, 1.5, 2.0))
    label_energy_axes(energy, 1000, "F1 still tank (wcsph): kinetic energy")

    time, x, v = frame_at(first, 1.5)
    speed = np.linalg.norm(v, axis=1)
    print(f"default run at t = {time:.2f} s: largest speed {speed.max():.4f} m/s, "
          f"rms {np.sqrt((speed ** 2).mean()):.4f} m/s")
    arrows = field.quiver(x[:, 0], x[:, 1], v[:, 0], v[:, 1], speed, cmap="viridis",
                          scale=0.6, width=0.003)
    fig.colorbar(arrows, ax=field, label="speed (m/s)")
    field.set_aspect("equal")
    field.set_xlim(0, 1)
    field.set_ylim(0, 1.05)
    field.set_xlabel("x (m)")
    field.set_ylabel("z (m)")
    field.set_title(f"default run, velocities at t = {time:.1f} s")

    for h_over_dx in (1.5, 2):
        plot_energy(energy_3d, run_tank_3d(args, h_over_dx), f"3D tank, h = {h_over_dx} dx",
                    (1.0, 2.0, 2.5, 3.0))
    label_energy_axes(energy_3d, 62.5, "3D tank 0.5 x 0.25 m, 0.5 m deep, dx = 0.025 m")
    save_figure(fig, "f1_still_tank_currents.png")


if __name__ == "__main__":
    main()
