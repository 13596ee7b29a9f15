#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: installs what it needs, builds mechsim, then runs
# the default scenario: the CC8 rover drives a waypoint route across mechsim's generated Mars
# Yard 2024 for 60 s of simulated time, and writes its report (CSV, summary.json, plots).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
exec build/release/bin/mechsim run robots/cc8/scenarios/mars_yard_route.yaml -o out/cc8_mars_yard_route "$@"
