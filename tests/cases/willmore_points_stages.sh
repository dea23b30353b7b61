# issue 39 (Fig. 18): -flow_points_stages K moves the point targets from the input's positions to the file's in K
# stages (src/methods/willmore/willmore_points_continuation.c). The level-2 icosphere (162 vertices) through the six
# octahedron vertices, the +x one moved to (1, 0.2, 0.2) (0.28, about 1.5 edges, off the start):
#  direct: CGD from the sphere does not converge (measured: diverged at iteration 2, W 279; the first steps trade the
#   points' violation for class violation, docs/willmore_flow.md "Fig. 18");
#  K = 10: converges (measured 194 iterations, W 14.8824106, q_max 1.15), the points met to 1e-10 of the file's
#   targets, the class to 1e-10, the 9 stage ends reported in order;
#  pgd: directly it does not start (measured: diverged at iteration 0, W 284); with K = 10 each stage begins with PGD's
#   projection onto its targets and the run goes on (40 iterations: stop max_it, stages ended; to convergence it
#   takes 182, W 14.882410623 as CGD's);
#  checkpoint: stopped at iteration 30 inside a stage and resumed to 60: the resumed run continues that stage (the next
#   stage end it reports is that stage's) and its history rows agree with the straight run's (W, violations, t to
#   1e-8); a resume with another K is refused by name.
# Bad values and combinations: one clear line, non-zero exit on every rank.
# Cost: 6 s serial, 31 s on 2 ranks before PGD and all but one refusal became serial-only (under load 6-7; 194 + 30 + 30 iterations: the convergence and the exact resume
# need them). -flow_factor_reuse_its 0 in every run: a resumed run starts with a new factorisation where the straight
# run may keep an earlier one, and the kept factors moved the history by 5e-7 (docs of tests/cases/flow_resume.sh).
# nprocs: 1 2
source tests/lib.sh
G="-task flow -gen icosphere -gen_level 2 -flow_type cgd -flow_max_it 400 -flow_factor_reuse_its 0"
printf '41 1 0.2 0.2\n21 -1 0 0\n16 0 1 0\n36 0 -1 0\n25 0 0 1\n28 0 0 -1\n' > "$TMP/p.txt"
run() { local n=$1; shift; timeout 120 $MPIEXEC "$CS_BIN" $G -flow_constraint_points "$TMP/p.txt" "$@" -summary "$TMP/$n.json" > "$TMP/$n.log" 2>&1 || { tail "$TMP/$n.log"; exit 1; }; }
run direct
run staged -flow_points_stages 10 -o "$TMP/staged.obj" -history_csv "$TMP/staged.csv"
run part -flow_points_stages 10 -flow_max_it 30 -checkpoint "$TMP/c.ck" -history_csv "$TMP/split.csv"
run resumed -flow_points_stages 10 -flow_max_it 60 -resume "$TMP/c.ck" -history_csv "$TMP/split.csv"
# PGD and most refusals serially only (the suite's budget): the 2-rank run keeps the staged CGD, the resume and one refusal
if [ "$NP" = 1 ]; then
  run pgd_direct -flow_type pgd
  run pgd -flow_type pgd -flow_points_stages 10 -flow_max_it 40
fi
python3 - "$TMP" <<'PY'
import csv, json, re, sys
d = sys.argv[1]
import os
S = {k: json.load(open('%s/%s.json' % (d, k))) for k in ('direct', 'staged', 'part', 'resumed', 'pgd_direct', 'pgd') if os.path.exists('%s/%s.json' % (d, k))}
log = {k: open('%s/%s.log' % (d, k)).read() for k in S}
X = [[float(t) for t in l.split()[1:4]] for l in open(d + '/staged.obj') if l.startswith('v ')]
miss = max(abs(X[int(p[0])][c] - float(p[1 + c])) for p in (l.split() for l in open(d + '/p.txt')) for c in range(3))
ends = [int(k) for k in re.findall(r'point stage (\d+) of 10 converged', log['staged'])]
stop = re.search(r'stopped in point stage (\d+) of 10', log['part'])
first = re.search(r'point stage (\d+) of 10 ', log['resumed'])
conv = lambda s: s['converged'] in (True, 1, 'true')
ha, hb = list(csv.DictReader(open(d + '/staged.csv'))), list(csv.DictReader(open(d + '/split.csv')))
rel = lambda a, b, f: abs(a - b) / max(abs(a), f)
cols = {'energy': 1.0, 'conformal_violation': 1e-6, 'constraint_violation': 1e-6, 't': 1.0, 'rejections': 1.0}
hd = max(rel(float(r[k]), float(q[k]), f) for r, q in zip(ha, hb) for k, f in cols.items())
checks = [
  ("direct: not converged", not conv(S['direct']), (S['direct']['stop_reason'], S['direct']['iterations'])),
  ("staged: converged", conv(S['staged']), (S['staged']['stop_reason'], S['staged']['iterations'], S['staged']['willmore'])),
  ("staged: the points met to 1e-10 of the file's targets", miss < 1e-10, miss),
  ("staged: class kept to 1e-10", S['staged']['conformal_violation'] < 1e-10, S['staged']['conformal_violation']),
  ("staged: stages 1..9 ended in order", ends == list(range(1, 10)), ends),
  ("part: stopped inside a stage, said so", S['part']['stop_reason'] == 'max_it' and stop is not None, stop and stop.group(0)),
  ("resumed: continues that stage", stop is not None and first is not None and first.group(1) == stop.group(1), first and first.group(0)),
  ("resumed: history rows 0..60 agree with the straight run's (max rel %.1e <= 1e-8)" % hd, [r['it'] for r in hb] == [str(i) for i in range(61)] and hd <= 1e-8, len(hb)),
]
if 'pgd' in S:
  checks += [
    ("pgd direct: not converged", not conv(S['pgd_direct']), (S['pgd_direct']['stop_reason'], S['pgd_direct']['iterations'])),
    ("pgd staged: goes on to max_it, stages ended", S['pgd']['stop_reason'] == 'max_it' and len(re.findall(r'point stage \d+ of 10 converged', log['pgd'])) >= 2, (S['pgd']['stop_reason'], len(re.findall(r'point stage \d+ of 10 converged', log['pgd'])))),
  ]
bad = 0
for name, good, v in checks:
    print(("ok  " if good else "BAD ") + name + ": " + repr(v)); bad += not good
sys.exit(bad)
PY
C="$G -flow_constraint_points $TMP/p.txt"
EXPECT="-resume: the checkpoint was written with -flow_points_stages 10, this run has 20" expect_fail timeout 30 $MPIEXEC "$CS_BIN" $C -flow_points_stages 20 -resume "$TMP/c.ck"
[ "$NP" = 1 ] || exit 0
EXPECT="-resume: the checkpoint was written with -flow_points_stages 10, this run has 0" expect_fail timeout 30 $MPIEXEC "$CS_BIN" $C -resume "$TMP/c.ck"
EXPECT="-flow_points_stages -2: use 0 \(off\) or a count of stages" expect_fail timeout 30 $MPIEXEC "$CS_BIN" $C -flow_points_stages -2
EXPECT="-flow_points_stages" expect_fail timeout 30 $MPIEXEC "$CS_BIN" $C -flow_points_stages ten
EXPECT="-flow_points_stage_rtol 0: must be > 0" expect_fail timeout 30 $MPIEXEC "$CS_BIN" $C -flow_points_stages 4 -flow_points_stage_rtol 0
EXPECT="-flow_points_stages 4: moves the targets of -flow_constraint_points, which is not given" expect_fail timeout 30 $MPIEXEC "$CS_BIN" $G -flow_points_stages 4
EXPECT="-flow_points_stages: not available for -flow_type trianglefield" expect_fail timeout 30 $MPIEXEC "$CS_BIN" $C -flow_type trianglefield -flow_points_stages 4
