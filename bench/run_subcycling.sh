#!/usr/bin/env bash
# C6's speed-up (docs/performance.md): cases/subcycling_2d.yaml with solid sub-cycling and with
# the fluid stepping at the solid step (contact.subcycling=false), REPEAT times each (default 3),
# alternating so that machine noise hits both alike. Prints each run and the medians.
# usage: bench/run_subcycling.sh [REPEAT]
set -euo pipefail
source "$(dirname "$0")/bench_setup.sh"
repeat=${1:-3}
for r in $(seq 1 "$repeat"); do
  for mode in true false; do
    "$sluice" run cases/subcycling_2d.yaml --set contact.subcycling=$mode --out "$work/out" \
      --stats "$work/stats_${mode}_${r}.json" > /dev/null 2>&1
  done
done
/usr/bin/python3 - "$work" "$repeat" <<'PY'
import json, statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
medians = {}
for mode, label in (("true", "sub-cycled"), ("false", "solid step everywhere")):
    runs = [json.load(open(f"{work}/stats_{mode}_{r}.json")) for r in range(1, repeat + 1)]
    for run in runs:
        print(f"  {label}: {run['wall_seconds']:.2f} s wall")
    medians[mode] = statistics.median(run["wall_seconds"] for run in runs)
    print(f"{label}: {runs[0]['steps']} fluid steps, {runs[0]['solid_substeps']} solid steps, "
          f"median {medians[mode]:.2f} s wall")
print(f"speed-up of sub-cycling: {medians['false'] / medians['true']:.2f}x")
PY
