#!/usr/bin/env bash
# `sluice compare` end to end: a small case run with all six fluid models gives a table with one
# row per model, each "done" with its settings, size, cost, loads and probe, a plot of the
# forces, and each model's run in its own directory.
#
#   compare.sh SLUICE CASE OUT_DIR
#
# OUT_DIR is removed first: give a path inside the build tree.
set -u

[ $# -eq 3 ] || {
  echo "usage: $0 SLUICE CASE OUT_DIR" >&2
  exit 1
}
sluice=$1
case_file=$2
out=$3
rm -rf "$out"
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

models=wcsph,mps,penalty-sph,constraint,mac,granular
"$sluice" compare "$case_file" --models "$models" --out "$out" > "$out.log" 2>&1 ||
  fail "compare exited with $? ($(tail -n 3 "$out.log"))"
table=$out/compare.csv
[ -f "$table" ] || fail "no $table"
header=$(head -n 1 "$table")
[ "$header" = "model,status,settings,fluid,steps,wall [s],wall per simulated s,mean drag [N/m],peak drag [N/m],mean lift [N/m],peak lift [N/m],gauge rise [m]" ] ||
  fail "unexpected header: $header"
[ "$(tail -n +2 "$table" | wc -l)" -eq 6 ] || fail "not six rows in $table"
for model in ${models//,/ }; do
  grep -q "^$model,done," "$table" || fail "no finished row for $model in $table"
  [ -f "$out/$model/stats.json" ] || fail "$model wrote no statistics"
done
grep -q '^mac,done,"model={name: mac, cell_size: 0.05}",[0-9]* cells,' "$table" ||
  fail "the grid model's row does not state its settings and cells"
grep -q "^wcsph,done,the case's,[0-9]* particles," "$table" ||
  fail "the case's own model does not say it ran as the case is"
[ -f "$out/compare.md" ] || fail "no compare.md"
if [ -x /usr/bin/python3 ] && /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
  [ -f "$out/compare_forces.png" ] || fail "no compare_forces.png"
fi
echo "compare: six models tabulated"
