#!/usr/bin/env bash
# Bodies on several ranks (docs/performance.md#bodies-on-several-ranks): the debris benchmark
# (cases/bench_debris_3d.yaml, 192 cubes) is run once to START seconds on two threads with a
# checkpoint there, then resumed from it to START + SPAN seconds, REPEAT times each (default 3),
# alternated: on one rank of one thread, and on two ranks of one thread with every rank
# advancing every body (ranks.bodies: every_rank) and with each island of bodies on one rank
# (islands). Prints the medians of the wall seconds and of the first rank's stage seconds
# (bodies: the rigid step and its gather; body_loads: the loads' reduction, which also absorbs
# the ranks' imbalance), and the islands and the first rank's bodies at the end.
# usage: bench/run_bodies_on_ranks.sh [REPEAT] [START] [SPAN]
set -euo pipefail
source "$(dirname "$0")/bench_setup.sh"
repeat=${1:-3}
start=${2:-0.3}
span=${3:-0.03}
case_file=cases/bench_debris_3d.yaml
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
OMP_NUM_THREADS=2 "$sluice" run "$case_file" --out "$work/start" --threads 2 --end "$start" \
  --set checkpoint_interval="$start" > /dev/null 2>&1
end=$(/usr/bin/python3 -c "print($start + $span)")
resume() {  # NAME RANKS DIVISION: resumes a copy of the checkpoint
  rm -rf "$work/run"
  cp -r "$work/start" "$work/run"
  local launch=()
  [ "$2" -eq 1 ] || launch=(mpirun -np "$2")
  OMP_NUM_THREADS=1 "${launch[@]}" "$sluice" run "$case_file" --resume "$work/run" \
    --threads 1 --end "$end" --stats "$work/$1.json" --set "ranks={bodies: $3}" \
    > "$work/$1.log" 2>&1
}
for r in $(seq 1 "$repeat"); do
  resume "one_rank_$r" 1 islands
  resume "every_rank_$r" 2 every_rank
  resume "islands_$r" 2 islands
done
/usr/bin/python3 - "$work" "$repeat" <<'PY'
import json, statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
for name, label in (("one_rank", "1 rank x 1 thread"),
                    ("every_rank", "2 ranks x 1 thread, every rank advances every body"),
                    ("islands", "2 ranks x 1 thread, each island on one rank")):
    runs = [json.load(open(f"{work}/{name}_{r}.json")) for r in range(1, repeat + 1)]
    med = lambda f: statistics.median(f(run) for run in runs)
    each = ", ".join("%.2f" % run["wall_seconds"] for run in runs)
    print(f"{label}: {runs[0]['steps']} steps, {runs[0]['solid_substeps']} solid sub-steps, "
          f"{med(lambda r: r['wall_seconds']):.2f} s wall (runs {each}); "
          f"bodies {med(lambda r: r['stage_seconds']['bodies']):.3f} s, "
          f"body_loads {med(lambda r: r['stage_seconds']['body_loads']):.3f} s; "
          f"{runs[0]['body_islands']} islands, the first rank advancing "
          f"{runs[0]['bodies_advanced_on_first_rank']} bodies at the end")
PY
