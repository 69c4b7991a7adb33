#!/usr/bin/env bash
# Submits a canopy sweep to Slurm as an array of N shards and a finishing job that waits for
# them (scripts/slurm/README.md):
#   scripts/slurm/submit.sh SWEEP.json OUT_DIR N [extra sbatch options...]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
sweep=${1:?usage: submit.sh SWEEP.json OUT_DIR N [sbatch options...]}
out=${2:?usage: submit.sh SWEEP.json OUT_DIR N [sbatch options...]}
n=${3:?usage: submit.sh SWEEP.json OUT_DIR N [sbatch options...]}
shift 3
array=$(sbatch --parsable --array="0-$((n - 1))" "$@" "$here/sweep.sbatch" "$sweep" "$out")
array=${array%%;*}  # "jobid;cluster" on federated sites
finish=$(sbatch --parsable --dependency="afterany:$array" "$@" "$here/finish.sbatch" "$sweep" "$out")
echo "shards: job array $array ($n tasks); finish: job ${finish%%;*}"
