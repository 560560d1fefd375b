#!/usr/bin/env bash
# On a machine with an NVIDIA GPU, from the repository root, with gpu_bundle/ from
# bench/gpu_bundle.sh: the GPU checks (tests/physics/test_wcsph_device.cpp) and the GPU
# benchmark (docs/performance.md), written to $OUT (the device tool's) or out/gpu.
#   1. the GPU's name and memory;
#   2. the GPU checks against the CPU (F1, F2, B1, the bench case's front and energy);
#   3. the bench case (cases/bench_dam_break_3d.yaml, 128,310 fluid particles) for 0.1 s on
#      the GPU, and for 0.025 s on the CPU's threads, with their statistics;
#   4. the bench case refined until the GPU's memory is nearly full: the particles that fit.
# The programs run under the carried loader with the carried libraries, so the machine's own
# C library (older or newer) does not matter; the GPU's driver comes from the machine.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-out/gpu}
mkdir -p "$out"
# The tests find the cases through the source path compiled into them: link it here.
source_dir=$(cat gpu_bundle/source_dir.txt)
if [ ! -e "$source_dir/cases" ]; then mkdir -p "$(dirname "$source_dir")" && ln -sfn "$PWD" "$source_dir"; fi
run() { gpu_bundle/lib/ld-linux-x86-64.so.2 --library-path gpu_bundle/lib "$@"; }
threads=$(nproc)

nvidia-smi --query-gpu=name,memory.total,memory.used --format=csv > "$out/gpu.txt" 2>&1
cat "$out/gpu.txt"

run gpu_bundle/physics_tests --gtest_filter='WcsphGpu.*:WcsphDevice.*' 2>&1 | tee "$out/gpu_checks.txt"

run gpu_bundle/sluice run cases/bench_dam_break_3d.yaml --device gpu --end 0.1 \
  --set output_interval=0.05 --out /tmp/bench_gpu --stats "$out/bench_gpu.json" 2>&1 |
  tail -n 12 | tee "$out/bench_gpu.txt"
run gpu_bundle/sluice run cases/bench_dam_break_3d.yaml --end 0.025 --threads "$threads" \
  --set output_interval=0.025 --out /tmp/bench_cpu --stats "$out/bench_cpu.json" 2>&1 |
  tail -n 12 | tee "$out/bench_cpu.txt"

# Finer spacings (particles grow as its cube) for a few steps each, until one no longer fits.
for spacing in 0.0042 0.0028 0.0021 0.0017; do
  if ! run gpu_bundle/sluice run cases/bench_dam_break_3d.yaml --device gpu --end 0.002 \
      --set spacing=$spacing --set output_interval=0.002 --out /tmp/bench_fine \
      --stats "$out/bench_gpu_$spacing.json" > "$out/bench_gpu_$spacing.txt" 2>&1; then
    echo "spacing $spacing: did not run (see bench_gpu_$spacing.txt)"
    break
  fi
  grep -h '"particles"\|wall_seconds_per' "$out/bench_gpu_$spacing.json"
  nvidia-smi --query-gpu=memory.used --format=csv >> "$out/gpu.txt" 2>&1
done
