# Sourced by the bench/run_*.sh scripts: moves to the repository root, sets $sluice to the
# release build's command line (building it if it is missing) and $work to a scratch folder
# that is removed on exit.
cd "$(dirname "${BASH_SOURCE[0]}")/.."
sluice=build/release/sluice
[ -x "$sluice" ] || { cmake --preset release > /dev/null && cmake --build --preset release; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
