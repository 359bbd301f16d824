#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the Debian package from a build tree and proves it: the metadata validates, the
# extracted tree runs from where it lands (install RPATH), and `apt install` of the .deb
# on this machine resolves its dependencies and runs. scripts/package.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"

rm -f "$build"/semhap_*.deb
(cd "$build" && cpack >/dev/null)
deb=$(ls "$build"/semhap_*.deb)
echo "-- $deb"
dpkg-deb -f "$deb" Package Version Depends

tree=$(mktemp -d)
trap 'rm -rf "$tree"' EXIT
dpkg-deb -x "$deb" "$tree"
appstreamcli validate --no-net "$tree/usr/share/metainfo/org.semhap.studio.metainfo.xml"
desktop-file-validate "$tree/usr/share/applications/org.semhap.studio.desktop"

smoke() { # PREFIX: the installed programs work
    local bin=$1/bin share=$1/share
    "$bin/semhap" --version
    "$bin/semhap" validate "$root/resources/routers/C3.json" "$root/resources/patterns/vib.geiger.json"
    "$bin/semhap" route --router C3 --frames "$share/doc/semhap/examples/demo.jsonl" \
        --events "$tree/events.jsonl"
    [ -s "$tree/events.jsonl" ]
    [ -s "$share/doc/semhap/docs/studio.md" ] # the studio's Help → Documentation
    xvfb-run -a -s '-screen 0 1600x1200x24' "$bin/semhap-studio" --screenshot "$tree/studio.png" \
        --quit-after 3 --size 1280x800
    [ -s "$tree/studio.png" ]
    man -l "$share/man/man1/semhap.1" >/dev/null
    # Completion: `semhap ro<Tab>`, `semhap route --rou<Tab>` and `semhap bandsim pn<Tab>`.
    local completed
    completed=$(PATH="$bin:$PATH" bash -c '
        source /usr/share/bash-completion/bash_completion
        source "$1"
        complete_words() {
            COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); COMP_LINE="$*"; COMP_POINT=${#COMP_LINE}
            _semhap; echo "${COMPREPLY[*]}"
        }
        complete_words semhap ro; complete_words semhap route --rou
        complete_words semhap bandsim pn' _ "$share/bash-completion/completions/semhap")
    [ "$completed" = $'route\n--router\npneumatic6' ] ||
        { echo "completion gave: $completed"; exit 1; }
}
echo "-- extracted into $tree/usr"
smoke "$tree/usr"

echo "-- apt install $deb"
$sudo apt-get install -y -qq "$deb" >/dev/null
smoke /usr
$sudo apt-get remove -y -qq semhap >/dev/null
echo "-- package ok"
