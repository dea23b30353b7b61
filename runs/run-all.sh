#!/usr/bin/env bash
# `make bench`: runs the benchmarks runs/bench_*.sh one after the other (they are not tests: each takes minutes
# and writes a markdown table, see its header and README "Benchmarks"). BENCH='regex' selects scripts by name,
# e.g. BENCH='spin|bs' make bench. Stops at the first benchmark that fails (after running it to its end).
set -u
cd "$(dirname "$0")/.."
BENCH=${BENCH:-.}
status=0
for b in runs/bench_*.sh; do
  name=$(basename "$b" .sh)
  echo "$name" | grep -Eq -- "$BENCH" || continue
  echo "== $name"
  if ! bash "$b"; then echo "== $name FAILED"; status=1; break; fi
done
exit $status
