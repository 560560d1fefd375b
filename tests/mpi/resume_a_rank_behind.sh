#!/usr/bin/env bash
# A kill while the ranks write a checkpoint leaves the ranks that finished it one checkpoint
# ahead of the others. Resuming then starts every rank from the newest step that all hold whole,
# and ends as the run that was never stopped: every output file byte for byte.
#
#   resume_a_rank_behind.sh SLUICE MPIEXEC WORK CASE [RUN OPTIONS...]
#
# Runs CASE on 2 ranks into WORK/whole; then into WORK/cut to half its end time, removes the
# second rank's newest checkpoint (its write cut short), and resumes WORK/cut to the end.
set -euo pipefail
sluice=$1 mpiexec=$2 work=$3 case_file=$4
shift 4
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
run() { "$mpiexec" --oversubscribe -np 2 "$sluice" run "$case_file" --threads 1 "$@"; }
rm -rf "$work"
mkdir -p "$work"
run --out "$work/whole" --end 0.4 "$@" >"$work/whole.log" 2>&1 ||
  fail "the whole run: $(tail -n 3 "$work/whole.log")"
run --out "$work/cut" --end 0.2 "$@" >"$work/cut.log" 2>&1 ||
  fail "the run to 0.2 s: $(tail -n 3 "$work/cut.log")"
behind="$work/cut/checkpoints/rank_1_of_2"
newest=$(ls "$behind" | grep -E '^step_[0-9]+\.ckpt$' | sort | tail -n 1)
older=$(ls "$behind" | grep -E '^step_[0-9]+\.ckpt$' | sort | tail -n 2 | head -n 1)
[ -n "$newest" ] && [ "$newest" != "$older" ] || fail "rank 1 kept fewer than two checkpoints"
rm "$behind/$newest"
run --resume "$work/cut" --end 0.4 "$@" >"$work/resume.log" 2>&1 ||
  fail "the resume: $(tail -n 3 "$work/resume.log")"
grep -q "resuming from .*${older}" "$work/resume.log" ||
  fail "the resume did not start from $older, the newest step both ranks hold: $(grep resuming "$work/resume.log")"
diff -r --exclude=checkpoints "$work/whole" "$work/cut" >"$work/diff.txt" ||
  fail "the resumed run's output differs from the whole run's:
$(head -n 20 "$work/diff.txt")"
echo "PASS: resumed from $older (rank 1's $newest removed); output identical to the whole run"
