#!/usr/bin/env bash
# The cost of the grid model's volume correction (docs/performance.md): cases/bench_mac_3d.yaml
# at 1/32 m cells (32^3) to END s (default 0.3) on one thread, with and without
# model.volume_correction, REPEAT times each (default 3), alternating so that machine noise
# hits both alike. Prints each run and the medians of the wall time and of the advection stage
# (which holds the correction).
# usage: bench/run_mac_volume_correction.sh [REPEAT] [END]
set -euo pipefail
source "$(dirname "$0")/bench_setup.sh"
repeat=${1:-3}
end=${2:-0.3}
for r in $(seq 1 "$repeat"); do
  for mode in false true; do
    "$sluice" run cases/bench_mac_3d.yaml --set spacing=0.03125 --set output_interval=1 \
      --set "model={name: mac, volume_correction: $mode}" --end "$end" --threads 1 \
      --out "$work/out" --stats "$work/stats_${mode}_${r}.json" > /dev/null 2>&1
  done
done
/usr/bin/python3 - "$work" "$repeat" <<'PY'
import json, statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
medians = {}
for mode, label in (("false", "without"), ("true", "with the volume correction")):
    runs = [json.load(open(f"{work}/stats_{mode}_{r}.json")) for r in range(1, repeat + 1)]
    for run in runs:
        print(f"  {label}: {run['wall_seconds']:.2f} s wall, advection "
              f"{run['stage_seconds']['advect']:.2f} s, {run['steps']} steps")
    wall = statistics.median(run["wall_seconds"] for run in runs)
    advect = statistics.median(run["stage_seconds"]["advect"] for run in runs)
    steps = runs[0]["steps"]
    medians[mode] = wall / steps
    print(f"{label}: median {wall:.2f} s wall ({1e3 * wall / steps:.1f} ms a step), advection "
          f"{advect:.2f} s, {runs[0]['fluid_counters']['marker particles']:.0f} markers at the end")
print(f"cost of the correction per step: {100 * (medians['true'] / medians['false'] - 1):+.1f} %")
PY
