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
