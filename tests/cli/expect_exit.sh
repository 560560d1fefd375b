#!/usr/bin/env bash
# Runs a command and checks how it ended: its exit code, its message, and the number of error
# lines. Used by tests/cli/CMakeLists.txt.
#
#   expect_exit.sh [--absent PATH]... [--raw] EXPECTED_CODE EXPECTED_REGEX -- COMMAND...
#
# Passes (exit 0) when all of these hold, and otherwise prints what happened and exits 1:
#   - COMMAND exits with EXPECTED_CODE;
#   - EXPECTED_REGEX (extended, grep -E, matched line by line) matches a line of COMMAND's
#     stderr, or of its stdout when EXPECTED_CODE is 0;
#   - stderr has exactly one line starting with "error:" (none when EXPECTED_CODE is 0);
#     --raw skips this check, for messages printed in another format (CLI11's own);
#   - no PATH given with --absent exists afterwards: a command that fails on bad input must not
#     create its output directory. Each such PATH is removed before COMMAND runs, so give only
#     paths inside the build tree.
set -u

usage() {
  echo "usage: $0 [--absent PATH]... [--raw] EXPECTED_CODE EXPECTED_REGEX -- COMMAND..." >&2
  exit 1
}

absent=()
raw=0
while [ $# -gt 0 ]; do
  case "$1" in
    --absent)
      [ $# -ge 2 ] || usage
      absent+=("$2")
      shift 2
      ;;
    --raw)
      raw=1
      shift
      ;;
    *) break ;;
  esac
done
[ $# -ge 4 ] || usage
expected_code=$1
expected_regex=$2
[ "$3" = "--" ] || usage
shift 3

for path in "${absent[@]+"${absent[@]}"}"; do
  case "$path" in
    "" | / | .. | ../* | */.. | */../*)
      echo "expect_exit.sh: refusing to remove '$path'" >&2
      exit 1
      ;;
  esac
  rm -rf -- "$path"
done

work=$(mktemp -d "${TMPDIR:-/tmp}/expect_exit.XXXXXX") || exit 1
trap 'rm -rf -- "$work"' EXIT

"$@" >"$work/stdout" 2>"$work/stderr"
code=$?

problems=()
if [ "$code" -ne "$expected_code" ]; then
  problems+=("exit code $code, expected $expected_code")
fi
if [ "$expected_code" -eq 0 ]; then
  searched="$work/stdout"
  stream=stdout
else
  searched="$work/stderr"
  stream=stderr
fi
if ! grep -Eq -- "$expected_regex" "$searched"; then
  problems+=("$stream does not match the regex: $expected_regex")
fi
if [ "$raw" -eq 0 ]; then
  error_lines=$(grep -c '^error:' "$work/stderr")
  wanted_lines=1
  [ "$expected_code" -eq 0 ] && wanted_lines=0
  if [ "$error_lines" -ne "$wanted_lines" ]; then
    problems+=("stderr has $error_lines lines starting with 'error:', expected $wanted_lines")
  fi
fi
for path in "${absent[@]+"${absent[@]}"}"; do
  if [ -e "$path" ] || [ -L "$path" ]; then
    problems+=("'$path' exists: the command created it although it failed")
  fi
done

if [ ${#problems[@]} -eq 0 ]; then
  exit 0
fi
{
  echo "FAILED: $*"
  for problem in "${problems[@]}"; do echo "  - $problem"; done
  echo "--- exit code: $code"
  echo "--- stdout:"
  cat "$work/stdout"
  echo "--- stderr:"
  cat "$work/stderr"
  echo "---"
} >&2
exit 1
