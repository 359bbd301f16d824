#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job: installs what is missing, builds, and starts the studio on its embedded
# defaults (the bundled box_and_block scene, the C3 preset, virtual wristbands, the scripted
# operator driving until you take over). Extra arguments go to semhap-studio.
# Without a display (a server, a container) it runs the studio for a while in a virtual one
# and saves a screenshot instead.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/deps.sh"
"$root/scripts/build.sh" "$root/build"
studio="$root/build/studio/semhap-studio"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    exec "$studio" "$@"
fi
shot="$root/build/studio.png"
echo "No display: running the studio for 10 s in a virtual one; screenshot: $shot"
exec xvfb-run -a -s '-screen 0 1920x1200x24' \
    "$studio" --size 1280x800 --quit-after 10 --screenshot "$shot" "$@"
