#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job: installs what is missing, builds, and runs the headless demo (until the studio
# exists): renders a built-in pattern and routes the bundled contact trace through C3,
# printing the semantic events.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/deps.sh"
"$root/scripts/build.sh" "$root/build"
exec "$root/scripts/demo.sh" "$root/build"
