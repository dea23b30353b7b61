#!/usr/bin/env bash
# The position-independent build (Makefile: -fPIC -fno-semantic-interposition for every object, so the static
# library, the binary and libconfsurf.so share one compile) against a build without it: OLD and NEW binaries,
# REPEAT alternating runs of a 10-iteration cgd flow on a level-5 bumped icosphere (20480 faces, explicit dual step
# so both builds take the same path); prints each run and the medians.
# Measured 2026-12-06 (quiet machine, 5 runs each): median 4.678 s (pic) against 4.673 s (no pic), ratio 1.001,
# inside both spreads (4.65-4.70 and 4.58-4.72); W equal to the last digit.
#   OLD=/path/to/nopic/confsurf NEW=bin/confsurf bash runs/bench_pic.sh
set -euo pipefail
OLD=${OLD:?set OLD to the binary built without -fPIC}; NEW=${NEW:-bin/confsurf}; REPEAT=${REPEAT:-5}
A="-task flow -gen icosphere -gen_level 5 -gen_deform_bump 0.2 -flow_max_it 10 -flow_rtol 0 -flow_t_mu 100"
out=$(mktemp)
for i in $(seq "$REPEAT"); do
  for v in old new; do
    b=$OLD; [ $v = new ] && b=$NEW
    s=$(date +%s.%N); "$b" $A > /dev/null; e=$(date +%s.%N)
    echo "$v $(echo "$e - $s" | bc)" | tee -a "$out"
  done
done
python3 - "$out" <<'PY'
import sys, statistics
t = {}
for l in open(sys.argv[1]):
    v, s = l.split(); t.setdefault(v, []).append(float(s))
m = {v: statistics.median(x) for v, x in t.items()}
print("median old %.3f s, new %.3f s, new/old %.3f" % (m["old"], m["new"], m["new"] / m["old"]))
PY
rm -f "$out"
