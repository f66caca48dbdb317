#!/usr/bin/env bash
# The sanitizer job (.ci/run runs it after the README's test command): the fast tests (ctest label
# "fast": no rendering, video, windows or browser) and the fuzz targets of fuzz/ (parsers,
# experiment files; each a ctest of label fast, 30 s at most) under AddressSanitizer + UBSan,
# built by clang into build-asan (CMake option MULTICPG_SANITIZE), every warning an error. Needs
# scripts/setup.sh.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
start=$(date +%s)
cmake -S . -B build-asan -DMULTICPG_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_COMPILE_WARNING_AS_ERROR=ON >/dev/null
cmake --build build-asan -j "$(nproc)" --target fast_tests
# Leaks in libraries we do not own (none of ours) are listed in .ci/lsan.supp.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export LSAN_OPTIONS=suppressions=$root/.ci/lsan.supp
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan -L fast --output-on-failure -j2
echo "sanitizer job: $(($(date +%s) - start)) s" >&2
