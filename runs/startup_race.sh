#!/usr/bin/env bash
# Start-up race of concurrent serial runs (issue 36, item 2): P concurrent `bin/confsurf -task info -gen icosphere
# -gen_level 1` (MPI singletons) x N rounds; counts the runs that fail and prints each distinct failure message.
# Usage: runs/startup_race.sh [ROUNDS=200] [P=8]; extra environment is passed through (e.g. CS_MPI_DEFAULTS=0, or
# OMPI_MCA_orte_tmpdir_base=/tmp for the shared session tree of before the fix). Exit 1 if any run failed.
set -uo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
N=${1:-200}
P=${2:-8}
BIN=${CS_BIN:-bin/confsurf} # a copy, when the tree is rebuilt meanwhile
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
t0=$(date +%s)
for ((r = 0; r < N; r++)); do
  for ((p = 0; p < P; p++)); do
    ("$BIN" -task info -gen icosphere -gen_level 1 >"$tmp/out.$p" 2>"$tmp/err.$p"; echo $? >"$tmp/rc.$p") &
  done
  wait
  for ((p = 0; p < P; p++)); do
    rc=$(cat "$tmp/rc.$p")
    if [ "$rc" != 0 ]; then
      fail=$((fail + 1))
      { echo "--- round $r run $p rc $rc"; cat "$tmp/err.$p"; } >>"$tmp/failures"
    fi
  done
done
echo "startup_race: $((N * P)) runs ($N rounds x $P concurrent), $fail failed, $(($(date +%s) - t0)) s"
if [ "$fail" -gt 0 ]; then
  echo "distinct failure lines (count):"
  grep -v '^--- ' "$tmp/failures" | sed 's/[0-9]\{3,\}/N/g' | sort | uniq -c | sort -rn | head -20
  echo "first failure in full:"
  awk '/^--- /{n++} n==1' "$tmp/failures" | head -40
  exit 1
fi
