#!/usr/bin/env bash
# Checks that C++ sources follow .clang-format (clang-format 14, Debian's): the files changed since BASE, or all
# tracked C++ files where that set cannot be told. Changes nothing; prints each deviation and fails.
#   scripts/check-format.sh [BASE]    (default: $FV_FORMAT_BASE, else origin/main, else main)
# Changed files: those that differ between the merge base of HEAD and BASE and the working tree (commits, staged
# and unstaged edits), and untracked C++ files not ignored. All tracked files instead when BASE is missing, when
# the clone is too shallow to hold the merge base (a CI clone may be), or when HEAD is BASE itself (CI's clone of
# main: there "changed" would be nothing). All ~260 files take ~2 s of CPU, so the fallback is cheap.
# Fix a file with: clang-format -i --style=file:.clang-format FILE
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh format

patterns=('*.cpp' '*.hpp' '*.h' '*.cc' '*.cxx' '*.hh')
base=${1:-${FV_FORMAT_BASE:-}}
if [ -z "$base" ]; then
  for candidate in origin/main main; do
    if git rev-parse --verify -q "$candidate^{commit}" >/dev/null; then base=$candidate; break; fi
  done
fi

files=()
why=""
if [ -z "$base" ] || ! git rev-parse --verify -q "$base^{commit}" >/dev/null; then
  why="no base commit${base:+ $base}"
elif ! merge_base=$(git merge-base HEAD "$base" 2>/dev/null); then
  why="no merge base of HEAD and $base (shallow clone?)"
elif [ "$merge_base" = "$(git rev-parse HEAD)" ] && git diff --quiet "$merge_base" -- "${patterns[@]}" &&
     [ -z "$(git ls-files --others --exclude-standard -- "${patterns[@]}")" ]; then
  why="HEAD is $base, nothing changed"
else
  mapfile -t files < <({ git diff --name-only --diff-filter=ACMR "$merge_base" -- "${patterns[@]}"
                          git ls-files --others --exclude-standard -- "${patterns[@]}"; } | sort -u)
  echo "check-format: ${#files[@]} C++ file(s) changed since $base (merge base ${merge_base:0:12})"
fi
if [ -n "$why" ]; then
  mapfile -t files < <(git ls-files -- "${patterns[@]}")
  echo "check-format: all ${#files[@]} tracked C++ files ($why)"
fi
[ ${#files[@]} -gt 0 ] || exit 0
if ! clang-format --dry-run -Werror --style=file:.clang-format "${files[@]}"; then
  echo "check-format: files above differ from .clang-format; fix with clang-format -i --style=file:.clang-format FILE" >&2
  exit 1
fi
echo "check-format: OK"
