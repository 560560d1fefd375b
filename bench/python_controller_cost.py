#!/usr/bin/python3
"""What a Python controller costs a step (docs/performance.md, issue 44).

Drives the box of tests/python's small tank (430 particles, 1 thread, 1 s: 1,800 steps) from a
controller that returns a constant velocity, REPEAT times, and prints the time spent in the
controller per call (Simulation.summary()['controller_seconds'] over the steps) beside the
wall time per step: the call's cost is the same on any case, the step's grows with it.

usage: /usr/bin/python3 bench/python_controller_cost.py [REPEAT]
"""
import os
import statistics
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "build", "release", "python"))
sys.path.insert(0, os.path.join(ROOT, "tests", "python"))
import sluice  # noqa: E402
from test_simulation import tank_with_a_paddle  # noqa: E402


def main():
    repeat = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    per_call, per_step = [], []
    with tempfile.TemporaryDirectory() as out:
        for _ in range(repeat):
            sim = sluice.Simulation(tank_with_a_paddle(), out=out, threads=1, end=1.0)
            sim.drive("paddle", lambda s: [0.05, 0.0])
            sim.run()
            summary = sim.summary()
            per_call.append(summary["controller_seconds"] / summary["steps"])
            per_step.append(summary["wall_seconds"] / summary["steps"])
            print(f"{summary['steps']} steps: {1e6 * per_call[-1]:.2f} us a call, "
                  f"{1e6 * per_step[-1]:.1f} us a step", flush=True)
    print(f"median of {repeat}: {1e6 * statistics.median(per_call):.2f} us a controller call, "
          f"{1e6 * statistics.median(per_step):.1f} us a step of "
          f"{summary['particles']} particles")


if __name__ == "__main__":
    main()
