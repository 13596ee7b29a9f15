#!/usr/bin/env bash
# The whole test suite, from a fresh Debian 12 machine: installs what it needs (ROS 1 included,
# for the optional ROS layer), builds the release flavour and runs every test (unit, conformance,
# scenario, cli, ros, ros2 (DDS peers in private network namespaces), slurm: a single-node Slurm the
# test starts), then builds the unit-test programs with AddressSanitizer + UBSan and runs the unit
# tests there, then fuzzes the readers of
# robot descriptions and controller parameters for a short fixed budget.
# Each stage's time and ccache's hit rate are printed at the end (scripts/stages.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/stages.sh
stage install scripts/install-deps.sh --with-ros
# Test data from Debian packages that mechsim does not install (a public DEM): the tests that need
# it skip, naming the script, when it cannot be fetched.
stage test-data scripts/fetch-test-data.sh
stage release-build scripts/build.sh release
# The ROS layer was just installed: a build without it would run fewer tests without a word.
grep -qx 'MECHSIM_ROS_ENABLED:INTERNAL=ON' build/release/CMakeCache.txt || {
  echo "test.sh: build/release was configured without the ROS layer although ROS is installed" \
       "(MECHSIM_ROS=OFF set by hand? configure with -DMECHSIM_ROS=AUTO)" >&2
  exit 1
}
# The ROS 2 layer likewise (Fast DDS comes with --with-ros).
grep -qx 'MECHSIM_ROS2_ENABLED:INTERNAL=ON' build/release/CMakeCache.txt || {
  echo "test.sh: build/release was configured without the ROS 2 layer although Fast DDS is installed" \
       "(MECHSIM_ROS2=OFF set by hand? configure with -DMECHSIM_ROS2=AUTO)" >&2
  exit 1
}
stage tests ctest --test-dir build/release --output-on-failure -j 2
stage sanitizer-build scripts/build.sh asan unit-tests
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  stage sanitizer-tests ctest --test-dir build/asan -L unit --output-on-failure -j 2
# A short fixed fuzzing budget (libFuzzer, Clang, ASan + UBSan): 15 s for each target whose layers
# build in about 3 minutes from scratch (description, mechanism, control, controllers; the other
# targets need the physics and simulation layers, a Clang build of their own that would double
# CI's time: `scripts/fuzz.sh all SECONDS` fuzzes them). A crash, a sanitizer report or a hang
# found here fails the run (fuzz/README.md).
MECHSIM_FUZZ_RUNS='' stage fuzzing scripts/fuzz.sh xacro_fuzz,urdf_fuzz,controllers_fuzz,xmlrpc_fuzz 15
