#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: installs what it needs, builds the mechsim program
# and its replay page (`mechsim view`; no test programs or benchmarks), then runs the default scenario:
# the CC8 rover drives a waypoint route across mechsim's generated Mars Yard 2024 for 60 s of
# simulated time, and writes its report (CSV, summary.json, plots). Each stage's time is printed
# at the end (scripts/stages.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/stages.sh
stage install scripts/install-deps.sh
stage build scripts/build.sh release mechsim mechsim_web_page
stage run build/release/bin/mechsim run robots/cc8/scenarios/mars_yard_route.yaml -o out/cc8_mars_yard_route "$@"
