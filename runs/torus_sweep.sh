#!/usr/bin/env bash
# Study (not a test), issue 35: the default constrained Willmore flow (CGD, guard on) on remeshed (irregular)
# tori of revolution R/r = 2, 2.5, 3, 4 (rectangular class b = sqrt(R^2/r^2 - 1)), one twisted class and,
# optionally, a genus-2 input; docs/real_meshes.md "Issue 35: the three findings".
# Per torus: the smooth torus is written by `-gen torus -gen_n 160 -gen_m 80` (fine enough that the remesher only
# samples it), remeshed isotropically to ~$FACES faces, and flowed for $MAXIT iterations:
#   bin/confsurf -task flow -mesh torus_R.obj -flow_max_it $MAXIT -summary S.json -history_csv H.csv -o out.obj $EXTRA
# The twisted class: a chiral torus (runs/chiral_torus.py: an elliptic tube whose ellipse turns once around the
# axis; no mirror symmetry, so Re tau != 0; a tube estimate gives Im tau ~ 4.3), remeshed. (The structured
# -gen lattice class on an irregular mesh, runs/lattice_lengths.py, does not work as a start: from the remeshed
# torus of revolution no step reaches a twisted class, the isothermic degeneracy of docs/triangle_fields.md.)
# GENUS2=FILE adds that closed genus-2 mesh (remeshed the same way; meshes/genus2_theta.obj: a fat theta, docs/real_meshes.md
# "Issue 35" section 5), flowed with the Moebius gauge (-flow_constraint_mobius) as well as without.
# The table (markdown) goes to runs/results/torus_sweep.md: W at the stop against pi^2 (b + 1/b) (the homogeneous
# torus of class b) and 8 pi, stop reason, iteration, area spread, q_max, violation, EL.
# Knobs (environment):
#   FACES=7000  remesh target    MAXIT=400    EXTRA=""   further flow options
#   REMESH=""   a command "REMESH in.obj out.obj FACES" to use instead of the code's own -mesh_remesh
#               (the session of issue 35 measured with a standalone CGAL isotropic_remeshing program before
#               -mesh_remesh was merged)
set -u
cd "$(dirname "$0")/.."
FACES=${FACES:-7000}; MAXIT=${MAXIT:-400}; EXTRA=${EXTRA:-}; REMESH=${REMESH:-}; GENUS2=${GENUS2:-}
BIN=$PWD/bin/confsurf
PY=$(bash scripts/find-python.sh) || exit 1
dir=runs/results/torus_sweep; md=runs/results/torus_sweep.md
mkdir -p "$dir"

remesh() { # in out
  if [ -n "$REMESH" ]; then $REMESH "$1" "$2" "$FACES" > "$2.log" 2>&1
  else "$BIN" -task info -mesh "$1" -mesh_remesh "$FACES" -o "$2" > "$2.log" 2>&1; fi
}

row() { # name b extra-flow-options...
  local name=$1 b=$2; shift 2
  "$BIN" -task flow -mesh "$dir/$name.obj" -flow_max_it "$MAXIT" -summary "$dir/$name.json" \
    -history_csv "$dir/$name.csv" -o "$dir/${name}_out.obj" "$@" $EXTRA > "$dir/$name.log" 2>&1
  "$PY" - "$dir/$name.json" "$dir/$name.csv" "$name" "$b" >> "$md" <<'PYEOF'
import json, math, sys
s = json.load(open(sys.argv[1]))
rows = [l.strip().split(',') for l in open(sys.argv[2]) if l.strip()]
h = dict(zip(rows[0], rows[-1]))
b = float(sys.argv[4])
ref = "%.4f" % (math.pi ** 2 * (b + 1 / b)) if b > 0 else "-"
g = lambda k, f="%.3g": f % s[k] if k in s and isinstance(s[k], (int, float)) else str(s.get(k, "-"))
print("| %s | %s | %d | %s | %s | %s | %.4f | %s | %s | %s | %s | %s |" % (
    sys.argv[3], "%.4f" % b if b > 0 else "-", int(s.get("faces", s.get("nf", 0)) or 0), g("energy_initial", "%.4f"),
    g("energy", "%.5f"), ref, 8 * math.pi, s.get("stop_reason", "-") + ("" if s.get("degeneration", "none") == "none" else " (" + s["degeneration"] + ")"), s.get("iterations", "-"),
    "%.3g" % float(h.get("area_spread", "nan")), "%.4g" % float(h.get("q_max", "nan")),
    "%.2g / %.2g" % (float(h.get("conformal_violation", "nan")), float(h.get("el_residual", "nan")))))
PYEOF
}

{ echo "# torus sweep, $(date -u +%F' '%H:%M) UTC, commit $(git rev-parse --short HEAD), FACES=$FACES MAXIT=$MAXIT EXTRA='$EXTRA' REMESH='$REMESH'"
  echo
  echo "| input | b | F | W input | W stop | pi^2 (b+1/b) | 8 pi | reason | it. | area spread | q_max | violation / EL |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"; } >> "$md"
for q in 2 2.5 3 4; do
  "$BIN" -task info -gen torus -gen_torus_R "$q" -gen_tube_r 1 -gen_n 160 -gen_m 80 -o "$dir/smooth_$q.obj" > /dev/null 2>&1
  remesh "$dir/smooth_$q.obj" "$dir/torus_$q.obj"
  row "torus_$q" "$("$PY" -c "import math; print(math.sqrt($q * $q - 1))")"
done
"$PY" runs/chiral_torus.py "$dir/smooth_chiral.obj"
remesh "$dir/smooth_chiral.obj" "$dir/twisted.obj"
row twisted 0
if [ -n "$GENUS2" ]; then remesh "$GENUS2" "$dir/genus2.obj"; row genus2 0
  cp "$dir/genus2.obj" "$dir/genus2_mobius.obj"; row genus2_mobius 0 -flow_constraint_mobius; fi
echo >> "$md"
cat "$md"
