#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds and runs the benchmarks, printing their numbers (tests/bench/README.md says what).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/deps.sh"
"$root/scripts/build.sh" "$root/build"
"$root/build/tests/bench/bench_pipeline" "$@"
"$root/build/tests/bench/bench_sim"
"$root/build/tests/bench/bench_devices"
"$root/build/tests/bench/bench_bandsim"
"$root/build/tests/bench/bench_audio"
"$root/build/tests/bench/bench_sessions"
"$root/build/tests/bench/bench_warnings"
"$root/build/tests/bench/bench_inputs"
"$root/build/tests/bench/bench_ros"
"$root/build/tests/bench/bench_foxglove"
"$root/build/tests/bench/bench_study"
# 3 routers x 30 seeds x 120 s of bimanual_sorting three ways: about 40 minutes on 2 cores.
"$root/build/tests/bench/bench_cluster"
# The studio's plots draw in a virtual display, so the number is the same on any machine.
xvfb-run -a -s '-screen 0 1920x1200x24' "$root/build/tests/bench/bench_plots"
# The studio at real time in a virtual display with software GL (no GPU): CPU and memory
# every minute for SEMHAP_STUDIO_SECONDS (600), at 1280x800 and 1920x1080.
LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s '-screen 0 1920x1200x24' \
    "$root/build/tests/bench/bench_studio" "${SEMHAP_STUDIO_SECONDS:-600}" 1280x800 1920x1080
