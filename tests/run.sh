#!/usr/bin/env bash
# confsurf test runner. Every tests/cases/*.sh is one test; it runs once per process count listed in its
# "# nprocs:" line (default "1 2"), with $MPIEXEC set to the launcher for that count (empty for 1), $NP to the count and
# $TMP to a fresh scratch directory. Exit 0 = pass. CS_TEST_NPROCS=1 restricts to serial runs,
# CS_TEST_FILTER=regex selects cases. Closing line: "N passed, N failed".
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
# mpirun waits odls_base_sigkill_timeout (1 s) between SIGTERM and SIGKILL after any rank exits non-zero: a second of
# idle per failing launch, ~200 launches in the bad-input cases. Our error paths exit on every rank by themselves (the
# cases assert it), so the grace period only costs time; a hung rank is still killed, and caught by `timeout`.
export OMPI_MCA_odls_base_sigkill_timeout=${OMPI_MCA_odls_base_sigkill_timeout:-0}
export CS_ROOT=$PWD CS_BIN=${CS_BIN:-$PWD/bin/confsurf} CS_TESTS=${CS_TESTS:-$PWD/build/tests} # make sanitize: build/san/
export CS_SHARED=${CS_SHARED:-$PWD/../shared}
pass=0; fail=0; failed=()
t_start=$(date +%s)
for c in tests/cases/*.sh; do
  name=$(basename "$c" .sh)
  if [ -n "${CS_TEST_FILTER:-}" ] && ! [[ $name =~ $CS_TEST_FILTER ]]; then continue; fi
  nps=$(sed -n 's/^# nprocs: *//p' "$c" | head -1); nps=${nps:-"1 2"}
  for np in $nps; do
    if [ "${CS_TEST_NPROCS:-}" = 1 ] && [ "$np" != 1 ]; then continue; fi
    # serial runs start the program directly (an MPI singleton): mpirun -n 1 adds ~2 s to every failing run
    if [ "$np" = 1 ]; then export NP=1 MPIEXEC=""; else export NP=$np MPIEXEC="mpirun -n $np"; fi
    export TMP=$(mktemp -d)
    t0=$(date +%s.%N)
    if bash "$c" >"$TMP/log" 2>&1; then
      pass=$((pass+1)); printf 'PASS %-40s np=%s  %5.1fs\n' "$name" "$np" "$(echo "$(date +%s.%N) - $t0" | bc)"
    else
      fail=$((fail+1)); failed+=("$name np=$np")
      printf 'FAIL %-40s np=%s\n' "$name" "$np"; sed 's/^/    | /' "$TMP/log" | tail -40
    fi
    rm -rf "$TMP"
  done
done
echo "suite time: $(( $(date +%s) - t_start )) s"
for f in "${failed[@]+"${failed[@]}"}"; do echo "failed: $f"; done
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
