#!/usr/bin/env bash
# A run's checkpoints resume on another number of ranks than wrote them: each rank reads every
# writing rank's piece, keeps the whole case's particles and splits them anew. The resumed run
# gives the one-rank answer within TOLERANCE (tests/mpi/compare_runs.py: the sums add in
# another order, as on any number of ranks), and once it holds its own checkpoints the ones it
# resumed from are gone.
#
#   resume_on_other_ranks.sh SLUICE MPIEXEC WORK "WRITE:RESUME ..." TOLERANCE END CASE [RUN OPTIONS...]
#
# For each pair, runs CASE to END/2 on WRITE ranks (1: without mpirun) and resumes it to END on
# RESUME ranks; and CASE to END on one rank, the answer each must give.
set -euo pipefail
sluice=$1 mpiexec=$2 work=$3 pairs=$4 tolerance=$5 end=$6 case_file=$7
shift 7
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
on() {
  local ranks=$1
  shift
  if [ "$ranks" = 1 ]; then
    "$sluice" run "$case_file" --threads 1 "$@"
  else
    "$mpiexec" --oversubscribe -np "$ranks" "$sluice" run "$case_file" --threads 1 "$@"
  fi
}
half=$(/usr/bin/python3 -c "print($end / 2)")
rm -rf "$work"
mkdir -p "$work"
on 1 --out "$work/one" --end "$end" "$@" >"$work/one.log" 2>&1 ||
  fail "the one-rank run: $(tail -n 3 "$work/one.log")"
for pair in $pairs; do
  wrote=${pair%:*} resumed=${pair#*:}
  run="$work/${wrote}_then_${resumed}"
  on "$wrote" --out "$run" --end "$half" "$@" >"$run.first.log" 2>&1 ||
    fail "the run on $wrote ranks to $half s: $(tail -n 3 "$run.first.log")"
  on "$resumed" --resume "$run" --end "$end" "$@" >"$run.resume.log" 2>&1 ||
    fail "the resume on $resumed ranks: $(tail -n 5 "$run.resume.log")"
  grep -q "split anew over" "$run.resume.log" ||
    fail "the resume on $resumed ranks does not say it split the run anew: $(grep resuming "$run.resume.log")"
  left=$(find "$run/checkpoints" -name 'step_*.ckpt' | grep -v "rank_[0-9]*_of_${resumed}/" || true)
  if [ "$resumed" = 1 ]; then
    left=$(find "$run/checkpoints" -mindepth 2 -name 'step_*.ckpt' || true)
  fi
  [ -z "$left" ] || fail "the checkpoints written on $wrote ranks are still there: $left"
  echo "$wrote ranks, resumed on $resumed:"
  /usr/bin/python3 "$(dirname "$0")/compare_runs.py" "$work/one" "$run" "$resumed" "$tolerance"
done
