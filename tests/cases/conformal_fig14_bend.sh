#!/usr/bin/env bash
# crane2013 Fig. 14 top (Sec. 6.3.1): rotated binormals at the top of a cylinder produce a bend. A cylinder (r 1,
# height 2, 16 x 12), V = B on both rims, V~ = B of the same cylinder bent by 40 deg (tests/tools/bend_cylinder.py:
# top binormals turned by 40 deg, bottom ones kept), rho = 0 (-flow_curvature_factor 0): the result's top rim plane
# is tilted by 40 deg (to 0.2; measured 40.04) against its bottom one, both rims stay planar (1e-3 of their size;
# 1.2e-4) and the run converges (converged_rtol, 8 steps). Without a target (V~ = V) factor 0 is the identity (W to
# 1e-12, q_max - 1 below 1e-10).
# nprocs: 1 2
source tests/lib.sh
PY=$(bash scripts/find-python.sh)
timeout 60 "$CS_BIN" -task info -gen cylinder -gen_n 16 -gen_m 12 -gen_height 2 -o "$TMP/cyl.obj" > "$TMP/in.log" 2>&1 || { tail -3 "$TMP/in.log"; exit 1; }
python3 tests/tools/bend_cylinder.py "$TMP/cyl.obj" "$TMP/bent.obj" 40
C="-task flow -flow_type conformal -mesh $TMP/cyl.obj -flow_boundary vector -flow_boundary_frame 0,0,1 -flow_curvature_factor 0 -flow_max_it 30"
timeout 60 $MPIEXEC "$CS_BIN" $C -flow_target_mesh "$TMP/bent.obj" -o "$TMP/out.obj" -summary "$TMP/bend.json" > "$TMP/bend.log" 2>&1 || { tail -3 "$TMP/bend.log"; exit 1; }
timeout 60 $MPIEXEC "$CS_BIN" $C -flow_max_it 3 -flow_rtol 0 -summary "$TMP/id.json" > "$TMP/id.log" 2>&1 || { tail -3 "$TMP/id.log"; exit 1; }
"$PY" - "$TMP" <<'PY'
import json, sys
import numpy as np
d = sys.argv[1]
bad = 0
def check(ok, msg):
    global bad
    print(("ok   " if ok else "BAD  ") + msg); bad += not ok
def obj(p):
    return np.array([[float(t) for t in l.split()[1:4]] for l in open(p) if l.startswith("v ")])
x0, x = obj(f"{d}/cyl.obj"), obj(f"{d}/out.obj")
def plane(rim):  # unit normal of the best plane through the rim, and its flatness (smallest / largest singular value)
    P = x[rim] - x[rim].mean(0)
    _, s, vt = np.linalg.svd(P)
    return vt[2], s[2] / s[0]
top, bot = np.abs(x0[:, 2] - x0[:, 2].max()) < 1e-9, np.abs(x0[:, 2] - x0[:, 2].min()) < 1e-9
(nt, ft), (nb, fb) = plane(top), plane(bot)
tilt = np.degrees(np.arccos(min(1, abs(nt @ nb))))
check(abs(tilt - 40) < 0.2, f"top rim tilted against the bottom one by {tilt:.3f} deg (target 40)")
check(ft < 1e-3 and fb < 1e-3, f"rims planar: {ft:.2g}, {fb:.2g}")
s = json.load(open(f"{d}/bend.json"))
check(s["stop_reason"] == "converged_rtol", f"stop {s['stop_reason']} after {s['iterations']} steps, q_mean {s['q_mean']:.4f}")
i = json.load(open(f"{d}/id.json"))
check(abs(i["willmore"] - i["willmore_initial"]) <= 1e-12 * i["willmore_initial"] and i["q_max"] - 1 < 1e-10, f"factor 0 without a target: W {i['willmore_initial']:.12g} -> {i['willmore']:.12g}, q_max - 1 {i['q_max'] - 1:.2g}")
sys.exit(bad)
PY
