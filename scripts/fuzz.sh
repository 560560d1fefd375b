#!/usr/bin/env bash
# Fuzzes sluice's input readers (case file with --set strings, meshes, motion tables) for longer
# than CI does: scripts/fuzz.sh [SECONDS_EACH] (default 600). Builds the fuzz preset (clang,
# AddressSanitizer + UndefinedBehaviorSanitizer) and runs each harness from its seeds, keeping
# the grown corpus in build/fuzz/tests/fuzz/corpus_NAME from one run to the next. A crash fails
# its test and leaves the input as build/fuzz/tests/fuzz/crash-*: once the reader is fixed, copy
# it into tests/fuzz/corpus/NAME/ so that every CI run replays it.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
cmake --preset fuzz -DFUZZ_SECONDS="$seconds" >/dev/null
cmake --build --preset fuzz
ctest --preset fuzz -j "$(nproc)"
