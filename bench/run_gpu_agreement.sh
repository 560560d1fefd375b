#!/usr/bin/env bash
# On a machine with an NVIDIA GPU, from the repository root, with gpu_bundle/ from
# bench/gpu_bundle.sh: the GPU's answers against the CPU's over time, for
# validation/gpu_agreement.py. Runs F2's 2D dam break (cases/dam_break_2d.yaml) to 0.75 s at
# 0.025 and 0.0125 m, and the bench case at 0.02 m to 0.5 s, each with --device gpu and cpu,
# and writes to $OUT (the device tool's) or out/gpu_agreement:
#   f2_SPACING_DEVICE.csv     the run's probes.csv (the surge front among them);
#   bench_0.02_DEVICE.csv     the run's energy.csv;
#   log.txt.
# About 40 s on an H100 with 16 host cores.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-out/gpu_agreement}
mkdir -p "$out"
exec > >(tee "$out/log.txt") 2>&1
run() {
  timeout 150 gpu_bundle/lib/ld-linux-x86-64.so.2 --library-path gpu_bundle/lib \
    gpu_bundle/sluice run "$@" | grep -E "done|particles"
}
for spacing in 0.025 0.0125; do
  for device in gpu cpu; do
    echo "== dam_break_2d, $spacing m, $device"
    run cases/dam_break_2d.yaml --device $device --end 0.75 --set spacing=$spacing \
      --out "/tmp/f2_${spacing}_$device"
    cp "/tmp/f2_${spacing}_$device/probes.csv" "$out/f2_${spacing}_$device.csv"
  done
done
for device in gpu cpu; do
  echo "== bench_dam_break_3d, 0.02 m, $device"
  run cases/bench_dam_break_3d.yaml --device $device --end 0.5 --set spacing=0.02 \
    --set output_interval=0.05 --out "/tmp/bench_0.02_$device"
  cp "/tmp/bench_0.02_$device/energy.csv" "$out/bench_0.02_$device.csv"
done
