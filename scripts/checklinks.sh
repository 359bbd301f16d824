#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Checks the relative links of every Markdown file in the repository, except in the build
# folders at its top (build*/) and the test tools npm installs (node_modules/): each `](target)`, with an optional #anchor, must name a
# file or folder inside the repository. http(s) and mailto links are not checked; links
# inside code (fenced blocks, `inline spans`) are not links. Prints
# `FILE:LINE: broken link TARGET` for each one that does not resolve and exits 1; exits 0
# when every link resolves.
#
# Usage: scripts/checklinks.sh [ROOT]   (ROOT: the repository, by default this script's)
set -u
shopt -s extglob

root=$(cd "${1:-$(dirname "$0")/..}" && pwd -P) || exit 2
cd "$root" || exit 2

link='\]\(([^)]*)\)'
broken=0

check() { # FILE LINE TARGET
    local file=$1 line=$2 target=$3 path resolved
    target=${target#<}
    target=${target%>}
    path=${target%%[[:space:]]*} # drop a "title"
    case $path in
    http://* | https://* | mailto:*) return ;;
    esac
    path=${path%%#*}
    [ -z "$path" ] && return # an anchor in the same file
    if [[ $path == /* ]]; then
        resolved=$path
    else
        resolved=$(realpath -m -- "$(dirname "$file")/$path")
    fi
    if [[ $resolved != "$root" && $resolved != "$root"/* ]] || [ ! -e "$resolved" ]; then
        echo "${file#./}:$line: broken link $target"
        broken=1
    fi
}

while IFS= read -r -d '' file; do
    number=0
    fence=''
    while IFS= read -r text || [ -n "$text" ]; do
        number=$((number + 1))
        if [[ $text =~ ^[[:space:]]*(\`\`\`|~~~) ]]; then
            if [ -z "$fence" ]; then
                fence=${BASH_REMATCH[1]}
            elif [ "${BASH_REMATCH[1]}" = "$fence" ]; then
                fence=''
            fi
            continue
        fi
        [ -n "$fence" ] && continue
        rest=${text//\`+([!\`])\`/} # inline code is not a link
        while [[ $rest =~ $link ]]; do
            check "$file" "$number" "${BASH_REMATCH[1]}"
            rest=${rest#*"${BASH_REMATCH[0]}"}
        done
    done <"$file"
done < <(find . \( -path ./.git -o -type d -path './build*' -o -type d -name node_modules \) -prune -o \
    -type f -name '*.md' -print0 | sort -z)

exit $broken
