#!/usr/bin/env bash
# Every C++ file of the source tree laid out as .clang-format says (docs/development.md "Tests"):
# clang-format's own check, each file it would change named with the first line it would.
set -euo pipefail
cd "$1"
mapfile -t files < <(find . \( -path './build*' -o -path './.git' \) -prune -o \
  \( -name '*.h' -o -name '*.cpp' \) -print | sort)
clang-format --dry-run --Werror "${files[@]}"
echo "${#files[@]} C++ files as .clang-format lays them out"
