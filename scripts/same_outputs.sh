#!/usr/bin/env bash
# Whether a change left the answers alone: runs the same short cases with two sluice binaries
# (before and after the change) and compares every file they write byte for byte (frames, body
# files, probes, loads, energy.csv, checkpoints), all but the run statistics, which hold timings.
# A case of each model, bodies alone, a joint-driven vehicle:
#
#   scripts/same_outputs.sh BEFORE_BINARY AFTER_BINARY [SCRATCH_DIR]
#
# Prints one line per case and exits 1 if any output differs. One thread, so that the runs do not
# wait on each other's cores. SKIP_CHECKPOINTS=1 leaves the checkpoints out of the comparison,
# for a change that moves a checkpoint's layout and not the answers.
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 BEFORE_BINARY AFTER_BINARY [SCRATCH_DIR]" >&2
  exit 2
fi
before=$(realpath "$1")
after=$(realpath "$2")
scratch=${3:-$(mktemp -d)}
cases_dir="$(cd "$(dirname "$0")/.." && pwd)/cases"

# name | case file | --set overrides
runs=(
  "cubes_3|dam_break_cubes_3.yaml|end_time=0.1"
  "drop_bounce|drop_bounce.yaml|end_time=0.3"
  "floating_box_wcsph|floating_box_2d.yaml|end_time=0.3"
  "dam_break_mps|dam_break_2d_mps.yaml|end_time=0.2"
  "free_bed_penalty_sph|free_bed_2d.yaml|end_time=0.1"
  "rain_on_concrete_penalty_sph|seed002_rain_concrete.yaml|end_time=0.05"
  "floating_box_constraint|floating_box_2d.yaml|end_time=0.3 model.name=constraint"
  "floating_box_granular|granular_floating_box_2d.yaml|end_time=0.3"
  "floating_box_mac|floating_box_2d.yaml|end_time=0.3 model.name=mac"
  "fording_wcsph|fording.yaml|end_time=0.05 spacing=0.08"
  "sphere_stack_complementarity|sphere_stack.yaml|end_time=0.3"
  "resting_cubes_complementarity|resting_cubes.yaml|end_time=0.3 contact.method=complementarity"
  "floating_box_emulated|floating_box_2d.yaml|end_time=0.1 model.device=emulated"
)

excluded=(--exclude='stats*.json')
[ "${SKIP_CHECKPOINTS:-0}" = 1 ] && excluded+=(--exclude='*.ckpt')
differ=0
for run in "${runs[@]}"; do
  IFS='|' read -r name file overrides <<<"$run"
  sets=()
  for o in $overrides; do sets+=(--set "$o"); done
  for side in before after; do
    binary=$before
    [ "$side" = after ] && binary=$after
    rm -rf "${scratch:?}/$side/$name"
    mkdir -p "$scratch/$side"
    OMP_NUM_THREADS=1 "$binary" run "$cases_dir/$file" --out "$scratch/$side/$name" \
      --set checkpoint_interval=0.05 "${sets[@]}" >"$scratch/$side/$name.log" 2>&1 ||
      { echo "$name: the $side run failed (see $scratch/$side/$name.log)"; differ=1; continue 2; }
  done
  if diff -rq "${excluded[@]}" "$scratch/before/$name" "$scratch/after/$name" >/dev/null; then
    echo "$name: same bytes ($(find "$scratch/after/$name" -type f | wc -l) files)"
  else
    echo "$name: DIFFERENT:"
    diff -rq "${excluded[@]}" "$scratch/before/$name" "$scratch/after/$name" | head -5 || true
    differ=1
  fi
done
exit $differ
