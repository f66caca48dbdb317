#!/usr/bin/env bash
# The Slurm path of docs/experiments.md "On a cluster (Slurm)": a one-node Slurm on 127.0.0.1 (scripts/slurm-local.sh) runs a sweep
# through both scripts of examples/slurm/ with `sbatch --wait`: the MPI job on 2 ranks, and a job
# array of 3 shards merged by a job that depends on it. Each must give the files of a plain
# `--jobs 1` run byte for byte. A job that fails must fail its sbatch. Every daemon is stopped on
# exit, and nothing of the cluster may be left running.
#
# Usage: tests/slurm_test.sh MULTICPG SWEEP.toml   (as root, after `scripts/setup.sh --cluster`)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ $# -ne 2 ]; then
  echo "usage: tests/slurm_test.sh MULTICPG SWEEP.toml" >&2
  exit 2
fi
# Without the cluster packages (scripts/setup.sh --cluster) there is no Slurm to test: ctest
# reports the test skipped (SKIP_RETURN_CODE 77), and .ci/run installs them and runs it.
if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  echo "slurm_test: Slurm is not installed (scripts/setup.sh --cluster); skipped" >&2
  exit 77
fi
multicpg="$(realpath "$1")"
sweep="$(realpath "$2")"
# What a run leaves in its out dir that must not depend on how it was run (provenance.json
# records the command line, so it does).
compared=(runs experiment.json runs.csv trials.csv table.csv table.md summary.json)
readonly ranks=2 shards=3
# Generous limits for a sweep that takes well under a minute; only a hung job reaches them.
readonly job_minutes=10
mpi_script="$root/examples/slurm/mpi.sbatch"
array_script="$root/examples/slurm/array.sbatch"
# The MPI job on one node: the script asks for several nodes of a real cluster.
mpi_job=(--nodes=1 --ntasks="$ranks" --ntasks-per-node="$ranks" --time="$job_minutes")
# The array's tasks: one core each, the script asks for more.
array_job=(--cpus-per-task=1 --time="$job_minutes")

work="$(mktemp -d /tmp/multicpg-slurm.XXXXXX)"
# munged wants every directory above its socket searchable by all.
chmod 755 "$work"
cluster="$work/slurm"
finish() {
  local status=$?
  "$root/scripts/slurm-local.sh" stop "$cluster" || status=1
  if [ $status -eq 0 ]; then rm -rf "$work"; else echo "slurm_test: kept $work" >&2; fi
  exit $status
}
trap finish EXIT
# A test runner's timeout or ^C stops the daemons too.
trap 'exit 1' INT TERM HUP

fail() {
  echo "slurm_test: FAILED: $*" >&2
  exit 1
}

# The state of job ID (COMPLETED, FAILED, CANCELLED, ...; Slurm keeps it for minutes).
job_state() {
  scontrol show job --oneliner "$1" | sed -n 's/.* JobState=\([A-Z_]*\) .*/\1/p'
}

"$root/scripts/slurm-local.sh" start "$cluster"
export SLURM_CONF="$cluster/slurm.conf"
export MULTICPG="$multicpg"
# CI runs as root; OpenMPI refuses that unless told (here only, not globally).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$work"

"$multicpg" run "$sweep" --out plain --jobs 1

sbatch --wait --quiet "${mpi_job[@]}" --output=mpi.log "$mpi_script" "$sweep" mpi ||
  fail "the MPI job failed: $(cat mpi.log)"

array=$(sbatch --parsable "${array_job[@]}" --array=0-$((shards - 1)) --output=shard-%a.log \
  "$array_script" "$sweep" array)
# A merge cancelled because a shard failed never ran, and sbatch --wait says 0 for it.
if ! merge=$(sbatch --wait --parsable --dependency="afterok:$array" --time="$job_minutes" \
  --output=merge.log --wrap "\"$multicpg\" merge array/merged array/shard-*") ||
  [ "$(job_state "$merge")" != COMPLETED ]; then
  fail "the array or its merge failed: $(cat shard-*.log merge.log 2>&1)"
fi

for style in mpi array/merged; do
  for item in "${compared[@]}"; do
    [ -e "plain/$item" ] || fail "the plain run has no $item"
    diff -r "plain/$item" "$style/$item" >/dev/null ||
      fail "$style/$item differs from the plain run"
  done
done
for ((i = 0; i < shards; i++)); do
  [ -n "$(ls "array/shard-$i/runs")" ] || fail "shard $i ran nothing"
done

# A job whose program fails (here: the sweep file does not exist) must fail sbatch --wait.
missing="$work/missing.toml"
if sbatch --wait --quiet "${mpi_job[@]}" --output=bad.log "$mpi_script" "$missing" bad; then
  fail "a failing MPI job gave sbatch exit 0"
fi
if sbatch --wait --quiet "${array_job[@]}" --array=0-1 --output=bad-%a.log "$array_script" \
  "$missing" bad; then
  fail "a failing job array gave sbatch exit 0"
fi

echo "slurm_test: the MPI job ($ranks ranks) and the merged array ($shards shards)" \
  "match the plain run; failing jobs fail"
