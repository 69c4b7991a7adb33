#!/usr/bin/env bash
# Sweeps beyond one machine, end to end (issue "Sweeps beyond one machine"): shards run one after
# another and at once, the Slurm scripts' steps with the Slurm variables set, MPI ranks, a rank
# killed and the sweep resumed — each compared byte for byte with `canopy sweep --jobs 1`.
#   cluster_sweeps_test.sh CANOPY_BINARY SOURCE_DIR CASE
set -euo pipefail
canopy=$1
source_dir=$2
case=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/canopy-cluster-$case.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"

# A small sweep: 4 configurations × 3 trials of a short Trajectory Handover.
sweep_file() {  # NAME TRIALS DURATION
  cat >"$1.json" <<JSON
{"name": "$1", "scenario": "trajectory_handover", "trials": $2, "seed": 5,
 "set": {"clock.duration": $3},
 "axes": [{"path": "planner.algorithm", "values": ["sma", "dec_pomdp"]},
          {"path": "planner.horizon", "values": [1, 3]}]}
JSON
}
fail() { echo "FAILED: $*" >&2; exit 1; }
# The same files with the same bytes, analysis/ aside (it is not part of a sweep's results).
same() { diff -r -x analysis "$1" "$2" >/dev/null || { diff -r -x analysis "$1" "$2" | head; fail "$2 differs from $1"; }; }
trial_files() { find "$1/trials" -name 'trial_*.json' | wc -l; }

sweep_file small 3 4.0
"$canopy" sweep small.json --out reference --jobs 1 >/dev/null 2>&1

case $case in
shards_one_after_another)
  for i in 0 1 2; do "$canopy" sweep small.json --out sharded --shard "$i/3" >/dev/null 2>&1; done
  [ ! -e sharded/summary.json ] || fail "a shard wrote the summary"
  "$canopy" sweep --status sharded | grep -q "small: 12/12 trials done" || fail "status"
  "$canopy" sweep small.json --out sharded 2>/dev/null | grep -q "ran 0 trials" ||
    fail "finishing ran trials"
  same reference sharded
  ;;
shards_at_once)
  pids=()
  for i in 0 1 2; do "$canopy" sweep small.json --out sharded --shard "$i/3" --jobs 1 >/dev/null 2>&1 & pids+=($!); done
  for p in "${pids[@]}"; do wait "$p" || fail "a shard failed"; done
  "$canopy" sweep small.json --out sharded >/dev/null 2>&1
  same reference sharded
  ;;
slurm_steps)
  # The job array's tasks (at once, 1-based array ids as with --array=1-3), then the dependent
  # finishing job, as Slurm would run them.
  pids=()
  for id in 1 2 3; do
    CANOPY=$canopy SLURM_ARRAY_TASK_ID=$id SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=3 \
      bash "$source_dir/scripts/slurm/sweep.sbatch" small.json slurm >/dev/null 2>&1 & pids+=($!)
  done
  for p in "${pids[@]}"; do wait "$p" || fail "an array task failed"; done
  [ "$(trial_files slurm)" -eq 12 ] || fail "the array ran $(trial_files slurm) of 12 trials"
  CANOPY=$canopy bash "$source_dir/scripts/slurm/finish.sbatch" small.json slurm >/dev/null 2>&1 ||
    fail "the finishing job failed"
  [ -s slurm/analysis/ownership_states.csv ] || fail "no analysis"
  same reference slurm
  # A task outside a contiguous array is refused.
  if CANOPY=$canopy SLURM_ARRAY_TASK_ID=7 SLURM_ARRAY_TASK_COUNT=3 \
      bash "$source_dir/scripts/slurm/sweep.sbatch" small.json slurm >/dev/null 2>&1; then
    fail "task 7 of 3 ran"
  fi
  ;;
other_sweep_refused)
  "$canopy" sweep small.json --out mixed --shard 0/2 >/dev/null 2>&1
  sweep_file other 3 6.0
  set +e
  "$canopy" sweep other.json --out mixed --shard 1/2 >/dev/null 2>err.txt
  code=$?
  set -e
  [ "$code" -eq 2 ] || fail "a shard of another sweep exited $code"
  grep -q "another sweep" err.txt || fail "message: $(cat err.txt)"
  ;;
mpi)
  set +e; "$canopy" sweep small.json --out single --mpi >/dev/null 2>err.txt; code=$?; set -e
  if grep -q "built without MPI" err.txt; then
    [ "$code" -eq 2 ] || fail "--mpi without MPI exited $code"
    echo "built without MPI: --mpi refused with exit code 2"; exit 0
  fi
  [ "$code" -eq 0 ] || fail "a single MPI process exited $code: $(cat err.txt)"
  same reference single
  mpirun --allow-run-as-root --oversubscribe -n 3 "$canopy" sweep small.json --out mpi --mpi \
    --jobs 1 >out.txt 2>&1 || { cat out.txt; fail "mpirun"; }
  ran=$(grep -o 'ran [0-9]* trials' out.txt | awk '{s += $2} END {print s}')
  [ "$ran" -eq 12 ] || fail "the ranks ran $ran trials, not 12"
  same reference mpi
  ;;
mpi_rank_killed)
  set +e; "$canopy" sweep small.json --out probe --mpi >/dev/null 2>err.txt; set -e
  if grep -q "built without MPI" err.txt; then echo "built without MPI"; exit 0; fi
  sweep_file long 12 8.0  # 48 trials
  "$canopy" sweep long.json --out long_reference --jobs 1 >/dev/null 2>&1
  mpirun --allow-run-as-root --oversubscribe -n 3 "$canopy" sweep long.json --out killed --mpi \
    --jobs 1 >/dev/null 2>&1 &
  launcher=$!
  for _ in $(seq 1 600); do
    [ -d killed/trials ] && [ "$(trial_files killed)" -ge 4 ] && break
    sleep 0.05
  done
  rank=$(pgrep -f "sweep long.json --out killed --mpi" | grep -v "^$launcher\$" | tail -1 || true)
  [ -n "$rank" ] || fail "no rank to kill"
  kill -9 "$rank"
  wait "$launcher" && fail "mpirun exited 0 after a rank was killed" || true
  sleep 1  # ranks still finishing a write when mpirun tears them down
  pkill -9 -f "sweep long.json --out killed --mpi" || true
  before=$(trial_files killed)
  [ "$before" -lt 48 ] || fail "every trial finished before the kill"
  "$canopy" sweep long.json --out killed >resume.txt 2>&1
  ran=$(grep -o 'ran [0-9]* trials' resume.txt | awk '{print $2}')
  [ $((before + ran)) -eq 48 ] || fail "$before finished + $ran rerun != 48"
  same long_reference killed
  echo "killed after $before of 48 trials; the resume ran $ran"
  ;;
*)
  fail "unknown case $case"
  ;;
esac
