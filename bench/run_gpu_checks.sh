#!/usr/bin/env bash
# On a machine with an NVIDIA GPU, from the repository root, with gpu_bundle/ from
# bench/gpu_bundle.sh: the GPU checks (tests/physics/test_wcsph_device.cpp) and the GPU
# benchmark (docs/performance.md). Writes eight files to $OUT (the device tool's) or out/gpu:
#   log.txt          the GPU, the checks' and the runs' output, the GPU memory in use;
#   checks.xml       the GPU checks' results (GoogleTest's XML);
#   bench_gpu.json   the bench case (cases/bench_dam_break_3d.yaml, 128,310 fluid particles)
#                    for 0.1 s on the GPU;
#   bench_gpu_h173.json  the same at DualSPHysics's smoothing length, h = sqrt(3) dx (its
#                    examples' coefh = 1; sluice's default is 1.5 dx);
#   bench_gpu_stages.json  the same for 0.02 s, waiting for the GPU at the end of every stage
#                    (model.time_device_stages): where the time goes;
#   bench_cpu.json   the same for 0.025 s on all the CPU's threads;
#   fine_*.json      the bench case at 8 and 28 times the particles (0.0042 and 0.0028 m,
#                    about 7 million particles at the finer) for 0.002 s on the GPU: with the
#                    GPU memory in use (log.txt), the bytes per particle and what fits.
# The programs run under the carried loader with the carried libraries, so the machine's own
# C library (older or newer) does not matter; the GPU's driver comes from the machine.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-out/gpu}
mkdir -p "$out"
exec > >(tee "$out/log.txt") 2>&1
# The tests find the cases through the source path compiled into them: link it here.
source_dir=$(cat gpu_bundle/source_dir.txt)
if [ ! -e "$source_dir/cases" ]; then mkdir -p "$(dirname "$source_dir")" && ln -sfn "$PWD" "$source_dir"; fi
run() { gpu_bundle/lib/ld-linux-x86-64.so.2 --library-path gpu_bundle/lib "$@"; }
memory() { nvidia-smi --query-gpu=memory.used --format=csv,noheader; }

nvidia-smi --query-gpu=name,memory.total,memory.used --format=csv

echo "== GPU checks"
run gpu_bundle/physics_tests --gtest_filter='WcsphGpu.*:WcsphDevice.*' \
  --gtest_output="xml:$out/checks.xml"

echo "== bench case, GPU, 0.1 s"
run gpu_bundle/sluice run cases/bench_dam_break_3d.yaml --device gpu --end 0.1 \
  --set output_interval=0.05 --out /tmp/bench_gpu --stats "$out/bench_gpu.json" | tail -n 12
echo "== bench case, GPU, 0.1 s, at h = sqrt(3) dx"
run gpu_bundle/sluice run cases/bench_dam_break_3d.yaml --device gpu --end 0.1 \
  --set output_interval=0.05 --set model.h_over_dx=1.7320508 --out /tmp/bench_gpu_h173 \
  --stats "$out/bench_gpu_h173.json" | tail -n 12
echo "== bench case, GPU, 0.02 s, each stage waited for"
run gpu_bundle/sluice run cases/bench_dam_break_3d.yaml --device gpu --end 0.02 \
  --set output_interval=0.02 --set model.time_device_stages=true --out /tmp/bench_gpu_stages \
  --stats "$out/bench_gpu_stages.json" | tail -n 12
echo "== bench case, CPU ($(nproc) threads), 0.025 s"
run gpu_bundle/sluice run cases/bench_dam_break_3d.yaml --end 0.025 --threads "$(nproc)" \
  --set output_interval=0.025 --out /tmp/bench_cpu --stats "$out/bench_cpu.json" | tail -n 12

for spacing in 0.0042 0.0028; do
  echo "== bench case at $spacing m, GPU, 0.002 s; GPU memory in use every 2 s:"
  (while sleep 2; do memory; done) &
  sampler=$!
  run gpu_bundle/sluice run cases/bench_dam_break_3d.yaml --device gpu --end 0.002 \
    --set spacing=$spacing --set output_interval=0.002 --out /tmp/bench_fine \
    --stats "$out/fine_$spacing.json" | tail -n 12
  status=$?
  kill $sampler
  [ $status -eq 0 ] || { echo "spacing $spacing: did not run"; break; }
done

echo "== summary: wall seconds per simulated second (DualSPHysics on an H100: 14.1)"
python3 - "$out"/*.json <<'PY'
import json, os, sys
for path in sys.argv[1:]:
    s = json.load(open(path))
    print(f"{os.path.basename(path)}: {s['particles']} particles, {s['steps']} steps, "
          f"{s['wall_seconds']:.2f} s, {s['wall_seconds_per_simulated_second']:.1f} s per "
          f"simulated s, {s['particle_steps_per_second'] / 1e6:.1f} M particle-steps/s")
PY
