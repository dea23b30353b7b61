# Checkpoint/resume of the triangle-field flow (trianglefield_state.c): on the 12 x 12 square lattice from -flow_init
# smooth with the Moebius rows and -flow_t_mu_final (switched on at iteration 18), 20 iterations straight give the
# same result as 10 with -checkpoint (-checkpoint_every 4) followed by -resume for the rest on the same ranks: final
# W, EL residual, conformal violation within 1e-10 (measured: bit-identical), the same iteration count, and the
# history rows after the resume likewise. Across rank counts (written here, resumed on the other count) the file is
# rank-independent: a resume at the checkpoint's own iteration writes the same fields back bit for bit, and the state
# evaluates to the writer's history row to 1e-10. Whole runs on 1 and 2 ranks differ at the saddle solve's Krylov
# tolerance (measured ~1e-7 after 20 iterations, with or without a checkpoint), so the cross-rank continuation is
# compared with tight solves (-flow_saddle_ksp_rtol 1e-13, no kept factorisation): 1e-9 (measured 4e-10).
# Bad input: a vertex-flow checkpoint for a triangle-field run and the inverse, one of another mesh (on every rank
# count); of another start (-flow_seed), an old version, and -flow_variables spinor (not stored; serially: the
# same collective checks as in flow_resume.sh and harden_files.sh).
# nprocs: 1 2
source tests/lib.sh
if [ "$NP" = 1 ]; then OTHER="mpirun -n 2"; else OTHER="mpirun -n 1"; fi
run() { timeout 60 "$@" > "$TMP/run.log" 2>&1 || { tail -20 "$TMP/run.log"; exit 1; }; }
L="-task flow -flow_type trianglefield -gen lattice -gen_tau 0,1 -gen_n 12 -gen_m 12 -flow_init smooth -flow_init_amplitude 1 -flow_constraint_mobius -flow_t_mu_final 4e9 -flow_t_mu_final_el 0.1"
TIGHT="-flow_saddle_ksp_rtol 1e-13 -flow_factor_reuse_its 0"

# 1. the same ranks, default solver
run $MPIEXEC "$CS_BIN" $L -flow_max_it 20 -summary "$TMP/full.json" -history_csv "$TMP/full.csv"
run $MPIEXEC "$CS_BIN" $L -flow_max_it 10 -checkpoint "$TMP/c.ck" -checkpoint_every 4 -history_csv "$TMP/split.csv"
[ "$(grep -c "wrote checkpoint" "$TMP/run.log")" = 3 ] || { echo "BAD: expected checkpoints at 4, 8 and 10"; exit 1; }
run $MPIEXEC "$CS_BIN" $L -flow_max_it 20 -resume "$TMP/c.ck" -summary "$TMP/res.json" -history_csv "$TMP/split.csv"
grep -q "resumed from checkpoint .* at iteration 10" "$TMP/run.log" || { echo "BAD: no resume line"; exit 1; }
grep -q "iteration 18: EL residual .* below -flow_t_mu_final_el" "$TMP/run.log" || { echo "BAD: the t_mu_final switch not at 18 after the resume"; exit 1; }

# 2. across rank counts: written here (tight solves), resumed on the other count; and a resume that takes no step
run $MPIEXEC "$CS_BIN" $L $TIGHT -flow_max_it 20 -summary "$TMP/tfull.json" -history_csv "$TMP/tfull.csv"
run $MPIEXEC "$CS_BIN" $L $TIGHT -flow_max_it 10 -checkpoint "$TMP/t.ck" -history_csv "$TMP/tsplit.csv"
run $OTHER "$CS_BIN" $L $TIGHT -flow_max_it 20 -resume "$TMP/t.ck" -summary "$TMP/tres.json" -history_csv "$TMP/tsplit.csv"
run $OTHER "$CS_BIN" $L -flow_max_it 10 -resume "$TMP/t.ck" -checkpoint "$TMP/t2.ck" # no step: no solver options

python3 - "$TMP" <<'PY'
import csv, json, struct, sys
t = sys.argv[1]
keys = ("energy", "el_residual", "conformal_violation")
rel = lambda a, b, floor=0.0: abs(a - b) / max(abs(a), floor, 1e-300)
def final(a, b):
  a, b = json.load(open(t + a)), json.load(open(t + b))
  return max(rel(a[k], b[k]) for k in keys), a["iterations"], b["iterations"]
def rows(a, b, first):  # rows from `first` on; violations relative to at least 1e-6 (they reach 1e-9 and below)
  ha, hb = list(csv.DictReader(open(t + a))), list(csv.DictReader(open(t + b)))
  cols = ("energy", "area", "volume", "el_residual", "conformal_violation", "constraint_violation", "t", "rejections")
  d = max(rel(float(r[k]), float(s[k]), 1e-6 if "violation" in k else 0) for r, s in zip(ha, hb) if int(r["it"]) >= first for k in cols)
  return d, [r["it"] for r in ha] == [r["it"] for r in hb]
def ckpt(p):
  b = open(t + p, "rb").read(); h = b.index(b"end_header\n") + 11
  head = dict(l.split(" ", 1) for l in b[:h].decode().split("\n")[1:-2])
  n = int(head["payload_bytes"]) // 8
  return int(head["scalars"]), struct.unpack("<%dd" % n, b[h:h + 8 * n])
ds, ia, ib = final("/full.json", "/res.json")
dh, same = rows("/full.csv", "/split.csv", 11)
dt, ta, tb = final("/tfull.json", "/tres.json")
d10, _ = rows("/tfull.csv", "/tsplit.csv", 10)
ns, p1 = ckpt("/t.ck"); _, p2 = ckpt("/t2.ck")
# the scalars: [2 fingerprints (the second, a sum, is ~0), flow kind, t, t_mu, rejections, its, its, guard, seconds,
# ...]: all but the seconds, relative to at least 1
dsc = max(rel(a, b, 1.0) for i, (a, b) in enumerate(zip(p1[:ns], p2[:ns])) if i != 9)
dfield = max(abs(a - b) for a, b in zip(p1[ns:], p2[ns:]))
checks = [
  ("same ranks: final W, EL, conformal violation agree (max rel %.2e <= 1e-10)" % ds, ds <= 1e-10),
  ("same ranks: iterations %s == %s" % (ia, ib), ia == ib == 20),
  ("same ranks: history rows after the resume agree (max rel %.2e <= 1e-10), same iteration numbers" % dh, dh <= 1e-10 and same),
  ("other ranks: the resumed state's row at iteration 10 and after agree with the writer's run (max rel %.2e <= 1e-9)" % d10, d10 <= 1e-9),
  ("other ranks: final W, EL, conformal violation (tight solves; max rel %.2e <= 1e-9)" % dt, dt <= 1e-9),
  ("other ranks: iterations %s == %s" % (ta, tb), ta == tb == 20),
  ("other ranks: a resume without steps writes the same %d fields back (max diff %.1e == 0; scalars rel %.1e <= 1e-12)" % (len(p1) - ns, dfield, dsc), len(p1) == len(p2) and dfield == 0 and dsc <= 1e-12),
]
bad = 0
for name, ok in checks:
  print(("ok   " if ok else "BAD  ") + name); bad += not ok
sys.exit(bad)
PY

# 4. bad input: clear errors naming the file
C="-task flow -flow_type cgd -gen lattice -gen_tau 0,1 -gen_n 12 -gen_m 12"
run $MPIEXEC "$CS_BIN" $C -flow_max_it 1 -checkpoint "$TMP/v.ck"
EXPECT="-resume .*v.ck: stores 3 values per vertex, 1 per edge and 0 per face, this run 0, 110 and 34" expect_fail timeout 60 $MPIEXEC "$CS_BIN" $L -resume "$TMP/v.ck"
EXPECT="-resume .*c.ck: stores 0 values per vertex, 110 per edge and 34 per face, this run 3, 1 and 0" expect_fail timeout 60 $MPIEXEC "$CS_BIN" $C -resume "$TMP/c.ck"
EXPECT="-resume .*c.ck: written for 144 vertices, 432 edges and 288 faces, the mesh has 168" expect_fail timeout 60 $MPIEXEC "$CS_BIN" $L -gen_n 14 -resume "$TMP/c.ck"
if [ "$NP" = 1 ]; then
  EXPECT="-resume .*c.ck: the checkpoint was written by a run from other input positions" expect_fail timeout 60 $MPIEXEC "$CS_BIN" $L -flow_seed 2 -resume "$TMP/c.ck"
  python3 -c "import sys; d = open(sys.argv[1], 'rb').read(); open(sys.argv[2], 'wb').write(d.replace(b'confsurf-checkpoint 4', b'confsurf-checkpoint 3', 1))" "$TMP/c.ck" "$TMP/old.ck"
  EXPECT="-resume .*old.ck: version 3, this program reads version 4" expect_fail timeout 60 $MPIEXEC "$CS_BIN" $L -resume "$TMP/old.ck"
  EXPECT="-checkpoint/-resume with -flow_variables spinor: the variables \(u, psi\) are not stored" expect_fail timeout 60 $MPIEXEC "$CS_BIN" -task flow -flow_type trianglefield -gen lattice -gen_tau 0,1 -gen_n 12 -gen_m 12 -flow_variables spinor -checkpoint "$TMP/s.ck"
fi
