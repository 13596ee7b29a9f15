#!/usr/bin/env bash
# What a live view costs a run: the CC8's real-time factor on the Mars Yard route, unpaced
# (--real-time-factor 0), without --live, with --live and no client, with one client reading /tf
# and /joint_states (30 Hz of simulated time each), and with one client that subscribes and never
# reads. The four runs alternate REPS times, so that other load on the machine spreads over all.
# Usage: scripts/live_rtf_bench.sh [BUILD_DIR] [DURATION_S] [REPS]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
duration=${2:-20}
reps=${3:-2}
mechsim="$build/bin/mechsim"
client=${LIVE_BENCH:-$build/bin/live_bench}  # the client program (src/live/bench/live_client_bench.cpp)
scenario=robots/cc8/scenarios/mars_yard_route.yaml
work=$(mktemp -d /tmp/mechsim_live_bench_XXXXXX)
trap 'rm -rf "$work"' EXIT
port=18765

rtf() { sed -n 's/.*real-time factor \([0-9.]*\)$/\1/p' "$1" | tail -1; }

run_case() {  # name, extra mechsim args..., then client mode after --client
  local name=$1 mode=$2
  shift 2
  local log="$work/$name.log"
  # perf stat's task-clock: the CPU time of every thread of the run (the tick and the server),
  # which other load on the machine changes far less than the wall-clock real-time factor.
  perf stat -x, -e task-clock -o "$work/$name.cpu" \
    "$mechsim" run "$scenario" --duration "$duration" --no-plots -o "$work/out" --real-time-factor 0 "$@" >"$log" 2>/dev/null &
  local pid=$!
  local client_pid=""
  if [[ "$mode" != none ]]; then
    "$client" "$port" "$mode" 600 >"$work/$name.client" 2>&1 &
    client_pid=$!
  fi
  wait "$pid" || true
  # The stalled client never notices the end: stop it (the reading one ends with the run).
  if [[ "$mode" == stall ]]; then kill "$client_pid" 2>/dev/null || true; fi
  if [[ -n "$client_pid" ]]; then wait "$client_pid" || true; fi
  local live
  live=$(grep '^live: [0-9]' "$log" || true)
  local cpu
  cpu=$(awk -F, '/task-clock/ {printf "%.2f", $1 / 1000}' "$work/$name.cpu")
  printf '%-14s real-time factor %-8s CPU %6s s  %s\n' "$name" "$(rtf "$log")" "$cpu" "$live"
  echo "$name $(rtf "$log") $cpu" >>"$work/table"
  if [[ "$mode" == read ]]; then sed 's/^/               client: /' "$work/$name.client"; fi
}

echo "CC8, $scenario, $duration s simulated, unpaced; load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for ((r = 1; r <= reps; ++r)); do
  run_case no-live none
  run_case live-no-client none --live --port "$port"
  run_case live-reading read --live --port "$port"
  run_case live-stalled stall --live --port "$port"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "medians over $reps runs (CPU: all threads of the run, world generation included):"
for name in no-live live-no-client live-reading live-stalled; do
  median() { sort -n | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
  printf '  %-14s real-time factor %s  CPU %s s\n' "$name" \
    "$(awk -v n="$name" '$1 == n {print $2}' "$work/table" | median)" \
    "$(awk -v n="$name" '$1 == n {print $3}' "$work/table" | median)"
done
