#!/usr/bin/env bash
# Installs every Debian package that sluice's build, tests, benchmarks and validation plots need.
# Idempotent: packages already present are left alone. Only Debian packages are downloaded.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libyaml-cpp-dev libcli11-dev libfmt-dev libspdlog-dev libomp-dev libassimp-dev
  libgtest-dev libgmock-dev libbenchmark-dev libhypre-dev libopenmpi-dev openmpi-bin zlib1g-dev
  libtrilinos-zoltan-dev
  clang-format clang libclang-rt-14-dev
  python3 python3-vtk9 python3-numpy python3-matplotlib python3-dev pybind11-dev python3-pytest
  ffmpeg
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
