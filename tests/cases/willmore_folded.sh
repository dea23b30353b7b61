# issue 35: the stop reason `folded` (the fold guard, -flow_fold_guard, on for gd and newton; willmore_guards.c CSWFCheckFolds)
# reached by genuine inputs. Newton on the cow (meshes/cow_cgal.obj: 5804 faces, smallest angle 2.8 degrees):
# (a) -flow_newton_relax 0.05: the tangential relaxation after the accepted step of iteration 1 (newton's accept
#     hook, which moves the vertices after the trial step's check) turns a face over; the guard stops at iteration 2
#     with the last good state, the one iteration 1 ends with. -o holds exactly that state (compared with a run
#     stopped by -flow_max_it 1): finite, no face turned over against the input, no new crease, W below the input's.
# (b) -flow_newton_relax 0: no relaxation, the normal steps themselves grow a crease of more than 150 degrees between
#     two faces (iteration 10 on 1 and 2 ranks); -o holds the last good state: finite, no new crease against the input.
# (c) the default relaxation (0.3) turns faces over after the first accepted step: folded at iteration 1, and the
#     last good state is the input itself.
# Each: stop_reason folded, converged false, exit 0 (a stop reason, not an error; docs/willmore_flow.md), the
# guard's one-line message once, and the final line naming the reason.
# nprocs: 1 2
source tests/lib.sh
N="-task flow -flow_type newton -mesh meshes/cow_cgal.obj -flow_max_it 30"
run() { local n=$1; shift; timeout 120 $MPIEXEC "$CS_BIN" "$@" -summary "$TMP/$n.json" -o "$TMP/$n.obj" > "$TMP/$n.log" 2>&1 || { echo "BAD: $n exit $?"; tail "$TMP/$n.log"; exit 1; }; }
run a $N -flow_newton_relax 0.05
run a1 $N -flow_newton_relax 0.05 -flow_max_it 1
run b $N -flow_newton_relax 0
run c $N
python3 - "$TMP" meshes/cow_cgal.obj <<'PY'
import json, math, re, sys
sys.path.insert(0, 'scripts')
from objio import read_obj
d, inp = sys.argv[1], sys.argv[2]
v0, f0 = read_obj(inp)

def normals(v, f):
  out = []
  for a, b, c in f:
    u = [v[b][k] - v[a][k] for k in range(3)]
    w = [v[c][k] - v[a][k] for k in range(3)]
    out.append([u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]])
  return out

def creases(f, n, deg=150.0):
  """interior edges whose faces' unit normals are more than deg apart (the guard's test, computed here anew)"""
  lim, adj, out = math.cos(math.radians(deg)), {}, set()
  for i, (a, b, c) in enumerate(f):
    for e in ((a, b), (b, c), (c, a)):
      adj.setdefault(tuple(sorted(e)), []).append(i)
  for e, fs in adj.items():
    if len(fs) == 2:
      p, q = n[fs[0]], n[fs[1]]
      if sum(x * y for x, y in zip(p, q)) < lim * math.sqrt(sum(x * x for x in p) * sum(x * x for x in q)):
        out.add(e)
  return out

n0 = normals(v0, f0)
c0 = creases(f0, n0)

def state(name):
  v, f = read_obj('%s/%s.obj' % (d, name))
  n = normals(v, f)
  return {'v': v, 'finite': f == f0 and all(math.isfinite(x) for p in v for x in p),
          'turned': sum(1 for a, b in zip(n0, n) if not sum(x * y for x, y in zip(a, b)) > 0), 'new_creases': len(creases(f, n) - c0)}

s = {k: json.load(open('%s/%s.json' % (d, k))) for k in ('a', 'a1', 'b', 'c')}
log = {k: open('%s/%s.log' % (d, k)).read() for k in ('a', 'b', 'c')}
o = {k: state(k) for k in ('a', 'a1', 'b')}
FOLD = re.compile(r'^flow: the surface folds at iteration (\d+): enclosed volume \S+ \(input \S+\), (\d+) faces turned over since the last accepted state, (\d+) new creases of more than 150 degrees between neighbouring faces \(-flow_fold_guard\)\. Stopping with the last good state$', re.M)
checks = []
for k in ('a', 'b', 'c'):
  m = FOLD.findall(log[k])
  checks += [
    ("(%s) stop_reason folded, not converged, state last" % k, s[k]['stop_reason'] == 'folded' and s[k]['converged'] in (False, 'false') and s[k]['state'] == 'last', (s[k]['stop_reason'], s[k]['converged'], s[k]['state'])),
    ("(%s) the guard's one-line message, once, at the stop's iteration" % k, len(m) == 1 and int(m[0][0]) == s[k]['iterations'], m),
    ("(%s) the final line names the reason" % k, 'NOT converged after %d iterations (folded;' % s[k]['iterations'] in log[k], None),
  ]
ma, mb = FOLD.findall(log['a']), FOLD.findall(log['b'])
dmax = max(abs(x - y) for p, q in zip(o['a']['v'], o['a1']['v']) for x, y in zip(p, q))
checks += [
  ("(a) the relaxation turned a face over at iteration 2", ma and ma[0][0] == '2' and int(ma[0][1]) > 0 and s['a']['iterations'] == 2, ma),
  ("(a) -o is the state iteration 1 ended with (max |dx| %.1e; W %.10g = %.10g)" % (dmax, s['a']['willmore'], s['a1']['willmore']), dmax <= 1e-9 and abs(s['a']['willmore'] - s['a1']['willmore']) <= 1e-9 * s['a1']['willmore'], None),
  ("(a) -o: finite, no face turned over against the input, no new crease", o['a']['finite'] and o['a']['turned'] == 0 and o['a']['new_creases'] == 0, (o['a']['turned'], o['a']['new_creases'])),
  ("(a) W fell before the fold", s['a']['energy'] < s['a']['energy_initial'], (s['a']['energy_initial'], s['a']['energy'])),
  ("(b) a crease grew, no face turned over within a step, after several iterations", mb and int(mb[0][1]) == 0 and int(mb[0][2]) > 0 and s['b']['iterations'] >= 5, mb),
  ("(b) -o: finite, no new crease against the input, W below the input's", o['b']['finite'] and o['b']['new_creases'] == 0 and s['b']['energy'] < s['b']['energy_initial'], (o['b']['new_creases'], o['b']['turned'], s['b']['energy'])),
  ("(c) default relaxation: folded at iteration 1, the last good state is the input", s['c']['iterations'] == 1 and abs(s['c']['energy'] - s['c']['energy_initial']) <= 1e-12 * s['c']['energy_initial'], (s['c']['iterations'], s['c']['energy'], s['c']['energy_initial'])),
]
bad = 0
for name, ok, v in checks:
  print(("ok  " if ok else "BAD ") + name + ("" if v is None else ": " + repr(v))); bad += not ok
sys.exit(bad)
PY
