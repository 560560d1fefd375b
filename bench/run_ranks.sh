#!/usr/bin/env bash
# Scaling over MPI ranks (docs/performance.md#several-ranks-issue-42): the benchmark case
# (cases/bench_dam_break_3d.yaml) for END seconds (default 0.01) on one rank of one thread, one
# rank of two threads and two ranks of one thread (strong scaling: the same particles), and
# twice the particles (the spacing over 2^(1/3)) on two ranks of one thread (weak scaling: the
# same particles a rank); REPEAT times each (default 3), alternated so that machine noise hits
# all alike. Prints the medians: wall seconds, particle-steps per second, the efficiency against
# one rank of one thread, and a split run's seconds of waiting for the busier rank, of
# migration, halo and balance. Options after END_TIME go to every run (another model:
# --set model.name=mps); SPACING sets the case's spacing (the weak runs' is finer by 2^(1/3)).
# usage: [SPACING=S] bench/run_ranks.sh [REPEAT] [END_TIME] [RUN OPTIONS...]
set -euo pipefail
source "$(dirname "$0")/bench_setup.sh"
repeat=${1:-3}
end=${2:-0.01}
shift $(($# < 2 ? $# : 2))
options=("$@")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
spacing=${SPACING:-$(sed -n 's/^spacing: *\([0-9.]*\).*/\1/p' cases/bench_dam_break_3d.yaml)}
options+=(--set spacing="$spacing")
fine=$(/usr/bin/python3 -c "print($spacing / 2 ** (1 / 3))")
for r in $(seq 1 "$repeat"); do
  OMP_NUM_THREADS=1 "$sluice" run cases/bench_dam_break_3d.yaml --end "$end" --threads 1 \
    --out "$work/out" --stats "$work/one_thread_$r.json" "${options[@]}" > /dev/null 2>&1
  OMP_NUM_THREADS=2 "$sluice" run cases/bench_dam_break_3d.yaml --end "$end" --threads 2 \
    --out "$work/out" --stats "$work/two_threads_$r.json" "${options[@]}" > /dev/null 2>&1
  OMP_NUM_THREADS=1 mpirun -np 2 "$sluice" run cases/bench_dam_break_3d.yaml --end "$end" \
    --threads 1 --out "$work/out" --stats "$work/two_ranks_$r.json" "${options[@]}" > /dev/null 2>&1
  OMP_NUM_THREADS=1 mpirun -np 2 "$sluice" run cases/bench_dam_break_3d.yaml --end "$end" \
    --threads 1 --out "$work/out" --stats "$work/two_ranks_twice_$r.json" "${options[@]}" \
    --set spacing="$fine" > /dev/null 2>&1
done
/usr/bin/python3 - "$work" "$repeat" <<'PY'
import json, statistics, sys
work, repeat = sys.argv[1], int(sys.argv[2])
runs = {name: [json.load(open(f"{work}/{name}_{r}.json")) for r in range(1, repeat + 1)]
        for name in ("one_thread", "two_threads", "two_ranks", "two_ranks_twice")}
med = lambda name, key: statistics.median(run[key] for run in runs[name])
base = med("one_thread", "particle_steps_per_second")
for name, label, workers in (("one_thread", "1 rank x 1 thread", 1),
                             ("two_threads", "1 rank x 2 threads", 2),
                             ("two_ranks", "2 ranks x 1 thread", 2),
                             ("two_ranks_twice", "2 ranks x 1 thread, twice the particles", 2)):
    rate = med(name, "particle_steps_per_second")
    first = runs[name][0]
    each = ", ".join("%.2f" % run["wall_seconds"] for run in runs[name])
    print(f"{label}: {first['particles']} particles, {first['steps']} steps, "
          f"{med(name, 'wall_seconds'):.2f} s wall (runs {each}), "
          f"{rate / 1e6:.3f} M particle-steps/s, efficiency {rate / (workers * base):.2f}")
    counters = first.get("fluid_counters", {})
    if "halo_seconds" in counters:
        keys = ("wait_seconds", "migration_seconds", "halo_seconds", "balance_seconds", "ghosts_per_exchange",
                "balances")
        print("  " + ", ".join(f"{k} {statistics.median(r['fluid_counters'][k] for r in runs[name]):.4g}"
                               for k in keys))
PY
