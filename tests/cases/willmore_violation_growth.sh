# Issue 21 item 4: a run whose constraint violation grows says so; it never ends out of the constraint set silently.
# The flow tracks the smallest and largest violation max(|C lambda - c0|_inf, global rows) of any evaluated state;
# the report prints "the constraint violation GREW ..." and the summary has violation_grew = true when the last
# state's violation is above -flow_ctol and 10x the smallest of the run (violation_min, violation_min_iteration,
# violation_max, violation_max_iteration give the numbers).
# (a) A run whose violation grows: eight_cgal (genus 2) with the step filter off (-flow_step_control false: every
#     explicit step accepted, as the paper's "explicit forward steps") and the resolution guard off, 25 iterations:
#     it starts in the class (0) and ends at 7e-4. Checked: not converged, violation_grew, the GREW line, and the
#     summary's numbers against the history written by the same run.
# (b) A converged run (bumpy icosphere level 2, default CGD): violation_grew false, no GREW line.
# (c) The guard's stop on eight_cgal, projected onto the constraints (-flow_project_at_stop): the end is in the class
#     (violation_grew false) while violation_max still reports the transient (> 1e-3 at an iteration >= 1). Serially
#     only: 8 s serially, 45 s for (a)-(c) on 2 ranks under load 19. With the dual step t_mu = 1e3 t (cgd's default
#     before issue 39): today's 1e5 t keeps the transient at 4.8e-5.
# nprocs: 1 2
source tests/lib.sh
M=meshes/eight_cgal.obj
run() { # name options...
  local n=$1; shift
  timeout 120 $MPIEXEC "$CS_BIN" -task flow "$@" -summary "$TMP/$n.json" -history_csv "$TMP/$n.csv" > "$TMP/$n.log" 2>&1 || { tail "$TMP/$n.log"; exit 1; }
}
run a -mesh $M -flow_step_control false -flow_max_area_ratio 0 -flow_max_it 25
run b -gen icosphere -gen_level 2 -gen_deform_bump 0.2 -flow_max_it 60
# (c) checks the report of a stop, which (a) and (b) already check on 2 ranks: serially only (the 30 s budget)
[ "$NP" = 1 ] && run c -mesh $M -flow_t_mu 1e3 -flow_max_it 50
python3 - "$TMP" <<'PY'
import csv, json, sys
d = sys.argv[1]
bad = 0
def load(n):
  s = json.load(open('%s/%s.json' % (d, n)))
  h = [max(float(r['conformal_violation']), float(r['constraint_violation'])) for r in csv.DictReader(open('%s/%s.csv' % (d, n)))]
  return s, h, open('%s/%s.log' % (d, n)).read()
def tf(x): return x in (True, 1, 'true')
sa, ha, la = load('a')
sb, hb, lb = load('b')
sc, hc, lc = load('c') if __import__('os').path.exists(d + '/c.json') else (None, None, None)
grew_hist = ha[-1] > max(1e-10, 10 * min(ha))
checks = [
  ("(a) step filter off: not converged, the violation at the end above ctol", not tf(sa['converged']) and sa['conformal_violation'] > 1e-10, (sa['stop_reason'], sa['conformal_violation'])),
  ("(a) the history shows growth (end > 10x the smallest of the run)", grew_hist, (min(ha), ha[-1])),
  ("(a) reported: violation_grew true and the GREW line", tf(sa['violation_grew']) and 'constraint violation GREW' in la, (sa['violation_grew'],)),
  ("(a) the summary's numbers are the history's (min, max, end)", abs(sa['violation_min'] - min(ha)) <= 1e-12 + 1e-9 * min(ha) and abs(sa['violation_max'] - max(ha)) <= 1e-9 * max(ha) and sa['violation_max_iteration'] == ha.index(max(ha)), (sa['violation_min'], min(ha), sa['violation_max'], max(ha), sa['violation_max_iteration'], ha.index(max(ha)))),
  ("(b) converged run: converged, violation_grew false, no GREW line", tf(sb['converged']) and not tf(sb['violation_grew']) and 'GREW' not in lb, (sb['stop_reason'], sb['violation_grew'], sb['conformal_violation'])),
]
if sc is not None: checks += [
  ("(c) guard's stop projected: in the class (< 1e-10), violation_grew false", sc['stop_reason'] == 'mesh_degenerate' and sc['conformal_violation'] < 1e-10 and not tf(sc['violation_grew']) and 'GREW' not in lc, (sc['stop_reason'], sc['conformal_violation'], sc['violation_grew'])),
  ("(c) the transient is still reported: violation_max > 1e-3 at an iteration >= 1", sc['violation_max'] > 1e-3 and sc['violation_max_iteration'] >= 1, (sc['violation_max'], sc['violation_max_iteration'])),
]
for name, ok, val in checks:
  print("%s: %s %s" % ("ok" if ok else "BAD", name, val))
  bad += not ok
sys.exit(1 if bad else 0)
PY
