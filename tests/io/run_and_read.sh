#!/usr/bin/env bash
# Runs a case through the command line, then reads every frame back with VTK's own reader
# (python3-vtk9, Debian's /usr/bin/python3): the point count must equal what `sluice check`
# reports and the arrays velocity, pressure, density and kind must be there.
# usage: run_and_read.sh SLUICE CASE OUT_DIR [--set k=v ...]
set -euo pipefail
sluice=$1 case_file=$2 out=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
particles=$("$sluice" check "$case_file" "$@" | sed -n 's/^ *particles: \([0-9]*\).*/\1/p')
[ -n "$particles" ] || { echo "sluice check printed no particle count"; exit 1; }
"$sluice" run "$case_file" --out "$out" "$@" > /dev/null
pvd=$(ls "$out"/*.pvd)
/usr/bin/python3 "$here/read_frame.py" "$pvd" --points "$particles" --arrays velocity,pressure,density,kind
