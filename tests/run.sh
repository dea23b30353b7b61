#!/usr/bin/env bash
# confsurf test runner. Every tests/cases/*.sh is one test; it runs once per process count listed in its
# "# nprocs:" line (default "1 2"), with $MPIEXEC set to the launcher for that count (empty for 1), $NP to the count and
# $TMP to a fresh scratch directory. Exit 0 = pass. CS_TEST_NPROCS=1 restricts to serial runs,
# CS_TEST_FILTER=regex selects cases. Closing line: "N passed, N failed".
#
# Runs share the machine's cores (CS_TEST_JOBS, default nproc): a run of NP ranks takes NP cores, and a serial run
# whose script launches more than one rank itself (an mpirun outside a comment and not "mpirun -n 1") takes them all,
# so two serial cases run side by side on a 2-core machine while a 2-rank case runs alone (Open MPI's ranks
# busy-poll: oversubscribing them costs more than it saves). A "# cores: N" line overrides that guess.
# CS_TEST_JOBS=1 runs them one after the other.
#
# Order: longest first (the seconds of each run in build/test-times.txt, written by the last full run, else in
# tests/times.txt; a run in neither goes first), and a run that does not fit in the free cores lets the next one that
# does go ahead, so no core idles while a serial run is left, and the suite does not end on one long run with a core
# idle (a simulation of the 2026-12-06 full run's 201 times: 1053 s in file order, 856 s this way, the sum of
# cores x seconds / 2 is 856 s).
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
# mpirun waits odls_base_sigkill_timeout (1 s) between SIGTERM and SIGKILL after any rank exits non-zero: a second of
# idle per failing launch, ~200 launches in the bad-input cases. Our error paths exit on every rank by themselves (the
# cases assert it), so the grace period only costs time; a hung rank is still killed, and caught by `timeout`.
export OMPI_MCA_odls_base_sigkill_timeout=${OMPI_MCA_odls_base_sigkill_timeout:-0}
# The ob1 PML (shared memory between the ranks of this one node) is the one Open MPI selects here anyway
# (OMPI_MCA_pml_base_verbose=10: "selected ob1"); naming it skips opening the cm PML and its MTL components (psm,
# psm2) in every rank of every mpirun: 0.22-0.31 s of wall per 2- or 4-rank launch (interleaved A/B, 8-10 launches
# each, load 5), and the suite has hundreds of such launches (golden alone 58 on 2 ranks). Serial runs (singletons)
# are unaffected (0.157 vs 0.160 CPU s).
export OMPI_MCA_pml=${OMPI_MCA_pml:-ob1}
# One OpenBLAS thread per process. A serial run is an MPI singleton, bound to no core, and OpenBLAS starts a thread
# per core in it (src/util/threads.c sets 1 only with several ranks; mpirun binds its ranks, which then start one):
# two serial runs side by side on 2 cores ran 4 spinning BLAS threads. Four flow-heavy serial cases two at a time
# through this runner: 81.6 / 86.3 -> 49.7 / 46.3 CPU s, 115 / 122 -> 66 / 67 s wall. Serially, at load 6-9: golden np 1 39.5 ->
# 28.5 CPU s (57.6 -> 45.0 s wall), a 30-iteration pgd on eight_cgal 2.35 / 1.94 -> 0.93 / 0.98 CPU s, a 1-iteration
# trianglefield run 0.71 -> 0.29 CPU s (8 each); docs/tests_time.md. The results move at round-off (the threads
# split the BLAS reductions); the golden suite pins 1 thread itself (tests/golden/run.py; its serial references were
# re-stored at 1 thread, tests/golden/CHANGES). A value set by the caller is kept.
if [ -z "${OPENBLAS_NUM_THREADS:-}" ]; then export OPENBLAS_NUM_THREADS=1; fi
export CS_ROOT=$PWD CS_BIN=${CS_BIN:-$PWD/bin/confsurf} CS_TESTS=${CS_TESTS:-$PWD/build/tests} # make sanitize: build/san/
export CS_SHARED=${CS_SHARED:-$PWD/../shared}
# python3 resolved once: the cases call it hundreds of times (json, check_close, the checks), and a version
# manager's shim in PATH (pyenv's is a shell script running `pyenv exec`) costs 1.1-1.9 s per call on a loaded
# 2-core machine against 0.1 s for the interpreter it picks. The same interpreter, first in PATH for the cases, run
# with -S (no `site`): the cases' python3 is standard library only (numpy and matplotlib come from
# scripts/find-python.sh's interpreter, not from this one), and `site` executes every site-packages .pth file: with
# this machine's pyenv 3.11, whose .pth imports certifi, a bare `python3 -c 'import json,sys'` costs 79-85 ms of CPU
# with site, 42 ms without, 48 ms through this wrapper (perf stat -r 20, under load average 20): ~33 ms saved per
# call, ~500 calls in the suite (the python3, json and check_close lines of the cases, times their rank counts).
if py=$(python3 -c 'import sys; print(sys.executable)' 2>/dev/null) && [ -x "$py" ]; then
  py_dir=$(mktemp -d); printf '#!/bin/sh\nexec %q -S "$@"\n' "$py" > "$py_dir/python3"; chmod +x "$py_dir/python3"
  export PATH="$py_dir:$PATH"; trap 'rm -rf "$py_dir"' EXIT
fi
jobs_max=${CS_TEST_JOBS:-$(nproc 2>/dev/null || echo 1)}
[[ $jobs_max =~ ^[1-9][0-9]*$ ]] || { echo "tests/run.sh: CS_TEST_JOBS=$jobs_max is not a positive integer" >&2; exit 2; }
pass=0; fail=0; failed=(); used=0
declare -A weight name_of np_of t0_of tmp_of cost_of
times_local=build/test-times.txt
# "name np seconds" lines; the later file wins
for f in tests/times.txt "$times_local"; do
  [ -f "$f" ] || continue
  while read -r n p sec; do [[ $n == \#* || -z $sec ]] || cost_of["$n $p"]=$sec; done < "$f"
done
declare -A measured
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
  local dt; dt=$(echo "$(date +%s.%N) - ${t0_of[$pid]}" | bc); measured["$name $np"]=$(printf '%.1f' "$dt")
  if [ "$rc" = 0 ]; then
    pass=$((pass+1)); printf 'PASS %-40s np=%s  %5.1fs\n' "$name" "$np" "$dt"
  else
    fail=$((fail+1)); failed+=("$name np=$np")
    printf 'FAIL %-40s np=%s\n' "$name" "$np"; sed 's/^/    | /' "$tmp/log" | tail -40
  fi
  rm -rf "$tmp"; used=$((used - ${weight[$pid]}))
  unset "weight[$pid]" "name_of[$pid]" "np_of[$pid]" "t0_of[$pid]" "tmp_of[$pid]"
}

runs=()   # "seconds<TAB>case<TAB>np<TAB>cores"
for c in tests/cases/*.sh; do
  name=$(basename "$c" .sh)
  if [ -n "${CS_TEST_FILTER:-}" ] && ! [[ $name =~ $CS_TEST_FILTER ]]; then continue; fi
  nps=$(sed -n 's/^# nprocs: *//p' "$c" | head -1); nps=${nps:-"1 2"}
  cores=$(sed -n 's/^# cores: *//p' "$c" | head -1)
  own_ranks=0                                                      # the script starts more than one rank of its own
  grep -v '^[[:space:]]*#' "$c" | grep 'mpirun' | grep -qv 'mpirun -n 1 ' && own_ranks=1
  for np in $nps; do
    if [ "${CS_TEST_NPROCS:-}" = 1 ] && [ "$np" != 1 ]; then continue; fi
    w=$np; extra=1; [ "$own_ranks" = 1 ] && extra=$jobs_max; [ -n "$cores" ] && extra=$cores
    [ "$extra" -gt "$w" ] && w=$extra
    [ "$w" -gt "$jobs_max" ] && w=$jobs_max
    runs+=("${cost_of["$name $np"]:-99999}"$'\t'"$c"$'\t'"$np"$'\t'"$w")
  done
done
mapfile -t pending < <(printf '%s\n' "${runs[@]+"${runs[@]}"}" | sort -s -t$'\t' -k1,1gr | grep .)
while [ "${#pending[@]}" -gt 0 ]; do
  started=0
  for i in "${!pending[@]}"; do                                     # the longest run that fits in the free cores
    IFS=$'\t' read -r _ c np w <<< "${pending[$i]}"
    if [ "$used" = 0 ] || [ $((used + w)) -le "$jobs_max" ]; then
      start_run "$c" "$np" "$w"; unset "pending[$i]"; started=1; break
    fi
  done
  [ "$started" = 1 ] || reap_one
done
while [ "$used" -gt 0 ]; do reap_one; done
# a full run keeps its times for the next run's order (a filtered run does not: one case timed alone or under
# another load would misplace it among the others)
if [ -d build ] && [ -z "${CS_TEST_FILTER:-}" ] && [ "${CS_TEST_NPROCS:-}" != 1 ] && [ "${#measured[@]}" -gt 0 ]; then
  for k in "${!measured[@]}"; do cost_of[$k]=${measured[$k]}; done
  { echo "# name np seconds: written by tests/run.sh (the order of the next run)"
    for k in "${!cost_of[@]}"; do echo "$k ${cost_of[$k]}"; done | sort; } > "$times_local.tmp" && mv "$times_local.tmp" "$times_local"
fi
echo "suite time: $(( $(date +%s) - t_start )) s ($jobs_max cores)"
for f in "${failed[@]+"${failed[@]}"}"; do echo "failed: $f"; done
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
