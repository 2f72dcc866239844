#!/bin/bash
# Submits a study as a Slurm job array of N slices and a merge that waits for all of them:
#   examples/slurm/submit.sh ROTBENCH STUDY N RUN_ARGUMENTS...
# e.g. examples/slurm/submit.sh build/rotbench study 20 --scenes silo_discharge,direct_shear \
#        --schemes direct,zvw,zvw_corrected,richardson --ensemble 10 --dt 1e-5,2e-5
# Prints the two job ids (array, merge). Extra sbatch options (partition, account, time):
# set SBATCH_PARTITION, SBATCH_ACCOUNT, SBATCH_TIMELIMIT, which sbatch reads itself.
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 ROTBENCH STUDY N RUN_ARGUMENTS..." >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
rotbench=$(realpath "$1") study=$(realpath -m "$2") slices=$3
shift 3
case "$slices" in '' | *[!0-9]* | 0) echo "$0: N must be a whole number of slices, not '$slices'" >&2; exit 2 ;; esac
mkdir -p "$study/logs"
array=$(sbatch --parsable --array="1-$slices" --output="$study/logs/shard_%a.txt" "$here/shard.sbatch" "$rotbench" "$study" "$@")
merge=$(sbatch --parsable --dependency="afterok:$array" --output="$study/logs/merge.txt" "$here/merge.sbatch" "$rotbench" "$study" "$slices")
echo "$array $merge"
