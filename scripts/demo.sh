#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The headless demo on an existing build: scripts/demo.sh [BUILD_DIR].
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
semhap="${1:-$root/build}/cli/semhap"
trace="$root/resources/traces/demo.jsonl"

echo "== semhap render vib.geiger --intensity 0.5 --duration 0.2 --rate 100 (first rows)"
"$semhap" render vib.geiger --intensity 0.5 --duration 0.2 --rate 100 | head -n 8
echo
echo "== semhap route --router C3 --frames $(basename "$trace") --events -"
"$semhap" route --router C3 --frames "$trace" --events -
echo
frames=$(mktemp)
trap 'rm -f "$frames"' EXIT
"$semhap" route --router C3 --frames "$trace" --device-frames "$frames"
echo "== device frames written: $(wc -l <"$frames") (every device at its own rate, C3 preset)"
