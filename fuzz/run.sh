#!/usr/bin/env bash
# Configures the `fuzz` preset (clang, ASan + UBSan, libFuzzer), builds the targets of fuzz/ and
# runs each for SECONDS (default 60). Fails when a target finds an input that crashes, leaks, hits
# undefined behaviour, throws something other than a ScenarioError, runs longer than 10 s or needs
# more than 2 GiB; the input is kept in build/fuzz/findings/TARGET/ (make it a regression test:
# tests/data/fuzz_regressions/TARGET/). Inputs that find new coverage accumulate in
# build/fuzz/corpus/TARGET/, so that longer runs go on where earlier ones stopped.
#
#   fuzz/run.sh [SECONDS_PER_TARGET] [TARGET...]
#     targets: scenario_loader sweep_loader track_csv result_files record_reader replay_reader
#              python_edits
#
# Environment: CANOPY_WERROR=1 builds with warnings as errors; CANOPY_JOBS=N build jobs (2);
# CANOPY_FUZZ_PARALLEL=N runs N targets at a time (1); CANOPY_FUZZ_FLAGS adds libFuzzer flags
# (e.g. "-runs=1000000" or "-jobs=2").
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build/fuzz"
seconds="${1:-60}"
[ $# -gt 0 ] && shift
targets=("$@")
[ ${#targets[@]} -eq 0 ] &&
  targets=(scenario_loader sweep_loader track_csv result_files record_reader replay_reader python_edits)

werror=OFF
[ "${CANOPY_WERROR:-0}" = 1 ] && werror=ON
mkdir -p "$build"
cmake --preset fuzz -S "$root" -DCANOPY_WERROR="$werror" >"$build/configure.log" 2>&1 ||
  { cat "$build/configure.log" >&2; exit 1; }
cmake --build "$build" -j "${CANOPY_JOBS:-2}" >"$build/build.log" 2>&1 ||
  { grep -E "error|Error" -A5 "$build/build.log" | head -60 >&2; exit 1; }

# One target: its executions and exit code go to $build/TARGET.status ("RUNS STATUS").
fuzz_one() {
  local target="$1" corpus="$build/corpus/$1" findings="$build/findings/$1" log="$build/$1.log"
  mkdir -p "$corpus" "$findings"
  local dict=()
  [ "$target" != track_csv ] && dict=(-dict="$root/fuzz/json.dict")
  local status=0
  # New inputs go to the first folder only: the seeds in the repo stay as they are.
  # shellcheck disable=SC2086
  "$build/fuzz/fuzz_$target" "$corpus" "$root/fuzz/corpus/$target" "${dict[@]}" \
    -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
    -artifact_prefix="$findings/" ${CANOPY_FUZZ_FLAGS:-} >"$log" 2>&1 || status=$?
  local runs
  runs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{s += $2} END {print s + 0}' || true)
  echo "$runs $status" >"$build/$target.status"
}

# CANOPY_FUZZ_PARALLEL targets at a time (default 1); each still gets SECONDS of one process.
parallel="${CANOPY_FUZZ_PARALLEL:-1}"
running=()
for target in "${targets[@]}"; do
  rm -f "$build/$target.status"
  fuzz_one "$target" &
  running+=($!)
  if [ ${#running[@]} -ge "$parallel" ]; then
    wait "${running[0]}"
    running=("${running[@]:1}")
  fi
done
wait

failed=0
for target in "${targets[@]}"; do
  log="$build/$target.log"
  read -r runs status <"$build/$target.status" || { runs=0; status=1; }
  echo "fuzz $target: $runs executions in ${seconds} s, exit code $status (log: $log)"
  if [ "$status" -ne 0 ]; then
    failed=1
    grep -E "ERROR: |SUMMARY: |==[0-9]+==|terminate called|what\(\)|Test unit written" "$log" |
      head -20 >&2
  fi
done
exit "$failed"
