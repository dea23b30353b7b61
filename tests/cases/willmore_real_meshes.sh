# The constrained Willmore flow on the real meshes of issue 22 (docs/real_meshes.md): the test of the diagnosis,
# not of convergence, which this vertex method does not reach on them.
# eight_cgal (genus 2, 315 vertices): fins.
# (a) Default CGD: the violation never exceeds the ceiling -flow_vmax (1e-2) at any iteration (before the
#     second-order correction and the ceiling it reached 4e-3 here and 0.9 on knot1_cgal, growing 1.7x per step),
#     and the run stops, not converged, as mesh_degenerate, reported as fins: a face's quasi-conformal error is
#     past -flow_fin_q (3), i.e. the discrete conformal factor jumps across faces.
# (b) The degeneration lies inside the exact constraint set: PGD, which projects every iterate back onto it
#     (|C lambda - c0|_inf < 1e-10 at every iteration), still lowers W by blowing a few vertices out into large flat
#     triangles: the vertex areas relative to the input spread past 200 and the largest quasi-conformal error of a
#     face grows past 20 while W falls and the Euler-Lagrange residual grows. So the stop in (a) is the discrete
#     problem's own degeneration on this mesh, not constraint drift.
# (c) The energy itself: unconstrained Sobolev descent (gd) of the same discrete W (soliman2021 Eq. 28) on the same
#     mesh goes below 2 pi^2, under which no closed surface of genus >= 1 lies (Marques-Neves for embedded ones,
#     Li-Yau's 8 pi for the others). On this connectivity Eq. 28 rewards the degeneration.
# knot1_cgal (genus 1), elephant_cgal (genus 3), bunny_lowres_npm (genus 0): smooth squeezes.
# (d) Default CGD decreases W, keeps the violation under the ceiling at every iteration and stops, not converged,
#     as mesh_degenerate with every face keeping its shape (q_max <= 3): reported as a smooth concentration. The
#     stopped state is projected onto the constraints (-flow_project_at_stop): the result lies in the input's
#     conformal class to 1e-10 (so does eight_cgal's in (a)).
# (e) With the Moebius gauge fixed (-flow_constraint_mobius) knot1 and the bunny stop the same way, reported as a
#     squeeze: the concentration is no slide along a Moebius orbit but the conformal squeeze of part of the surface
#     (the bunny's ears toward the round sphere, the trefoil's outer bends), which the mesh cannot resolve.
#     (The elephant does the same, measured in docs/real_meshes.md, but takes 76 s, too long for the suite.)
# (f) The bunny's unconstrained descent of Eq. 28 goes below 4 pi (Willmore's bound for every closed surface).
# nprocs: 1 2
source tests/lib.sh
M=meshes/eight_cgal.obj
timeout 300 $MPIEXEC "$CS_BIN" -task flow -mesh $M -flow_max_it 150 -summary "$TMP/a.json" -history_csv "$TMP/a.csv" > "$TMP/a.log" 2>&1 || { tail "$TMP/a.log"; exit 1; }
grep -q "mesh resolution collapse at iteration" "$TMP/a.log" || { echo "BAD: no guard message"; tail -3 "$TMP/a.log"; exit 1; }
timeout 300 $MPIEXEC "$CS_BIN" -task flow -flow_type pgd -mesh $M -flow_max_it 90 -flow_max_area_ratio 0 -summary "$TMP/b.json" -history_csv "$TMP/b.csv" > "$TMP/b.log" 2>&1 || { tail "$TMP/b.log"; exit 1; }
for m in knot1_cgal elephant_cgal bunny_lowres_npm; do
  timeout 300 $MPIEXEC "$CS_BIN" -task flow -mesh meshes/$m.obj -flow_max_it 100 -summary "$TMP/$m.json" -history_csv "$TMP/$m.csv" > "$TMP/$m.log" 2>&1 || { tail "$TMP/$m.log"; exit 1; }
  grep -q "mesh resolution collapse at iteration" "$TMP/$m.log" || { echo "BAD: $m: no guard message"; tail -3 "$TMP/$m.log"; exit 1; }
done
for m in knot1_cgal bunny_lowres_npm; do
  timeout 300 $MPIEXEC "$CS_BIN" -task flow -mesh meshes/$m.obj -flow_max_it 100 -flow_constraint_mobius -summary "$TMP/$m.mob.json" > "$TMP/$m.mob.log" 2>&1 || { tail "$TMP/$m.mob.log"; exit 1; }
done
# (c/f) is about the infimum of the discrete energy, not the step control: -flow_max_step 0 is the uncapped descent
# (gd's geometric step cap of issue #19 only makes it take more iterations: the bunny passes 4 pi at iteration 70
# instead of ~40), with the default fold guard, which no longer takes the flattening of the bunny's ears for a fold
timeout 300 $MPIEXEC "$CS_BIN" -task flow -flow_type gd -mesh $M -flow_max_it 200 -flow_max_area_ratio 0 -flow_max_step 0 -summary "$TMP/eight.gd.json" -history_csv "$TMP/eight.gd.csv" > "$TMP/eight.gd.log" 2>&1 || { tail "$TMP/eight.gd.log"; exit 1; }
timeout 300 $MPIEXEC "$CS_BIN" -task flow -flow_type gd -mesh meshes/bunny_lowres_npm.obj -flow_max_it 60 -flow_max_area_ratio 0 -flow_max_step 0 -summary "$TMP/bunny.gd.json" -history_csv "$TMP/bunny.gd.csv" > "$TMP/bunny.gd.log" 2>&1 || { tail "$TMP/bunny.gd.log"; exit 1; }
python3 - "$TMP" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
bad = 0
for m in ('knot1_cgal', 'elephant_cgal', 'bunny_lowres_npm'):
  s = json.load(open(d + '/%s.json' % m))
  h = list(csv.DictReader(open(d + '/%s.csv' % m)))
  v = max(float(r['conformal_violation']) for r in h)
  checks = [
    ("(d) %s: not converged, stopped as mesh_degenerate" % m, s['stop_reason'] == 'mesh_degenerate' and s['converged'] in (False, 0, 'false'), (s['stop_reason'], s['iterations'])),
    ("(d) %s: W decreased" % m, s['energy'] < s['energy_initial'], (s['energy_initial'], s['energy'])),
    ("(d) %s: violation <= 1e-2 at every iteration" % m, v <= 1e-2, v),
    ("(d) %s: every face keeps its shape (q_max <= 3), reported as smooth" % m, s['q_max'] <= 3 and s['degeneration'] == 'smooth', (s['q_max'], s['degeneration'])),
    ("(d) %s: the stopped state projected onto the constraints (violation < 1e-10)" % m, s['conformal_violation'] < 1e-10, s['conformal_violation']),
  ]
  if m != 'elephant_cgal':
    g = json.load(open(d + '/%s.mob.json' % m))
    checks += [("(e) %s, Moebius gauge fixed: stopped as mesh_degenerate, reported as a squeeze" % m, g['stop_reason'] == 'mesh_degenerate' and g['degeneration'] == 'squeeze' and g['q_max'] <= 3, (g['stop_reason'], g['degeneration'], g['q_max'], g['iterations'])),
               ("(e) %s, Moebius gauge fixed: W decreased" % m, g['energy'] < g['energy_initial'], (g['energy_initial'], g['energy']))]
  for name, good, val in checks:
    print(("ok  " if good else "BAD ") + name + ": " + repr(val)); bad += not good
# (c), (f): the unconstrained energy below the smooth lower bounds
for m, bound, label in (('eight', 2 * math.pi ** 2, '2 pi^2'), ('bunny', 4 * math.pi, '4 pi')):
  h = [float(r['energy']) for r in csv.DictReader(open(d + '/%s.gd.csv' % m))]
  good = min(h) < bound and h[-1] < bound
  print(("ok  " if good else "BAD ") + "(c/f) %s: unconstrained descent of Eq. 28 goes below %s = %.4f" % (m, label, bound) + ": " + repr((h[0], h[-1]))); bad += not good
# the fold guard (on) does not take the flattening of the bunny's ears for a fold (issue #19)
g = json.load(open(d + '/bunny.gd.json'))
good = g['stop_reason'] != 'folded'
print(("ok  " if good else "BAD ") + "(f) bunny: the fold guard lets the ears flatten: " + repr((g['stop_reason'], g['iterations']))); bad += not good
if bad: sys.exit(bad)
PY
python3 - "$TMP" <<'PY'
import csv, json, sys
d = sys.argv[1]
a, b = (json.load(open(d + '/%s.json' % k)) for k in 'ab')
ha, hb = (list(csv.DictReader(open(d + '/%s.csv' % k))) for k in 'ab')
va = max(float(r['conformal_violation']) for r in ha)
vb = max(float(r['conformal_violation']) for r in hb)
Wb = [float(r['energy']) for r in hb]
checks = [
  ("(a) cgd: not converged, stopped as mesh_degenerate", a['stop_reason'] == 'mesh_degenerate' and a['converged'] in (False, 0, 'false'), (a['stop_reason'], a['iterations'])),
  ("(a) cgd: violation <= -flow_vmax (1e-2) at every iteration", va <= 1e-2, va),
  ("(a) cgd: area_spread reported beyond the guard's 200", a['area_spread'] > 200, a['area_spread']),
  ("(a) cgd: reported as fins (q_max past -flow_fin_q 3)", a['degeneration'] == 'fins' and a['q_max'] > 3, (a['degeneration'], a['q_max'])),
  ("(a) cgd: the stopped state projected onto the constraints (violation < 1e-10), W still below the input's", a['conformal_violation'] < 1e-10 and a['energy'] < a['energy_initial'] - 5, (a['conformal_violation'], a['energy_initial'], a['energy'])),
  ("(b) pgd: violation < 1e-10 at every iteration", vb < 1e-10, vb),
  ("(b) pgd: W falls", Wb[-1] < Wb[0] - 5, (Wb[0], Wb[-1])),
  ("(b) pgd: vertex areas spread past 200", float(hb[-1]['area_spread']) > 200, hb[-1]['area_spread']),
  ("(b) pgd: largest quasi-conformal error past 20", float(hb[-1]['q_max']) > 20 and b['q_max'] > 20, (hb[-1]['q_max'], b['q_max'])),
  ("(b) pgd: Euler-Lagrange residual grows (no critical point ahead)", float(hb[-1]['el_residual']) > float(hb[30]['el_residual']), (hb[30]['el_residual'], hb[-1]['el_residual'])),
]
bad = 0
for name, good, v in checks:
  print(("ok  " if good else "BAD ") + name + ": " + repr(v)); bad += not good
sys.exit(bad)
PY
