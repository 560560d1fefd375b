#!/usr/bin/env bash
# Sets up (Debian packages), builds, and runs every test: the release build's unit, physics,
# command-line and output tests; the physics checks again in a portable build for x86-64-v2
# (4-wide SSE, no FMA: other rounding than the release build's AVX2, so a check whose margin
# is too thin for another processor fails here); the input readers under libFuzzer (clang); the
# unit and command-line tests under AddressSanitizer + UndefinedBehaviorSanitizer; and a
# formatting check.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
jobs=$(nproc)
# Each stage's line says how long the one before it took (CI's budget is an hour on two cores).
stage() {
  [ -z "${stage_name:-}" ] || echo "   ($stage_name: $((SECONDS - stage_start)) s)"
  stage_name=$1 stage_start=$SECONDS
  echo "== $1"
}

stage "format check"
bad=$(find src apps tests bench python -name '*.cpp' -o -name '*.hpp' -o -name '*.cu' -o -name '*.cuh' | xargs clang-format --dry-run -Werror 2>&1 | grep -c 'error:' || true)
if [ "$bad" != "0" ]; then
  find src apps tests bench python -name '*.cpp' -o -name '*.hpp' -o -name '*.cu' -o -name '*.cuh' | xargs clang-format --dry-run -Werror
  exit 1
fi

stage "release build and tests"
cmake --preset release
cmake --build --preset release -j "$jobs"
bash scripts/python_path.sh
ctest --preset release -j "$jobs"

# The slowest physics checks (a minute or more each: the falling cube, the granular column
# collapses and floating box, the six-cube dam break, F3 to 1 s, F2 at half each model's CI
# spacing and the sliding wheel) run in the release build only, to keep CI well under an hour on two cores; their margins on
# both builds are in docs/testing.md.
stage "baseline build (x86-64-v2) and the physics checks but the slowest"
cmake --preset baseline
cmake --build --preset baseline -j "$jobs" --target physics_tests
ctest --preset baseline -j "$jobs"

# The readers of cases, meshes and motion tables under libFuzzer, 15 s each from their seeds
# (scripts/fuzz.sh runs them longer).
stage "fuzz build (clang, asan + ubsan) and the fuzzers, 15 s each"
cmake --preset fuzz -DFUZZ_SECONDS=15
cmake --build --preset fuzz -j "$jobs"
ctest --preset fuzz -j "$jobs"

stage "sanitizer build (asan + ubsan) and its tests (physics excluded: too slow there)"
cmake --preset asan
cmake --build --preset asan -j "$jobs" --target sluice unit_tests
ctest --preset asan -j "$jobs"
stage "done"
