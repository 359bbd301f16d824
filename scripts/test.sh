#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs what is missing, builds, and runs every test:
#  1. the normal build (gcc): every Qt Test, under Xvfb; timing-sensitive ones (label
#     "timing") serially; the interop tests against the reference libraries that
#     `npm ci` installs into tests/interop;
#  2. the sanitizer build (clang, ASan + UBSan) of the core, patterns and devices tests, and
#     each libFuzzer target (one per core) for a capped number of runs on its seed
#     corpus, each input within 10 s;
#  3. the Debian package (scripts/package.sh): built, validated, run from its extracted tree
#     and installed with apt;
#  4. the exported CMake package: an outside project's Qt Test against the installed core,
#     and every link of the installed documentation leading to an installed file;
#  5. the docs: every relative link in a Markdown file resolves inside the repository.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)
fuzz_runs=${SEMHAP_FUZZ_RUNS:-20000}

"$root/scripts/deps.sh"

echo "== documentation links"
"$root/scripts/checklinks.sh"

echo "== interop tests' reference libraries (tests/interop/package-lock.json)"
(cd "$root/tests/interop" && npm ci --no-audit --no-fund --loglevel=error)

echo "== normal build"
"$root/scripts/build.sh" "$root/build"
# OpenGL tests need an X display: a virtual one, for this run only.
xvfb="xvfb-run -a -s '-screen 0 1600x1200x24'"
(cd "$root/build" && eval "$xvfb" ctest --output-on-failure -j "$jobs" -LE timing \
    && eval "$xvfb" ctest --output-on-failure -L timing)

echo "== sanitizer build (ASan + UBSan) and fuzzers"
CC=clang CXX=clang++ "$root/scripts/build.sh" "$root/build-asan" \
    -DSEMHAP_SANITIZE=ON -DSEMHAP_FUZZ=ON -DSEMHAP_BUILD_BENCH=OFF -DSEMHAP_BUILD_STUDIO=OFF
(cd "$root/build-asan" && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --output-on-failure -j "$jobs" -L sanitize)
# One fuzzer per core: five of them run into their 60 s cap, which is most of CI's time
# when they queue on one core.
fuzz() {
    local fuzzer=$1 name corpus work output status=0
    name=$(basename "$fuzzer")
    corpus="$root/tests/fuzz/corpus/${name#fuzz_}"
    work=$(mktemp -d)
    cp -r "$corpus"/. "$work"/
    # Large seeds make work that grows faster than the input show as a timeout.
    case "$name" in
    fuzz_convert | fuzz_router) "$root/build-asan/tests/fuzz/largeseeds" "$work" "$work" ;;
    esac
    output=$("$fuzzer" -runs="$fuzz_runs" -max_total_time=60 -timeout=10 -rss_limit_mb=2048 \
        "$work" 2>&1) || status=$?
    rm -rf "$work"
    if [ "$status" -eq 0 ]; then
        echo "-- $name: $fuzz_runs runs: ${output##*$'\n'}"
    else
        printf -- '-- %s: FAILED (exit %d)\n%s\n' "$name" "$status" "$output"
    fi
    return "$status"
}
export -f fuzz
export root fuzz_runs
find "$root/build-asan/tests/fuzz" -maxdepth 1 -type f -name 'fuzz_*' -perm -u+x -print0 \
    | sort -z | xargs -0 -n 1 -P "$jobs" bash -c 'fuzz "$1"' fuzz

echo "== desktop package"
"$root/scripts/package.sh" "$root/build"

echo "== exported package"
stage="$root/build/stage"
rm -rf "$stage" "$root/build/package"
cmake --install "$root/build" --prefix "$stage" >/dev/null
cmake -S "$root/tests/package" -B "$root/build/package" -G Ninja \
    -DCMAKE_PREFIX_PATH="$stage" >/dev/null
cmake --build "$root/build/package"
(cd "$root/build/package" && LD_LIBRARY_PATH="$stage/lib" ctest --output-on-failure)
