# Stage timing for the README's two commands (sourced by scripts/run.sh and scripts/test.sh):
#   stage NAME COMMAND...   runs one stage and records its wall time;
# when the script ends (passed or not) it prints every stage's time, the total, and how many of
# the compilations in the run ccache answered from its cache, so that CI's time is visible and its
# largest stage can be cut.
_stage_names=()
_stage_secs=()
_stage_t0=$(date +%s.%N)

_ccache_count() {  # hits or misses so far (ccache's counters; 0 without ccache)
  command -v ccache >/dev/null || { echo 0; return; }
  ccache --print-stats 2>/dev/null | awk -v want="$1" '
    want == "hits" && ($1 == "direct_cache_hit" || $1 == "preprocessed_cache_hit") { n += $2 }
    want == "misses" && $1 == "cache_miss" { n += $2 }
    END { print n + 0 }'
}
_stage_hits0=$(_ccache_count hits)
_stage_misses0=$(_ccache_count misses)

stage() {
  local name=$1
  shift
  local t0
  t0=$(date +%s.%N)
  echo "== stage: $name" >&2
  # The time is recorded whether the stage passes or fails (the EXIT trap prints it).
  _stage_names+=("$name")
  _stage_secs+=("")
  local i=$((${#_stage_names[@]} - 1))
  local rc=0
  "$@" || rc=$?
  _stage_secs[$i]=$(awk -v a="$(date +%s.%N)" -v b="$t0" 'BEGIN { printf "%.1f", a - b }')
  return $rc
}

_stage_summary() {
  local rc=$?
  local total hits misses
  total=$(awk -v a="$(date +%s.%N)" -v b="$_stage_t0" 'BEGIN { printf "%.1f", a - b }')
  hits=$(( $(_ccache_count hits) - _stage_hits0 ))
  misses=$(( $(_ccache_count misses) - _stage_misses0 ))
  {
    echo "== stage times ($(basename "$0"), $( ((rc == 0)) && echo passed || echo "failed, status $rc"))"
    local i
    for i in "${!_stage_names[@]}"; do
      printf '  %-22s %8.1f s\n' "${_stage_names[$i]}" "${_stage_secs[$i]:-0}"
    done
    printf '  %-22s %8.1f s\n' "total" "$total"
    if ((hits + misses > 0)); then
      printf '  ccache: %d of %d compilations from the cache (%d%%)\n' "$hits" "$((hits + misses))" \
        "$((100 * hits / (hits + misses)))"
    else
      echo "  ccache: no compilation in this run"
    fi
  } >&2
  exit $rc
}
trap _stage_summary EXIT
