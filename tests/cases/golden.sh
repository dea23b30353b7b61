#!/usr/bin/env bash
# nprocs: 1 2
# The golden regression suite (issue #23, tests/golden/): short runs of every options/*.opts and of each test's
# main command; their summaries and output meshes must agree with those stored from the binary before the
# redesign to 1e-10 relative. Guards every refactor: change a stored result only with a note in
# tests/golden/CHANGES.
. tests/lib.sh
# coverage: every options file has a case (or is named on a "# pending:" line of cases.txt), so a new file
# cannot drift outside the suite
missing=0
for f in options/*.opts; do
  b=$(basename "$f")
  grep -q "options/$b" tests/golden/cases.txt || grep -q "^# pending:.* $b" tests/golden/cases.txt || { echo "BAD: $f has no golden case"; missing=1; }
done
[ "$missing" = 0 ] || exit 1
python3 tests/golden/run.py --np "$NP" --bin "$CS_BIN"
