#!/usr/bin/env bash
# Packs what a GPU machine without sluice's Debian libraries needs to run the GPU checks and
# the GPU benchmark (bench/run_gpu_checks.sh): the release build's `sluice` and `physics_tests`
# (built with nvcc: the CUDA policy in them) and every shared library they load, the dynamic
# loader included, into gpu_bundle/ (git-ignored; about 55 MB, under the device tool's 64 MiB).
# usage: bench/gpu_bundle.sh      then, on the GPU machine: bench/run_gpu_checks.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release > /dev/null
grep -q "^SLUICE_WITH_CUDA:BOOL=ON" build/release/CMakeCache.txt ||
  { echo "gpu_bundle: this build has no CUDA policy (nvcc not found)" >&2; exit 1; }
cmake --build --preset release --target sluice physics_tests
rm -rf gpu_bundle
mkdir -p gpu_bundle/lib
cp build/release/sluice build/release/tests/physics_tests gpu_bundle/
for program in gpu_bundle/sluice gpu_bundle/physics_tests; do
  ldd "$program" | awk '/=> \// {print $3} /^\t\/lib/ {print $1}' | while read -r lib; do
    cp -Ln "$lib" gpu_bundle/lib/
  done
done
# The tests find the cases through this path, compiled into them.
pwd > gpu_bundle/source_dir.txt
du -sh gpu_bundle
