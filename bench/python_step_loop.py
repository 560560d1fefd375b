#!/usr/bin/python3
"""What stepping from Python costs over the command line (docs/performance.md, issue 44).

Runs cases/bench_dam_break_3d.yaml to END simulated seconds on THREADS threads REPEAT times
each way, alternating: with `sluice run --stats` and with sluice.Simulation(...).run(), a
callback every 0.005 s (half the case's output interval: the step that lands on each call
is shortened, as an output's is; both took 100 steps) reading the probes, as a script would. Both report the
wall seconds of their steps alone (building the particles is not counted): the command line in
its statistics, Python in Simulation.summary(). Prints each run and the medians.

usage: /usr/bin/python3 bench/python_step_loop.py [REPEAT] [END] [THREADS]
(PYTHONPATH=build/release/python where scripts/python_path.sh has not been run)
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "build", "release", "python"))
import sluice  # noqa: E402

CASE = os.path.join(ROOT, "cases", "bench_dam_break_3d.yaml")


def command_line_run(work, end, threads):
    stats = os.path.join(work, "stats.json")
    subprocess.run([os.path.join(ROOT, "build", "release", "sluice"), "run", CASE, "--end",
                    str(end), "--threads", str(threads), "--out", os.path.join(work, "cli"),
                    "--stats", stats], check=True, capture_output=True)
    with open(stats) as f:
        run = json.load(f)
    return run["wall_seconds"], run["steps"]


def python_run(work, end, threads):
    case = sluice.Case.from_yaml(CASE)
    sim = sluice.Simulation(case, out=os.path.join(work, "python"), threads=threads, end=end)
    sim.run(every=0.005, callback=lambda s: s.probes())
    summary = sim.summary()
    return summary["wall_seconds"], summary["steps"]


def main():
    repeat = int(sys.argv[1]) if len(sys.argv) > 1 else 7
    end = float(sys.argv[2]) if len(sys.argv) > 2 else 0.01
    threads = int(sys.argv[3]) if len(sys.argv) > 3 else 2
    walls = {"command line": [], "python": []}
    with tempfile.TemporaryDirectory() as work:
        for r in range(repeat):
            for name, run in (("command line", command_line_run), ("python", python_run)):
                wall, steps = run(work, end, threads)
                walls[name].append(wall)
                print(f"run {r + 1} {name}: {wall:.3f} s wall, {steps} steps", flush=True)
    cli, py = statistics.median(walls["command line"]), statistics.median(walls["python"])
    print(f"median of {repeat}: command line {cli:.3f} s, python {py:.3f} s, "
          f"python costs {100 * (py / cli - 1):+.2f} %")


if __name__ == "__main__":
    main()
