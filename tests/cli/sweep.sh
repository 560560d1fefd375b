#!/usr/bin/env bash
# `sluice sweep` end to end: a sweep of two values of one key and two of another gives four
# runs, each in its own directory, and a summary table with a row per run (the swept values,
# "done", the model's figures and each probe at the end); a sweep whose runs diverge marks them
# so in the table and exits with code 3.
#
#   sweep.sh SLUICE GOOD_CASE DIVERGING_CASE OUT_DIR
#
# OUT_DIR is removed first: give a path inside the build tree.
set -u

[ $# -eq 4 ] || {
  echo "usage: $0 SLUICE GOOD_CASE DIVERGING_CASE OUT_DIR" >&2
  exit 1
}
sluice=$1
good_case=$2
diverging_case=$3
out=$4
rm -rf "$out"
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

"$sluice" sweep "$good_case" --set end_time=0.02 --set spacing=0.1,0.2 \
  --set model.artificial_viscosity=0.01,0.05 --out "$out/good" --jobs 2 > "$out.log" 2>&1 ||
  fail "the sweep exited with $? ($(tail -3 "$out.log"))"
summary=$out/good/summary.csv
[ -f "$summary" ] || fail "no $summary"
header=$(head -1 "$summary")
case "$header" in
  "run,spacing,model.artificial_viscosity,status,"*"front [m],bottom [Pa],steps,wall_seconds") ;;
  *) fail "unexpected header: $header" ;;
esac
[ "$(tail -n +2 "$summary" | wc -l)" -eq 4 ] || fail "not four rows in $summary"
for row in "1,0.1,0.01,done," "2,0.1,0.05,done," "3,0.2,0.01,done," "4,0.2,0.05,done,"; do
  grep -q "^$row" "$summary" || fail "no row starting '$row' in $summary"
done
for k in 001 002 003 004; do
  [ -f "$out/good/run_$k/stats.json" ] || fail "run_$k wrote no statistics"
done
[ -f "$out/good/summary.md" ] || fail "no summary.md"

"$sluice" sweep "$diverging_case" --set output_interval=0.01,0.02 --out "$out/diverging" \
  > "$out.log" 2>&1
code=$?
[ $code -eq 3 ] || fail "a sweep of diverging runs exited with $code, not 3"
[ "$(grep -c ',diverged$' "$out/diverging/summary.csv")" -eq 2 ] ||
  fail "the diverged runs are not marked in $out/diverging/summary.csv"
echo "sweep: four runs tabulated, diverged runs marked"
