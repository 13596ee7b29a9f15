#!/usr/bin/env bash
# Configures and builds one flavour of mechsim.
# Usage: scripts/build.sh [release|asan] [unit-tests|TARGET...]
#   unit-tests: build only the programs of the CTest "unit" label (what the sanitizer run needs);
#   TARGET...: only those targets (scripts/run.sh: `mechsim`); nothing: everything.
set -euo pipefail
cd "$(dirname "$0")/.."
flavour=${1:-release}
case "$flavour" in
  release) flags=(-DCMAKE_BUILD_TYPE=Release) ;;
  asan) flags=(-DCMAKE_BUILD_TYPE=Debug -DMECHSIM_SANITIZE=ON -DMECHSIM_BENCHMARKS=OFF) ;;
  *) echo "build.sh: unknown flavour '$flavour' (release or asan)" >&2; exit 1 ;;
esac
cmake -S . -B "build/$flavour" -G Ninja "${flags[@]}" >/dev/null
targets=()
if [[ $# -gt 1 && "$2" != "unit-tests" ]]; then
  targets=(--target "${@:2}")
elif [[ "${2:-}" == "unit-tests" ]]; then
  # <layer>_test programs hold the unit tests (conformance, scenario and cli programs are separate).
  mapfile -t targets < <(ninja -C "build/$flavour" -t targets all | sed -n 's/^\([a-z0-9]*_\(test\|fuzz\)\): phony$/\1/p' \
                           | grep -vE '_(conformance|scenario)_test$|^cli_test$' | sort -u)
  ((${#targets[@]})) || { echo "build.sh: no unit-test targets found" >&2; exit 1; }
  targets=(--target "${targets[@]}")
fi
cmake --build "build/$flavour" -j "${MECHSIM_JOBS:-2}" "${targets[@]}"
