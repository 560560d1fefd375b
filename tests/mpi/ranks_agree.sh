#!/usr/bin/env bash
# A case run on one rank and split over each of RANK_COUNTS ("2 3") gives the same answer
# (tests/mpi): the tables within TOLERANCE (compare_runs.py), the last frame in as many pieces
# as ranks holding every particle, and the split run's first lines naming its ranks and slabs.
# Every rank runs one thread (OMP_NUM_THREADS=1), the one-rank run too.
#
#   [EXPECT_BALANCE="2 3"] ranks_agree.sh SLUICE MPIEXEC WORK RANK_COUNTS TOLERANCE CASE [RUN OPTIONS...]
#
# With EXPECT_BALANCE the runs on each rank count it lists must have moved their cuts at least
# once (the water of a dam break moves across the tank: shift balancing follows it).
set -euo pipefail
sluice=$1 mpiexec=$2 work=$3 rank_counts=$4 tolerance=$5 case_file=$6
shift 6
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf "$work"
mkdir -p "$work"
"$sluice" run "$case_file" --out "$work/one" --threads 1 "$@" >"$work/one.log" 2>&1 ||
  { echo "FAIL: the one-rank run: $(tail -n 3 "$work/one.log")"; exit 1; }
for ranks in $rank_counts; do
  split="$work/split_$ranks"
  "$mpiexec" --oversubscribe -np "$ranks" "$sluice" run "$case_file" --out "$split" \
    --threads 1 --stats "$split.json" "$@" >"$split.log" 2>&1 ||
    { echo "FAIL: the run on $ranks ranks: $(tail -n 5 "$split.log")"; exit 1; }
  grep -q "threads on each of $ranks ranks" "$split.log" ||
    { echo "FAIL: the run's first line does not name its $ranks ranks"; exit 1; }
  grep -Eq "$ranks (slabs along|boxes by)" "$split.log" ||
    { echo "FAIL: the run on $ranks ranks does not say how it split the domain"; exit 1; }
  echo "$ranks ranks: $(grep -o '"fluid_counters": {[^}]*}' "$split.json")"
  balances=$(grep -o '"balances": [0-9]*' "$split.json" | grep -o '[0-9]*$')
  if [[ " ${EXPECT_BALANCE:-} " == *" $ranks "* ]] && ! [ "${balances:-0}" -ge 1 ]; then
    echo "FAIL: the cuts never moved on $ranks ranks"
    exit 1
  fi
  /usr/bin/python3 "$(dirname "$0")/compare_runs.py" "$work/one" "$split" "$ranks" "$tolerance"
done
