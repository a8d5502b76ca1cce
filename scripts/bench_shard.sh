# Sourced by scripts/bench-suite.sh: its independent steps dealt across shards (docs/distributed.md,
# "Sharded sweeps"). Kept apart from the suite's steps and logging.
#
# SHARD of SHARDS comes from --shard K/N or, under mpirun, from Open MPI's OMPI_COMM_WORLD_RANK and
# OMPI_COMM_WORLD_SIZE (0 of 1 otherwise). Step i (in the suite's order) runs on shard i mod N. Every
# shard writes into the same OUT directory (one host, or a shared file system), so the merged result set
# is the unsharded one's files. Shard 0 then waits for every other shard's mark in OUT and runs the steps
# that read all results (after_all). A failing shard exits non-zero; under mpirun that stops every rank.
# With BENCH_DRY_RUN=1 nothing runs: each step this shard owns is printed as "step NAME" (after_all's as
# "final NAME"), which tests/mpi/bench_shard_test.py checks.

SHARD="${SHARD:-${OMPI_COMM_WORLD_RANK:-0}}"
SHARDS="${SHARDS:-${OMPI_COMM_WORLD_SIZE:-1}}"
BENCH_DRY_RUN="${BENCH_DRY_RUN:-0}"
STEP_INDEX=0
# Marks of one run: mpirun's job id (every rank has it), else BENCH_RUN_ID (give every shard the same).
RUN_ID="${BENCH_RUN_ID:-${OMPI_MCA_ess_base_jobid:-manual}}"

# Parses K/N of --shard into SHARD and SHARDS; a bad value is a usage error (exit 2).
set_shard() {
  case "$1" in
    */*) SHARD="${1%/*}"; SHARDS="${1#*/}" ;;
    *) SHARD=x ;;
  esac
  case "$SHARD$SHARDS" in *[!0-9]*|"") echo "bench-suite: --shard wants K/N with 0 <= K < N (got '$1')" >&2; exit 2 ;; esac
  if [ "$SHARDS" -lt 1 ] || [ "$SHARD" -ge "$SHARDS" ]; then
    echo "bench-suite: --shard wants K/N with 0 <= K < N (got '$1')" >&2
    exit 2
  fi
}

# True when this shard runs the next step (NAME names it in the dry run). Called once per step on every
# shard, in the same order, so the index means the same step everywhere.
step() {
  i=$STEP_INDEX
  STEP_INDEX=$((STEP_INDEX + 1))
  [ $((i % SHARDS)) -eq "$SHARD" ] || return 1
  if [ "$BENCH_DRY_RUN" = 1 ]; then
    echo "step $1"
    return 1
  fi
  echo "bench-suite: shard $SHARD of $SHARDS: $1" >&2
  return 0
}

# The other shards mark their end and leave; shard 0 waits for every mark, once, and goes on.
SHARDS_JOINED=0
join_shards() {
  [ "$SHARDS" -gt 1 ] && [ "$BENCH_DRY_RUN" != 1 ] || return 0
  if [ "$SHARD" -ne 0 ]; then
    touch "$OUT/.shard-$SHARD-of-$SHARDS.$RUN_ID.done"
    exit 0
  fi
  [ "$SHARDS_JOINED" = 1 ] && return 0
  k=1
  while [ "$k" -lt "$SHARDS" ]; do
    while [ ! -e "$OUT/.shard-$k-of-$SHARDS.$RUN_ID.done" ]; do sleep 5; done
    k=$((k + 1))
  done
  SHARDS_JOINED=1
}

# True on shard 0 for a step that reads every shard's results (the others have finished).
after_all() {
  join_shards
  if [ "$BENCH_DRY_RUN" = 1 ]; then
    [ "$SHARD" -eq 0 ] && echo "final $1"
    return 1
  fi
  return 0
}
