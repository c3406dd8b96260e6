#!/usr/bin/env bash
# `sph-mol` on 2 ranks, interrupted (docs/parallel.md, "Signals"): SIGTERM sent to one rank only ends
# both at the same step, mpirun exits with 143, rank 0 writes the checkpoint at the time reached and
# the summary with "status": "interrupted"; SIGTERM sent to Open MPI's mpirun reaches the ranks as
# SIGTERM (odls_base_sigkill_timeout seconds later, and as long again before its SIGKILL), they
# write the same, and mpirun exits with 1. From tests/CMakeLists.txt:
#   sph_mol_signals_under_mpirun.sh SPHMOL MPIEXEC FLAGS(comma-separated) SOURCE_DIR WORK_DIR
set -u
sphmol=$1 mpiexec=$2 flags=${3//,/ } src=$4 work=$5
rm -rf "$work" && mkdir -p "$work" || exit 1
fail() {
  echo "FAIL: $*"
  exit 1
}

# Starts the dam break on 2 ranks into $work/NAME (further mpirun options after NAME) and waits for
# a checkpoint; sets pid (mpirun's).
start() {
  local name=$1
  shift
  # shellcheck disable=SC2086  # flags: separate words
  "$mpiexec" -n 2 $flags "$@" "$sphmol" --config "$src/verification/dam_break.yaml" --set discretization.spacing=0.02 \
    --set time.t_end=10 --set output.times=[10] --set output.plots=false --set output.checkpoint_every=0.005 --quiet \
    --output "$work/$name" >"$work/$name.out" 2>&1 &
  pid=$!
  for _ in $(seq 600); do
    # Any checkpoint: the run keeps only its latest ones, and a fast run may have pruned the first.
    compgen -G "$work/$name/checkpoint-*/checkpoint.json" >/dev/null && return
    kill -0 "$pid" 2>/dev/null || fail "$name: ended before a checkpoint: $(cat "$work/$name.out")"
    sleep 0.1
  done
  fail "$name: no checkpoint after 60 s"
}

# Waits (at most 60 s) for mpirun to end and checks its exit code, the summary and the checkpoint.
check_interrupted() {
  local name=$1 code=$2 rc=
  for _ in $(seq 600); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$pid" 2>/dev/null; then
    pkill -KILL -P "$pid"
    kill -KILL "$pid"
    fail "$name: still running 60 s after the signal"
  fi
  wait "$pid"
  rc=$?
  local out summary t
  out=$(cat "$work/$name.out")
  [ "$rc" -eq "$code" ] || fail "$name: mpirun exited with $rc, expected $code: $out"
  summary=$(cat "$work/$name/summary.json") || fail "$name: no summary.json: $out"
  grep -q '"status": "interrupted"' <<<"$summary" || fail "$name: the summary does not say interrupted"
  grep -q '"signal": 15' <<<"$summary" || fail "$name: the summary does not name SIGTERM"
  t=$(sed -n 's/^ *"t_reached": \([0-9.e+-]*\),\{0,1\}$/\1/p' <<<"$summary")
  [ -n "$t" ] || fail "$name: no t_reached in the summary"
  [ -e "$work/$name/checkpoint-$(printf '%.10g' "$t")/checkpoint.json" ] || fail "$name: no checkpoint at t_reached = $t"
  [ "$(grep -c 'sph-mol: interrupted at t = ' <<<"$out")" -eq 1 ] || fail "$name: rank 0 alone should print the end: $out"
  echo "$name: mpirun exit $rc, interrupted at t = $t s with a checkpoint"
}

start one_rank
ranks=($(pgrep -P "$pid"))
[ "${#ranks[@]}" -eq 2 ] || fail "expected 2 ranks under mpirun $pid, found: ${ranks[*]}"
kill -TERM "${ranks[1]}"
check_interrupted one_rank 143

if "$mpiexec" --version 2>/dev/null | grep -qE "Open MPI|OpenRTE"; then
  start mpirun --mca odls_base_sigkill_timeout 3
  kill -TERM "$pid"
  check_interrupted mpirun 1
fi
