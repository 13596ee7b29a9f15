#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: installs what it needs, builds mechsim and
# expands and checks the CC8 rover's description.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
shared=${MECHSIM_SHARED_DIR:-../shared}
build/release/bin/mechsim check "$shared/robots/cc8_description/urdf/cc8.xacro" \
  --package cc8_description="$shared/robots/cc8_description"
