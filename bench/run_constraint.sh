#!/usr/bin/env bash
# Constraint-fluid measurements of docs/performance.md: the constraint model against wcsph,
# REPEAT times each (default 3), alternating, on
#  1. F2 (cases/dam_break_2d.yaml at its shipped spacing) to SECONDS_2D of physical time
#     (default 0.7), and
#  2. the 3D benchmark (cases/bench_dam_break_3d.yaml) to SECONDS_3D (default 0.02);
# the median wall time per simulated second, steps, mean step, the solve's iterations per step
# and the share of the stages.
# usage: bench/run_constraint.sh [REPEAT] [SECONDS_2D] [SECONDS_3D]
set -euo pipefail
source "$(dirname "$0")/bench_setup.sh"
repeat=${1:-3}
seconds_2d=${2:-0.7}
seconds_3d=${3:-0.02}
for r in $(seq 1 "$repeat"); do
  for model in constraint wcsph; do
    "$sluice" run cases/dam_break_2d.yaml --out "$work/out" --set end_time=$seconds_2d \
      --set output_interval=1 --set probe_interval=1 --set model.name=$model \
      --stats "$work/f2_${model}_${r}.json" > /dev/null 2>&1
    "$sluice" run cases/bench_dam_break_3d.yaml --out "$work/out" --set end_time=$seconds_3d \
      --set output_interval=1 --set model.name=$model \
      --stats "$work/bench3d_${model}_${r}.json" > /dev/null 2>&1
  done
done
/usr/bin/python3 - "$work" "$repeat" <<'PY'
import json, statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
for case in ("f2", "bench3d"):
    print(f"{case}: {repeat} alternating runs each, 2 threads")
    for model in ("constraint", "wcsph"):
        runs = [json.load(open(f"{work}/{case}_{model}_{r}.json")) for r in range(1, repeat + 1)]
        per = [r["wall_seconds_per_simulated_second"] for r in runs]
        s = runs[0]
        solves = s.get("velocity_solves", {})
        stages = s["stage_seconds"]
        total = sum(stages.values())
        share = ", ".join(f"{k} {100 * v / total:.0f} %" for k, v in stages.items()
                          if v / total >= 0.02)
        extra = (f", {solves['iterations_per_solve']:.1f} iterations a step (most "
                 f"{solves['most_iterations']})" if solves else "")
        print(f"  {model}: {s['particles']} particles ({s['fluid_particles']} fluid), "
              f"{s['steps']} steps (mean {s['simulated_seconds'] / s['steps']:.3g} s){extra}; "
              f"wall s per simulated s: median {statistics.median(per):.1f} "
              f"(runs {', '.join(f'{p:.1f}' for p in per)}); "
              f"{statistics.median(r['particle_steps_per_second'] for r in runs) / 1e6:.3f} "
              f"M particle-steps/s; {share}")
        if model == "constraint":
            print(f"    fluid counters: {s['fluid_counters']}")
PY
