#!/usr/bin/env bash
# What --resume does with checkpoints it cannot use. Used by tests/cli/CMakeLists.txt.
#
#   resume_refusals.sh SLUICE CASE WORK MODE
#
# Runs CASE (2D, a few hundred steps) to 0.1 s with a checkpoint every 0.02 s into WORK/out,
# then, by MODE:
#   other_case      resume with another spacing: refused (exit 2), naming the checkpoint
#   other_model     resume with another model: refused (exit 2)
#   at_end          resume without a later --end: refused (exit 2), saying to give --end
#   cut_newest      the newest checkpoint cut short: skipped with a warning, the run resumes
#                   from the one before and ends as the run that was never cut
#   flipped_newest  a byte of the newest changed: the same
#   all_damaged     both checkpoints damaged: refused (exit 2)
#   none            no checkpoint (a run without checkpoint_interval): refused (exit 2)
#   fresh_run_clears  a new run into the folder removes the older run's checkpoints
set -uo pipefail
sluice=$1 case_file=$2 work=$3 mode=$4

fail() {
  echo "FAIL ($mode): $*" >&2
  exit 1
}

# expect CODE REGEX -- ARGS...: runs sluice, checks its exit code and a line of its stderr.
expect() {
  local code=$1 regex=$2
  shift 3
  "$sluice" "$@" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  [ "$got" -eq "$code" ] || fail "exit $got, expected $code: $(cat "$work/stderr")"
  grep -Eq "$regex" "$work/stderr" || fail "no line matches '$regex' in: $(cat "$work/stderr")"
}

rm -rf "$work"
mkdir -p "$work"
base=(--end 0.1 --set spacing=0.05 --threads 1)
checkpoints=(--set checkpoint_interval=0.02)
"$sluice" run "$case_file" --out "$work/out" "${base[@]}" "${checkpoints[@]}" >/dev/null 2>&1 ||
  fail "the first run failed"
mapfile -t files < <(ls "$work/out/checkpoints"/step_*.ckpt | sort -r)
[ "${#files[@]}" -eq 2 ] || fail "expected the newest two checkpoints, found ${#files[@]}"

# The run resumed from the older checkpoint must end as the one never damaged.
resumes_from_older() {
  cp -r "$work/out" "$work/reference"
  expect 0 "^warning: skipping the checkpoint .*$1" -- \
    run "$case_file" --resume "$work/out" --end 0.2 --set spacing=0.05 --threads 1 "${checkpoints[@]}"
  grep -q "resuming from ${files[1]}" "$work/stderr" || fail "did not resume from ${files[1]}"
  "$sluice" run "$case_file" --resume "$work/reference" --end 0.2 --set spacing=0.05 --threads 1 \
    "${checkpoints[@]}" >/dev/null 2>&1 || fail "the reference resume failed"
  diff -r "$work/out" "$work/reference" >/dev/null || fail "the resumed run differs"
}

case $mode in
  other_case)
    expect 2 "^error: .*step_[0-9]+\.ckpt: cannot resume: the checkpoint is of another version of the case 'dam_break_2d'" -- \
      run "$case_file" --resume "$work/out" --end 0.2 --set spacing=0.04 --threads 1 ;;
  other_model)
    expect 2 "^error: .*step_[0-9]+\.ckpt: cannot resume: the checkpoint is of the model 'wcsph', this case runs 'mps'" -- \
      run "$case_file" --resume "$work/out" --end 0.2 --set spacing=0.05 --set model.name=mps ;;
  at_end)
    expect 2 "^error: .*checkpoints: the run already reached t = 0.1 s, its end time is 0.1 s: give --end a later time to go on" -- \
      run "$case_file" --resume "$work/out" "${base[@]}" ;;
  cut_newest)
    truncate -s 100 "${files[0]}"
    resumes_from_older "where the header promises" ;;
  flipped_newest)
    printf '\x42' | dd of="${files[0]}" bs=1 seek=5000 conv=notrunc status=none
    resumes_from_older "checksum mismatch" ;;
  all_damaged)
    for f in "${files[@]}"; do truncate -s 10 "$f"; done
    expect 2 "^error: .*checkpoints: no checkpoint reads back whole. cannot resume" -- \
      run "$case_file" --resume "$work/out" --end 0.2 --set spacing=0.05 ;;
  none)
    "$sluice" run "$case_file" --out "$work/plain" "${base[@]}" >/dev/null 2>&1 || fail "plain run"
    expect 2 "^error: .*plain/checkpoints: no checkpoint to resume from" -- \
      run "$case_file" --resume "$work/plain" --end 0.2 --set spacing=0.05 ;;
  fresh_run_clears)
    "$sluice" run "$case_file" --out "$work/out" --end 0.05 --set spacing=0.05 --threads 1 \
      >/dev/null 2>&1 || fail "the second run failed"
    [ -z "$(ls "$work/out/checkpoints")" ] || fail "the older run's checkpoints remain"
    expect 2 "no checkpoint to resume from" -- \
      run "$case_file" --resume "$work/out" --end 0.2 --set spacing=0.05 ;;
  *) fail "unknown mode" ;;
esac
echo "PASS ($mode)"
