#!/usr/bin/env bash
# The whole test suite, from a fresh Debian 12 machine: installs what it needs, builds the
# release and the AddressSanitizer+UBSan flavours, runs every test in the first and the unit
# tests in the second.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --with-ros
scripts/build.sh release
ctest --test-dir build/release --output-on-failure -j 2
scripts/build.sh asan
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build/asan -L unit --output-on-failure -j 2
