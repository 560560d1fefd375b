#!/usr/bin/env bash
# A failed run loses nothing already written: runs a good case into OUT_DIR, then re-runs it
# into the same directory with bad input (a bad --set caught while reading the case, and an
# unknown model caught while building the simulation), and checks that each re-run exits with
# code 2 and leaves every file in OUT_DIR as it was (same names, same SHA-256).
#
#   keeps_output.sh SLUICE GOOD_CASE OUT_DIR
#
# OUT_DIR is removed first: give a path inside the build tree.
set -u

[ $# -eq 3 ] || {
  echo "usage: $0 SLUICE GOOD_CASE OUT_DIR" >&2
  exit 1
}
sluice=$1
good_case=$2
out=$3
here=$(cd "$(dirname "$0")" && pwd)

case "$out" in
  "" | / | .. | ../* | */.. | */../*)
    echo "keeps_output.sh: refusing to use '$out' as the output directory" >&2
    exit 1
    ;;
esac
rm -rf -- "$out"

# One thread: quick even on a loaded machine, where OpenMP threads wait on each other.
if ! "$sluice" run "$good_case" --out "$out" --threads 1 >/dev/null 2>&1; then
  echo "FAILED: the good run '$sluice run $good_case --out $out --threads 1' did not succeed" >&2
  exit 1
fi

# Every file and directory below OUT_DIR with the checksum of each file.
snapshot() {
  (cd "$out" && find . -print | LC_ALL=C sort && find . -type f -print0 | LC_ALL=C sort -z |
    xargs -0 sha256sum)
}

before=$(snapshot)
if ! grep -q '\.pvd$' <<<"$before" || ! grep -q '^\./frames/frame_000000\.vtp$' <<<"$before"; then
  echo "FAILED: the good run wrote no .pvd or no first frame in $out:" >&2
  echo "$before" >&2
  exit 1
fi

status=0
"$here/expect_exit.sh" 2 "^error: --set spacing(:[0-9]+)?: key 'spacing': must be greater than zero" \
  -- "$sluice" run "$good_case" --out "$out" --set spacing=-1 || status=1
"$here/expect_exit.sh" 2 "key 'model\.name': unknown model 'wcpsh'" \
  -- "$sluice" run "$good_case" --out "$out" --set model.name=wcpsh || status=1

after=$(snapshot)
if [ "$before" != "$after" ]; then
  echo "FAILED: a failed re-run changed the output directory $out" >&2
  diff <(echo "$before") <(echo "$after") >&2
  status=1
fi
exit $status
