#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the tests that wait on time or kill processes RUNS times each (default 10) while
# stress-ng keeps every core busy, and prints a line per test with its passes:
#   scripts/stress-tests.sh [BUILD_DIR] [RUNS]
# Exits 1 unless every test passed every run. The build must exist (scripts/build.sh).
# A failed run's output is kept in BUILD_DIR/stress/NAME.FUNCTION.RUN.log.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
runs=${2:-10}
[ -x "$build/tests/tst_engine" ] || { echo "$build: no build (scripts/build.sh $build)" >&2; exit 1; }
build=$(cd "$build" && pwd)

# Under a virtual display of our own, as scripts/test.sh runs them.
if [ -z "${SEMHAP_STRESS_INSIDE:-}" ]; then
    "$root/scripts/deps.sh"
    export SEMHAP_STRESS_INSIDE=1
    exec xvfb-run -a -s '-screen 0 1600x1200x24' "$0" "$build" "$runs"
fi

# ctest name, then its Qt Test functions (none: every function of the test).
tests=(
    "audio"
    "transports identifyIsAskedUntilAnswered virtualTransportCountsItsRate sentIsWhatTheBandGot"
    "devicespanel connectToSoundCard"
    "endtoend"
    "bandsim"
    "sessioncli"
    "sessions"
    "outputs interruptedRouteKeepsItsOutput sessionKilledAtOnceLeavesNothingBroken"
    "engine"
    "liverig"
    "waveformdesigner auditionKeepsTheDevicesRate"
    "studycli aKillLosesAtMostTheRunningTrial"
    "studiosessions engineRecordsWhatTheHistorySees windowRecordsReopensAndScrubs"
    "studymode aTrialIsAbortedWithAReason stopAllPausesATrial ordinaryRunsOutliveTheStudy theStudyComesBackAfterAKill"
    "studio workComesBackAfterACrash driveShowsTheGhostAtOnce followKeepsTheHandInView auditionShowsInTheReadouts auditionPlaysOnASoundCard"
)
# The OpenGL tests need X; the others run offscreen, as ctest runs them.
platform() {
    case "$1" in
    viewport | studio | studiosessions | studymode | simview) echo xcb ;;
    *) echo offscreen ;;
    esac
}

logs="$build/stress"
mkdir -p "$logs"
stress-ng --cpu "$(nproc)" --timeout 0 --quiet &
stress=$!
trap 'kill "$stress" 2>/dev/null; wait "$stress" 2>/dev/null || true' EXIT

failed=0
printf '%-60s %s\n' "test" "passes"
for entry in "${tests[@]}"; do
    read -r -a words <<<"$entry"
    name=${words[0]}
    functions=("${words[@]:1}")
    [ ${#functions[@]} -gt 0 ] || functions=("")
    for function in "${functions[@]}"; do
        label=$name${function:+ $function}
        passes=0
        for ((run = 1; run <= runs; run++)); do
            log="$logs/$name${function:+.$function}.$run.log"
            # shellcheck disable=SC2086 # an empty function runs the whole test
            if (cd "$build/tests" && QT_QPA_PLATFORM=$(platform "$name") \
                timeout 600 "./tst_$name" $function >"$log" 2>&1); then
                passes=$((passes + 1))
                rm -f "$log"
            fi
        done
        printf '%-60s %d/%d\n' "$label" "$passes" "$runs"
        [ "$passes" -eq "$runs" ] || failed=1
    done
done
exit "$failed"
