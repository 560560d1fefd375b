#!/usr/bin/env bash
# A run killed with SIGKILL at random moments, and resumed after each kill, ends exactly as the
# run that was never killed: every output file byte for byte (frames, series, probes, bodies'
# CSVs, energy) and the final checkpoint. Used by tests/cli/CMakeLists.txt.
#
#   [LAUNCH="mpirun -np N ..." CHECKPOINTS=checkpoints/rank_0_of_N] \
#   kill_and_resume.sh SLUICE WORK SEED KILLS CASE [RUN OPTIONS...]
#
# With LAUNCH every run starts through it, on several ranks: a kill is SIGKILL to every rank
# at once (a machine lost), and CHECKPOINTS names the folder, under a run's output, whose
# newest checkpoint times the kills and is compared at the end (the first rank's).
#
# Runs CASE once into WORK/whole; then into WORK/killed, killed KILLS times. The kill points
# come from bash's generator seeded with SEED: each is a step of the whole run (drawn below
# 95 % of its steps) and a delay of 0 to 40 ms after the killed run's newest checkpoint has
# reached that step, so kills land anywhere: while stepping, while writing a frame, a CSV row
# or a checkpoint, or while a resumed run starts. Every kill must land on a running process.
set -euo pipefail

if [ $# -lt 5 ]; then
  echo "usage: $0 SLUICE WORK SEED KILLS CASE [RUN OPTIONS...]" >&2
  exit 1
fi
sluice=$1 work=$2 seed=$3 kills=$4 case_file=$5
shift 5
options=("$@")
launch=(${LAUNCH:-})
checkpoints=${CHECKPOINTS:-checkpoints}

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

rm -rf "$work"
mkdir -p "$work"
"${launch[@]}" "$sluice" run "$case_file" --out "$work/whole" "${options[@]}" --stats "$work/whole_stats.json" \
  >"$work/whole.log" 2>&1 ||
  fail "the run without kills failed: $(tail -n 3 "$work/whole.log")"

# The step of a folder's newest checkpoint (0 if none).
newest_step() {
  local newest
  newest=$(ls "$1/$checkpoints" 2>/dev/null | grep -E '^step_[0-9]+\.ckpt$' | sort | tail -n 1)
  [ -n "$newest" ] || { echo 0; return; }
  newest=${newest#step_}
  echo $((10#${newest%.ckpt}))
}

total=$(newest_step "$work/whole")
[ "$total" -gt 100 ] || fail "the whole run took $total steps: too few to kill it in between"

RANDOM=$seed
targets=()
for ((k = 0; k < kills; ++k)); do
  # Two draws of bash's 15-bit generator make a 30-bit number.
  targets+=($(((RANDOM * 32768 + RANDOM) % (total * 95 / 100) + 1)))
done
mapfile -t targets < <(printf '%s\n' "${targets[@]}" | sort -n)

landed=0
segment=0
start_run() {
  segment=$((segment + 1))
  if [ "$segment" -eq 1 ]; then
    "${launch[@]}" "$sluice" run "$case_file" --out "$work/killed" "${options[@]}" >"$work/run_$segment.log" 2>&1 &
  else
    "${launch[@]}" "$sluice" run "$case_file" --resume "$work/killed" "${options[@]}" >"$work/run_$segment.log" 2>&1 &
  fi
  pid=$!
}

# SIGKILL to the run: to its process, or with LAUNCH to every rank (the launcher's children;
# a kill drawn at a resumed run's start waits until the launcher has started them).
kill_run() {
  if [ ${#launch[@]} -eq 0 ]; then
    kill -KILL "$pid" 2>/dev/null
    return
  fi
  while kill -0 "$pid" 2>/dev/null; do
    pkill -KILL -P "$pid" && return 0
    sleep 0.005
  done
  return 1
}

for target in "${targets[@]}"; do
  start_run
  while kill -0 "$pid" 2>/dev/null && [ "$(newest_step "$work/killed")" -lt "$target" ]; do
    sleep 0.005
  done
  delay=$((RANDOM % 41))
  sleep "$(printf '0.%03d' "$delay")"
  if kill_run; then
    # A launcher whose ranks died before they had all registered with it may never notice
    # (OpenMPI's PMIx: "UNREACHABLE", seen here once in a few dozen runs): one still there after
    # 10 s is killed too, as the rest of the lost machine.
    for ((wait_ms = 0; wait_ms < 10000; wait_ms += 10)); do
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.01
    done
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    landed=$((landed + 1))
    echo "kill $landed: at step >= $target of $total, $delay ms after (segment $segment)"
  else
    wait "$pid" || fail "segment $segment ended on its own with an error: $(tail -n 3 "$work/run_$segment.log")"
    fail "segment $segment finished before its kill (step $target of $total)"
  fi
done
[ "$landed" -eq "$kills" ] || fail "$landed kills landed of $kills"

# The last resume runs to the end, and counts the steps from the case's start as the whole run
# does (its own "steps" are since its checkpoint).
options+=(--stats "$work/last_stats.json")
start_run
wait "$pid" || fail "the last resume failed: $(tail -n 3 "$work/run_$segment.log")"
last_step() { grep -o '"last_step": [0-9]*' "$1" | grep -o '[0-9]*$'; }
[ "$(last_step "$work/whole_stats.json")" = "$(last_step "$work/last_stats.json")" ] ||
  fail "last_step $(last_step "$work/last_stats.json") after the resumes, $(last_step "$work/whole_stats.json") in the whole run"

if ! diff -r --exclude=checkpoints "$work/whole" "$work/killed" >"$work/diff.txt"; then
  fail "the killed run's output differs from the whole run's:
$(head -n 20 "$work/diff.txt")"
fi
whole_last=$(ls "$work/whole/$checkpoints" | sort | tail -n 1)
killed_last=$(ls "$work/killed/$checkpoints" | sort | tail -n 1)
[ "$whole_last" = "$killed_last" ] || fail "newest checkpoints differ: $whole_last, $killed_last"
cmp "$work/whole/$checkpoints/$whole_last" "$work/killed/$checkpoints/$killed_last" ||
  fail "the final checkpoints differ"
echo "PASS: $landed kills, $segment segments, output identical to the run without kills"
