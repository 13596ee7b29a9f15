#!/usr/bin/env bash
# Fuzzes mechsim's readers with libFuzzer (Clang, AddressSanitizer + UBSan): each fuzz target
# (src/<layer>/fuzz/NAME_fuzz.cpp) runs for SECONDS on a corpus seeded from fuzz/regressions/NAME,
# the project's own robots and scenarios and, when present, ../shared (robots, xacro's conformance
# cases, terrain). Crashes, hangs (> 1 s per input) and out-of-memory inputs are saved under
# build/fuzz/artifacts/NAME; a fixed one is added to fuzz/regressions/NAME, which every ordinary
# build replays as a unit test.
# Usage: scripts/fuzz.sh [NAME[,NAME...]|all] [SECONDS per target, default 60]
# Two lists at once (e.g. one per core) share the build: start the second once the first fuzzes.
# MECHSIM_FUZZ_RUNS=N also stops a target after N executions (whichever comes first), e.g. to
# reach the one million executions per target the reliability issue asks for.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
which=${1:-all}
seconds=${2:-60}
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "fuzz.sh: SECONDS must be a whole number, not '$seconds'" >&2; exit 2; }
if [[ -n "${MECHSIM_FUZZ_RUNS:-}" ]]; then
  [[ "$MECHSIM_FUZZ_RUNS" =~ ^[0-9]+$ ]] || { echo "fuzz.sh: MECHSIM_FUZZ_RUNS must be a whole number, not '$MECHSIM_FUZZ_RUNS'" >&2; exit 2; }
fi
scripts/install-deps.sh --with-fuzz
build=build/fuzz
# -O1 keeps asserts and sanitizer reports readable and fuzzes at nearly full speed.
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O1 \
  -DMECHSIM_FUZZ=ON -DMECHSIM_ROS=OFF -DMECHSIM_ROS2=OFF -DMECHSIM_BENCHMARKS=OFF -DMECHSIM_WERROR=OFF >/dev/null
mapfile -t all < <(ninja -C "$build" -t targets all | sed -n 's/^\([a-z0-9]*_fuzz\): phony$/\1/p' | sort -u)
if [[ "$which" == all ]]; then
  targets=("${all[@]}")
else
  IFS=, read -r -a targets <<<"$which"
  for t in "${targets[@]}"; do
    [[ " ${all[*]} " == *" $t "* ]] || { echo "fuzz.sh: no fuzz target '$t' (targets: ${all[*]})" >&2; exit 2; }
  done
fi
cmake --build "$build" -j "${MECHSIM_JOBS:-2}" --target "${targets[@]}"

shared=../shared  # absent on a machine without the shared data: its seeds are skipped (an `if`, not
                  # `[[ ]] &&`: a false test would end the pipeline, and with it this script, under pipefail)
# Seeds beyond the regression inputs: files each target reads in real use.
seed() {
  local name=$1 corpus=$2
  case "$name" in
    xacro_fuzz)
      find robots -name '*.xacro' -o -name '*.urdf' 2>/dev/null | head -200
      if [[ -d $shared ]]; then find "$shared/conformance/xacro" "$shared/robots" -name '*.xacro' -size -200k 2>/dev/null | head -400; fi ;;
    urdf_fuzz | mjcf_fuzz)
      find robots -name '*.urdf' 2>/dev/null
      if [[ -d $shared ]]; then find "$shared/robots/reference" -name '*.urdf' 2>/dev/null; fi ;;
    scenario_fuzz) find robots -path '*scenarios*' -name '*.yaml' 2>/dev/null ;;
    controllers_fuzz)
      find robots -name '*.yaml' -not -path '*scenarios*' 2>/dev/null
      if [[ -d $shared ]]; then find "$shared/robots" -path '*config*' -name '*.yaml' 2>/dev/null | head -100; fi ;;
  esac | while read -r f; do cp -f "$f" "$corpus/seed_$(basename "$(dirname "$f")")_$(basename "$f")"; done
  case "$name" in
    sweep_fuzz)
      # A sweep file with the scenario it names, as one input (fuzz_files.hpp's "=== NAME").
      find robots src/batch/test/data -name '*.yaml' 2>/dev/null | while read -r f; do
        grep -q '^axes:' "$f" || continue
        scenario=$(dirname "$f")/$(sed -n 's/^scenario: *//p' "$f" | head -1)
        [[ -f "$scenario" ]] || continue
        { sed 's/^scenario: .*/scenario: scenario.yaml/' "$f"; echo "=== scenario.yaml"; cat "$scenario"; } \
          >"$corpus/seed_$(basename "$f")"
      done ;;
    xmlrpc_fuzz)
      # The controller YAMLs as the parameter server returns them: an XML-RPC <value>.
      { find robots -name '*.yaml' -not -path '*scenarios*' -not -path '*sweeps*' 2>/dev/null
        if [[ -d $shared ]]; then find "$shared/robots" -path '*config*' -name '*.yaml' 2>/dev/null | head -100; fi; } |
        while read -r f; do
          /usr/bin/python3 -c 'import sys, yaml, xmlrpc.client
v = yaml.safe_load(open(sys.argv[1]))
if isinstance(v, dict):
    x = xmlrpc.client.dumps((v,), allow_none=False)
    sys.stdout.write(x[x.index("<value>"):x.rindex("</value>") + 8])' "$f" \
            >"$corpus/seed_$(basename "$(dirname "$f")")_$(basename "$f" .yaml).xml" 2>/dev/null || true
        done
      find "$corpus" -name 'seed_*.xml' -empty -delete ;;
  esac
}

# Without the allocation stack of every malloc (ASan's default keeps 30 frames) the targets run
# about twice as fast; a finding is then replayed through its regression test for the full report.
export ASAN_OPTIONS=${ASAN_OPTIONS:-malloc_context_size=0:quarantine_size_mb=16}
# The targets' scratch folders (fuzz/fuzz_files.hpp) go under the build folder: a target stopped
# by a finding or a timeout exits without removing its own, and this script clears them when done.
export TMPDIR=$root/$build/tmp
rm -rf "$TMPDIR"
mkdir -p "$TMPDIR"
trap 'rm -rf "$TMPDIR"' EXIT
status=0
summary=()
for t in "${targets[@]}"; do
  corpus=$build/corpus/$t
  artifacts=$build/artifacts/$t
  mkdir -p "$corpus" "$artifacts"
  cp -f fuzz/regressions/"$t"/* "$corpus"/ 2>/dev/null || true
  seed "$t" "$corpus"
  case "$t" in
    xacro_fuzz) dict=(-dict=fuzz/dicts/xacro.dict) ;;
    urdf_fuzz | mjcf_fuzz) dict=(-dict=fuzz/dicts/urdf.dict) ;;
    controllers_fuzz | scenario_fuzz | sweep_fuzz) dict=(-dict=fuzz/dicts/yaml.dict) ;;
    xmlrpc_fuzz) dict=(-dict=fuzz/dicts/xmlrpc.dict) ;;
    *) dict=() ;;
  esac
  # Scenario files are a few kB (the largest shipped: 2.3 kB): 16 kB inputs leave room to grow
  # while keeping the fuzzer off 100 kB nesting bombs, which only yaml-cpp's parser sees (the
  # regression inputs replay them in full in every build).
  # xmlrpc_fuzz: roscpp's own XML-RPC parser (xmlrpcpp) is quadratic in nesting: 0.13 s for a
  # 57 kB value 900 levels deep, over 1 s under the sanitizers; parameter namespaces are a few kB.
  max_len=65536
  [[ "$t" == scenario_fuzz || "$t" == sweep_fuzz || "$t" == xmlrpc_fuzz ]] && max_len=16384
  before=$(find "$artifacts" -type f | wc -l)
  log=$build/$t.log
  echo "fuzz.sh: $t for $seconds s (corpus $(find "$corpus" -type f | wc -l) inputs)" >&2
  # A "timeout" on a loaded machine is often starvation, not a hang: such an input is replayed
  # alone three times, and when it runs within the bound every time the artifact is dropped
  # (named in the log) and fuzzing goes on from the grown corpus with the time and runs left.
  # Each stretch's runs add up; rate = runs / fuzzing seconds.
  runs=0
  spent=0
  left=$seconds
  : >"$log"
  while ((left > 0)); do
    limit=()
    if [[ -n "${MECHSIM_FUZZ_RUNS:-}" ]]; then
      ((runs < MECHSIM_FUZZ_RUNS)) || break
      limit=(-runs=$((MECHSIM_FUZZ_RUNS - runs)))
    fi
    started=$(date +%s)
    # Run inside the build folder: MuJoCo writes MUJOCO_LOG.TXT into the working directory.
    (cd "$build" && "bin/$t" "corpus/$t" "${dict[@]/-dict=/-dict=$root/}" -max_total_time="$left" "${limit[@]}" -timeout=1 \
       -rss_limit_mb=2048 -max_len="$max_len" -print_final_stats=1 -artifact_prefix="artifacts/$t/") >"$log.part" 2>&1 || true
    cat "$log.part" >>"$log"
    elapsed=$(($(date +%s) - started))
    spent=$((spent + elapsed))
    left=$((left - elapsed))
    part=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log.part" | tail -1)
    [[ -n "$part" ]] || { runs=""; break; }
    runs=$((runs + part))
    timeout=$(sed -n 's/.*Test unit written to \(artifacts\/.*\/timeout-[0-9a-f]*\)$/\1/p' "$log.part" | tail -1)
    [[ -n "$timeout" ]] || break
    slow=0
    for _ in 1 2 3; do
      (cd "$build" && timeout 10 "bin/$t" "$timeout" -timeout=1 >/dev/null 2>&1) || slow=1
    done
    if ((slow)); then
      echo "fuzz.sh: $t: $timeout runs over 1 s alone: a hang" >>"$log"
      break
    fi
    echo "fuzz.sh: $t: $timeout ran within 1 s alone three times: starvation, not a hang; fuzzing on" | tee -a "$log" >&2
    rm -f "$build/$timeout"
  done
  rm -f "$log.part"
  rate=$(( spent > 0 ? ${runs:-0} / spent : 0 ))
  found=$(( $(find "$artifacts" -type f | wc -l) - before ))
  summary+=("$(printf '%-18s %12s runs %8s/s  %d new finding(s)' "$t" "${runs:-?}" "${rate:-?}" "$found")")
  if ((found > 0)) || [[ -z "$runs" ]]; then
    status=1
    echo "fuzz.sh: $t: see $log and $artifacts" >&2
  fi
done
printf '%s\n' "${summary[@]}"
exit $status
