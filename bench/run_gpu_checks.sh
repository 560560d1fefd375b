#!/usr/bin/env bash
# On a machine with an NVIDIA GPU, from the repository root, with gpu_bundle/ from
# bench/gpu_bundle.sh: the GPU checks (tests/physics/test_wcsph_device.cpp) and the GPU
# benchmark (docs/performance.md). Writes eight files to $OUT (the device tool's) or out/gpu:
#   log.txt          the GPU, the checks' and the runs' output, the GPU memory in use;
#   checks.xml       the GPU checks' results (GoogleTest's XML);
#   bench_gpu.json   the bench case (cases/bench_dam_break_3d.yaml, 128,310 fluid particles)
#                    for 0.1 s on the GPU, the first of three runs (log.txt has all three);
#   bench_gpu_long.json  the same for 0.5 s, as DualSPHysics's GPU run in issue 16 was timed;
#   bench_gpu_h173.json  the same for 0.5 s at DualSPHysics's smoothing length, h = sqrt(3) dx
#                    (its examples' coefh = 1; sluice's default is 1.5 dx);
#   bench_gpu_stages.json  0.02 s, waiting for the GPU at the end of every stage
#                    (model.time_device_stages): where the time goes;
#   bench_cpu.json   0.025 s on all the CPU's threads;
#   large.json       the bench case at 0.0014 m (about 39 million particles) for a few steps,
#                    with the GPU memory in use (log.txt): the bytes a particle takes.
# The programs run under the carried loader with the carried libraries, so the machine's own
# C library (older or newer) does not matter; the GPU's driver comes from the machine.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-out/gpu}
mkdir -p "$out" /tmp/gpu_stats
exec > >(tee "$out/log.txt") 2>&1
# The tests find the cases through the source path compiled into them: link it here.
source_dir=$(cat gpu_bundle/source_dir.txt)
if [ ! -e "$source_dir/cases" ]; then mkdir -p "$(dirname "$source_dir")" && ln -sfn "$PWD" "$source_dir"; fi
# Each program gets a time limit (seconds, the first argument), so that one that hangs on a new
# GPU leaves the device's few minutes to the others.
run() {
  local limit=$1
  shift
  timeout "$limit" gpu_bundle/lib/ld-linux-x86-64.so.2 --library-path gpu_bundle/lib "$@"
}
memory() { nvidia-smi --query-gpu=memory.used --format=csv,noheader; }
# bench NAME SECONDS [sluice run's options]: the bench case, its stats in /tmp/gpu_stats.
bench() {
  local name=$1 end=$2
  shift 2
  echo "== $name: $end s $*"
  run 120 gpu_bundle/sluice run cases/bench_dam_break_3d.yaml --end "$end" --out "/tmp/$name" \
    --stats "/tmp/gpu_stats/$name.json" "$@" | tail -n 9
}

nvidia-smi --query-gpu=name,memory.total,memory.used --format=csv

echo "== GPU checks"
run 180 gpu_bundle/physics_tests --gtest_filter='WcsphGpu.*:WcsphDevice.*' \
  --gtest_output="xml:$out/checks.xml"

for round in 1 2 3; do bench "bench_gpu_$round" 0.1 --device gpu --set output_interval=0.05; done
bench bench_gpu_long 0.5 --device gpu --set output_interval=0.05
bench bench_gpu_h173 0.5 --device gpu --set output_interval=0.05 --set model.h_over_dx=1.7320508
bench bench_gpu_stages 0.02 --device gpu --set output_interval=0.02 \
  --set model.time_device_stages=true
bench bench_cpu 0.025 --threads "$(nproc)" --set output_interval=0.025

echo "GPU memory in use every 5 s:"
(while sleep 5; do memory; done) &
sampler=$!
bench large 0.0002 --device gpu --set spacing=0.0014 --set output_interval=1
kill $sampler

cp /tmp/gpu_stats/bench_gpu_1.json "$out/bench_gpu.json"
for name in bench_gpu_long bench_gpu_h173 bench_gpu_stages bench_cpu large; do
  cp "/tmp/gpu_stats/$name.json" "$out/"
done
echo "== summary: wall seconds per simulated second (DualSPHysics on an H100: 14.1)"
python3 - /tmp/gpu_stats/*.json <<'PY'
import json, os, sys
for path in sys.argv[1:]:
    s = json.load(open(path))
    print(f"{os.path.basename(path)}: {s['particles']} particles, {s['steps']} steps, "
          f"{s['wall_seconds']:.2f} s, {s['wall_seconds_per_simulated_second']:.1f} s per "
          f"simulated s, {s['particle_steps_per_second'] / 1e6:.1f} M particle-steps/s")
PY
