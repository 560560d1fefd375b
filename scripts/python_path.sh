#!/usr/bin/env bash
# Lets Debian's /usr/bin/python3 import sluice from the release build: a .pth file naming
# build/release/python in the user's site-packages (no root needed; rebuilds are picked up).
set -euo pipefail
cd "$(dirname "$0")/.."
site=$(/usr/bin/python3 -m site --user-site)
mkdir -p "$site"
echo "$PWD/build/release/python" > "$site/sluice.pth"
echo "python: /usr/bin/python3 imports sluice from $PWD/build/release/python ($site/sluice.pth)"
