#!/usr/bin/python3
"""Granular model (issue 11) measurements of docs/performance.md, with the release build:

 1. scale: a pool of frictionless spheres n x n x n (n = 22, 46, 100 ... : 10,000 to 1,000,000
    spheres, 0.01 m apart and touching, so that every contact carries load) in a tank, one step from rest of collision detection plus
    exactly 100 APGD iterations (tolerance 1e-12 m/s, never reached), then a second, warm-started one: wall time of
    each step's `bodies` stage (detection and solve), the whole run's peak memory (RSS) and
    bytes per sphere;
 2. solvers: a pool of 100 x 100 x 10 spheres (100,000, ten deep) from rest, one step, APGD
    against projected Jacobi: iterations to a residual of 1e-4 m/s (up to 20,000).

usage: /usr/bin/python3 bench/run_granular.py [scale|solvers|all] [--largest N]
"""
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SLUICE = os.path.join(ROOT, "build", "release", "sluice")


def pool_case(nx, ny, nz, dx=0.01):
    width, depth, height = nx * dx, ny * dx, nz * dx
    return f"""name: granular_pool
dimension: 3
spacing: {dx}
domain: {{min: [0, 0, 0], max: [{width}, {depth}, {2 * height}]}}
end_time: 1
output_interval: 1
fluid:
  blocks:
    - {{min: [0, 0, 0], max: [{width}, {depth}, {height}]}}
walls:
  - {{type: tank, min: [0, 0, 0], max: [{width}, {depth}, {2 * height}], open: [z+]}}
model:
  name: granular
  time_step: 0.001
  radius: {dx / 2}
  jitter: 0
  restitution: 0
"""


def run(case_text, work, name, sets, steps):
    case = os.path.join(work, name + ".yaml")
    with open(case, "w") as f:
        f.write(case_text)
    stats = os.path.join(work, name + ".json")
    command = ["/usr/bin/time", "-f", "%M", SLUICE, "run", case, "--out",
               os.path.join(work, "out_" + name), "--end", str(0.001 * steps), "--stats", stats]
    for s in sets:
        command += ["--set", s]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{name}: sluice failed\n{done.stderr[-2000:]}")
    peak_kib = int(done.stderr.strip().splitlines()[-1])
    with open(stats) as f:
        return json.load(f), peak_kib * 1024


def scale(work, largest):
    print("| spheres | contacts per step | first step [s] | second step [s] | peak memory [MB] "
          "| bytes per sphere |")
    print("|---|---|---|---|---|---|")
    for n in [22, 46, 70, 100]:
        if n ** 3 > largest:
            break
        sets = ["contact.complementarity.max_iterations=100",
                "contact.complementarity.tolerance=1e-12"]
        one, _ = run(pool_case(n, n, n), work, f"pool{n}_1", sets, 1)
        two, peak = run(pool_case(n, n, n), work, f"pool{n}_2", sets, 2)
        first = one["stage_seconds"]["bodies"]
        second = two["stage_seconds"]["bodies"] - first
        spheres = two["fluid_particles"]
        contacts = two["fluid_counters"]["sphere_contacts_per_step"]
        print(f"| {spheres:,} | {contacts:,.0f} | {first:.2f} | {second:.2f} | {peak / 1e6:.0f} "
              f"| {peak / spheres:.0f} |", flush=True)


def solvers(work):
    print("| solver | iterations to 1e-4 m/s | residual reached [m/s] | solve [s] |")
    print("|---|---|---|---|")
    for solver in ["apgd", "jacobi"]:
        sets = [f"contact.complementarity.solver={solver}",
                "contact.complementarity.max_iterations=20000",
                "contact.complementarity.tolerance=1e-4"]
        stats, _ = run(pool_case(100, 100, 10), work, f"solver_{solver}", sets, 1)
        v = stats["velocity_solves"]
        print(f"| {solver} | {v['most_iterations']:.0f} | {v['largest_residual']:.3g} "
              f"| {stats['stage_seconds']['bodies']:.2f} |", flush=True)


def main():
    what = sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("--") else "all"
    largest = int(sys.argv[sys.argv.index("--largest") + 1]) if "--largest" in sys.argv else 10**7
    with tempfile.TemporaryDirectory() as work:
        if what in ("scale", "all"):
            scale(work, largest)
        if what in ("solvers", "all"):
            solvers(work)


if __name__ == "__main__":
    main()
