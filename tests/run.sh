#!/usr/bin/env bash
# confsurf test runner. Every tests/cases/*.sh is one test; it runs once per process count listed in its
# "# nprocs:" line (default "1 2"), with $MPIEXEC set to the launcher for that count (empty for 1), $NP to the count and
# $TMP to a fresh scratch directory. Exit 0 = pass. CS_TEST_NPROCS=1 restricts to serial runs,
# CS_TEST_FILTER=regex selects cases. Closing line: "N passed, N failed".
#
# Runs share the machine's cores (CS_TEST_JOBS, default nproc): a run of NP ranks takes NP cores, and a serial run
# whose script launches mpirun itself takes them all, so two serial cases run side by side on a 2-core machine while
# a 2-rank case runs alone (Open MPI's ranks busy-poll: oversubscribing them costs more than it saves).
# CS_TEST_JOBS=1 is the plain one-after-the-other order.
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
# mpirun waits odls_base_sigkill_timeout (1 s) between SIGTERM and SIGKILL after any rank exits non-zero: a second of
# idle per failing launch, ~200 launches in the bad-input cases. Our error paths exit on every rank by themselves (the
# cases assert it), so the grace period only costs time; a hung rank is still killed, and caught by `timeout`.
export OMPI_MCA_odls_base_sigkill_timeout=${OMPI_MCA_odls_base_sigkill_timeout:-0}
export CS_ROOT=$PWD CS_BIN=${CS_BIN:-$PWD/bin/confsurf} CS_TESTS=${CS_TESTS:-$PWD/build/tests} # make sanitize: build/san/
export CS_SHARED=${CS_SHARED:-$PWD/../shared}
jobs_max=${CS_TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
[[ $jobs_max =~ ^[1-9][0-9]*$ ]] || { echo "tests/run.sh: CS_TEST_JOBS=$jobs_max is not a positive integer" >&2; exit 2; }
pass=0; fail=0; failed=(); used=0
declare -A weight name_of np_of t0_of tmp_of
t_start=$(date +%s)

# One run of case $1 with $2 ranks, in its own scratch directory, in the background; its exit code is its verdict.
start_run() {
  local c=$1 np=$2 w=$3 tmp mpiexec="mpirun -n $2"; tmp=$(mktemp -d)
  # serial runs start the program directly (an MPI singleton): mpirun -n 1 adds ~2 s to every failing run
  [ "$np" = 1 ] && mpiexec=""
  NP=$np MPIEXEC=$mpiexec TMP=$tmp bash "$c" >"$tmp/log" 2>&1 &
  local pid=$!
  weight[$pid]=$w; name_of[$pid]=$(basename "$c" .sh); np_of[$pid]=$np; t0_of[$pid]=$(date +%s.%N); tmp_of[$pid]=$tmp
  used=$((used + w))
}

# Wait for any run to end, print its line (and its log's tail if it failed), free its cores.
reap_one() {
  local pid rc
  wait -n -p pid; rc=$?
  local name=${name_of[$pid]} np=${np_of[$pid]} tmp=${tmp_of[$pid]}
  if [ "$rc" = 0 ]; then
    pass=$((pass+1)); printf 'PASS %-40s np=%s  %5.1fs\n' "$name" "$np" "$(echo "$(date +%s.%N) - ${t0_of[$pid]}" | bc)"
  else
    fail=$((fail+1)); failed+=("$name np=$np")
    printf 'FAIL %-40s np=%s\n' "$name" "$np"; sed 's/^/    | /' "$tmp/log" | tail -40
  fi
  rm -rf "$tmp"; used=$((used - ${weight[$pid]}))
  unset "weight[$pid]" "name_of[$pid]" "np_of[$pid]" "t0_of[$pid]" "tmp_of[$pid]"
}

for c in tests/cases/*.sh; do
  name=$(basename "$c" .sh)
  if [ -n "${CS_TEST_FILTER:-}" ] && ! [[ $name =~ $CS_TEST_FILTER ]]; then continue; fi
  nps=$(sed -n 's/^# nprocs: *//p' "$c" | head -1); nps=${nps:-"1 2"}
  own_ranks=0; grep -q 'mpirun' "$c" && own_ranks=1                 # the script starts ranks of its own
  for np in $nps; do
    if [ "${CS_TEST_NPROCS:-}" = 1 ] && [ "$np" != 1 ]; then continue; fi
    w=$np; [ "$own_ranks" = 1 ] && w=$jobs_max
    [ "$w" -gt "$jobs_max" ] && w=$jobs_max
    while [ "$used" -gt 0 ] && [ $((used + w)) -gt "$jobs_max" ]; do reap_one; done
    start_run "$c" "$np" "$w"
  done
done
while [ "$used" -gt 0 ]; do reap_one; done
echo "suite time: $(( $(date +%s) - t_start )) s ($jobs_max cores)"
for f in "${failed[@]+"${failed[@]}"}"; do echo "failed: $f"; done
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
