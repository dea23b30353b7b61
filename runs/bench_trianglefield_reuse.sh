#!/usr/bin/env bash
# The flow's Poisson reconstruction kept alive across evaluations (CSTriangleFieldReconstruction, branch poisson15)
# against the one-shot reconstruction at every evaluation: two binaries, BEFORE and AFTER, run alternately REPS times
# (default 3) on the square lattice tau = i, N x N (default 12 24), 30 omega-flow iterations with -flow_rtol 0, and
# -log_view. Per run: KSPs and Mats created, MatCholFctrSym / MatCholFctrNum counts, the flow's seconds per iteration
# and the process CPU seconds (user + sys); the medians per build, and whether the summaries agree (all keys but
# the times). Usage: BEFORE=/path/old/confsurf AFTER=bin/confsurf bash runs/bench_trianglefield_reuse.sh
set -euo pipefail
cd "$(dirname "$0")/.."
BEFORE=${BEFORE:?path of the binary before}; AFTER=${AFTER:-bin/confsurf}; SIZES=${SIZES:-"12 24"}; REPS=${REPS:-3}
tmp=$(mktemp -d)
for n in $SIZES; do
  for r in $(seq 1 $REPS); do
    for v in before after; do
      b=$BEFORE; [ $v = after ] && b=$AFTER
      /usr/bin/time -f "%U %S" -o $tmp/time.$v.$n.$r $b -task flow -gen lattice -gen_tau 0,1 -gen_n $n -gen_m $n \
        -flow_type trianglefield -flow_max_it 30 -flow_rtol 0 -log_view -summary $tmp/s.$v.$n.$r.json > $tmp/log.$v.$n.$r 2>&1
    done
  done
done
/usr/bin/python3 - $tmp "$SIZES" $REPS <<'PY'
import json, re, statistics, sys
tmp, sizes, reps = sys.argv[1], sys.argv[2].split(), int(sys.argv[3])
def count(log, pat):
    m = re.search(pat, log, re.M)
    return int(m.group(1)) if m else 0
print("| lattice | build | KSPs created | Mats created | MatCholFctrSym | MatCholFctrNum | s/iteration (median of %d) | process CPU s (median) | summary = before |" % reps)
print("|---|---|---|---|---|---|---|---|---|")
for n in sizes:
    ref = json.load(open(f"{tmp}/s.before.{n}.1.json"))
    for v in ("before", "after"):
        rows = []
        for r in range(1, reps + 1):
            log = open(f"{tmp}/log.{v}.{n}.{r}").read()
            s = json.load(open(f"{tmp}/s.{v}.{n}.{r}.json"))
            u, y = map(float, open(f"{tmp}/time.{v}.{n}.{r}").read().split()[-2:])
            same = all(s.get(k) == ref[k] for k in ref if 'second' not in k and k != 'time')
            rows.append((count(log, r"^\s*Krylov Solver\s+(\d+)"), count(log, r"^\s*Matrix\s+(\d+)"),
                         count(log, r"^MatCholFctrSym\s+(\d+)"), count(log, r"^MatCholFctrNum\s+(\d+)"),
                         s['seconds_per_iteration'], u + y, same))
        k, mt, fs, fn = rows[0][:4]
        print("| %s x %s | %s | %d | %d | %d | %d | %.4f | %.2f | %s |" % (n, n, v, k, mt, fs, fn,
              statistics.median(r[4] for r in rows), statistics.median(r[5] for r in rows),
              "yes" if all(r[6] for r in rows) else "NO"))
PY
rm -rf $tmp
