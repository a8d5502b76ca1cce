# Sourced by scripts/bench-suite.sh: its independent steps dealt across shards (docs/distributed.md,
# "Sharded sweeps"). Kept apart from the suite's steps and logging.
#
# SHARD of SHARDS comes from --shard K/N or, under mpirun, from Open MPI's OMPI_COMM_WORLD_RANK and
# OMPI_COMM_WORLD_SIZE (0 of 1 otherwise). Step i (in the suite's order) runs on shard i mod N. Every
# shard writes into the same OUT directory (one host, or a shared file system), so the merged result set
# is the unsharded one's files. Shard 0 then waits for every other shard's mark in OUT and runs the steps
# that read all results (after_all). A failing shard exits non-zero; under mpirun that stops every rank.
# With BENCH_DRY_RUN=1 nothing runs: the suite prints each step this shard owns as "step NAME" (the final
# ones as "final NAME"), which tests/mpi/bench_shard_test.py checks.

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

# True when this shard runs the next step. Called once per step on every shard, in the same order, so
# the index means the same step everywhere.
shard_owns() {
  i=$STEP_INDEX
  STEP_INDEX=$((STEP_INDEX + 1))
  [ $((i % SHARDS)) -eq "$SHARD" ]
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

# Before a step that reads every shard's results: the other shards mark their end and leave (exit 0);
# shard 0 waits, once, for every mark and goes on. Nothing to wait for in the dry run.
after_all() {
  join_shards
}
