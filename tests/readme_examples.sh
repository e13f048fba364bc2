#!/usr/bin/env bash
# Runs every example command of a markdown file (README.md, docs/cli.md) and compares its output with the text
# printed under it. An example is a fenced block whose line starts with "$ frictionviz "; the lines after it, up to
# the block's end, are the expected standard output (exactly). The commands run in the repository's top folder, so
# that paths such as tests/data/... read as they do for a user there. Usage: readme_examples.sh FRICTIONVIZ FILE.md
# After a deliberate change of output: python3 scripts/update-readme-examples.py (rewrites both files).
set -uo pipefail
exe=$1
readme=$2
case $exe in /*) ;; */*) exe=$PWD/$exe ;; esac
case $readme in /*) ;; *) readme=$PWD/$readme ;; esac
cd "$(dirname "$0")/.." || exit 1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

count=0
failed=0
in_block=0
cmd=""
: >"$work/expected"
run_example() {
    [ -n "$cmd" ] || return 0
    count=$((count + 1))
    # The command as written, with the program's path for "frictionviz" (arguments are plain words).
    read -r -a argv <<<"${cmd#frictionviz }"
    "$exe" "${argv[@]}" >"$work/actual" 2>"$work/stderr"
    local code=$?
    if ! cmp -s "$work/expected" "$work/actual"; then
        failed=$((failed + 1))
        echo "$(basename "$readme") example differs: \$ $cmd (exit $code)"
        diff "$work/expected" "$work/actual" | head -20
        cat "$work/stderr"
    fi
    cmd=""
    : >"$work/expected"
}

while IFS= read -r line || [ -n "$line" ]; do
    if [[ $line == '```'* ]]; then
        if [ $in_block = 1 ]; then
            run_example
            in_block=0
        else
            in_block=1
        fi
        continue
    fi
    [ $in_block = 1 ] || continue
    if [[ $line == '$ frictionviz '* ]]; then
        run_example
        cmd=${line#\$ }
    elif [ -n "$cmd" ]; then
        printf '%s\n' "$line" >>"$work/expected"
    fi
done <"$readme"

echo "$(basename "$readme") examples: $count run, $failed differ"
[ "$count" -gt 0 ] && [ "$failed" = 0 ]
