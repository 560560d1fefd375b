#!/usr/bin/env bash
# The throughput benchmark of docs/performance.md: cases/bench_dam_break_3d.yaml for 0.025 s of
# physical time on 1 and 2 threads, REPEAT times each (default 3), alternating thread counts so
# that machine noise hits both alike. Prints each run and the medians. With OTHER (the path of
# another build's sluice, e.g. of an older commit in a git worktree) every run of this build is
# followed by the same run of OTHER, and both are reported.
# usage: bench/run_benchmark.sh [REPEAT] [END_TIME] [OTHER]
set -euo pipefail
source "$(dirname "$0")/bench_setup.sh"
repeat=${1:-3}
end=${2:-0.025}
builds=("$sluice")
[ -n "${3:-}" ] && builds+=("$(realpath "$3")")
for r in $(seq 1 "$repeat"); do
  for t in 1 2; do
    for b in "${!builds[@]}"; do
      "${builds[$b]}" run cases/bench_dam_break_3d.yaml --end "$end" --threads "$t" \
        --out "$work/out" --stats "$work/stats_${b}_${t}_${r}.json" > /dev/null 2>&1
    done
  done
done
/usr/bin/python3 - "$work" "$repeat" "${builds[@]}" <<'PY'
import json, statistics, sys
work, repeat, builds = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
for b, build in enumerate(builds):
    if len(builds) > 1:
        print(f"== {build}")
    for t in (1, 2):
        runs = [json.load(open(f"{work}/stats_{b}_{t}_{r}.json")) for r in range(1, repeat + 1)]
        med = lambda key: statistics.median(run[key] for run in runs)
        print(f"threads {t}: {runs[0]['particles']} particles ({runs[0]['fluid_particles']} fluid), "
              f"{runs[0]['steps']} steps")
        for run in runs:
            print(f"  run: {run['wall_seconds']:.2f} s wall, "
                  f"{run['particle_steps_per_second'] / 1e6:.3f} M particle-steps/s")
        print(f"  median: {med('wall_seconds'):.2f} s wall, "
              f"{med('particle_steps_per_second') / 1e6:.3f} M particle-steps/s (all particles), "
              f"{med('fluid_particle_steps_per_second') / 1e6:.3f} M (fluid only), "
              f"{med('wall_seconds_per_simulated_second'):.0f} s wall per simulated s")
        stages = runs[0]["stage_seconds"].keys()
        total = sum(statistics.median(run["stage_seconds"][s] for run in runs) for s in stages)
        shares = ", ".join(
            f"{s} {100 * statistics.median(run['stage_seconds'][s] for run in runs) / total:.1f} %"
            for s in stages)
        print(f"  time per stage (median): {shares}")
PY
