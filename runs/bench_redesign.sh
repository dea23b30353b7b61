#!/usr/bin/env bash
# Benchmark (not a test) of the redesign of issue 23: the same work through the binary from before the redesign
# (OLD, e.g. a build of commit b83cb41 in a git worktree) and the current one (NEW, default bin/confsurf), runs
# alternating OLD, NEW, OLD, NEW, ... so the drift of this VM falls on both; medians of REPEAT runs (default 5).
# Cases (moderate sizes so the whole study takes minutes):
#   cgd    constrained Willmore flow, bumpy stretched icosphere level 5 (20k faces), 5 iterations:
#          summary seconds_per_iteration, serial and 2 ranks
#   spin   spin transformation of a painted bump on a 64x64 torus: seconds_setup + seconds_eigen +
#          seconds_poisson, serial and 2 ranks
#   bs     Bobenko-Schroeder semi-implicit flow on meshes/bunny_closed_cgal.obj (75k faces), 3 steps: the
#          summary seconds_per_step, serial
#   info   read + distribute + energy summary of the bunny: wall seconds of the whole run, serial
# The options were renamed by the redesign; each case lists both spellings. Writes runs/results/bench_redesign.md.
#   git worktree add /tmp/pre b83cb41 && make -C /tmp/pre -j2
#   OLD=/tmp/pre/bin/confsurf bash runs/bench_redesign.sh
# A later redesign step compares two builds that share the option names: OLD_OPTIONS=new gives OLD the new
# spellings (issue 37: OLD=<build of 7d1ad92> OLD_OPTIONS=new; the results of 2026-12-06 in runs/bench_redesign2.md).
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
OLD=${OLD:?set OLD to the binary from before the redesign}
NEW=${NEW:-$PWD/bin/confsurf}
REPEAT=${REPEAT:-5}
OUT=${OUT:-runs/results/bench_redesign.md}
mkdir -p runs/results
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

CGD_OLD="-task flow -gen icosphere -gen_level 5 -flow_init_bump 0.2 -flow_init_stretch 1.5,1,0.8 -flow_max_it 5 -flow_rtol 0"
CGD_NEW="-task flow -gen icosphere -gen_level 5 -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8 -flow_max_it 5 -flow_rtol 0"
SPIN="-task spin -gen torus -gen_n 64 -gen_m 64 -rho_bump_center 1.4,0,0 -rho_bump_radius 0.3 -rho_bump_height 3"
BS="-task flow -flow_type bs -mesh meshes/bunny_closed_cgal.obj -bs_max_it 3"
INFO="-task info -mesh meshes/bunny_closed_cgal.obj"
[ "${OLD_OPTIONS:-old}" = new ] && CGD_OLD=$CGD_NEW

# run LABEL NP BIN ARGS...: appends "LABEL value" to $T/times
run() {
  local label=$1 np=$2 bin=$3; shift 3
  local launch=""; [ "$np" = 1 ] || launch="mpirun -n $np"
  local t0 t1
  t0=$(date +%s.%N)
  $launch "$bin" "$@" -summary "$T/s.json" > "$T/log" 2>&1 || { tail -5 "$T/log"; exit 1; }
  t1=$(date +%s.%N)
  /usr/bin/env python3 - "$label" "$T/s.json" "$t0" "$t1" >> "$T/times" <<'PY'
import json, sys
label, path, t0, t1 = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
s = json.load(open(path))
case = label.split()[0]
if case.startswith("cgd"): v = s["seconds_per_iteration"]
elif case.startswith("spin"): v = s["seconds_setup"] + s["seconds_eigen"] + s["seconds_poisson"]
elif case.startswith("bs"): v = s["seconds_per_step"]
else: v = t1 - t0
print(label, v)
PY
}

for r in $(seq 1 "$REPEAT"); do
  for np in 1 2; do
    run "cgd_np$np old" $np "$OLD" $CGD_OLD; run "cgd_np$np new" $np "$NEW" $CGD_NEW
    run "spin_np$np old" $np "$OLD" $SPIN;   run "spin_np$np new" $np "$NEW" $SPIN
  done
  run "bs_np1 old" 1 "$OLD" $BS;     run "bs_np1 new" 1 "$NEW" $BS
  run "info_np1 old" 1 "$OLD" $INFO; run "info_np1 new" 1 "$NEW" $INFO
  echo "round $r of $REPEAT done"
done

/usr/bin/env python3 - "$T/times" "$REPEAT" > "$OUT" <<'PY'
import sys, statistics
rows = {}
for line in open(sys.argv[1]):
    case, var, v = line.split()
    rows.setdefault(case, {}).setdefault(var, []).append(float(v))
print("# Redesign benchmark (runs/bench_redesign.sh): medians of %s alternating runs, seconds\n" % sys.argv[2])
print("| case | before (median) | after (median) | after/before | before min-max | after min-max |")
print("|---|---|---|---|---|---|")
for case, d in rows.items():
    o, n = d["old"], d["new"]
    mo, mn = statistics.median(o), statistics.median(n)
    print("| %s | %.4f | %.4f | %.3f | %.4f-%.4f | %.4f-%.4f |" % (case, mo, mn, mn / mo, min(o), max(o), min(n), max(n)))
PY
cat "$OUT"
