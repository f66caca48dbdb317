#!/usr/bin/env bash
# `cmake --install BUILD --prefix P` lays out P/bin/multicpg beside P/share/multicpg, and the
# installed program's prior learns from P/share/multicpg/landscapes before the source tree's
# (learning/landscapes.h): a damaged installed manifest is refused naming it (exit 2, before
# anything walks), and a dataset no place holds is refused naming the installed folder too.
# Usage: tests/cli_install_test.sh BUILD_DIR
set -euo pipefail
build="$1"
prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT
unset MULTICPG_DATA
cmake --install "$build" --prefix "$prefix" >/dev/null
program="$prefix/bin/multicpg"
installed="$prefix/share/multicpg/landscapes"
for f in "$installed"/quadruped.json "$installed"/quadruped.csv.gz "$program"; do
  [ -f "$f" ] || { echo "cmake --install left out $f" >&2; exit 1; }
done

# Refused with exit 2 and one line on stderr that names $2.
refused() {
  local err status=0
  err="$("$program" learn --learner prior --steering off $1 2>&1 >/dev/null)" || status=$?
  if [ "$status" != 2 ] || [ "$(printf '%s\n' "$err" | wc -l)" != 1 ] || [[ "$err" != *"$2"* ]]; then
    echo "multicpg learn $1: exit $status, expected 2 and one line naming $2: $err" >&2
    exit 1
  fi
}
refused "--robot octopod --disable R1" "$installed"
echo '{}' > "$installed/quadruped.json"
refused "--robot quadruped --disable L2" "$installed/quadruped.json"
echo "the installed program learns from $installed"
