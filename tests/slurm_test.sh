#!/usr/bin/env bash
# The Slurm path of issue 10: a one-node Slurm on 127.0.0.1 (scripts/slurm-local.sh) runs a sweep
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
multicpg="$(realpath "$1")"
sweep="$(realpath "$2")"
# What a run leaves in its out dir that must not depend on how it was run.
compared=(runs)
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

# Until `multicpg run` and `multicpg merge` exist (issue 10 items 1 and 3), a stand-in gives the
# examples something with their interface to run. Its sweep file lists one `multicpg learn`
# argument line per run; `run` does the runs of its part (its MPI rank of the ranks, or its
# --shard i/N: every N-th run from the i-th) into OUT/runs/N.json, `merge` copies the shards'
# runs together. Integration deletes this block and runs the real program on examples/quick.toml.
stand_in="$work/multicpg"
cat >"$stand_in" <<'EOF'
#!/usr/bin/env bash
set -euo pipefail
command=$1
shift
case $command in
  run)
    list=$1 part=${OMPI_COMM_WORLD_RANK:-0} parts=${OMPI_COMM_WORLD_SIZE:-1}
    shift
    while [ $# -gt 0 ]; do
      case $1 in
        --out) out=$2 ;;
        --jobs) ;;
        --shard) part=${2%/*} parts=${2#*/} ;;
        *) echo "multicpg run: unknown option $1" >&2; exit 2 ;;
      esac
      shift 2
    done
    mkdir -p "$out/runs"
    mapfile -t lines <"$list"
    for ((n = part; n < ${#lines[@]}; n += parts)); do
      "$MULTICPG_REAL" learn ${lines[n]} --json </dev/null >"$out/runs/$n.json"
    done
    ;;
  merge)
    out=$1
    shift
    mkdir -p "$out/runs"
    for dir in "$@"; do cp "$dir"/runs/*.json "$out/runs/"; done
    ;;
  *) echo "multicpg: unknown command $command" >&2; exit 2 ;;
esac
EOF
chmod +x "$stand_in"
export MULTICPG_REAL="$multicpg"
multicpg="$stand_in"
sweep="$work/sweep.txt"
for seed in 1 2 3 4 5; do
  echo "--robot quadruped --disable R1 --mode paper --max-trials 2 --seed $seed" >>"$sweep"
done

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
