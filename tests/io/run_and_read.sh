#!/usr/bin/env bash
# Runs a case through the command line, then reads every frame back with VTK's own reader
# (python3-vtk9, Debian's /usr/bin/python3). A particle model: the point count must equal what
# `sluice check` reports and the arrays velocity, pressure, density and kind must be there. The
# grid model (a case whose check counts cells): every grid must hold that many cells with the
# arrays pressure, level_set, velocity and solid, and every surface frame must be lines or
# triangles.
# usage: [LAUNCH="mpirun -np 2 ..."] run_and_read.sh SLUICE CASE OUT_DIR [--set k=v ...]
# (LAUNCH, where set, starts the run: on several ranks.)
set -euo pipefail
sluice=$1 case_file=$2 out=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
checked=$("$sluice" check "$case_file" "$@")
particles=$(echo "$checked" | sed -n 's/^ *particles: \([0-9]*\).*/\1/p')
cells=$(echo "$checked" | sed -n 's/^ *cells: \([0-9]*\).*/\1/p')
[ -n "$particles$cells" ] || { echo "sluice check printed no particle or cell count"; exit 1; }
${LAUNCH:-} "$sluice" run "$case_file" --out "$out" "$@" > /dev/null
pvd=$(ls "$out"/*.pvd)
if [ -n "$cells" ]; then
  /usr/bin/python3 "$here/read_frame.py" "$pvd" --cells "$cells" \
    --cell-arrays pressure,level_set,velocity,solid
else
  /usr/bin/python3 "$here/read_frame.py" "$pvd" --points "$particles" \
    --arrays velocity,pressure,density,kind
fi
