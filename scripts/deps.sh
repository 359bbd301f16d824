#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian packages semhap needs that are not installed yet (nothing else).
set -euo pipefail

packages=(
    # build
    cmake ninja-build g++ ccache pkg-config clang libclang-rt-14-dev
    # Qt 6 and the libraries of the studio, the simulation and the devices
    qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-qpa-plugins
    libqt6opengl6-dev libqt6sql6-sqlite libqcustomplot-dev libqcustomplot2.1-qt6
    # Qt's own words (dialog buttons, file dialogs) in the studio's languages
    qt6-translations-l10n
    libmujoco-dev libqhull-dev libhidapi-dev libserialport-dev
    # sound cards (the audio: transport): PortAudio, and ALSA and JACK to quiet their messages
    portaudio19-dev libasound2-dev libjack-jackd2-dev
    # the analogue drive devices: gamepads (SDL2) and 3D mice (spacenavd's client library)
    libsdl2-dev libspnav-dev
    # statistics (semhap compare's paired tests)
    libgsl-dev
    # the reference bands' firmware images (firmware/boards): the AVR compiler and C library;
    # the simulated chip that runs them (semhap bandsim; libelf-dev for simavr's pkg-config)
    gcc-avr avr-libc libsimavr-dev libelf-dev
    # GUI tests and screenshots without a display; a real window manager (openbox) and the
    # X tools that read windows' frames, for the studio's placement on small screens
    xvfb xauth libgl1-mesa-dri openbox x11-utils
    # scripts/stress-tests.sh: the timing and kill tests with every core busy
    stress-ng
    # scripts/replicate.py (the paper's studies simulated) and scripts/make-scenes.py
    python3
    # ROS 2 recordings: MCAP's chunk compressions and CRC-32; robots live over Foxglove's
    # WebSocket protocol
    libzstd-dev liblz4-dev zlib1g-dev qt6-websockets-dev
    # tests/xdf: XDF files read back by the Lab Streaming Layer's reference reader
    libxdf-dev
    # tests/ranalysis: study export --r's analysis.R run by R, afex and emmeans
    r-base-core r-cran-afex r-cran-emmeans
    # tests/cluster and bench_cluster: a one-node Slurm cluster that the test starts as root
    slurm-wlm munge
    # the desktop package: man pages, metadata checks, .deb dependencies
    help2man appstream desktop-file-utils dpkg-dev man-db bash-completion
)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
        || missing+=("$p")
done
# The interop tests' reference libraries (tests/interop) run on Node.js and install with npm.
# A Node already on the PATH is kept: NodeSource's nodejs conflicts with Debian's npm.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    for p in nodejs npm; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
            || missing+=("$p")
    done
fi
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
