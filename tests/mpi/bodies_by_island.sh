#!/usr/bin/env bash
# Bodies advanced island by island on several ranks (ranks.bodies: islands) move exactly as
# where every rank advances every body (ranks.bodies: every_rank): the same split of the
# fluid, so every body's file and the loads are the same byte for byte. The islands must have
# been shared out (the first rank advanced fewer than all the bodies), and the first lines
# must say how.
#
#   bodies_by_island.sh SLUICE MPIEXEC WORK RANKS BODIES CASE [RUN OPTIONS...]
set -euo pipefail
sluice=$1 mpiexec=$2 work=$3 ranks=$4 bodies=$5 case_file=$6
shift 6
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf "$work"
mkdir -p "$work"
for division in islands every_rank; do
  "$mpiexec" --oversubscribe -np "$ranks" "$sluice" run "$case_file" --out "$work/$division" \
    --threads 1 --stats "$work/$division.json" --set "ranks={bodies: $division}" "$@" \
    >"$work/$division.log" 2>&1 ||
    { echo "FAIL: the run with ranks.bodies=$division: $(tail -n 5 "$work/$division.log")"; exit 1; }
done
grep -q "bodies: each island of bodies" "$work/islands.log" ||
  { echo "FAIL: the first lines do not say that the ranks share the bodies by island"; exit 1; }
grep -q "bodies: every rank advances every body" "$work/every_rank.log" ||
  { echo "FAIL: the first lines do not say that every rank advances every body"; exit 1; }
islands=$(grep -o '"body_islands": [0-9]*' "$work/islands.json" | grep -o '[0-9]*$')
first=$(grep -o '"bodies_advanced_on_first_rank": [0-9]*' "$work/islands.json" | grep -o '[0-9]*$')
echo "$ranks ranks: $islands islands at the end, the first rank advancing $first of $bodies bodies"
[ "$islands" -ge 2 ] || { echo "FAIL: fewer than two islands"; exit 1; }
[ "$first" -lt "$bodies" ] || { echo "FAIL: the first rank advanced every body"; exit 1; }
checked=0
for file in "$work"/every_rank/bodies/*.csv "$work"/every_rank/loads.csv; do
  [ -e "$file" ] || continue
  other="$work/islands/${file#"$work"/every_rank/}"
  cmp -s "$file" "$other" || { echo "FAIL: $other differs from $file"; exit 1; }
  checked=$((checked + 1))
done
[ "$checked" -gt "$bodies" ] || { echo "FAIL: only $checked files to compare"; exit 1; }
echo "PASS: $checked files the same byte for byte"
