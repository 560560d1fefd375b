#!/usr/bin/env bash
# Sets up (Debian packages), builds the release preset and runs the default case:
# a 3D dam break whose frames open in ParaView from out/dam_break_3d/dam_break_3d.pvd.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release
cmake --build --preset release
bash scripts/python_path.sh
./build/release/sluice run cases/dam_break_3d.yaml --out out/dam_break_3d
