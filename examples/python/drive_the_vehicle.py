#!/usr/bin/python3
"""A controller that drives the fording vehicle to a target speed.

cases/fording.yaml tows a four-wheeled vehicle through water 0.16 m deep by a prescribed
carriage, joined to the chassis by a vertical slider (its suspension). Here a Python controller
drives the carriage instead of the case's constant velocity: before every step it asks for the
speed that closes on TARGET at no more than ACCELERATION, and the vehicle follows. Every 0.02 s
the script records the carriage's and the chassis's speeds and the water's drag on the vehicle
(chassis and wheels, against the travel). Plots both against time into FIGURE (default
OUT/drive_the_vehicle.png) and prints the mean drag once at speed.

usage: /usr/bin/python3 examples/python/drive_the_vehicle.py [--quick] [--out DIR] [--figure PNG]
  --quick: 0.08 m particles to 1 s (about 10 s on 2 cores; what CI runs); without it the case's
           0.04 m to 2 s (about 20 minutes)
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import sluice

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TARGET, ACCELERATION = 1.5, 3.0  # [m/s], [m/s^2]
VEHICLE = ("chassis", "wheel_fl", "wheel_fr", "wheel_rl", "wheel_rr")


class Cruise:
    """Speeds up at ACCELERATION until TARGET, from the last speed it asked for."""

    def __init__(self):
        self.speed, self.time = 0.0, 0.0

    def __call__(self, sim):
        step = sim.time - self.time
        self.speed = min(TARGET, self.speed + ACCELERATION * step)
        self.time = sim.time
        return [self.speed, 0.0, 0.0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out", default=os.path.join(ROOT, "out", "examples", "drive_the_vehicle"))
    parser.add_argument("--figure", help="the plot's path (default OUT/drive_the_vehicle.png)")
    args = parser.parse_args()
    spacing, end = (0.08, 1.0) if args.quick else (0.04, 2.0)
    case = sluice.Case.from_yaml(os.path.join(ROOT, "cases", "fording.yaml"),
                                 set={"spacing": spacing, "end_time": end,
                                      "checkpoint_interval": 0})
    sim = sluice.Simulation(case, out=args.out, progress=not args.quick)
    sim.drive("carriage", Cruise())
    rows = []

    def record(s):
        bodies = s.bodies()
        drag = -sum(bodies[name]["fluid_force"][0] for name in VEHICLE)
        rows.append((s.time, bodies["carriage"]["velocity"][0], bodies["chassis"]["velocity"][0],
                     drag))

    sim.run(every=0.02, callback=record)
    t, carriage, chassis, drag = np.array(rows).T
    at_speed = t > TARGET / ACCELERATION + 0.2
    print(f"{spacing:g} m: chassis at {chassis[-1]:.3f} m/s (target {TARGET}); mean drag at speed "
          f"{drag[at_speed].mean():.1f} N; {sim.summary()['controller_seconds'] * 1e3:.1f} ms "
          f"in the controller over {sim.steps} steps")

    fig, (speed_axes, drag_axes) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    speed_axes.plot(t, carriage, label="carriage (commanded)")
    speed_axes.plot(t, chassis, "--", label="chassis")
    speed_axes.axhline(TARGET, color="k", lw=0.8, label="target")
    speed_axes.set_ylabel("speed [m/s]")
    speed_axes.legend()
    drag_axes.plot(t, drag)
    drag_axes.set_xlabel("t [s]")
    drag_axes.set_ylabel("water's drag on the vehicle [N]")
    speed_axes.set_title(f"The fording vehicle driven from Python ({spacing:g} m particles)")
    for ax in (speed_axes, drag_axes):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    path = args.figure or os.path.join(args.out, "drive_the_vehicle.png")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
