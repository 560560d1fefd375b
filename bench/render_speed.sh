#!/usr/bin/env bash
# How fast `sluice render` draws a frame (docs/performance.md, issue 44): the benchmark case
# (261,950 particles) run for 0.002 s (two frames), then drawn from the side, the top and an
# isometric corner; render prints its median seconds a frame.
# usage: bench/render_speed.sh
set -euo pipefail
source "$(dirname "$0")/bench_setup.sh"
"$sluice" run cases/bench_dam_break_3d.yaml --end 0.002 --threads 2 --out "$work/run" > /dev/null 2>&1
for view in side top iso; do
  "$sluice" render "$work/run" --field pressure --view "$view"
done
