#!/usr/bin/env bash
# Runs every libFuzzer target of fuzz/ for FUZZ_SECONDS (default 60) each, starting from the committed corpus
# fuzz/corpus/<target>/ with the dictionary fuzz/<target>.dict; new inputs go to build/fuzz/new/<target>/ (the
# committed corpus is not modified). Any finding (crash, sanitizer report, leak, timeout of one input) fails the
# run; the input is left in build/fuzz/findings/: after the fix, add it to fuzz/corpus/<target>/.
# Usage: make fuzz && bash fuzz/run.sh [target...]
set -u
cd "$(dirname "$0")/.."
secs=${FUZZ_SECONDS:-60}
targets=${*:-obj off ply values}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=0:detect_leaks=1} LSAN_OPTIONS=suppressions=$PWD/.ci/sanitizer.supp
mkdir -p build/fuzz/findings
fail=0
for t in $targets; do
  mkdir -p "build/fuzz/new/$t"
  log="build/fuzz/findings/$t.log"
  if build/fuzz/fuzz_$t -max_total_time="$secs" -timeout=10 -rss_limit_mb=4096 -dict="fuzz/$t.dict" \
      -artifact_prefix="build/fuzz/findings/$t-" "build/fuzz/new/$t" "fuzz/corpus/$t" > "$log" 2>&1; then
    echo "fuzz $t: $(grep -o 'Done [0-9]* runs' "$log" | tail -1) in ${secs} s, no finding"
  else
    fail=1
    echo "fuzz $t: FINDING (log $log):"
    grep -v '^#\|^Warning' "$log" | grep -m1 -A12 'ERROR\|==[0-9]*==\|deadly signal\|timeout'
    ls build/fuzz/findings/$t-* 2> /dev/null
  fi
done
exit $fail
