#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds semhap: scripts/build.sh [BUILD_DIR [CMAKE_ARGS...]].
# Default: build/ with gcc, RelWithDebInfo. Uses ccache when it is there.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-$root/build}
shift || true
cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
cmake --build "$dir" -j "$(nproc)"
