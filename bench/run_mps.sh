#!/usr/bin/env bash
# MPS measurements of docs/performance.md, on the Kleefsman case (cases/kleefsman_3d.yaml):
#  1. scaling: 0.02 s of physical time at spacings from about 25,000 to 400,000 fluid
#     particles, each solver in turn (the conjugate gradients and BoomerAMG with
#     wall_pressure: solved, whose system is symmetric); per step, the time of each stage and
#     the pressure solve's iterations;
#  2. mps against wcsph at the shipped spacing: SECONDS of physical time (default 0.1),
#     REPEAT times each (default 3), alternating, and the median wall time per simulated second.
# usage: bench/run_mps.sh [REPEAT] [SECONDS] [SOLVERS]   (SOLVERS: comma-separated)
set -euo pipefail
source "$(dirname "$0")/bench_setup.sh"
repeat=${1:-3}
seconds=${2:-0.1}
solvers=${3:-bicgstab_diagonal,cg_diagonal,cg_incomplete_cholesky,boomeramg}
case=cases/kleefsman_3d.yaml
for dx in 0.03 0.0238 0.0189 0.015 0.0119; do
  for solver in ${solvers//,/ }; do
    walls=solved
    [ "$solver" = bicgstab_diagonal ] && walls=extrapolated
    "$sluice" run "$case" --out "$work/out" --set spacing=$dx --set end_time=0.02 \
      --set output_interval=1 --set "model={name: mps}" --set model.solver=$solver \
      --set model.wall_pressure=$walls \
      --stats "$work/scale_${dx}_${solver}.json" > /dev/null 2>&1 || echo "failed: $dx $solver"
  done
done
for r in $(seq 1 "$repeat"); do
  for model in mps wcsph; do
    "$sluice" run "$case" --out "$work/out" --set end_time=$seconds --set output_interval=1 \
      --set "model={name: $model}" --stats "$work/model_${model}_${r}.json" > /dev/null 2>&1
  done
done
/usr/bin/python3 - "$work" "$repeat" "$solvers" <<'PY'
import glob, json, statistics, sys
work, repeat, solvers = sys.argv[1], int(sys.argv[2]), sys.argv[3].split(",")
print("scaling (0.02 s, 2 threads): ms per step by stage")
print(f"{'spacing':>8} {'solver':>24} {'particles':>9} {'fluid':>7} {'steps':>5} {'unknowns':>8}"
      f" {'iter':>6} {'neigh':>7} {'assem':>7} {'solve':>7} {'rest':>7} {'total':>7} {'Mp-st/s':>7}")
for dx in ("0.03", "0.0238", "0.0189", "0.015", "0.0119"):
    for solver in solvers:
        try:
            s = json.load(open(f"{work}/scale_{dx}_{solver}.json"))
        except FileNotFoundError:
            continue
        st, n = s["stage_seconds"], s["steps"]
        neigh = st.get("neighbours", 0) + st.get("neighbour_list", 0)
        assem, solve = st.get("assembly", 0), st.get("solve", 0)
        total = sum(st.values())
        c = s["fluid_counters"]
        ms = lambda v: 1e3 * v / n
        print(f"{dx:>8} {solver:>24} {s['particles']:>9} {s['fluid_particles']:>7} {n:>5}"
              f" {c['pressure_unknowns_per_solve']:>8.0f} {c['pressure_iterations_per_solve']:>6.1f}"
              f" {ms(neigh):>7.1f} {ms(assem):>7.1f} {ms(solve):>7.1f}"
              f" {ms(total - neigh - assem - solve):>7.1f} {ms(total):>7.1f}"
              f" {s['particle_steps_per_second'] / 1e6:>7.3f}")
print(f"\nmps against wcsph, shipped spacing, {repeat} alternating runs each")
for model in ("mps", "wcsph"):
    runs = [json.load(open(f"{work}/model_{model}_{r}.json")) for r in range(1, repeat + 1)]
    per = [r["wall_seconds_per_simulated_second"] for r in runs]
    print(f"  {model}: {runs[0]['particles']} particles, {runs[0]['steps']} steps, wall s per "
          f"simulated s: median {statistics.median(per):.1f} (runs {', '.join(f'{p:.1f}' for p in per)})"
          f", {statistics.median(r['particle_steps_per_second'] for r in runs) / 1e6:.3f} M particle-steps/s")
PY
