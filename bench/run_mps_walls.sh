#!/usr/bin/env bash
# The cost of MPS's extrapolated wall pressures (docs/performance.md): the 2D dam break
# (cases/dam_break_2d_mps.yaml, 0.3 s) and the Kleefsman case (cases/kleefsman_3d.yaml, 0.05 s)
# with wall_pressure: extrapolated (BiCGSTAB) and solved (conjugate gradient), REPEAT times each
# (default 3), alternating; the median wall time, and per step the unknowns, iterations and
# the time of the neighbour list, assembly and solve.
# usage: bench/run_mps_walls.sh [REPEAT]
set -euo pipefail
source "$(dirname "$0")/bench_setup.sh"
repeat=${1:-3}
for r in $(seq 1 "$repeat"); do
  for walls in extrapolated solved; do
    "$sluice" run cases/dam_break_2d_mps.yaml --out "$work/out" --set end_time=0.3 \
      --set model.wall_pressure=$walls --stats "$work/2d_${walls}_${r}.json" > /dev/null
    "$sluice" run cases/kleefsman_3d.yaml --out "$work/out" --set end_time=0.05 \
      --set output_interval=1 --set checkpoint_interval=0 --set "model={name: mps}" \
      --set model.wall_pressure=$walls --stats "$work/3d_${walls}_${r}.json" > /dev/null
  done
done
/usr/bin/python3 - "$work" "$repeat" <<'PY'
import json, statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
print(f"{'case':>4} {'walls':>12} {'wall s (median)':>15} {'steps':>5} {'unknowns':>8} {'iter':>6}"
      f" {'list ms':>7} {'assem ms':>8} {'solve ms':>8} {'total ms':>8} {'Mp-st/s':>7}")
for case in ("2d", "3d"):
    for walls in ("extrapolated", "solved"):
        runs = [json.load(open(f"{work}/{case}_{walls}_{r}.json")) for r in range(1, repeat + 1)]
        s = sorted(runs, key=lambda x: x["wall_seconds"])[len(runs) // 2]
        st, n, c = s["stage_seconds"], s["steps"], s["fluid_counters"]
        ms = lambda v: 1e3 * v / n
        print(f"{case:>4} {walls:>12} {s['wall_seconds']:>15.2f} {n:>5}"
              f" {c['pressure_unknowns_per_solve']:>8.0f} {c['pressure_iterations_per_solve']:>6.1f}"
              f" {ms(st.get('neighbour_list', 0)):>7.2f} {ms(st.get('assembly', 0)):>8.2f}"
              f" {ms(st.get('solve', 0)):>8.2f} {ms(sum(st.values())):>8.2f}"
              f" {s['particle_steps_per_second'] / 1e6:>7.3f}")
PY
