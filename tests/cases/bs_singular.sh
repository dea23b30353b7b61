# bobenko-schroeder2005 Sec. 3.2, vanishing betas. -bs_singular single: where exactly one beta at a vertex
# vanishes, the paper's steepest descent direction instead of the eps heuristic; -bs_singular delta: the paper's
# delta minimisation at every vertex with one or several. The unit program checks CSBSSingularDescent against the
# paper's definition of delta by brute force over the sphere (and the closed form for one). On the twice linearly
# subdivided coarse torus (flat subdivided quads: 256 vertices with one vanishing beta, 128 with several) both
# rules change the flow, delta differently from single (it acts at the 128), and the distributed computation (each
# vertex of a vanishing diamond counted by one rank, the lists gathered on the owner) gives the same history on 1
# and 2 ranks. On the generator's curvature-line torus (every diagonal co-circular) delta >= 0 at every vertex (the
# paper's no-descent case): delta stops converged after one step with W unchanged, where the heuristic stalls.
# nprocs: 1
source tests/lib.sh
"$CS_TESTS/test_bs_singular"
M=tests/data/bs_torus_coarse2.obj
"$CS_BIN" -task flow -flow_type bs -mesh $M -bs_max_it 3 -history_csv "$TMP/h.csv" > /dev/null
for r in single delta; do
  "$CS_BIN" -task flow -flow_type bs -mesh $M -bs_max_it 3 -bs_singular $r -history_csv "$TMP/${r}1.csv" > /dev/null
  mpirun -n 2 "$CS_BIN" -task flow -flow_type bs -mesh $M -bs_max_it 3 -bs_singular $r -history_csv "$TMP/${r}2.csv" > /dev/null
done
T="-task flow -flow_type bs -gen torus -gen_n 32 -gen_m 16 -bs_max_it 5"
"$CS_BIN" $T -summary "$TMP/th.json" > /dev/null
"$CS_BIN" $T -bs_singular delta -summary "$TMP/td.json" > /dev/null
python3 - "$TMP" <<'PY'
import sys
d = sys.argv[1]
W = lambda f: [float(l.split(",")[1]) for l in list(open(d + "/" + f))[1:]]
h = W("h.csv")
bad = 0
for r in ("single", "delta"):
    s1, s2 = W(r + "1.csv"), W(r + "2.csv")
    diff = max(abs(a - b) for a, b in zip(s1, s2))
    for ok, msg in ((len(s1) == 4 and abs(s1[-1] - h[-1]) > 1e-3 * h[-1], "%s acts: W %.6g vs %.6g (heuristic)" % (r, s1[-1], h[-1])),
                    (len(s1) == len(s2) and diff < 1e-9 * s1[0], "%s: 1 and 2 ranks agree (max diff %.1e)" % (r, diff)),
                    (all(s1[i + 1] < s1[i] for i in range(3)), "%s: W falls: " % r + " ".join("%.5g" % w for w in s1))):
        print(("ok  " if ok else "BAD ") + msg); bad += not ok
s, t = W("single1.csv"), W("delta1.csv")
ok = abs(s[1] - t[1]) > 1e-3 * s[1]
print(("ok  " if ok else "BAD ") + "delta differs from single after step 1 (several vanishing betas): %.6g vs %.6g" % (t[1], s[1])); bad += not ok
import json
th, td = json.load(open(d + "/th.json")), json.load(open(d + "/td.json"))
ok = th["stop_reason"] == "stalled" and td["stop_reason"] == "converged" and td["iterations"] == 1 and td["willmore_bs"] == th["willmore_bs"]
print(("ok  " if ok else "BAD ") + "curvature-line torus: heuristic %s, delta %s after %d step(s), W %.10g and %.10g" % (th["stop_reason"], td["stop_reason"], td["iterations"], th["willmore_bs"], td["willmore_bs"])); bad += not ok
sys.exit(bad)
PY
